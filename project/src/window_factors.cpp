// Frame and maintenance factors of room windows (docs/materials.md, "Frame and maintenance
// factors"): the window's glazing material with its transmitted light multiplied by
//     frame_factor x maintenance_factor,
// the practice of the average daylight factor method, where the glazed area is the window
// area times the frame factor and the glazing transmittance is corrected for dirt
// (ADF = T Aw theta / (A (1 - R^2)) with Aw the net glazed area and T the dirt-corrected
// transmittance: P. Littlefair, "Site layout planning for daylight and sunlight: a guide to
// good practice", BRE 209, 2011; CIBSE Lighting Guide LG10, "Daylighting - a guide for
// designers", 2014). The light not
// transmitted is absorbed: the frame is not modelled as geometry (no reveal shading, no
// frame reflection), and the glazing's reflection is unchanged.
#include <cmath>
#include <sstream>

#include "dayphoton/engine/material_registry.h"
#include "geometry_generators.h"

namespace dayphoton::project::detail {

int MaterialLookup::with_transmittance_factor(int index, double factor) {
  if (index < 0 || factor == 1.0) return index;
  const MaterialSpec base = m_materials[static_cast<std::size_t>(index)];
  std::ostringstream name;
  name << base.name << " x " << format_number(factor);
  for (std::size_t i = 0; i < m_materials.size(); ++i)
    if (m_materials[i].name == name.str()) return static_cast<int>(i);
  MaterialSpec derived = base;
  derived.name = name.str();
  derived.transmittance_factor = base.transmittance_factor * factor;
  m_materials.push_back(derived);
  return static_cast<int>(m_materials.size()) - 1;
}

int window_material(const WindowSpec& w, const std::string& what, MaterialLookup& materials,
                    Diagnostics& diag) {
  const int index = materials.resolve(w.material, w.location, what);
  if (index < 0) return index;
  const double factor = w.frame_factor * w.maintenance_factor;
  if (factor == 1.0) return index;
  if (!(factor > 0.0 && factor <= 1.0) || !std::isfinite(factor)) {
    report(diag, w.location, what + ": frame_factor x maintenance_factor must be in (0, 1], got " +
                                 format_number(factor));
    return -1;
  }
  const MaterialSpec& spec = materials.spec(index);
  const engine::MaterialModelEntry* model = engine::find_material_model(
      spec.type == MaterialType::Registered ? spec.model : material_type_name(spec.type));
  if (!model || !model->takes_transmittance_factor) {
    report(diag, w.location,
           what + ": frame_factor and maintenance_factor scale straight-through transmission; material '" +
               w.material + "' is " + material_type_as_written(spec) + " (use glass, glazing or opening)");
    return -1;
  }
  return materials.with_transmittance_factor(index, factor);
}

}  // namespace dayphoton::project::detail
