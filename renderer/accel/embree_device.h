#pragma once
// RAII owners of Embree handles. The device installs its error callback right
// after rtcNewDevice; Embree reports errors through that callback (it returns
// no status codes), and check() turns a reported error into an exception.
// Only renderer/accel/embree_*.cpp (and code that replays rays through
// EmbreeAccelerator::rtcHandle) include this header.

#include <embree3/rtcore.h>

#include <mutex>
#include <string>

namespace raylab {

/// Owns one RTCDevice. Not copyable or movable: the error callback keeps a
/// pointer to this object.
class EmbreeDevice {
public:
    /// \brief Creates the device with the given rtcNewDevice configuration string.
    /// \details Pass "" for the default. A "threads=" setting is rejected: Embree
    ///   turns it into a process-wide tbb::global_control that would also
    ///   throttle the renderer's own parallel loop (NUMERICS.md §2).
    /// \throws std::invalid_argument for a "threads=" config, std::runtime_error
    ///   when Embree cannot create the device.
    explicit EmbreeDevice(const std::string& config = "");
    ~EmbreeDevice();
    EmbreeDevice(const EmbreeDevice&) = delete;
    EmbreeDevice& operator=(const EmbreeDevice&) = delete;

    /// The raw handle (owned by this object).
    RTCDevice get() const { return m_device; }

    /// \brief Throws std::runtime_error ("embree: <code>: <message> (during
    ///   <what>)") if Embree reported an error since the last check, and
    ///   clears it. Call after every Embree API call that can fail.
    void check(const char* what) const;

private:
    static void onError(void* self, RTCError code, const char* message);

    RTCDevice m_device = nullptr;
    mutable std::mutex m_mutex;     ///< guards m_pending (callbacks may run on any thread)
    mutable std::string m_pending;  ///< first unreported error, or empty
};

/// Owns one RTCScene (the scene keeps its device alive by reference count).
class EmbreeScene {
public:
    /// Creates an empty scene on the device; errors surface in device.check().
    explicit EmbreeScene(const EmbreeDevice& device);
    ~EmbreeScene();
    EmbreeScene(const EmbreeScene&) = delete;
    EmbreeScene& operator=(const EmbreeScene&) = delete;

    /// The raw handle (owned by this object).
    RTCScene get() const { return m_scene; }

private:
    RTCScene m_scene = nullptr;
};

/// Owns one RTCGeometry until it is attached to a scene and released.
class EmbreeGeometry {
public:
    /// Creates a geometry of the given type; errors surface in device.check().
    EmbreeGeometry(const EmbreeDevice& device, RTCGeometryType type);
    ~EmbreeGeometry();
    EmbreeGeometry(const EmbreeGeometry&) = delete;
    EmbreeGeometry& operator=(const EmbreeGeometry&) = delete;

    /// The raw handle (owned by this object).
    RTCGeometry get() const { return m_geometry; }

private:
    RTCGeometry m_geometry = nullptr;
};

/// Human-readable name of an Embree error code ("RTC_ERROR_INVALID_ARGUMENT").
const char* embreeErrorName(RTCError code);

}  // namespace raylab
