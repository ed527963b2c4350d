// Small helpers shared by the built-in scattering models (engine/src/*_material.cpp):
// RGB means, the mirror direction, cosine-weighted sampling and the parameter checks that
// turn a bad MaterialSpec into std::invalid_argument naming the material.
#pragma once

#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

#include "bsdf_frame.h"
#include "dayphoton/core/scene_description.h"
#include "dayphoton/core/units.h"
#include "dayphoton/core/vec3.h"
#include "dayphoton/engine/material_model.h"

namespace dayphoton::engine::detail {

inline double mean(const Vec3& v) { return (v.x + v.y + v.z) / 3.0; }
inline bool any_positive(const Vec3& v) { return v.x > 0 || v.y > 0 || v.z > 0; }

inline Vec3 reflect(const Vec3& direction, const Vec3& normal) {
  return direction - normal * (2.0 * dot(direction, normal));
}

// Cosine-weighted direction about `normal` (Malley's method: uniform disc, lifted).
inline Vec3 sample_cosine(const Vec3& normal, double u1, double u2) {
  const double r = std::sqrt(u1);
  const double phi = 2.0 * Pi * u2;
  const BsdfFrame frame(normal);
  return normalize(frame.to_world({r * std::cos(phi), r * std::sin(phi), std::sqrt(1.0 - u1)}));
}

inline void check_unit_range(const MaterialSpec& spec, const char* what, double value) {
  if (!(value >= 0.0 && value <= 1.0))
    throw std::invalid_argument("material '" + spec.name + "': " + what + " " + std::to_string(value) +
                                " is outside [0, 1]");
}

inline void check_unit_range(const MaterialSpec& spec, const char* what, const Vec3& rgb) {
  for (int c = 0; c < 3; ++c) check_unit_range(spec, what, rgb[c]);
}

// Glass and glazing: delta reflection about the normal and straight transmission, both from
// one per-channel response. `Pane` provides `void response(double cos_in, Vec3& t, Vec3& r)`
// (transmittance and the reflectance of the side the light arrives from, for light whose
// propagation direction has cosine cos_in to the normal); it is called directly, not through
// a virtual, because it lies on every photon's path through a port. sample() chooses
// reflection with probability mean(r) / (mean(t) + mean(r)), transmission otherwise, each
// weighted by its value over its probability.
template <class Pane>
class PaneModel : public MaterialModel {
 public:
  std::optional<ScatterSample> sample(const Vec3& incoming, const Vec3& normal, double u_component, double,
                                      double) const final {
    Vec3 t, r;
    pane().response(dot(incoming, normal), t, r);
    const double total = mean(t) + mean(r);
    if (!(total > 0)) return std::nullopt;
    const double p_reflect = mean(r) / total;
    if (u_component < p_reflect)
      return ScatterSample{reflect(incoming, normal), r / p_reflect, ScatterType::SpecularReflection, true};
    return ScatterSample{incoming, t / (1.0 - p_reflect), ScatterType::StraightTransmission, true};
  }
  Vec3 eval(const Vec3&, const Vec3&, const Vec3&) const final { return {0, 0, 0}; }
  double pdf(const Vec3&, const Vec3&, const Vec3&) const final { return 0.0; }
  Vec3 albedo(const Vec3& incoming, const Vec3& normal) const final {
    Vec3 t, r;
    pane().response(dot(incoming, normal), t, r);
    return t + r;
  }
  Vec3 straight_transmittance(const Vec3& incoming, const Vec3& normal) const final {
    Vec3 t, r;
    pane().response(dot(incoming, normal), t, r);
    return t;
  }

 private:
  const Pane& pane() const { return static_cast<const Pane&>(*this); }
};

}  // namespace dayphoton::engine::detail
