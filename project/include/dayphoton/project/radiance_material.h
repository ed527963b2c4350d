// RADIANCE material -> dayphoton material: the mapping of ONE RADIANCE modifier (its type,
// name and arguments, already parsed) to the engine's MaterialSpec, or the reason it cannot
// be mapped. No file parsing here: the RADIANCE scene reader (radiance_scene.h) and any other
// importer whose modifiers are RADIANCE types with their arguments given as numbers (e.g.
// Honeybee's JSON modifiers) call the same function, so both map alike.
//
// The mapping (formulas, sources and approximations in docs/radiance-import.md; the
// engine's models in docs/materials.md). Argument lists are the RADIANCE reference manual's
// (G. Ward, "The RADIANCE 5.x Synthetic Imaging System", section "Materials"):
//
//   RADIANCE (reals)                     dayphoton MaterialSpec
//   plastic  R G B spec rough            lambertian (written "plastic"): reflectance RGB,
//                                        specularity spec, roughness rough
//   metal    R G B spec rough            metal: the same parameters (specular part tinted)
//   trans    R G B spec rough trans tspec  translucent: reflectance, specularity, roughness,
//                                        transmissivity trans, transmitted_specular tspec
//   mirror   R G B  [1 string: alternate material]   mirror: reflectance RGB
//   glass    rtn gtn btn [n]             glass: transmittance Tn per channel from the
//                                        transmissivity tn (below), refractive index n
//                                        (default 1.52)
//   dielectric rtn gtn btn n hc          dielectric: transmission per unit length (per
//                                        metre; radiance_material_in_metres converts from
//                                        another unit), index n; hc ignored
//   BSDF thick file ux uy uz . [0|3|6|9 zeros]   bsdf: a Klems BSDF file (read by the caller:
//   aBSDF     file ux uy uz . [...]      bsdf_file, bsdf_up), up vector ux uy uz; a non-zero
//                                        thickness is ignored (warning); aBSDF is used as BSDF
//   void                                 Invisible: RADIANCE traces straight through
//   light R G B, glow R G B maxrad,      LightSource: emitters; the sky and the sun are
//   spotlight R G B angle dx dy dz,      dayphoton's only sources
//   illum R G B [1 string: alternate]
//
// Glass: RADIANCE's `glass` takes the transmissivity tn of the pane material (one pass,
// normal incidence), not the transmittance Tn a data sheet quotes. With the normal-incidence
// Fresnel reflectance r0 = ((n - 1) / (n + 1))^2 of each face and the internal reflections
// summed (RADIANCE reference manual, `glass`; the same series engine/thin_glass_fresnel.h
// evaluates at every angle):
//     Tn = (1 - r0)^2 tn / (1 - r0^2 tn^2)
// the inverse of the manual's tn = (sqrt(0.8402528435 + 0.0072522239 Tn^2) - 0.9166530661)
// / 0.0036261119 / Tn for n = 1.52 (0.654 -> 0.59996). tn > 1 (a pane that would transmit
// more than a clear pane of its index) is refused.
//
// Colour: the engine transports RGB, so colours are kept per channel; nothing is turned
// grey. radiance_grey() gives RADIANCE's luminance-weighted grey for messages.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "dayphoton/core/scene_description.h"
#include "dayphoton/core/vec3.h"

namespace dayphoton::project {

/// What a RADIANCE modifier is to dayphoton.
enum class RadianceModifierRole {
  Material,     ///< mapped: RadianceMaterialResult::material is the engine's model
  Invisible,    ///< `void`: RADIANCE traces straight through a surface with no material
  LightSource,  ///< light, glow, spotlight, illum: an emitter (dayphoton's sources are the
                ///< sky and the sun); an illum's alternate material, if any, is named
  Unsupported,  ///< a RADIANCE type dayphoton does not model; `reason` says why
  Invalid,      ///< wrong argument counts or values (or an unknown type); `reason` says which
};

/// The outcome of mapping one modifier.
struct RadianceMaterialResult {
  RadianceModifierRole role = RadianceModifierRole::Invalid;
  /// Role Material: the model, named after the modifier; `location` left empty (the caller
  /// knows where the modifier was written).
  MaterialSpec material;
  /// Unsupported / Invalid: one sentence for a located error, naming the type and the
  /// modifier ("glass 'pane': transmissivity 1.2 (green) is above 1 ...").
  std::string reason;
  /// Approximations made or arguments ignored (Material, LightSource), one sentence each,
  /// for warnings ("dielectric 'prism': Hartmann constant 0.1 ignored (no dispersion)").
  std::vector<std::string> notes;
  /// mirror and illum with one string argument: the alternate material it names (RADIANCE
  /// uses it for rays that are not source samples); empty if none or "void".
  std::string alternate_material;
  /// BSDF and aBSDF: the BSDF file as the modifier names it (relative to the folder of the
  /// file that defines it) and the up vector; `material` is completed by the caller, which
  /// reads the file (core/bsdf_xml.h) and makes the `bsdf` material. Empty otherwise.
  std::string bsdf_file;
  Vec3 bsdf_up{0, 0, 1};

  bool mapped() const { return role == RadianceModifierRole::Material; }
};

/// Map the RADIANCE modifier `type name` with its arguments (string, integer, real, in the
/// counts RADIANCE writes them). Never throws for bad input; the result says what was wrong.
/// `type` is matched exactly (RADIANCE is case-sensitive); `void` may be given as the type.
RadianceMaterialResult radiance_material(std::string_view type, std::string_view name,
                                         const std::vector<double>& real_args,
                                         const std::vector<std::string>& string_args = {},
                                         std::size_t integer_arg_count = 0);

/// `material`, mapped from a modifier written in a scene whose unit is `metres_per_unit`
/// metres (a `units` key, or the scale of the `!xform -s` that places it), with its lengths
/// in metres: a dielectric's transmission per unit length t becomes t^(1 / metres_per_unit)
/// per metre (over L units, t^L = (t^(1/s))^(L s)), as RADIANCE's xform rewrites a scaled
/// dielectric (xform.c, m_dielectric: pow(t, 1/scale)). No other mapped material carries a
/// length.
MaterialSpec radiance_material_in_metres(MaterialSpec material, double metres_per_unit);

/// Normal-incidence transmittance Tn of a RADIANCE `glass` pane of transmissivity `tn` in
/// [0, 1] and refractive index `n` >= 1 (formula above).
double radiance_glass_normal_transmittance(double transmissivity, double refractive_index);

/// RADIANCE's default refractive index of `glass` (the reference manual's 1.52).
constexpr double RadianceGlassDefaultIndex = 1.52;

/// RADIANCE's grey value of an RGB colour, 0.265 R + 0.670 G + 0.065 B (its luminance
/// weights, core/units.h RgbLuminanceWeights).
double radiance_grey(const Vec3& rgb);

/// True if `type` is a RADIANCE modifier type the RADIANCE reference manual lists
/// (materials, light sources, patterns, textures, mixtures, alias), mapped or not: a word
/// that is not one is a typo or a primitive.
bool is_radiance_modifier_type(std::string_view type);

}  // namespace dayphoton::project
