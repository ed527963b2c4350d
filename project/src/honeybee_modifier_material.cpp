// honeybee_modifier_material (honeybee_modifiers.h): a Honeybee modifier through the one
// mapping of RADIANCE materials, project::radiance_material; a BSDF modifier, whose Klems XML
// is inline, read here into a `bsdf` material (docs/honeybee-import.md, "BSDF modifiers").
#include "dayphoton/core/bsdf_xml.h"
#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/scene_description.h"
#include "dayphoton/engine/bsdf_material.h"
#include "dayphoton/project/radiance_material.h"
#include "honeybee_modifiers.h"

namespace dayphoton::project::detail {
namespace {

/// A BSDF modifier's material: its `bsdf_data` read as a Klems XML file (its errors reported
/// at the `bsdf_data` field, with the line and column inside the XML), its up vector as
/// written. The orientation (the file's front outdoors) is the geometry's: the Honeybee import
/// turns the aperture round (honeybee_model.cpp); the user is told how this differs from
/// honeybee-radiance's static export.
bool bsdf_modifier_material(const RadianceModifier& modifier, const SourceLocation& at, const std::string& what,
                            Diagnostics& diag, MaterialSpec& out) {
  const SourceLocation field = modifier.bsdf_data_location.known() ? modifier.bsdf_data_location : at;
  std::shared_ptr<const KlemsBsdfData> data;
  try {
    data = read_bsdf_xml_text(modifier.bsdf_xml, at.file + " bsdf_data of '" + modifier.identifier + "'");
  } catch (const InputError& e) {
    for (const Diagnostic& d : e.diagnostics()) {
      const std::string inside = d.location.known() ? " (line " + std::to_string(d.location.line) + ", column " +
                                                          std::to_string(d.location.column) + " of the XML)"
                                                    : "";
      diag.error(field, what + ".bsdf_data" + inside + ": " + d.message, read_source_line(field.file, field.line));
    }
    return false;
  }
  // RADIANCE's BSDF material takes the side its surface normal points to as its front, and
  // reads WINDOW's "Front" blocks as its back (src/common/bsdf_m.c, load_bsdf_data: "front
  // and back are reversed from WINDOW 6 orientations"; src/rt/m_bsdf.c, hitfront), so the
  // normal must point into the room for the file's front to face outdoors (genBSDF(1): "the
  // positive Z-axis points into the room"). honeybee-radiance writes a static aperture with
  // its own vertices (writer.py, _write_static_files: Polygon(face.identifier, face.vertices,
  // ...)), whose normal points out of the room, and flips it only for the view and daylight
  // matrices of its three-phase recipes (dynamic/state.py, vmtx_geometry, dmtx_geometry).
  diag.warning(at,
               what + ": the BSDF's front (the XML's 'Front' data, WINDOW's exterior side) is put outdoors, as the "
                      "file means it; honeybee-radiance writes a static aperture with its normal out of the room, "
                      "where RADIANCE takes the file's back (WINDOW's room side) as outdoors, so for a device whose "
                      "two sides differ (a tilted blind) honeybee-radiance's results for this model (annual "
                      "daylight, daylight factor, point in time) are those of the device turned round",
               read_source_line(at.file, at.line));
  out = engine::bsdf_material_spec(modifier.identifier, std::move(data), modifier.bsdf_up);
  out.location = at;
  return true;
}

}  // namespace

bool honeybee_modifier_material(const RadianceModifier& modifier, const SourceLocation& where,
                                Diagnostics& diag, MaterialSpec& out) {
  const SourceLocation at = modifier.location.known() ? modifier.location : where;
  const std::string what = (modifier.path.empty() ? "Honeybee generic modifier" : modifier.path) + " ('" +
                           modifier.identifier + "')";
  if (modifier.type == "BSDF") return bsdf_modifier_material(modifier, at, what, diag, out);
  const RadianceMaterialResult result = radiance_material(modifier.type, modifier.identifier, modifier.args);
  switch (result.role) {
    case RadianceModifierRole::Material:
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
