// Sensor support: whether a sensor lies on a surface, and whether that surface stores
// photons. The surface estimate (daylight_coefficients.h) reads the photons stored where a
// sensor lies, so it is meaningful only for a sensor on a surface with a diffuse component,
// facing away from it; a final gather (final_gather.h) works anywhere. `check` and `run` use
// this to say how each sensor set is estimated and to refuse a surface estimate that would
// silently read nothing.
//
// Test: a ray from the sensor's position moved SupportProbe_m along its normal, cast back
// against the normal for 2 SupportProbe_m: a surface hit there lies within SupportProbe_m of
// the sensor, behind it, and the sensor faces away from it (either side of a two-sided
// surface counts).
#pragma once

#include <vector>

#include "dayphoton/core/scene_description.h"
#include "dayphoton/engine/material.h"
#include "dayphoton/engine/scene.h"

namespace dayphoton::engine {

/// How far from a surface a sensor may lie and still be "on" it, metres (1 mm: far below
/// any photometric scale, far above the scene's ray offset).
constexpr double SupportProbe_m = 1e-3;

enum class SensorSupport {
  Free,                ///< no surface within SupportProbe_m behind the sensor
  OnStoringSurface,    ///< on a surface whose material stores photons
  OnNonStoringSurface  ///< on a black, specular or transparent surface
};

SensorSupport sensor_support(const Scene& scene, const std::vector<Material>& materials,
                             const SensorPoint& sensor);

}  // namespace dayphoton::engine
