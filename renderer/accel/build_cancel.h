#pragma once
// Lets a stop request (renderer/cancel.h) cancel an Embree BVH build, which
// can take tens of seconds on a large scene: Embree polls a scene's progress
// monitor during the build and abandons it (RTC_ERROR_CANCELLED, reported by
// rtcCommitScene through the device's error callback) when it returns false.

#include <embree3/rtcore.h>

namespace raylab {

/// Installs the monitor on `scene`; every EmbreeScene gets it on creation.
void cancelBuildOnRequest(RTCScene scene);

}  // namespace raylab
