#pragma once
// Which accelerator a render uses: the Embree BVH or the textbook loop over
// every object. The command line and the scene file name it in words
// (renderer/render_option_names.h); the renderer passes this enum.

#include <memory>

#include "renderer/accel/accel_options.h"

namespace raylab {

class Accelerator;
struct Scene;

enum class AcceleratorKind { Embree, Naive };

/// "embree" or "naive": the word of --accel and of the scene file's
/// "render"."accel", and the built accelerator's Accelerator::name().
const char* acceleratorName(AcceleratorKind kind);

/// Builds the accelerator of `kind` over `scene`, which must outlive it.
std::unique_ptr<Accelerator> makeAccelerator(AcceleratorKind kind, const Scene& scene,
                                             const AccelOptions& options = {});

}  // namespace raylab
