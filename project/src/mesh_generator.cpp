// Mesh generator: OBJ faces (obj_reader.h) placed in the model by scale, then rotation about
// +Z (counter-clockwise seen from above for positive rotation_deg), then translation, and
// given project materials: an OBJ `usemtl` name found in material_map takes the mapped
// project material; other faces take default_material; with no default an unmapped usemtl
// is an error at its first `usemtl` line. Surface names are "<mesh>:<line>" (the OBJ line of
// the face); each Surface's location is the face's `f` statement, so later geometry errors
// point into the OBJ file.
#include <cmath>
#include <map>

#include "dayphoton/core/units.h"
#include "dayphoton/project/obj_reader.h"
#include "geometry_generators.h"

namespace dayphoton::project::detail {

void generate_mesh(const MeshSpec& mesh, MaterialLookup& materials, Diagnostics& diag,
                   std::vector<Surface>& out) {
  const std::string what = "mesh '" + mesh.name + "'";
  if (!std::isfinite(mesh.scale) || mesh.scale <= 0) {
    report(diag, mesh.location, what + ": scale must be positive (a negative scale would turn faces inside out)");
    return;
  }
  if (!is_finite(mesh.translate) || !std::isfinite(mesh.rotation_deg)) {
    report(diag, mesh.location, what + ": translate and rotation must be finite");
    return;
  }
  const std::string path = mesh.path.empty() ? mesh.path_as_written : mesh.path;
  if (path.empty()) {
    report(diag, mesh.location, what + ": no OBJ file given");
    return;
  }

  // Project materials of the map and the default, resolved once.
  std::map<std::string, int> mapped;
  for (const auto& [obj_name, project_name] : mesh.material_map)
    mapped[obj_name] = materials.resolve(project_name, mesh.location,
                                         "OBJ material '" + obj_name + "' of " + what);
  int default_mat = -1;
  if (!mesh.default_material.empty())
    default_mat = materials.resolve(mesh.default_material, mesh.location, "the default material of " + what);

  const std::size_t errors_before = diag.error_count();
  const ObjMesh obj = read_obj(path, diag, mesh.location);
  if (diag.error_count() == errors_before && obj.faces.empty())
    report(diag, mesh.location, what + ": the OBJ file '" + path + "' has no faces");

  // Unmapped usemtl names (reported once each, at their first use).
  for (const ObjMaterialUse& use : obj.materials)
    if (!mapped.count(use.name) && mesh.default_material.empty())
      diag.error(use.location,
                 "OBJ material '" + use.name + "' is not in the material_map of " + what +
                     " and the mesh has no default_material",
                 read_source_line(use.location.file, use.location.line));
  for (const auto& [obj_name, project_name] : mesh.material_map) {
    bool used = false;
    for (const ObjMaterialUse& use : obj.materials) used = used || use.name == obj_name;
    if (!used && !obj.faces.empty())
      diag.warning(mesh.location, "material_map entry '" + obj_name + "' of " + what +
                                      " matches no usemtl in '" + path + "'");
  }
  bool reported_no_material = false;

  const double a = deg_to_rad(mesh.rotation_deg);
  const double c = std::cos(a), s = std::sin(a);
  for (const ObjFace& face : obj.faces) {
    Surface surface;
    surface.name = mesh.name + ":" + std::to_string(face.location.line);
    const auto it = mapped.find(face.material);
    if (it != mapped.end()) {
      surface.material = it->second;
    } else if (!mesh.default_material.empty()) {
      surface.material = default_mat;
    } else if (face.material.empty() && !reported_no_material) {
      // Faces before any usemtl, with no default to fall back on.
      diag.error(face.location,
                 "face has no usemtl and " + what + " has no default_material",
                 read_source_line(face.location.file, face.location.line));
      reported_no_material = true;
    }
    for (const Vec3& p : face.vertices) {
      const Vec3 q = p * mesh.scale;
      surface.vertices.push_back(Vec3{q.x * c - q.y * s, q.x * s + q.y * c, q.z} + mesh.translate);
    }
    surface.port = mesh.port;
    surface.facing = mesh.facing;
    // OBJ faces are wound counter-clockwise seen from outside (the format's convention), so
    // a closed mesh is a solid with outward normals; a mesh of ports is an opening.
    surface.solid_face = !mesh.port;
    surface.outdoor_scatterer = mesh.outdoor;
    surface.location = face.location;
    out.push_back(std::move(surface));
  }
}

}  // namespace dayphoton::project::detail
