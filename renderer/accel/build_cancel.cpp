#include "renderer/accel/build_cancel.h"

#include "renderer/cancel.h"

namespace raylab {

namespace {

// Called concurrently from Embree's build threads: a relaxed atomic load only.
bool continueBuild(void*, double) { return !cancelRequested(); }

}  // namespace

void cancelBuildOnRequest(RTCScene scene) {
    rtcSetSceneProgressMonitorFunction(scene, &continueBuild, nullptr);
}

}  // namespace raylab
