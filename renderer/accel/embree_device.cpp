#include "renderer/accel/embree_device.h"

#include "renderer/accel/build_cancel.h"

#include <algorithm>
#include <cctype>
#include <sstream>
#include <stdexcept>

namespace raylab {

namespace {

/// Whether a comma-separated rtcNewDevice config sets the key "threads".
bool setsThreads(const std::string& config) {
    std::istringstream in(config);
    std::string item;
    while (std::getline(in, item, ',')) {
        std::string key = item.substr(0, item.find('='));
        key.erase(std::remove_if(key.begin(), key.end(),
                                 [](unsigned char c) { return std::isspace(c) != 0; }),
                  key.end());
        if (key == "threads") return true;
    }
    return false;
}

}  // namespace

const char* embreeErrorName(RTCError code) {
    switch (code) {
        case RTC_ERROR_NONE:
            return "RTC_ERROR_NONE";
        case RTC_ERROR_UNKNOWN:
            return "RTC_ERROR_UNKNOWN";
        case RTC_ERROR_INVALID_ARGUMENT:
            return "RTC_ERROR_INVALID_ARGUMENT";
        case RTC_ERROR_INVALID_OPERATION:
            return "RTC_ERROR_INVALID_OPERATION";
        case RTC_ERROR_OUT_OF_MEMORY:
            return "RTC_ERROR_OUT_OF_MEMORY";
        case RTC_ERROR_UNSUPPORTED_CPU:
            return "RTC_ERROR_UNSUPPORTED_CPU";
        case RTC_ERROR_CANCELLED:
            return "RTC_ERROR_CANCELLED";
    }
    return "RTC_ERROR_?";
}

EmbreeDevice::EmbreeDevice(const std::string& config) {
    if (setsThreads(config))
        throw std::invalid_argument(
            "embree: 'threads' device config would limit the whole process's TBB "
            "parallelism; set the thread count with tbb::global_control instead");
    m_device = rtcNewDevice(config.empty() ? nullptr : config.c_str());
    if (!m_device) {
        // Device creation failures are only reported through the null device.
        throw std::runtime_error(std::string("embree: cannot create device (") +
                                 embreeErrorName(rtcGetDeviceError(nullptr)) + ")");
    }
    // Installed before any other call, so no error goes unreported. The
    // callback only records: throwing through Embree's C API is not safe.
    rtcSetDeviceErrorFunction(m_device, &EmbreeDevice::onError, this);
}

EmbreeDevice::~EmbreeDevice() { rtcReleaseDevice(m_device); }

void EmbreeDevice::onError(void* self, RTCError code, const char* message) {
    auto* device = static_cast<EmbreeDevice*>(self);
    std::lock_guard<std::mutex> lock(device->m_mutex);
    if (device->m_pending.empty())
        device->m_pending =
            std::string(embreeErrorName(code)) + ": " + (message ? message : "(no message)");
}

void EmbreeDevice::check(const char* what) const {
    std::string error;
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        error.swap(m_pending);
    }
    if (!error.empty()) throw std::runtime_error("embree: " + error + " (during " + what + ")");
}

EmbreeScene::EmbreeScene(const EmbreeDevice& device) : m_scene(rtcNewScene(device.get())) {
    if (m_scene) cancelBuildOnRequest(m_scene);  // a stop request ends the build
}

EmbreeScene::~EmbreeScene() {
    if (m_scene) rtcReleaseScene(m_scene);
}

EmbreeGeometry::EmbreeGeometry(const EmbreeDevice& device, RTCGeometryType type)
    : m_geometry(rtcNewGeometry(device.get(), type)) {}

EmbreeGeometry::~EmbreeGeometry() {
    if (m_geometry) rtcReleaseGeometry(m_geometry);
}

}  // namespace raylab
