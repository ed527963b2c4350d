// The Embree 3 adapter: the only file that includes <embree3/rtcore.h> (STYLE.md A.9).
//
// Follows Embree's documented discipline (Embree 3 API reference: rtcNewDevice,
// rtcSetDeviceErrorFunction, rtcCommitScene, rtcIntersect1, rtcOccluded1; and the
// tutorials/minimal example's structure):
//  - one device per scene, an error callback installed before anything else; the callback
//    only records the first error (it must not throw through Embree's C frames), and
//    check() turns it into EngineError after the Embree call returned;
//  - geometry is created, filled, committed and attached, then the scene is committed, and
//    only then queried (commit-then-query); a committed scene is never modified, so queries
//    are thread-safe;
//  - RTC_SCENE_FLAG_ROBUST: watertight triangle tests (no leaks through shared edges and
//    vertices of a closed room), at a small speed cost. Measured with Embree 3.13.5: without
//    it, 465 of 1e5 rays aimed at the edges and corners of a closed unit box escaped, and 91
//    of 1e5 in the office (tests/engine/scene_test.cpp, ClosedBoxIsWatertight and
//    OfficeWithWindowIsClosed); with it, none. RTC_BUILD_QUALITY_HIGH since a
//    scene is built once and traced 1e7..1e9 times.
#include "embree_accel.h"

#include <embree3/rtcore.h>

#include <cstring>
#include <mutex>
#include <sstream>
#include <string>

#include "dayphoton/engine/engine_error.h"

namespace dayphoton::engine {

std::string embree_error_name(int embree_code) {
  switch (embree_code) {
    case RTC_ERROR_NONE: return "RTC_ERROR_NONE";
    case RTC_ERROR_UNKNOWN: return "RTC_ERROR_UNKNOWN";
    case RTC_ERROR_INVALID_ARGUMENT: return "RTC_ERROR_INVALID_ARGUMENT";
    case RTC_ERROR_INVALID_OPERATION: return "RTC_ERROR_INVALID_OPERATION";
    case RTC_ERROR_OUT_OF_MEMORY: return "RTC_ERROR_OUT_OF_MEMORY";
    case RTC_ERROR_UNSUPPORTED_CPU: return "RTC_ERROR_UNSUPPORTED_CPU";
    case RTC_ERROR_CANCELLED: return "RTC_ERROR_CANCELLED";
  }
  return "RTC_ERROR_" + std::to_string(embree_code);
}

EngineError embree_error(int embree_code, const std::string& message) {
  return EngineError("Embree error " + embree_error_name(embree_code) + ": " +
                         (message.empty() ? std::string("(no message)") : message),
                     embree_code);
}

/// First error reported by Embree's callback since the last check.
struct EmbreeErrorSink {
  std::mutex mutex;
  RTCError code = RTC_ERROR_NONE;
  std::string message;

  static void callback(void* user, RTCError code, const char* message) {
    auto* self = static_cast<EmbreeErrorSink*>(user);
    std::lock_guard<std::mutex> lock(self->mutex);
    if (self->code != RTC_ERROR_NONE) return;  // keep the first, it explains the rest
    self->code = code;
    self->message = message ? message : "";
  }

  /// Throw the recorded error (if any) as EngineError and clear it.
  void check() {
    std::lock_guard<std::mutex> lock(mutex);
    if (code == RTC_ERROR_NONE) return;
    const EngineError error = embree_error(code, message);
    code = RTC_ERROR_NONE;
    message.clear();
    throw error;
  }
};

namespace {

/// A device with `sink` as its error callback; throws if Embree cannot create one.
RTCDevice new_device(EmbreeErrorSink* sink) {
  RTCDevice device = rtcNewDevice(nullptr);
  if (!device) {
    // Device creation errors go to the thread's error slot (rtcGetDeviceError(NULL)).
    throw embree_error(rtcGetDeviceError(nullptr), "rtcNewDevice failed");
  }
  rtcSetDeviceErrorFunction(device, &EmbreeErrorSink::callback, sink);
  return device;
}

RTCRay to_rtc_ray(const Ray& ray) {
  RTCRay r;
  r.org_x = static_cast<float>(ray.origin.x);
  r.org_y = static_cast<float>(ray.origin.y);
  r.org_z = static_cast<float>(ray.origin.z);
  r.dir_x = static_cast<float>(ray.direction.x);
  r.dir_y = static_cast<float>(ray.direction.y);
  r.dir_z = static_cast<float>(ray.direction.z);
  r.tnear = static_cast<float>(ray.tmin);
  r.tfar = static_cast<float>(ray.tmax);  // +inf stays +inf
  r.time = 0.0f;
  r.mask = 0xFFFFFFFFu;
  r.id = 0;
  r.flags = 0;
  return r;
}

}  // namespace

EmbreeAccel::EmbreeAccel(const std::vector<float>& vertices_xyz,
                         const std::vector<std::uint32_t>& indices)
    : m_errors(std::make_unique<EmbreeErrorSink>()) {
  m_device = new_device(m_errors.get());
  try {
    m_scene = rtcNewScene(m_device);
    m_errors->check();
    rtcSetSceneFlags(m_scene, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(m_scene, RTC_BUILD_QUALITY_HIGH);
    m_errors->check();

    const std::size_t vertex_count = vertices_xyz.size() / 3;
    const std::size_t triangle_count = indices.size() / 3;
    if (triangle_count > 0) {
      RTCGeometry geometry = rtcNewGeometry(m_device, RTC_GEOMETRY_TYPE_TRIANGLE);
      m_errors->check();
      // Embree-owned buffers: Embree pads them as its SIMD loads require.
      auto* vertex_buffer = static_cast<float*>(rtcSetNewGeometryBuffer(
          geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float),
          vertex_count));
      auto* index_buffer = static_cast<std::uint32_t*>(rtcSetNewGeometryBuffer(
          geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(std::uint32_t),
          triangle_count));
      if (!vertex_buffer || !index_buffer) {
        rtcReleaseGeometry(geometry);
        m_errors->check();
        throw EngineError("Embree returned no geometry buffer");
      }
      std::memcpy(vertex_buffer, vertices_xyz.data(), vertex_count * 3 * sizeof(float));
      std::memcpy(index_buffer, indices.data(), triangle_count * 3 * sizeof(std::uint32_t));
      rtcCommitGeometry(geometry);
      rtcAttachGeometry(m_scene, geometry);  // geomID 0
      rtcReleaseGeometry(geometry);          // the scene holds the reference now
      m_errors->check();
    }
    rtcCommitScene(m_scene);
    m_errors->check();
  } catch (...) {
    if (m_scene) rtcReleaseScene(m_scene);
    rtcReleaseDevice(m_device);
    throw;
  }
}

EmbreeAccel::~EmbreeAccel() {
  if (m_scene) rtcReleaseScene(m_scene);
  if (m_device) rtcReleaseDevice(m_device);
}

bool EmbreeAccel::intersect(const Ray& ray, AccelHit& hit) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit query;
  query.ray = to_rtc_ray(ray);
  query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  query.hit.primID = RTC_INVALID_GEOMETRY_ID;
  query.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(m_scene, &context, &query);
  if (query.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
  hit.t = query.ray.tfar;
  hit.u = query.hit.u;
  hit.v = query.hit.v;
  hit.primitive = query.hit.primID;
  return true;
}

bool EmbreeAccel::occluded(const Ray& ray) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay query = to_rtc_ray(ray);
  rtcOccluded1(m_scene, &context, &query);
  // Embree marks an occluded ray by setting tfar to -inf.
  return query.tfar < 0.0f;
}

std::string embree_version() {
  RTCDevice device = rtcNewDevice(nullptr);
  if (!device) return RTC_VERSION_STRING " (headers; no device)";
  const ssize_t v = rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_VERSION);
  rtcReleaseDevice(device);
  // Encoded as major * 10000 + minor * 100 + patch (rtcore_config.h, RTC_VERSION).
  std::ostringstream s;
  s << v / 10000 << '.' << (v / 100) % 100 << '.' << v % 100;
  return s.str();
}

namespace detail {
void provoke_embree_error() {
  EmbreeErrorSink sink;
  RTCDevice device = new_device(&sink);
  // No geometry type has this value: Embree rejects it with RTC_ERROR_INVALID_ARGUMENT
  // (or INVALID_OPERATION) through the callback and returns NULL.
  RTCGeometry geometry = rtcNewGeometry(device, static_cast<RTCGeometryType>(0x7fff));
  if (geometry) rtcReleaseGeometry(geometry);
  try {
    sink.check();
  } catch (...) {
    rtcReleaseDevice(device);
    throw;
  }
  rtcReleaseDevice(device);
  throw EngineError("Embree accepted an invalid geometry type without reporting an error");
}
}  // namespace detail

}  // namespace dayphoton::engine
