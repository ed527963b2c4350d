// Material: the scattering models of material.h. Every model is one of three shapes:
//   - layered (Lambertian = RADIANCE plastic, metal, mirror, translucent = RADIANCE trans):
//     up to four components, diffuse reflection, specular reflection (delta mirror or Ward
//     lobe, ward_lobe.h), diffuse transmission, specular transmission (straight through or a
//     Ward lobe of roughness alpha / 2 mirrored through the surface, see below); two-sided
//     (a back-side hit flips the normal);
//   - thin glass (thin_glass_fresnel.h) and glazing systems (glazing_system.h): delta
//     reflection and straight transmission;
//   - dielectric interface (fresnel.h): delta reflection and refraction;
//   - opening: straight transmission with weight 1.
// The parameters of each model and their RADIANCE counterparts are in docs/materials.md.
//
// Component selection (analogue transport, seeds/000 section 3.1.1.2): a component is chosen
// with probability proportional to the mean over RGB of its albedo at this incidence
// (for Ward lobes the tabulated WardLobe::selection_albedo). Delta samples weigh
// albedo_c / P_c; non-delta samples weigh eval * |cos| / pdf with eval and pdf summed over
// all non-delta components (the one-sample mixture estimator), which is what pdf() and eval()
// return, so the weight is unbiased whichever component produced the direction.
#include "dayphoton/engine/material.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "bsdf_frame.h"
#include "dayphoton/core/units.h"
#include "fresnel.h"
#include "glazing_system.h"
#include "thin_glass_fresnel.h"
#include "ward_lobe.h"

namespace dayphoton::engine {
namespace {

double mean(const Vec3& v) { return (v.x + v.y + v.z) / 3.0; }
bool any_positive(const Vec3& v) { return v.x > 0 || v.y > 0 || v.z > 0; }

Vec3 reflect(const Vec3& direction, const Vec3& normal) {
  return direction - normal * (2.0 * dot(direction, normal));
}

// Cosine-weighted direction about `normal` (Malley's method: uniform disc, lifted).
Vec3 sample_cosine(const Vec3& normal, double u1, double u2) {
  const double r = std::sqrt(u1);
  const double phi = 2.0 * Pi * u2;
  const BsdfFrame frame(normal);
  return normalize(frame.to_world({r * std::cos(phi), r * std::sin(phi), std::sqrt(1.0 - u1)}));
}

void check_unit_range(const MaterialSpec& spec, const char* what, double value) {
  if (!(value >= 0.0 && value <= 1.0))
    throw std::invalid_argument("material '" + spec.name + "': " + what + " " +
                                std::to_string(value) + " is outside [0, 1]");
}

void check_unit_range(const MaterialSpec& spec, const char* what, const Vec3& rgb) {
  for (int c = 0; c < 3; ++c) check_unit_range(spec, what, rgb[c]);
}

// Indices of the layered model's components.
enum Component : int {
  DiffuseReflect = 0,
  SpecularReflect = 1,
  DiffuseTransmit = 2,
  SpecularTransmit = 3,
  ComponentCount = 4,
};

}  // namespace

struct Material::Model {
  MaterialSpec spec;

  // Layered models: per-channel albedo factors of the four components and the Ward lobes of
  // the specular ones (absent when roughness is 0: delta mirror / straight through).
  std::array<Vec3, ComponentCount> factor{};
  std::optional<WardLobe> lobe;               // glossy reflection, alpha = roughness
  std::optional<WardLobe> transmission_lobe;  // glossy transmission, alpha = roughness / 2

  // Thin glass: per-pass transmissivity per channel.
  Vec3 glass_transmissivity{0, 0, 0};
  // Glazing: the resolved panes, from the outside in, and whether all channels are equal.
  std::vector<ResolvedPane> panes;
  bool grey_panes = true;

  // Mean-RGB selection weights of the layered components at incidence cosine cos_i.
  std::array<double, ComponentCount> selection(double cos_i) const {
    const double reflect_albedo = lobe ? lobe->selection_albedo(cos_i) : 1.0;
    const double transmit_albedo =
        transmission_lobe ? transmission_lobe->selection_albedo(cos_i) : 1.0;
    return {mean(factor[DiffuseReflect]), mean(factor[SpecularReflect]) * reflect_albedo,
            mean(factor[DiffuseTransmit]), mean(factor[SpecularTransmit]) * transmit_albedo};
  }

  bool layered() const {
    const MaterialType t = spec.type;
    return t == MaterialType::Lambertian || t == MaterialType::Metal ||
           t == MaterialType::Mirror || t == MaterialType::Translucent;
  }

  // Transmittance and reflectance per channel. Grey panes (the usual case) evaluate the
  // series once instead of three times: this is on every photon's path through a port.
  ThinGlassResponse glass_channel(double cos_i, int c) const {
    return thin_glass_response(cos_i, spec.refractive_index, glass_transmissivity[c]);
  }
  void glass_response(double cos_i, Vec3& t, Vec3& r) const {
    const ThinGlassResponse g0 = glass_channel(cos_i, 0);
    t = {g0.transmittance, g0.transmittance, g0.transmittance};
    r = {g0.reflectance, g0.reflectance, g0.reflectance};
    for (int c = 1; c < 3; ++c) {
      if (glass_transmissivity[c] == glass_transmissivity[0]) continue;
      const ThinGlassResponse g = glass_channel(cos_i, c);
      t[c] = g.transmittance;
      r[c] = g.reflectance;
    }
  }
  // Glazing: transmittance and the reflectance of the side the light arrives from. Pane 1
  // faces the side the normal points away from, so light with dot(incoming, normal) > 0
  // (arriving against the back of the surface) meets pane 1 first.
  void glazing_response(double cos_in, Vec3& t, Vec3& r) const {
    const bool from_outside = cos_in > 0;
    const double cos_i = std::fabs(cos_in);
    for (int c = 0; c < 3; ++c) {
      if (c > 0 && grey_panes) {
        t[c] = t[0];
        r[c] = r[0];
        continue;
      }
      const LayerOptics o = glazing_optics(panes, cos_i, c);
      t[c] = o.transmittance;
      r[c] = from_outside ? o.outer_reflectance : o.inner_reflectance;
    }
  }

  // Glass and glazing: transmittance (times the window's transmittance factor) and
  // reflectance for light arriving along a direction with cosine cos_in to the normal.
  void pane_response(double cos_in, Vec3& t, Vec3& r) const {
    if (spec.type == MaterialType::Glazing)
      glazing_response(cos_in, t, r);
    else
      glass_response(std::fabs(cos_in), t, r);
    if (spec.transmittance_factor != 1.0) t = t * spec.transmittance_factor;
  }
};

Material Material::from_spec(const MaterialSpec& spec) {
  auto model = std::make_unique<Model>();
  model->spec = spec;
  Model& m = *model;
  const Vec3 white{1, 1, 1};
  switch (spec.type) {
    case MaterialType::Lambertian:
    case MaterialType::Metal:
    case MaterialType::Translucent: {
      check_unit_range(spec, "reflectance", spec.reflectance);
      check_unit_range(spec, "specularity", spec.specularity);
      if (!(spec.roughness >= 0.0) || !std::isfinite(spec.roughness))
        throw std::invalid_argument("material '" + spec.name + "': roughness " +
                                    std::to_string(spec.roughness) + " must be >= 0");
      const double s = spec.specularity;
      const Vec3& colour = spec.reflectance;
      double t = 0, ts = 0;
      if (spec.type == MaterialType::Translucent) {
        check_unit_range(spec, "transmissivity", spec.transmissivity);
        check_unit_range(spec, "transmitted specular fraction", spec.transmitted_specular);
        t = spec.transmissivity;
        ts = spec.transmitted_specular;
      }
      m.factor[DiffuseReflect] = colour * ((1.0 - s) * (1.0 - t));
      m.factor[SpecularReflect] = spec.type == MaterialType::Metal ? colour * s : white * s;
      m.factor[DiffuseTransmit] = colour * ((1.0 - s) * t * (1.0 - ts));
      m.factor[SpecularTransmit] = colour * ((1.0 - s) * t * ts);
      if (spec.roughness > 0 && s > 0) m.lobe.emplace(spec.roughness);
      // RADIANCE's trans spreads its specular transmission as a Gaussian of width alpha / sqrt(2)
      // per axis about the straight direction (normal.c), half the angular spread of its
      // reflected lobe (a half-vector slope of alpha / sqrt(2) per axis, doubled by the
      // reflection). A mirrored Ward lobe of roughness alpha / 2 has that small-angle spread.
      if (spec.roughness > 0 && t * ts > 0) m.transmission_lobe.emplace(0.5 * spec.roughness);
      break;
    }
    case MaterialType::Mirror:
      check_unit_range(spec, "reflectance", spec.reflectance);
      m.factor[SpecularReflect] = spec.reflectance;
      break;
    case MaterialType::Glass:
      check_unit_range(spec, "transmittance", spec.transmittance);
      if (!(spec.refractive_index >= 1.0) || !std::isfinite(spec.refractive_index))
        throw std::invalid_argument("material '" + spec.name + "': glass refractive index " +
                                    std::to_string(spec.refractive_index) + " must be >= 1");
      try {
        for (int c = 0; c < 3; ++c)
          m.glass_transmissivity[c] =
              glass_transmissivity(spec.transmittance[c], spec.refractive_index);
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument("material '" + spec.name + "': " + e.what());
      }
      break;
    case MaterialType::Dielectric:
      check_unit_range(spec, "transmission per metre", spec.transmittance);
      if (!(spec.refractive_index > 0) || !std::isfinite(spec.refractive_index))
        throw std::invalid_argument("material '" + spec.name + "': refractive index " +
                                    std::to_string(spec.refractive_index) + " must be > 0");
      break;
    case MaterialType::Glazing:
      try {
        m.panes = resolve_panes(spec.panes);
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument("material '" + spec.name + "': " + e.what());
      }
      m.grey_panes = is_grey(m.panes);
      break;
    case MaterialType::Opening:
      break;
    default:
      throw std::invalid_argument("material '" + spec.name + "': unknown material type");
  }
  const bool transmits_straight = spec.type == MaterialType::Glass ||
                                  spec.type == MaterialType::Glazing ||
                                  spec.type == MaterialType::Opening;
  if (spec.transmittance_factor != 1.0 &&
      (!transmits_straight || !(spec.transmittance_factor > 0.0 && spec.transmittance_factor <= 1.0)))
    throw std::invalid_argument("material '" + spec.name + "': transmittance factor " +
                                std::to_string(spec.transmittance_factor) +
                                " needs a glass, glazing or opening material and a value in (0, 1]");
  return Material(std::move(model));
}

Material::Material(std::unique_ptr<Model> model) : m_model(std::move(model)) {}
Material::Material(const Material& other) : m_model(std::make_unique<Model>(*other.m_model)) {}
Material& Material::operator=(const Material& other) {
  if (this != &other) m_model = std::make_unique<Model>(*other.m_model);
  return *this;
}
Material::Material(Material&&) noexcept = default;
Material& Material::operator=(Material&&) noexcept = default;
Material::~Material() = default;

MaterialType Material::type() const { return m_model->spec.type; }
const MaterialSpec& Material::spec() const { return m_model->spec; }

std::optional<ScatterSample> Material::sample(const Vec3& incoming, const Vec3& normal,
                                              double u_component, double u1, double u2) const {
  const Model& m = *m_model;
  const double cos_in = dot(incoming, normal);
  const double cos_i = std::fabs(cos_in);
  switch (m.spec.type) {
    case MaterialType::Opening: {
      const double f = m.spec.transmittance_factor;
      return ScatterSample{incoming, Vec3{f, f, f}, ScatterType::StraightTransmission, true};
    }

    case MaterialType::Glass:
    case MaterialType::Glazing: {
      Vec3 t, r;
      m.pane_response(cos_in, t, r);
      const double total = mean(t) + mean(r);
      if (!(total > 0)) return std::nullopt;
      const double p_reflect = mean(r) / total;
      if (u_component < p_reflect)
        return ScatterSample{reflect(incoming, normal), r / p_reflect,
                             ScatterType::SpecularReflection, true};
      return ScatterSample{incoming, t / (1.0 - p_reflect), ScatterType::StraightTransmission,
                           true};
    }

    case MaterialType::Dielectric: {
      // Front side (against the normal) is outside, index 1; the back side is inside.
      const bool front = cos_in < 0;
      const double eta = front ? m.spec.refractive_index : 1.0 / m.spec.refractive_index;
      const Vec3 towards_light = front ? normal : -normal;  // unit normal on the incident side
      const double reflectance = fresnel_dielectric(cos_i, eta).unpolarised();
      // Albedo-proportional choice between reflectance R and transmittance 1 - R: both
      // weights are 1 (uncoloured interface; absorption inside is the tracer's job).
      if (u_component < reflectance)
        return ScatterSample{reflect(incoming, normal), Vec3{1, 1, 1},
                             ScatterType::SpecularReflection, true};
      const double cos_t = refracted_cosine(cos_i, eta);
      const Vec3 refracted =
          normalize((incoming + towards_light * cos_i) / eta - towards_light * cos_t);
      return ScatterSample{refracted, Vec3{1, 1, 1}, ScatterType::SpecularTransmission, true};
    }

    default:
      break;
  }

  // Layered models, two-sided: work with the normal on the incident side.
  const Vec3 n = cos_in < 0 ? normal : -normal;
  const Vec3 to_light = -incoming;
  const std::array<double, ComponentCount> w = m.selection(cos_i);
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
      break;
    case DiffuseTransmit:
      outgoing = sample_cosine(-n, u1, u2);
      type = ScatterType::DiffuseTransmission;
      break;
    case SpecularReflect:
      if (!m.lobe)
        return ScatterSample{reflect(incoming, normal), m.factor[SpecularReflect] / p_chosen,
                             ScatterType::SpecularReflection, true};
      {
        const std::optional<Vec3> o = m.lobe->sample(to_light, n, u1, u2);
        if (!o) return std::nullopt;
        outgoing = *o;
      }
      type = ScatterType::GlossyReflection;
      break;
    default:  // SpecularTransmit
      if (!m.transmission_lobe)
        return ScatterSample{incoming, m.factor[SpecularTransmit] / p_chosen,
                             ScatterType::StraightTransmission, true};
      {
        // The transmission lobe is a reflection lobe mirrored through the surface plane,
        // i.e. centred on the straight-through direction.
        const std::optional<Vec3> o = m.transmission_lobe->sample(to_light, n, u1, u2);
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

Vec3 Material::eval(const Vec3& incoming, const Vec3& outgoing, const Vec3& normal) const {
  const Model& m = *m_model;
  if (!m.layered()) return {0, 0, 0};
  const Vec3 n = dot(incoming, normal) < 0 ? normal : -normal;
  const Vec3 to_light = -incoming;
  const double cos_o = dot(outgoing, n);
  if (cos_o > 0) {
    Vec3 f = m.factor[DiffuseReflect] / Pi;
    if (m.lobe) f += m.factor[SpecularReflect] * m.lobe->eval(to_light, outgoing, n);
    return f;
  }
  if (cos_o < 0) {
    Vec3 f = m.factor[DiffuseTransmit] / Pi;
    if (m.transmission_lobe)
      f += m.factor[SpecularTransmit] * m.transmission_lobe->eval(to_light, reflect(outgoing, n), n);
    return f;
  }
  return {0, 0, 0};
}

double Material::pdf(const Vec3& incoming, const Vec3& outgoing, const Vec3& normal) const {
  const Model& m = *m_model;
  if (!m.layered()) return 0.0;
  const Vec3 n = dot(incoming, normal) < 0 ? normal : -normal;
  const Vec3 to_light = -incoming;
  const std::array<double, ComponentCount> w = m.selection(std::fabs(dot(incoming, normal)));
  const double total = w[0] + w[1] + w[2] + w[3];
  if (!(total > 0)) return 0.0;
  const double cos_o = dot(outgoing, n);
  double density = 0;
  if (cos_o > 0) {
    density += w[DiffuseReflect] * cos_o / Pi;
    if (m.lobe) density += w[SpecularReflect] * m.lobe->pdf(to_light, outgoing, n);
  } else if (cos_o < 0) {
    density += w[DiffuseTransmit] * -cos_o / Pi;
    if (m.transmission_lobe)
      density += w[SpecularTransmit] * m.transmission_lobe->pdf(to_light, reflect(outgoing, n), n);
  }
  return density / total;
}

Vec3 Material::albedo(const Vec3& incoming, const Vec3& normal) const {
  const Model& m = *m_model;
  const double cos_i = std::fabs(dot(incoming, normal));
  switch (m.spec.type) {
    case MaterialType::Opening: {
      const double f = m.spec.transmittance_factor;
      return {f, f, f};
    }
    case MaterialType::Dielectric:
      return {1, 1, 1};  // R + (1 - R): the interface itself loses nothing
    case MaterialType::Glass:
    case MaterialType::Glazing: {
      Vec3 t, r;
      m.pane_response(dot(incoming, normal), t, r);
      return t + r;
    }
    default:
      break;
  }
  // Layered: diffuse components are exact (their cosine lobes lie wholly on one side); the
  // specular ones are exact for delta events and Ward-lobe quadrature otherwise.
  const double reflect_albedo = m.lobe ? m.lobe->albedo(cos_i) : 1.0;
  const double transmit_albedo = m.transmission_lobe ? m.transmission_lobe->albedo(cos_i) : 1.0;
  return m.factor[DiffuseReflect] + m.factor[DiffuseTransmit] +
         m.factor[SpecularReflect] * reflect_albedo + m.factor[SpecularTransmit] * transmit_albedo;
}

Vec3 Material::straight_transmittance(const Vec3& incoming, const Vec3& normal) const {
  const Model& m = *m_model;
  switch (m.spec.type) {
    case MaterialType::Opening: {
      const double f = m.spec.transmittance_factor;
      return {f, f, f};
    }
    case MaterialType::Glass:
    case MaterialType::Glazing: {
      Vec3 t, r;
      m.pane_response(dot(incoming, normal), t, r);
      return t;
    }
    case MaterialType::Translucent:
      // A rough translucent scatters its specular transmission into a glossy lobe (eval()),
      // so nothing passes undeviated.
      return m.transmission_lobe ? Vec3{0, 0, 0} : m.factor[SpecularTransmit];
    default:
      return {0, 0, 0};
  }
}

bool Material::stores_photons() const {
  const Model& m = *m_model;
  return m.layered() &&
         (any_positive(m.factor[DiffuseReflect]) || any_positive(m.factor[DiffuseTransmit]));
}

Vec3 Material::interior_transmittance_per_m() const {
  const Model& m = *m_model;
  return m.spec.type == MaterialType::Dielectric ? m.spec.transmittance : Vec3{1, 1, 1};
}

Vec3 diffuse_reflectance(const MaterialSpec& spec) {
  switch (spec.type) {
    case MaterialType::Lambertian:
    case MaterialType::Metal:
    case MaterialType::Translucent: {
      const double t = spec.type == MaterialType::Translucent ? spec.transmissivity : 0.0;
      return spec.reflectance * ((1.0 - spec.specularity) * (1.0 - t));
    }
    default:
      return {0, 0, 0};
  }
}

Vec3 diffuse_transmittance(const MaterialSpec& spec) {
  if (spec.type != MaterialType::Translucent) return {0, 0, 0};
  return spec.reflectance * ((1.0 - spec.specularity) * spec.transmissivity * (1.0 - spec.transmitted_specular));
}

}  // namespace dayphoton::engine
