// Material: the scattering models photons and shadow rays meet (DESIGN.md section 5), built
// from a MaterialSpec (core/scene_description.h). Each model offers sample / eval / pdf /
// albedo so that tests can check sampling against evaluation (chi-square, sample/pdf
// consistency, energy <= 1, reciprocity). Models, parameters, formulas and their RADIANCE
// counterparts: docs/materials.md. Implementation: engine/src/material.cpp, with
// fresnel.h, thin_glass_fresnel.h and ward_lobe.h.
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
#include <memory>
#include <optional>

#include "dayphoton/core/scene_description.h"
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

class Material {
 public:
  /// Build the model of `spec`. Parameters are assumed valid (the project reader checks
  /// ranges); throws std::invalid_argument if they are not. Glass additionally needs its
  /// normal transmittance reachable by a pane of its index: Tn <= (1 - r0) / (1 + r0),
  /// r0 = ((n - 1) / (n + 1))^2 (0.918 for n = 1.52); a clearer "glass" is an opening. So
  /// does each uncoated pane of a glazing. A transmittance factor other than 1 needs a
  /// glass, glazing or opening material.
  /// Glossy materials tabulate their lobe's albedo here (about 1 ms each).
  static Material from_spec(const MaterialSpec& spec);

  Material(const Material&);
  Material& operator=(const Material&);
  Material(Material&&) noexcept;
  Material& operator=(Material&&) noexcept;
  ~Material();

  MaterialType type() const;
  const MaterialSpec& spec() const;

  /// Sample a scattering event for light arriving along `incoming`, from three independent
  /// uniform numbers in [0, 1) (u_component picks the component, u1/u2 the direction).
  /// Returns nothing when the light is absorbed by the sampling itself (a glossy direction
  /// below the surface, or a material whose albedo is zero at this incidence); otherwise the
  /// caller plays Russian roulette on `weight`.
  std::optional<ScatterSample> sample(const Vec3& incoming, const Vec3& normal,
                                      double u_component, double u1, double u2) const;

  /// BSDF of the non-delta components, 1/sr per channel (zero if none).
  Vec3 eval(const Vec3& incoming, const Vec3& outgoing, const Vec3& normal) const;
  /// Density of sample() producing `outgoing` through non-delta components, 1/sr.
  double pdf(const Vec3& incoming, const Vec3& outgoing, const Vec3& normal) const;

  /// Directional albedo: fraction of the light arriving along `incoming` that is scattered
  /// (reflected + transmitted), per channel. Exact where a closed form exists (diffuse,
  /// mirror, thin glass, dielectric interface); for Ward lobes a deterministic quadrature
  /// over the half vector (WardLobe::albedo, ~1e-6 accurate, ~0.1 ms): meant for setup and
  /// tests, not for every photon.
  Vec3 albedo(const Vec3& incoming, const Vec3& normal) const;

  /// Per-channel transmittance of the straight (unrefracted) pass-through for light along
  /// `incoming`: the thin-glass Fresnel transmittance, the glazing system's angular
  /// transmittance, 1 for an opening (each times the spec's transmittance_factor), a smooth
  /// (roughness 0) translucent's specular transmission, 0 for everything else (a rough
  /// translucent spreads that light into a glossy lobe, which is in eval()). Shadow rays of
  /// the direct component pass through surfaces with this weight.
  Vec3 straight_transmittance(const Vec3& incoming, const Vec3& normal) const;

  /// True if the material has a diffuse component (reflection or transmission) with non-zero
  /// albedo, i.e. photons arriving here are stored.
  bool stores_photons() const;

  /// Dielectric only: per-channel transmission per metre of path inside the material
  /// (the tracer attenuates segments that travel inside); (1, 1, 1) otherwise.
  Vec3 interior_transmittance_per_m() const;

 private:
  struct Model;
  explicit Material(std::unique_ptr<Model> model);
  std::unique_ptr<Model> m_model;
};

/// The Lambertian part of a material's reflection (RADIANCE's diffuse reflectance: the
/// reflectance less its specular and transmitted fractions), per channel; zero for models
/// without one (mirror, glass, dielectric, opening).
Vec3 diffuse_reflectance(const MaterialSpec& spec);
/// The Lambertian part of a translucent material's transmission, per channel; zero for
/// every other model.
Vec3 diffuse_transmittance(const MaterialSpec& spec);

/// RADIANCE glass transmissivity tn (per pass through the pane material) giving a normal
/// transmittance `normal_transmittance` for refractive index 1.52: RADIANCE's documented
/// conversion tn = (sqrt(0.8402528435 + 0.0072522239 Tn^2) - 0.9166530661) / 0.0036261119 / Tn.
double radiance_glass_transmissivity(double normal_transmittance);

}  // namespace dayphoton::engine
