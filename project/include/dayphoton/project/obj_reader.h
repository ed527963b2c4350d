// Wavefront OBJ reader for meshes placed by a project file (geometry.meshes).
//
// Supported statements (Wavefront "Object Files (.obj)", Appendix B1 of the Advanced
// Visualizer manual):
//   v x y z [w]          vertex (w ignored; 6 or 7 numbers = vertex with RGB colour, ignored)
//   vt u [v [w]], vn i j k   counted so that face references to them can be checked
//   f v1 v2 v3 ...       polygon, each vertex as v, v/vt, v//vn or v/vt/vn; indices are
//                        1-based, negative indices count back from the last vertex so far
//   usemtl name          material of the following faces (mapped to project materials by
//                        the mesh's material_map / default_material)
//   o, g, s, mtllib, l, p, vp and display attributes   ignored (no area)
//   # comment            anywhere on a line
// Free-form geometry (cstype, curv, surf, ...) is rejected rather than silently dropped.
// Every problem is reported located, "file.obj:LINE:COL: error: ...", with the line and a
// caret; faces with errors are left out, the rest are still read so all errors show at once.
#pragma once

#include <string>
#include <vector>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/source_location.h"
#include "dayphoton/core/vec3.h"

namespace dayphoton::project {

struct ObjFace {
  std::vector<Vec3> vertices;  ///< in file order (the winding gives the normal)
  std::string material;        ///< the `usemtl` in effect, "" if none
  SourceLocation location;     ///< the `f` statement
};

struct ObjMaterialUse {
  std::string name;
  SourceLocation location;  ///< first `usemtl` naming it
};

struct ObjMesh {
  std::vector<ObjFace> faces;
  std::vector<ObjMaterialUse> materials;  ///< distinct `usemtl` names in order of appearance
  std::size_t vertex_count = 0;
};

/// Read `path` (also the name printed in messages). Problems go to `diag`; if the file
/// cannot be opened the error is placed at `referenced_from` (e.g. the project's mesh entry)
/// when that is known.
ObjMesh read_obj(const std::string& path, Diagnostics& diag,
                 const SourceLocation& referenced_from = {});

/// Same, from text in memory; `path` is used in messages.
ObjMesh read_obj_from_string(const std::string& text, const std::string& path, Diagnostics& diag);

}  // namespace dayphoton::project
