// EmbreeAccel: the one adapter between dayphoton and Embree 3 (STYLE.md A.9). Only
// embree_accel.cpp includes <embree3/rtcore.h>; this header forward-declares Embree's handle
// types (as Mitsuba's accel_embree.h does), so an Embree 3 -> 4 change stays in one file.
//
// It holds one device and one scene with a single triangle mesh; the primitive id Embree
// returns is the index of the triangle in the arrays given to the constructor (Scene keeps
// the primitive -> surface map).
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "dayphoton/engine/ray.h"

struct RTCDeviceTy;
struct RTCSceneTy;

namespace dayphoton::engine {

struct EmbreeErrorSink;  // records the first error Embree's callback reports

/// Raw single-precision hit as Embree reports it.
struct AccelHit {
  float t = 0;
  float u = 0, v = 0;
  std::uint32_t primitive = 0;
};

class EmbreeAccel {
 public:
  /// Build and commit a robust-mode scene of triangles: `vertices_xyz` holds 3 floats per
  /// vertex, `indices` 3 vertex indices per triangle. Throws EngineError if Embree reports
  /// an error (through the device error callback) at any step.
  EmbreeAccel(const std::vector<float>& vertices_xyz, const std::vector<std::uint32_t>& indices);
  ~EmbreeAccel();
  EmbreeAccel(const EmbreeAccel&) = delete;
  EmbreeAccel& operator=(const EmbreeAccel&) = delete;

  /// Closest hit in [ray.tmin, ray.tmax] (converted to float).
  bool intersect(const Ray& ray, AccelHit& hit) const;
  bool occluded(const Ray& ray) const;

 private:
  std::unique_ptr<EmbreeErrorSink> m_errors;
  RTCDeviceTy* m_device = nullptr;
  RTCSceneTy* m_scene = nullptr;
};

}  // namespace dayphoton::engine
