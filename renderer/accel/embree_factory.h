#pragma once
// Builds the Embree back end without exposing <embree3/rtcore.h> to the
// caller (make_accelerator.cpp); embree_accelerator.h has the full class.

#include <memory>

#include "renderer/accel/accelerator.h"
#include "renderer/scene.h"

namespace raylab {

/// An EmbreeAccelerator over `scene` (which must outlive it), default device.
std::unique_ptr<Accelerator> makeEmbreeAccelerator(const Scene& scene, const AccelOptions& options);

}  // namespace raylab
