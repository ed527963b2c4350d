// Layered scattering model: RADIANCE plastic (type `lambertian` / `plastic`), metal, mirror
// and translucent (RADIANCE trans). Up to four components: diffuse reflection, specular
// reflection (delta mirror or Ward lobe, ward_lobe.h), diffuse transmission, specular
// transmission (straight through, or a Ward lobe of roughness alpha / 2 mirrored through the
// surface, see below). Two-sided: a back-side hit flips the normal, as in RADIANCE.
// Parameters and their RADIANCE counterparts: docs/materials.md ("Plastic and metal",
// "Translucent").
//
// Component selection (analogue transport, seeds/000 section 3.1.1.2): a component is chosen
// with probability proportional to the mean over RGB of its albedo at this incidence (for
// Ward lobes the tabulated WardLobe::selection_albedo). Delta samples weigh albedo_c / P_c;
// non-delta samples weigh eval * |cos| / pdf with eval and pdf summed over all non-delta
// components (the one-sample mixture estimator), which is what pdf() and eval() return, so
// the weight is unbiased whichever component produced the direction.
#include <array>
#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "builtin_materials.h"
#include "material_common.h"
#include "ward_lobe.h"

namespace dayphoton::engine {
namespace {

using namespace detail;

// Indices of the components.
enum Component : int {
  DiffuseReflect = 0,
  SpecularReflect = 1,
  DiffuseTransmit = 2,
  SpecularTransmit = 3,
  ComponentCount = 4,
};

class LayeredMaterial final : public MaterialModel {
 public:
  explicit LayeredMaterial(const MaterialSpec& spec) {
    const Vec3 white{1, 1, 1};
    if (spec.type == MaterialType::Mirror) {
      check_unit_range(spec, "reflectance", spec.reflectance);
      m_factor[SpecularReflect] = spec.reflectance;
      return;
    }
    check_unit_range(spec, "reflectance", spec.reflectance);
    check_unit_range(spec, "specularity", spec.specularity);
    if (!(spec.roughness >= 0.0) || !std::isfinite(spec.roughness))
      throw std::invalid_argument("material '" + spec.name + "': roughness " + std::to_string(spec.roughness) +
                                  " must be >= 0");
    const double s = spec.specularity;
    const Vec3& colour = spec.reflectance;
    double t = 0, ts = 0;
    if (spec.type == MaterialType::Translucent) {
      check_unit_range(spec, "transmissivity", spec.transmissivity);
      check_unit_range(spec, "transmitted specular fraction", spec.transmitted_specular);
      t = spec.transmissivity;
      ts = spec.transmitted_specular;
    }
    m_factor[DiffuseReflect] = colour * ((1.0 - s) * (1.0 - t));
    m_factor[SpecularReflect] = spec.type == MaterialType::Metal ? colour * s : white * s;
    m_factor[DiffuseTransmit] = colour * ((1.0 - s) * t * (1.0 - ts));
    m_factor[SpecularTransmit] = colour * ((1.0 - s) * t * ts);
    if (spec.roughness > 0 && s > 0) m_lobe.emplace(spec.roughness);
    // RADIANCE's trans spreads its specular transmission as a Gaussian of width alpha / sqrt(2)
    // per axis about the straight direction (normal.c), half the angular spread of its
    // reflected lobe (a half-vector slope of alpha / sqrt(2) per axis, doubled by the
    // reflection). A mirrored Ward lobe of roughness alpha / 2 has that small-angle spread.
    if (spec.roughness > 0 && t * ts > 0) m_transmission_lobe.emplace(0.5 * spec.roughness);
    m_pure_diffuse = !any_positive(m_factor[SpecularReflect]) && !any_positive(m_factor[DiffuseTransmit]) &&
                     !any_positive(m_factor[SpecularTransmit]);
  }

  std::optional<ScatterSample> sample(const Vec3& incoming, const Vec3& normal, double u_component, double u1,
                                      double u2) const override {
    const double cos_in = dot(incoming, normal);
    const double cos_i = std::fabs(cos_in);
    // Two-sided: work with the normal on the incident side.
    const Vec3 n = cos_in < 0 ? normal : -normal;
    if (m_pure_diffuse) {
      // A pure diffuse reflector (the Lambertian walls of most rooms): what the general path
      // below does when only the diffuse reflection has a weight, without the selection.
      if (!(mean(m_factor[DiffuseReflect]) > 0)) return std::nullopt;
      const Vec3 outgoing = sample_cosine(n, u1, u2);
      if (!(dot(outgoing, n) > 0)) return std::nullopt;
      return ScatterSample{outgoing, m_factor[DiffuseReflect], ScatterType::DiffuseReflection, false};
    }
    const Vec3 to_light = -incoming;
    const std::array<double, ComponentCount> w = selection(cos_i);
    const double total = w[0] + w[1] + w[2] + w[3];
    if (!(total > 0)) return std::nullopt;
    double target = u_component * total;
    int chosen = ComponentCount - 1;
    for (int c = 0; c < ComponentCount; ++c) {
      if (target < w[static_cast<std::size_t>(c)]) {
        chosen = c;
        break;
      }
      target -= w[static_cast<std::size_t>(c)];
    }
    // Rounding can leave `chosen` on a zero-weight last component; step back to a live one.
    while (w[static_cast<std::size_t>(chosen)] <= 0) --chosen;
    const double p_chosen = w[static_cast<std::size_t>(chosen)] / total;

    Vec3 outgoing;
    ScatterType type = ScatterType::DiffuseReflection;
    switch (chosen) {
      case DiffuseReflect:
        outgoing = sample_cosine(n, u1, u2);
        type = ScatterType::DiffuseReflection;
        if (w[SpecularReflect] == 0 && w[DiffuseTransmit] == 0 && w[SpecularTransmit] == 0) {
          // A pure diffuse reflector (the Lambertian walls of most rooms): the mixture's pdf is
          // the cosine lobe's, so eval |cos| / pdf below is exactly the reflectance.
          if (!(dot(outgoing, n) > 0)) return std::nullopt;
          return ScatterSample{outgoing, m_factor[DiffuseReflect], type, false};
        }
        break;
      case DiffuseTransmit:
        outgoing = sample_cosine(-n, u1, u2);
        type = ScatterType::DiffuseTransmission;
        break;
      case SpecularReflect:
        if (!m_lobe)
          return ScatterSample{reflect(incoming, normal), m_factor[SpecularReflect] / p_chosen,
                               ScatterType::SpecularReflection, true};
        {
          const std::optional<Vec3> o = m_lobe->sample(to_light, n, u1, u2);
          if (!o) return std::nullopt;
          outgoing = *o;
        }
        type = ScatterType::GlossyReflection;
        break;
      default:  // SpecularTransmit
        if (!m_transmission_lobe)
          return ScatterSample{incoming, m_factor[SpecularTransmit] / p_chosen, ScatterType::StraightTransmission,
                               true};
        {
          // The transmission lobe is a reflection lobe mirrored through the surface plane,
          // i.e. centred on the straight-through direction.
          const std::optional<Vec3> o = m_transmission_lobe->sample(to_light, n, u1, u2);
          if (!o) return std::nullopt;
          outgoing = reflect(*o, n);
        }
        type = ScatterType::GlossyTransmission;
        break;
    }
    const double density = pdf(incoming, outgoing, normal);
    if (!(density > 0)) return std::nullopt;
    const Vec3 weight = eval(incoming, outgoing, normal) * (std::fabs(dot(outgoing, normal)) / density);
    return ScatterSample{outgoing, weight, type, false};
  }

  Vec3 eval(const Vec3& incoming, const Vec3& outgoing, const Vec3& normal) const override {
    const Vec3 n = dot(incoming, normal) < 0 ? normal : -normal;
    const Vec3 to_light = -incoming;
    const double cos_o = dot(outgoing, n);
    if (cos_o > 0) {
      Vec3 f = m_factor[DiffuseReflect] / Pi;
      if (m_lobe) f += m_factor[SpecularReflect] * m_lobe->eval(to_light, outgoing, n);
      return f;
    }
    if (cos_o < 0) {
      Vec3 f = m_factor[DiffuseTransmit] / Pi;
      if (m_transmission_lobe)
        f += m_factor[SpecularTransmit] * m_transmission_lobe->eval(to_light, reflect(outgoing, n), n);
      return f;
    }
    return {0, 0, 0};
  }

  double pdf(const Vec3& incoming, const Vec3& outgoing, const Vec3& normal) const override {
    const Vec3 n = dot(incoming, normal) < 0 ? normal : -normal;
    const Vec3 to_light = -incoming;
    const std::array<double, ComponentCount> w = selection(std::fabs(dot(incoming, normal)));
    const double total = w[0] + w[1] + w[2] + w[3];
    if (!(total > 0)) return 0.0;
    const double cos_o = dot(outgoing, n);
    double density = 0;
    if (cos_o > 0) {
      density += w[DiffuseReflect] * cos_o / Pi;
      if (m_lobe) density += w[SpecularReflect] * m_lobe->pdf(to_light, outgoing, n);
    } else if (cos_o < 0) {
      density += w[DiffuseTransmit] * -cos_o / Pi;
      if (m_transmission_lobe)
        density += w[SpecularTransmit] * m_transmission_lobe->pdf(to_light, reflect(outgoing, n), n);
    }
    return density / total;
  }

  Vec3 albedo(const Vec3& incoming, const Vec3& normal) const override {
    const double cos_i = std::fabs(dot(incoming, normal));
    // Diffuse components are exact (their cosine lobes lie wholly on one side); the specular
    // ones are exact for delta events and Ward-lobe quadrature otherwise.
    const double reflect_albedo = m_lobe ? m_lobe->albedo(cos_i) : 1.0;
    const double transmit_albedo = m_transmission_lobe ? m_transmission_lobe->albedo(cos_i) : 1.0;
    return m_factor[DiffuseReflect] + m_factor[DiffuseTransmit] + m_factor[SpecularReflect] * reflect_albedo +
           m_factor[SpecularTransmit] * transmit_albedo;
  }

  Vec3 straight_transmittance(const Vec3&, const Vec3&) const override {
    // A rough translucent scatters its specular transmission into a glossy lobe (eval()), so
    // nothing passes undeviated; the other layered models transmit nothing (factor 0).
    return m_transmission_lobe ? Vec3{0, 0, 0} : m_factor[SpecularTransmit];
  }

  bool stores_photons() const override {
    return any_positive(m_factor[DiffuseReflect]) || any_positive(m_factor[DiffuseTransmit]);
  }

  Vec3 diffuse_reflectance() const override { return m_factor[DiffuseReflect]; }
  Vec3 diffuse_transmittance() const override { return m_factor[DiffuseTransmit]; }

 private:
  // Mean-RGB selection weights of the components at incidence cosine cos_i.
  std::array<double, ComponentCount> selection(double cos_i) const {
    const double reflect_albedo = m_lobe ? m_lobe->selection_albedo(cos_i) : 1.0;
    const double transmit_albedo = m_transmission_lobe ? m_transmission_lobe->selection_albedo(cos_i) : 1.0;
    return {mean(m_factor[DiffuseReflect]), mean(m_factor[SpecularReflect]) * reflect_albedo,
            mean(m_factor[DiffuseTransmit]), mean(m_factor[SpecularTransmit]) * transmit_albedo};
  }

  // Per-channel albedo factors of the four components, and the Ward lobes of the specular
  // ones (absent when roughness is 0: delta mirror / straight through).
  std::array<Vec3, ComponentCount> m_factor{};
  std::optional<WardLobe> m_lobe;               // glossy reflection, alpha = roughness
  std::optional<WardLobe> m_transmission_lobe;  // glossy transmission, alpha = roughness / 2
  bool m_pure_diffuse = false;  // every factor but the diffuse reflection's is zero
};

}  // namespace

std::shared_ptr<const MaterialModel> make_layered_material(const MaterialSpec& spec) {
  return std::make_shared<LayeredMaterial>(spec);
}

}  // namespace dayphoton::engine
