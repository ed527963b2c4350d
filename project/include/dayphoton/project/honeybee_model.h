// Honeybee model import (HBJSON, the Model schema of ladybug-tools' honeybee-schema, with its
// Radiance extension): rooms of faces with apertures, doors and shades, modifiers and modifier
// sets, sensor grids, units. read_honeybee_model turns one file into surfaces with materials
// and sensor sets in metres, model coordinates; the project file places it with
// `geometry: {honeybee: model.hbjson}` and uses its grids with `sensors: {honeybee_grids: ...}`
// (docs/honeybee-import.md has the whole mapping and what is refused).
//
// Every problem is a located error: a syntax error at the file's line:column (from
// nlohmann-json's byte offset), a missing, mistyped or unsupported field at the line:column
// where its object starts, naming the object's identifier and its JSON path
// (`rooms[1].faces[3].geometry.boundary`).
#pragma once

#include <string>
#include <vector>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/scene_description.h"
#include "dayphoton/core/source_location.h"
#include "dayphoton/core/vec3.h"

namespace dayphoton::project {

/// What a surface of the model is in the scene.
enum class HoneybeeRole {
  Opaque,         ///< room face, opaque door, indoor shade: an ordinary surface
  Port,           ///< aperture or glass door in an Outdoors face: glazing and a photon port
  InteriorGlass,  ///< aperture or glass door between two rooms (Surface): glazing, not a port
  OutdoorShade,   ///< outdoor shade: an outdoor scatterer (Surface::outdoor_scatterer)
};

struct HoneybeeSurface {
  std::string name;             ///< the object's identifier; "<identifier>:<k>" for the
                                ///< k-th triangle of a face with holes cut in it
  std::vector<Vec3> vertices;   ///< metres, model coordinates, the HBJSON winding
  std::string material;         ///< a name in HoneybeeModel::materials
  HoneybeeRole role = HoneybeeRole::Opaque;
  /// Ports: Out for the openings of room faces (Honeybee's faces point out of their room),
  /// Auto for orphaned apertures, doors and the openings of orphaned faces (no room to say).
  PortFacing facing = PortFacing::Out;
  std::string path;             ///< JSON path of the object (`rooms[0].faces[2]`)
  SourceLocation location;
};

/// Why a measured BSDF cannot be put on a surface of `role` and port `facing`, or nullptr where
/// it can. A BSDF's front (WINDOW's exterior side) is the side its surface's normal points
/// away from (docs/materials.md, "Measured BSDF (Klems)") and must face outdoors, so it is
/// read on the openings of room faces facing Outdoors only (facing Out, as Honeybee writes
/// them, or In once turned round for a BSDF: turn_for_bsdf); where no room says which side is
/// outdoors (orphaned, between two rooms) or on other objects, it is refused. The import
/// applies it to a BSDF modifier, the scene builder to a project `bsdf` material that a
/// variant puts in a modifier's place.
const char* honeybee_bsdf_refusal(HoneybeeRole role, PortFacing facing);

/// An opening of a room face turned round for a BSDF (vertices reversed, its port facing In),
/// so that the BSDF's front faces outdoors; a surface already turned is left as it is.
void turn_for_bsdf(std::vector<Vec3>& vertices, PortFacing& facing);

/// One sensor grid of `properties.radiance.sensor_grids`.
struct HoneybeeGrid {
  std::string identifier;
  std::vector<SensorPoint> points;  ///< metres; normals of unit length
  SourceLocation location;
  /// The areas (m^2) of the faces of the grid's `mesh` (Mesh3D: one face per sensor, the
  /// floor area Honeybee weighs each sensor's result by, honeybee-radiance-postprocess); empty
  /// without a mesh, or when it is malformed or its face count is not the sensors'. The
  /// project loader gives them to the grid's sensors when they differ (load_project.cpp).
  std::vector<double> mesh_face_areas_m2;
  /// Why a mesh the grid has is not used (cannot be read, or another face count than the
  /// sensors'), for a located warning at `mesh_location`; empty otherwise.
  std::string mesh_problem;
  SourceLocation mesh_location;
};

struct HoneybeeModel {
  std::string identifier;
  std::string units;               ///< as written (Meters, Millimeters, Feet, Inches, Centimeters)
  double metres_per_unit = 1;
  double tolerance_m = 0.01;       ///< the model's tolerance, in metres
  /// An old file's model-level `north_angle` (honeybee-schema Model before the north moved
  /// to the energy simulation parameter): degrees clockwise, seen from above, from +Y to
  /// north (honeybee-core's Model.north_vector, +Y rotated by minus the angle), which is
  /// site.north's convention; 0 when not written. The loader takes it as site.north where the
  /// project writes none (docs/honeybee-import.md).
  double north_angle_deg = 0;
  SourceLocation north_angle_location;  ///< where it is written (file:line:column)
  /// Every modifier a surface uses (the model's own and Honeybee's generic defaults), named by
  /// identifier, mapped by project::radiance_material.
  std::vector<MaterialSpec> materials;
  std::vector<HoneybeeSurface> surfaces;
  std::vector<HoneybeeGrid> grids;
  std::vector<std::string> rooms;  ///< room identifiers, in file order
  /// Faces left out, one phrase each, for `check` (the second face of each shared wall, air
  /// boundaries).
  std::vector<std::string> notes;
  /// Located warnings of the reader (what is read but not modelled as Honeybee would, e.g.
  /// the dynamic states of an aperture) and notes (Severity::Note: a grid weighted by its
  /// mesh's face areas); `check` and `run` print them with the scene's.
  std::vector<Diagnostic> warnings;
};

/// Metres per unit of a Honeybee `units` value; 0 for an unknown name.
double honeybee_metres_per_unit(const std::string& units);

/// Read and map an HBJSON file. `shown_path` is the name locations carry (the path as
/// resolved from the project file). Throws InputError with every problem found.
HoneybeeModel read_honeybee_model(const std::string& path, const std::string& shown_path);

/// Same, from text in memory (`file` names it in locations).
HoneybeeModel read_honeybee_model_from_string(const std::string& text, const std::string& file);

}  // namespace dayphoton::project
