// RADIANCE scene generator: geometry.radiance -> Surfaces (see geometry_generators.h and
// docs/radiance-import.md). The reading and the material mapping are radiance_scene.cpp's
// and radiance_material.cpp's; this file decides the materials' final indices and the ports.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>

#include "dayphoton/engine/bsdf_material.h"
#include "dayphoton/project/radiance_scene.h"
#include "dayphoton/project/scene_unit_check.h"
#include "geometry_generators.h"

namespace dayphoton::project::detail {
namespace {

/// Materials whose surfaces `ports: auto` considers glazing: everything that lets light
/// through (docs/radiance-import.md, "Ports").
bool transmits(const MaterialSpec& m) {
  if (engine::bsdf_parameters(m)) return true;  // a measured BSDF (RADIANCE BSDF / aBSDF)
  switch (m.type) {
    case MaterialType::Glass:
    case MaterialType::Glazing:
    case MaterialType::Dielectric:
    case MaterialType::Opening: return true;
    case MaterialType::Translucent: return m.transmissivity > 0 && m.specularity < 1;
    default: return false;
  }
}

bool same_parameters(const MaterialSpec& a, const MaterialSpec& b) {
  const engine::BsdfMaterialParameters *bsdf_a = engine::bsdf_parameters(a), *bsdf_b = engine::bsdf_parameters(b);
  if (bsdf_a || bsdf_b)
    return bsdf_a && bsdf_b && bsdf_a->data->content_sha256 == bsdf_b->data->content_sha256 && bsdf_a->up == bsdf_b->up;
  return a.type == b.type && a.reflectance == b.reflectance && a.specularity == b.specularity &&
         a.roughness == b.roughness && a.transmittance == b.transmittance &&
         a.refractive_index == b.refractive_index && a.transmissivity == b.transmissivity &&
         a.transmitted_specular == b.transmitted_specular;
}

}  // namespace

void generate_radiance(const RadianceSceneSpec& spec, std::size_t project_material_count,
                       std::vector<MaterialSpec>& scene_materials, Diagnostics& diag,
                       std::vector<Surface>& out) {
  std::vector<std::string> paths;
  std::vector<SourceLocation> written_at;
  for (const auto& f : spec.files) {
    paths.push_back(f.value);
    written_at.push_back(f.location);
  }
  RadianceSceneOptions options;
  options.skip_unsupported = spec.skip_unsupported;
  options.metres_per_unit = spec.metres_per_unit;
  const std::size_t errors_before = diag.error_count();
  const RadianceScene scene = read_radiance_scene(paths, options, diag, written_at);

  // Without `units` the metre is assumed: say so where the rooms only make sense in another
  // unit (scene_unit_check.h).
  if (!spec.units_written && diag.error_count() == errors_before) {
    std::vector<UnitCheckFacet> facets;
    facets.reserve(scene.surfaces.size());
    for (const RadianceSurface& r : scene.surfaces)
      facets.push_back({r.vertices, transmits(scene.materials[static_cast<std::size_t>(r.material)])});
    if (const std::optional<SceneUnitSuggestion> u = suggest_scene_units(facets)) {
      std::string unit = u->units;
      for (char& c : unit) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      diag.warning(spec.location,
                   "RADIANCE scene without 'units', read in metres: its rooms are " +
                       format_number(u->room_height_as_read) + " m from floor to ceiling (" +
                       format_number(std::round(100 * u->share)) + " % of its lit floor area), " +
                       format_number(u->room_height_m) + " m in " + unit + ": if the files are in " + unit +
                       ", set 'units: " + u->units + "' on this entry; if they are in metres, write 'units: "
                       "Meters' to say so",
                   read_source_line(spec.location.file, spec.location.line));
    }
  }

  // Scene index of each imported material: the project's own of that name, an equal one
  // another RADIANCE scene added, or a new one (renamed if the name is taken).
  std::vector<int> index(scene.materials.size(), -1);
  for (std::size_t i = 0; i < scene.materials.size(); ++i) {
    const MaterialSpec& m = scene.materials[i];
    for (std::size_t j = 0; j < scene_materials.size() && index[i] < 0; ++j) {
      if (scene_materials[j].name != m.name) continue;
      if (j < project_material_count) {
        index[i] = static_cast<int>(j);
        diag.warning(m.location, "the project's material '" + m.name + "' (" +
                                     material_type_as_written(scene_materials[j]) +
                                     ") replaces this RADIANCE definition",
                     read_source_line(m.location.file, m.location.line));
      } else if (same_parameters(scene_materials[j], m)) {
        index[i] = static_cast<int>(j);
      }
    }
    if (index[i] >= 0) continue;
    MaterialSpec added = m;
    for (const MaterialSpec& existing : scene_materials)
      if (existing.name == added.name) added.name += "@" + m.location.to_string();
    scene_materials.push_back(std::move(added));
    index[i] = static_cast<int>(scene_materials.size()) - 1;
  }

  // A `ports` or `outdoor` name must be a modifier of the files, and not in both lists.
  auto check_listed = [&](const std::vector<Located<std::string>>& names, const char* key) {
    for (const auto& name : names)
      if (std::find(scene.modifier_names.begin(), scene.modifier_names.end(), name.value) ==
          scene.modifier_names.end()) {
        const std::string hint = closest_match(name.value, scene.modifier_names);
        report(diag, name.location,
               std::string(key) + ": modifier '" + name.value + "' is not defined in the RADIANCE scene's files" +
                   (hint.empty() ? std::string() : " (did you mean '" + hint + "'?)"));
      }
  };
  check_listed(spec.port_modifiers, "ports");
  check_listed(spec.outdoor_modifiers, "outdoor");
  for (const auto& name : spec.outdoor_modifiers)
    for (const auto& port : spec.port_modifiers)
      if (name.value == port.value)
        report(diag, name.location,
               "outdoor: modifier '" + name.value + "' is also listed under 'ports' (at " + port.location.to_string() +
                   "): light enters the room through a port; an outdoor surface sends light toward the ports");
  auto listed = [](const std::vector<Located<std::string>>& names, const RadianceSurface& s) {
    for (const auto& name : names)
      if (name.value == s.modifier || name.value == s.material_modifier) return true;
    return false;
  };

  for (const RadianceSurface& r : scene.surfaces) {
    Surface s;
    s.name = r.name;
    s.material = index[static_cast<std::size_t>(r.material)];
    s.vertices = r.vertices;
    s.location = r.location;
    s.solid_face = r.solid_face;
    const MaterialSpec& m = scene_materials[static_cast<std::size_t>(s.material)];
    if (listed(spec.outdoor_modifiers, r)) {
      s.outdoor_scatterer = true;
    } else if (spec.ports_auto) {
      s.port_if_outdoors = transmits(m);
    } else if (listed(spec.port_modifiers, r)) {
      s.port = true;
      s.facing = PortFacing::Auto;
      s.solid_face = false;
    }
    out.push_back(std::move(s));
  }
}

}  // namespace dayphoton::project::detail
