#include "renderer/accelerator_kind.h"

#include "renderer/accel/accelerator.h"

namespace raylab {

const char* acceleratorName(AcceleratorKind kind) {
    return kind == AcceleratorKind::Naive ? "naive" : "embree";
}

std::unique_ptr<Accelerator> makeAccelerator(AcceleratorKind kind, const Scene& scene,
                                             const AccelOptions& options) {
    return makeAccelerator(acceleratorName(kind), scene, options);
}

}  // namespace raylab
