// Material: the value the tracers hold for each scene material: the MaterialSpec it was
// built from and its scattering model (material_model.h, the interface every model
// implements; the models are chosen by type name in material_registry.h). Each model offers
// sample / eval / pdf / albedo so that tests can check sampling against evaluation
// (chi-square, sample/pdf consistency, energy <= 1, reciprocity). Models, parameters,
// formulas and their RADIANCE counterparts: docs/materials.md. The built-in models are in
// engine/src/*_material.cpp, with fresnel.h, thin_glass_fresnel.h, glazing_system.h and
// ward_lobe.h. The direction conventions and the sampling contract are written once, in
// material_model.h.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>
#include <optional>

#include "dayphoton/core/scene_description.h"
#include "dayphoton/core/vec3.h"
#include "dayphoton/engine/material_model.h"

namespace dayphoton::engine {

class Material {
 public:
  /// Build the model of `spec`. Parameters are assumed valid (the project reader checks
  /// ranges); throws std::invalid_argument if they are not. Glass additionally needs its
  /// normal transmittance reachable by a pane of its index: Tn <= (1 - r0) / (1 + r0),
  /// r0 = ((n - 1) / (n + 1))^2 (0.918 for n = 1.52); a clearer "glass" is an opening. So
  /// does each uncoated pane of a glazing. A transmittance factor other than 1 needs a
  /// glass, glazing or opening material.
  /// Glossy materials tabulate their lobe's albedo here (about 1 ms each).
  /// The model is the factory registered for the spec's type name (material_registry.h).
  static Material from_spec(const MaterialSpec& spec);

  /// A material from a model built elsewhere (tests, or a model not in the registry).
  Material(MaterialSpec spec, std::shared_ptr<const MaterialModel> model);

  MaterialType type() const;
  const MaterialSpec& spec() const;
  /// The scattering model; shared by the copies of this material (models are immutable).
  const MaterialModel& model() const { return *m_model; }

  /// Sample a scattering event for light arriving along `incoming`, from three independent
  /// uniform numbers in [0, 1) (u_component picks the component, u1/u2 the direction).
  /// Returns nothing when the light is absorbed by the sampling itself (a glossy direction
  /// below the surface, or a material whose albedo is zero at this incidence); otherwise the
  /// caller plays Russian roulette on `weight`.
  std::optional<ScatterSample> sample(const Vec3& incoming, const Vec3& normal,
                                      double u_component, double u1, double u2) const {
    return m_model->sample(incoming, normal, u_component, u1, u2);
  }

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
  Vec3 straight_transmittance(const Vec3& incoming, const Vec3& normal) const {
    return m_model->straight_transmittance(incoming, normal);
  }

  /// True if the material has a diffuse component (reflection or transmission) with non-zero
  /// albedo, i.e. photons arriving here are stored.
  bool stores_photons() const { return m_stores_photons; }

  /// Dielectric only: per-channel transmission per metre of path inside the material
  /// (the tracer attenuates segments that travel inside); (1, 1, 1) otherwise.
  Vec3 interior_transmittance_per_m() const;
  /// True if interior_transmittance_per_m() is not (1, 1, 1): the tracers attenuate the
  /// segments that end on this material's back side.
  bool absorbs_inside() const { return m_absorbs_inside; }

  /// The Lambertian parts of the reflection and the transmission, per channel
  /// (MaterialModel::diffuse_reflectance / diffuse_transmittance).
  Vec3 diffuse_reflectance() const;
  Vec3 diffuse_transmittance() const;

 private:
  MaterialSpec m_spec;
  std::shared_ptr<const MaterialModel> m_model;
  // The model's answers, asked once: the tracers ask at every hit.
  bool m_stores_photons = false;
  bool m_absorbs_inside = false;
};

/// Built-in models, from the spec alone (Material::diffuse_reflectance() /
/// diffuse_transmittance() serve every model, registered ones included):
/// the Lambertian part of a material's reflection (RADIANCE's diffuse reflectance: the
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

/// The engine material of every spec, in order (a scene's materials by index).
std::vector<Material> materials_of(const std::vector<MaterialSpec>& specs);

}  // namespace dayphoton::engine
