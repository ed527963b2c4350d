// honeybee_modifier_material (honeybee_modifiers.h): a Honeybee modifier through the one
// mapping of RADIANCE materials, project::radiance_material.
#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/scene_description.h"
#include "dayphoton/project/radiance_material.h"
#include "honeybee_modifiers.h"

namespace dayphoton::project::detail {

bool honeybee_modifier_material(const RadianceModifier& modifier, const SourceLocation& where,
                                Diagnostics& diag, MaterialSpec& out) {
  const SourceLocation at = modifier.location.known() ? modifier.location : where;
  const std::string what = (modifier.path.empty() ? "Honeybee generic modifier" : modifier.path) + " ('" +
                           modifier.identifier + "')";
  const RadianceMaterialResult result = radiance_material(modifier.type, modifier.identifier, modifier.args);
  switch (result.role) {
    case RadianceModifierRole::Material:
      if (!result.bsdf_file.empty()) {
        // Honeybee carries a BSDF's XML inline (bsdf_data), not as a file beside the model.
        diag.error(at, what + ": BSDF modifiers of Honeybee models are not supported yet; give the window a "
                              "project material of type bsdf with the XML file instead",
                   read_source_line(at.file, at.line));
        return false;
      }
      out = result.material;
      out.location = at;
      return true;
    case RadianceModifierRole::Invisible:
      diag.error(at, what + ": a void modifier makes a surface invisible; leave the object out of the model instead",
                 read_source_line(at.file, at.line));
      return false;
    case RadianceModifierRole::LightSource:
      diag.error(at, what + ": '" + modifier.type + "' is a light source; dayphoton's only sources are the sky and the sun",
                 read_source_line(at.file, at.line));
      return false;
    default:
      diag.error(at, what + ": " + result.reason, read_source_line(at.file, at.line));
      return false;
  }
}

}  // namespace dayphoton::project::detail
