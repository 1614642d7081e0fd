#include <stdexcept>

#include "renderer/accel/accelerator.h"
#include "renderer/accel/embree_factory.h"
#include "renderer/accel/naive_accelerator.h"

namespace raylab {

std::unique_ptr<Accelerator> makeAccelerator(const std::string& name, const Scene& scene,
                                             const AccelOptions& options) {
    if (name == "embree") return makeEmbreeAccelerator(scene, options);
    if (name == "naive") return std::make_unique<NaiveAccelerator>(scene, options);
    throw std::invalid_argument("unknown accelerator '" + name + "' (expected embree or naive)");
}

void validateShapes(const Scene& scene, const char* accelName) {
    for (const Object& o : scene.objects) {
        if (!o.shape) continue;
        try {
            o.shape->validate();
        } catch (const std::invalid_argument& e) {
            throw std::invalid_argument(std::string(accelName) + ": object '" + o.name + "' (" +
                                        o.shape->kind() + "): " + e.what());
        }
    }
}

}  // namespace raylab
