// MaterialModel: the one interface every scattering model implements (the pbrt-v4 `BxDF` /
// Mitsuba 3 `BSDF` role). engine::Material (material.h) holds a MaterialSpec and a shared,
// immutable MaterialModel; the photon tracer, the final gather, the renderer and the direct
// component see models only through this interface. A model is built once per scene material
// by the factory its type name is registered with (material_registry.h) and is then used
// read-only from many threads at once: every method is const and must not mutate state.
//
// Direction conventions (the photon tracer's view):
//   - `incoming` is the PROPAGATION direction of the arriving light (it points at the
//     surface), unit length;
//   - `outgoing` is the propagation direction after scattering, unit length;
//   - `normal` is the surface's geometric normal as in Hit::normal (either side). A hit is
//     on the front side when dot(incoming, normal) < 0. Reflecting models (Lambertian,
//     plastic, metal, mirror, translucent) are two-sided: a back-side hit behaves like a
//     front-side hit with the normal flipped, as in RADIANCE. Thin glass is symmetric; a
//     glazing system transmits the same both ways but reflects with the side's own
//     reflectance (pane 1 faces the side the normal points away from).
//     Dielectric is not: the front side is outside (index 1), the back side inside (index n).
//
// eval(incoming, outgoing, normal) returns the BSDF f (1/sr, per RGB channel) of the
// non-delta components only; pdf() the density (per sr) with which sample() produces
// `outgoing` through those components, component-selection probability included. For a
// non-delta sample, weight == eval * |dot(outgoing, normal)| / pdf (the consistency the
// tests check). Delta events (mirror, smooth specular, glass, refraction, straight
// transmission) are flagged and covered only by sample(). eval() is reciprocal in
// propagation-direction form: eval(a, b, n) == eval(-b, -a, n).
//
// Component selection: sample() picks a component (diffuse / specular reflection, diffuse /
// specular transmission) with probability proportional to the mean over RGB of its albedo at
// this incidence, so that E[weight] = albedo per channel and, for white light, the photon
// survives Russian roulette with probability equal to the mean albedo. Glossy (Ward) lobes
// sample the half vector and absorb directions that fall below the surface (sample() returns
// nothing), which is how their albedo falls below the specular reflectance.
//
// Analogue photon transport (seeds/000 section 3.1.1.2; digest section 2.1.4): the tracer
// multiplies the photon's RGB flux by `weight`, then plays Russian roulette with survival
// probability P = mean(flux * weight) / mean(flux) and divides the survivor by P, which
// keeps the flux constant and stays unbiased for coloured light.
#pragma once

#include <cstdint>
#include <optional>

#include "dayphoton/core/vec3.h"

namespace dayphoton::engine {

/// What a scattering event did. The photon tracer's path classes (caustic / global) and the
/// direct component's shadow rays are decided from it.
enum class ScatterType : std::uint8_t {
  DiffuseReflection,     ///< Lambertian reflection
  GlossyReflection,      ///< rough specular lobe (counts as specular for caustics)
  SpecularReflection,    ///< mirror-like, delta
  DiffuseTransmission,   ///< Lambertian transmission (translucent)
  GlossyTransmission,    ///< rough specular transmission (translucent)
  SpecularTransmission,  ///< refraction through a dielectric interface, delta
  StraightTransmission,  ///< unrefracted pass-through (thin glass, opening,
                         ///< translucent's specular part), delta, direction unchanged
};

/// True for the diffuse events that turn a caustic path into a global one.
inline bool is_diffuse(ScatterType t) {
  return t == ScatterType::DiffuseReflection || t == ScatterType::DiffuseTransmission;
}

struct ScatterSample {
  Vec3 direction;  ///< outgoing propagation direction, unit
  Vec3 weight;     ///< per channel: f |cos| / pdf, or for delta events the component's
                   ///< reflectance/transmittance divided by its selection probability
  ScatterType type = ScatterType::DiffuseReflection;
  bool delta = false;  ///< direction drawn from a delta distribution (not in eval/pdf)
};

class MaterialModel {
 public:
  virtual ~MaterialModel() = default;

  /// Sample a scattering event for light arriving along `incoming` (unit, pointing at the
  /// surface) at a surface with geometric normal `normal` (either side), from three
  /// independent uniform numbers in [0, 1): `u_component` picks the component, `u1`/`u2` the
  /// direction. Returns nothing when the light is absorbed by the sampling itself (a glossy
  /// direction below the surface, or an albedo of zero at this incidence); otherwise the
  /// caller multiplies the flux by `weight` and plays Russian roulette on it, so E[weight]
  /// must equal albedo() per channel. A non-delta sample must satisfy
  /// weight == eval(incoming, direction, normal) * |dot(direction, normal)| / pdf(...).
  virtual std::optional<ScatterSample> sample(const Vec3& incoming, const Vec3& normal, double u_component,
                                              double u1, double u2) const = 0;

  /// BSDF of the non-delta components, 1/sr per RGB channel (zero if there are none).
  /// Reciprocal in propagation-direction form: eval(a, b, n) == eval(-b, -a, n).
  virtual Vec3 eval(const Vec3& incoming, const Vec3& outgoing, const Vec3& normal) const = 0;

  /// Density (1/sr) with which sample() produces `outgoing` through its non-delta
  /// components, the component-selection probability included; 0 if there are none.
  virtual double pdf(const Vec3& incoming, const Vec3& outgoing, const Vec3& normal) const = 0;

  /// Directional albedo: the fraction of the light arriving along `incoming` that is
  /// scattered (reflected + transmitted, delta parts included), per channel, <= 1. Used by
  /// setup code and tests, not per photon, so a deterministic quadrature is acceptable.
  virtual Vec3 albedo(const Vec3& incoming, const Vec3& normal) const = 0;

  /// Per-channel transmittance of the undeviated (straight-through) part for light along
  /// `incoming`: the weight with which the direct component's shadow rays pass this surface.
  /// A model whose transmitted light is all spread out returns zero (its transmission is in
  /// eval()). Default: opaque to shadow rays.
  virtual Vec3 straight_transmittance(const Vec3& incoming, const Vec3& normal) const {
    (void)incoming, (void)normal;
    return {0, 0, 0};
  }

  /// True if the model has a diffuse component (reflection or transmission) with non-zero
  /// albedo: photons arriving here are stored, and the final gather looks them up through
  /// diffuse_reflectance() / diffuse_transmittance(). Default: false.
  virtual bool stores_photons() const { return false; }

  /// The Lambertian part of the reflection, per channel (the final gather's and renderer's
  /// density estimate multiplies the stored irradiance by it / pi). Default: none.
  virtual Vec3 diffuse_reflectance() const { return {0, 0, 0}; }
  /// The Lambertian part of the transmission, per channel. Default: none.
  virtual Vec3 diffuse_transmittance() const { return {0, 0, 0}; }

  /// A volume-bounding interface (dielectric): per-channel transmission per metre of path
  /// inside the material, which the tracers apply to segments that travel inside. Default
  /// (1, 1, 1): nothing is absorbed between surfaces.
  virtual Vec3 interior_transmittance_per_m() const { return {1, 1, 1}; }
};

}  // namespace dayphoton::engine
