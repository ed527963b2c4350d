// RADIANCE modifier -> engine MaterialSpec (radiance_material.h; docs/radiance-import.md).
// Argument lists and meanings: G. Ward, "The RADIANCE 5.x Synthetic Imaging System"
// (reference manual), section "Materials"; glass transmissivity vs transmittance: its
// `glass` entry.
#include "dayphoton/project/radiance_material.h"

#include <array>
#include <cmath>
#include <cstdlib>
#include <string>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/units.h"

namespace dayphoton::project {
namespace {

using Role = RadianceModifierRole;

const char* const ChannelNames[3] = {"red", "green", "blue"};

// Every modifier type of the reference manual (light sources, materials, textures,
// patterns, mixtures, auxiliary), and the spectral ones of RADIANCE 6.
constexpr std::array<std::string_view, 48> ModifierTypes = {
    "light",     "illum",     "glow",      "spotlight", "mirror",     "prism1",    "prism2",
    "mist",      "plastic",   "metal",     "trans",     "plastic2",   "metal2",    "trans2",
    "dielectric", "interface", "glass",    "plasfunc",  "metfunc",    "transfunc", "BRTDfunc",
    "plasdata",  "metdata",   "transdata", "antimatter", "BSDF",      "aBSDF",     "ashik2",
    "WGMDfunc",  "texfunc",   "texdata",   "colorfunc", "brightfunc", "colordata", "brightdata",
    "colorpict", "colortext", "brighttext", "spectrum", "specfile",   "specfunc",  "specdata",
    "specpict",  "mixfunc",   "mixdata",   "mixpict",   "mixtext",    "alias"};

std::string describe(std::string_view type, std::string_view name) {
  return std::string(type) + " '" + std::string(name) + "'";
}

class Mapper {
 public:
  Mapper(std::string_view type, std::string_view name, const std::vector<double>& reals,
         const std::vector<std::string>& strings, std::size_t integers)
      : m_type(type), m_name(name), m_reals(reals), m_strings(strings), m_integers(integers) {}

  RadianceMaterialResult run() {
    if (m_type == "void") return m_result.role = Role::Invisible, m_result;
    if (m_type == "plastic" || m_type == "metal") return reflector();
    if (m_type == "trans") return translucent();
    if (m_type == "mirror") return mirror();
    if (m_type == "glass") return glass();
    if (m_type == "dielectric") return dielectric();
    if (m_type == "BSDF" || m_type == "aBSDF") return bsdf();
    if (m_type == "light" || m_type == "glow" || m_type == "spotlight" || m_type == "illum")
      return light_source();
    return unsupported();
  }

 private:
  // ---- argument checks: each records the first problem as the reason -------------------
  bool invalid(const std::string& what) {
    m_result.role = Role::Invalid;
    m_result.reason = describe(m_type, m_name) + ": " + what;
    return false;
  }

  /// Exactly `strings` string arguments (or up to `max_strings`), no integers, and
  /// `min_reals`..`max_reals` reals, all finite.
  bool counts(std::size_t min_strings, std::size_t max_strings, std::size_t min_reals,
              std::size_t max_reals, const char* real_meaning) {
    if (m_strings.size() < min_strings || m_strings.size() > max_strings)
      return invalid("takes " + count_text(min_strings, max_strings) + " string argument" +
                     (max_strings == 1 ? "" : "s") + ", got " + std::to_string(m_strings.size()));
    if (m_integers != 0)
      return invalid("takes no integer arguments, got " + std::to_string(m_integers));
    if (m_reals.size() < min_reals || m_reals.size() > max_reals)
      return invalid("takes " + count_text(min_reals, max_reals) + " real arguments (" +
                     real_meaning + "), got " + std::to_string(m_reals.size()));
    for (std::size_t i = 0; i < m_reals.size(); ++i)
      if (!std::isfinite(m_reals[i]))
        return invalid("real argument " + std::to_string(i + 1) + " is not a finite number");
    return true;
  }

  static std::string count_text(std::size_t lo, std::size_t hi) {
    return lo == hi ? std::to_string(lo) : std::to_string(lo) + " or " + std::to_string(hi);
  }

  bool unit_range(const char* what, double value) {
    if (value >= 0.0 && value <= 1.0) return true;
    return invalid(std::string(what) + " " + format_number(value) + " is outside [0, 1]");
  }

  /// Reals first, first + 1, first + 2 as an RGB triple in [0, 1].
  bool rgb(const char* what, std::size_t first, Vec3& out) {
    for (int c = 0; c < 3; ++c) {
      const double v = m_reals[first + c];
      if (!(v >= 0.0 && v <= 1.0))
        return invalid(std::string(what) + " " + format_number(v) + " (" + ChannelNames[c] +
                       ") is outside [0, 1]");
      out[c] = v;
    }
    return true;
  }

  MaterialSpec& spec(MaterialType type) {
    m_result.role = Role::Material;
    m_result.material.name = std::string(m_name);
    m_result.material.type = type;
    return m_result.material;
  }

  RadianceMaterialResult failed() {
    // The role was set to Invalid with its reason; drop a half-filled model.
    m_result.material = MaterialSpec{};
    return m_result;
  }

  // ---- the mapped types -----------------------------------------------------------------
  // plastic / metal: C (RGB), specularity s, roughness alpha. The engine's Lambertian (with
  // its specular lobe) and metal models take exactly these parameters (docs/materials.md).
  RadianceMaterialResult reflector() {
    Vec3 colour;
    if (!counts(0, 0, 5, 5, "red green blue specularity roughness") ||
        !rgb("reflectance", 0, colour) || !unit_range("specularity", m_reals[3]) ||
        !unit_range("roughness", m_reals[4]))
      return failed();
    MaterialSpec& m = spec(m_type == "metal" ? MaterialType::Metal : MaterialType::Lambertian);
    if (m_type == "plastic") m.type_as_written = "plastic";
    m.reflectance = colour;
    m.specularity = m_reals[3];
    m.roughness = m_reals[4];
    return m_result;
  }

  // trans: C, s, alpha, transmissivity t, transmitted specular ts (RADIANCE normal.c's split,
  // which the engine's translucent model reproduces).
  RadianceMaterialResult translucent() {
    Vec3 colour;
    if (!counts(0, 0, 7, 7, "red green blue specularity roughness transmissivity tspec") ||
        !rgb("reflectance", 0, colour) || !unit_range("specularity", m_reals[3]) ||
        !unit_range("roughness", m_reals[4]) || !unit_range("transmissivity", m_reals[5]) ||
        !unit_range("transmitted specular fraction", m_reals[6]))
      return failed();
    MaterialSpec& m = spec(MaterialType::Translucent);
    m.reflectance = colour;
    m.specularity = m_reals[3];
    m.roughness = m_reals[4];
    m.transmissivity = m_reals[5];
    m.transmitted_specular = m_reals[6];
    return m_result;
  }

  RadianceMaterialResult mirror() {
    Vec3 colour;
    if (!counts(0, 1, 3, 3, "red green blue") || !rgb("reflectance", 0, colour)) return failed();
    MaterialSpec& m = spec(MaterialType::Mirror);
    m.reflectance = colour;
    alternate("rays that are not source samples see it; dayphoton's photons and shadow rays "
              "all see the mirror");
    return m_result;
  }

  // glass: transmissivity tn per channel (one pass through the pane material at normal
  // incidence) -> normal transmittance Tn (radiance_glass_normal_transmittance).
  RadianceMaterialResult glass() {
    if (!counts(0, 0, 3, 4, "red green blue transmissivity [refractive index]")) return failed();
    const double n = m_reals.size() == 4 ? m_reals[3] : RadianceGlassDefaultIndex;
    if (!(n >= 1.0)) {
      invalid("refractive index " + format_number(n) + " is below 1");
      return failed();
    }
    Vec3 transmittance;
    for (int c = 0; c < 3; ++c) {
      const double tn = m_reals[c];
      if (!(tn >= 0.0 && tn <= 1.0)) {
        invalid("transmissivity " + format_number(tn) + " (" + ChannelNames[c] + ") is " +
                (tn < 0 ? std::string("negative")
                        : "above 1: no pane of index " + format_number(n) +
                              " transmits that much (use void or an opening for a clear aperture)"));
        return failed();
      }
      transmittance[c] = radiance_glass_normal_transmittance(tn, n);
    }
    MaterialSpec& m = spec(MaterialType::Glass);
    m.transmittance = transmittance;
    m.refractive_index = n;
    return m_result;
  }

  // dielectric: transmission per unit length (per metre here; radiance_material_in_metres
  // converts a scene in another unit),
  // refractive index n, Hartmann constant hc (dispersion; not modelled).
  RadianceMaterialResult dielectric() {
    Vec3 per_m;
    if (!counts(0, 0, 5, 5, "red green blue transmission, refractive index, Hartmann constant") ||
        !rgb("transmission per metre", 0, per_m))
      return failed();
    const double n = m_reals[3];
    if (!(n > 0.0)) {
      invalid("refractive index " + format_number(n) + " is not positive");
      return failed();
    }
    MaterialSpec& m = spec(MaterialType::Dielectric);
    m.transmittance = per_m;
    m.refractive_index = n;
    if (m_reals[4] != 0.0)
      m_result.notes.push_back(describe(m_type, m_name) + ": Hartmann constant " +
                               format_number(m_reals[4]) +
                               " ignored (the engine has no dispersion: one index for all "
                               "wavelengths)");
    return m_result;
  }

  // BSDF: strings thick BSDFfile ux uy uz funcfile [transform ...], reals 0|3|6|9 (extra
  // diffuse front and back reflectance, diffuse transmittance); aBSDF: the same without
  // `thick`. The up vector must be given as numbers with funcfile '.' (RADIANCE lets them
  // name variables of the function file), and no transform; the extra diffuse components
  // must be zero (or absent). The BSDF file is read by the caller (bsdf_file, bsdf_up): it
  // knows which folder the name is relative to.
  RadianceMaterialResult bsdf() {
    auto bad = [this](const std::string& why) {
      invalid(why);
      return failed();
    };
    const bool thick = m_type == "BSDF";
    const std::size_t first = thick ? 1 : 0;  // index of the file name
    if (m_integers != 0) return bad("takes no integer arguments, got " + std::to_string(m_integers));
    if (m_strings.size() < first + 5)
      return bad("takes " + std::to_string(first + 5) + " or more string arguments (" +
                     (thick ? std::string("thickness, ") : std::string()) +
                     "BSDF file, up vector x y z, function file), got " + std::to_string(m_strings.size()));
    if (m_strings.size() > first + 5)
      return bad("a transform after the function file (string " + std::to_string(first + 6) +
                     ", '" + m_strings[first + 5] + "') is not supported; apply it to the up vector yourself");
    if (m_reals.size() != 0 && m_reals.size() != 3 && m_reals.size() != 6 && m_reals.size() != 9)
      return bad("takes 0, 3, 6 or 9 real arguments (extra diffuse front reflectance, back reflectance, "
                     "transmittance), got " + std::to_string(m_reals.size()));
    for (std::size_t i = 0; i < m_reals.size(); ++i)
      if (m_reals[i] != 0.0)
        return bad("extra diffuse components (real arguments) are not supported; real argument " +
                       std::to_string(i + 1) + " is " + format_number(m_reals[i]) +
                       " (add them to the BSDF file's matrices instead)");
    if (m_strings[first + 4] != ".")
      return bad("function file '" + m_strings[first + 4] +
                     "' is not read: give the up vector as numbers and the function file as '.'");
    Vec3 up;
    for (int c = 0; c < 3; ++c) {
      const std::string& text = m_strings[first + 1 + static_cast<std::size_t>(c)];
      char* end = nullptr;
      const double v = std::strtod(text.c_str(), &end);
      if (text.empty() || *end != '\0' || !std::isfinite(v))
        return bad("up vector component '" + text + "' is not a number (variables of a function file "
                       "are not read)");
      up[c] = v;
    }
    if (!(length(up) > 0)) return bad("the up vector is zero");
    if (thick) {
      char* end = nullptr;
      const double t = std::strtod(m_strings[0].c_str(), &end);
      if (m_strings[0].empty() || *end != '\0' || !std::isfinite(t))
        return bad("thickness '" + m_strings[0] + "' is not a number");
      if (t != 0.0)
        m_result.notes.push_back(describe(m_type, m_name) + ": thickness " + format_number(t) +
                                 " ignored (the BSDF is applied at the surface; RADIANCE uses the "
                                 "thickness for the proxy geometry behind it)");
    }
    if (!thick)
      m_result.notes.push_back(describe(m_type, m_name) +
                               ": aBSDF is used as a BSDF (RADIANCE's separate treatment of the "
                               "through-view peak is a rendering refinement; the matrix is sampled as it is)");
    m_result.role = Role::Material;
    m_result.material.name = std::string(m_name);
    m_result.bsdf_file = m_strings[first];
    m_result.bsdf_up = up;
    return m_result;
  }

  RadianceMaterialResult light_source() {
    bool ok = true;
    if (m_type == "light") ok = counts(0, 0, 3, 3, "red green blue radiance");
    if (m_type == "glow") ok = counts(0, 0, 4, 4, "red green blue radiance, maximum radius");
    if (m_type == "spotlight")
      ok = counts(0, 0, 7, 7, "red green blue radiance, cone angle, direction");
    if (m_type == "illum") ok = counts(0, 1, 3, 3, "red green blue radiance");
    if (!ok) return failed();
    m_result.role = Role::LightSource;
    if (m_type == "illum") alternate("");
    return m_result;
  }

  /// The optional string argument of mirror and illum: the alternate material.
  void alternate(const std::string& mirror_note) {
    if (m_strings.empty() || m_strings[0] == "void") return;
    m_result.alternate_material = m_strings[0];
    if (!mirror_note.empty())
      m_result.notes.push_back(describe(m_type, m_name) + ": alternate material '" +
                               m_strings[0] + "' ignored (in RADIANCE " + mirror_note + ")");
  }

  RadianceMaterialResult unsupported() {
    const std::string t(m_type);
    std::string why;
    if (t == "plastic2" || t == "metal2" || t == "trans2" || t == "ashik2" || t == "WGMDfunc")
      why = "anisotropic reflection is not modelled (use plastic, metal or trans)";
    else if (t == "plasfunc" || t == "metfunc" || t == "transfunc" || t == "BRTDfunc" ||
             t == "plasdata" || t == "metdata" || t == "transdata")
      why = "reflectance given by function or data files is not supported";
    else if (t == "interface")
      why = "an interface between two dielectrics is not modelled (dielectric against air only)";
    else if (t == "antimatter")
      why = "antimatter (which cuts other surfaces) is not modelled";
    else if (t == "prism1" || t == "prism2")
      why = "virtual light sources of prisms are not modelled (model the prism as dielectric "
            "geometry)";
    else if (t == "mist")
      why = "participating media are not modelled";
    else if (t == "alias")
      why = "an alias names another modifier: resolve it before mapping";
    else if (is_radiance_modifier_type(t))
      why = "patterns, textures, mixtures and spectra (functions, data and pictures) are not "
            "supported: dayphoton's materials are uniform";
    if (!why.empty()) {
      m_result.role = Role::Unsupported;
      m_result.reason = describe(m_type, m_name) + ": " + why;
      return m_result;
    }
    std::vector<std::string> known = {"void"};
    for (std::string_view k : ModifierTypes) known.emplace_back(k);
    const std::string hint = closest_match(t, known);
    m_result.role = Role::Invalid;
    m_result.reason = "unknown RADIANCE modifier type '" + t + "' of '" + std::string(m_name) + "'" +
                      (hint.empty() ? std::string() : " (did you mean '" + hint + "'?)");
    return m_result;
  }

  std::string_view m_type, m_name;
  const std::vector<double>& m_reals;
  const std::vector<std::string>& m_strings;
  std::size_t m_integers;
  RadianceMaterialResult m_result;
};

}  // namespace

MaterialSpec radiance_material_in_metres(MaterialSpec material, double metres_per_unit) {
  if (material.type == MaterialType::Dielectric && metres_per_unit != 1.0)
    for (int c = 0; c < 3; ++c) material.transmittance[c] = std::pow(material.transmittance[c], 1.0 / metres_per_unit);
  return material;
}

RadianceMaterialResult radiance_material(std::string_view type, std::string_view name,
                                         const std::vector<double>& real_args,
                                         const std::vector<std::string>& string_args,
                                         std::size_t integer_arg_count) {
  return Mapper(type, name, real_args, string_args, integer_arg_count).run();
}

double radiance_glass_normal_transmittance(double transmissivity, double refractive_index) {
  // Each face reflects r0 at normal incidence (Fresnel); a pass through the pane keeps tn;
  // the multiple reflections between the faces sum to a geometric series (RADIANCE reference
  // manual, `glass`; M. Rubin, "Optical properties of soda lime silica glasses", Solar Energy
  // Materials 12, 1985).
  const double r0 = std::pow((refractive_index - 1.0) / (refractive_index + 1.0), 2);
  const double tn = transmissivity;
  return (1.0 - r0) * (1.0 - r0) * tn / (1.0 - r0 * r0 * tn * tn);
}

double radiance_grey(const Vec3& rgb) { return dot(RgbLuminanceWeights, rgb); }

bool is_radiance_modifier_type(std::string_view type) {
  for (std::string_view t : ModifierTypes)
    if (t == type) return true;
  return false;
}

}  // namespace dayphoton::project
