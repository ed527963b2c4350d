// Wavefront OBJ import:
// - every vertex reference form (v, v/vt, v//vn, v/vt/vn), negative (relative) indices,
//   usemtl, ignored o/g/s/mtllib statements and comments;
// - a malformed OBJ reports each problem as file:LINE:COL with the line and a caret;
// - meshes through the scene builder: material_map / default_material, scale + rotation +
//   translation, port flag, degenerate faces and missing files as located errors.
#include <gtest/gtest.h>

#include <cmath>

#include "dayphoton/core/polygon.h"
#include "dayphoton/project/obj_reader.h"
#include "dayphoton/project/project.h"
#include "geometry_fixture.h"

namespace dayphoton::project {
namespace {

using testing::build_error;
using testing::TempFile;

const char* const UnitCubeTopAndSide =
    "# exported by hand\n"
    "mtllib scene.mtl\n"
    "o shelf\n"
    "v 0 0 1\n"
    "v 1 0 1\n"
    "v 1 1 1\n"
    "v 0 1 1   # comment after data\n"
    "vt 0 0\n"
    "vt 1 0\n"
    "vt 1 1\n"
    "vn 0 0 1\n"
    "g top\n"
    "s off\n"
    "usemtl white\n"
    "f 1/1/1 2/2/1 3/3/1 4//1\n"
    "usemtl steel\n"
    "v 0 0 0\n"
    "v 1 0 0\n"
    "f -2 -1 2 1\n"
    "f 5/1 6/2 2/3\n";

TEST(ObjReader, AMaterialNameWithBlanksIsOneName) {
  // usemtl takes one name (Wavefront OBJ, Appendix B1); exporters write names with blanks.
  Diagnostics diag;
  const ObjMesh mesh = read_obj_from_string(
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl Glass  Pane 01   # double-glazed\nf 1 2 3\n", "pane.obj", diag);
  ASSERT_FALSE(diag.has_errors()) << diag.format();
  ASSERT_EQ(mesh.faces.size(), 1u);
  EXPECT_EQ(mesh.faces[0].material, "Glass  Pane 01");
  ASSERT_EQ(mesh.materials.size(), 1u);
  EXPECT_EQ(mesh.materials[0].location.column, 8);
}

TEST(ObjReader, ReadsEveryVertexReferenceForm) {
  Diagnostics diag;
  const ObjMesh mesh = read_obj_from_string(UnitCubeTopAndSide, "shelf.obj", diag);
  ASSERT_FALSE(diag.has_errors()) << diag.format();
  EXPECT_EQ(mesh.vertex_count, 6u);
  ASSERT_EQ(mesh.faces.size(), 3u);
  const ObjFace& top = mesh.faces[0];
  EXPECT_EQ(top.material, "white");
  EXPECT_EQ(top.location.line, 15);
  EXPECT_EQ(top.location.column, 1);
  ASSERT_EQ(top.vertices.size(), 4u);
  EXPECT_EQ(top.vertices[2], Vec3(1, 1, 1));
  EXPECT_EQ(polygon_normal(top.vertices), Vec3(0, 0, 1));
  // Negative indices count back from the last vertex read: -2 -> v5, -1 -> v6.
  const ObjFace& side = mesh.faces[1];
  EXPECT_EQ(side.material, "steel");
  ASSERT_EQ(side.vertices.size(), 4u);
  EXPECT_EQ(side.vertices[0], Vec3(0, 0, 0));
  EXPECT_EQ(side.vertices[1], Vec3(1, 0, 0));
  EXPECT_EQ(side.vertices[2], Vec3(1, 0, 1));
  EXPECT_EQ(polygon_normal(side.vertices), Vec3(0, -1, 0));
  EXPECT_NEAR(polygon_area_m2(mesh.faces[2].vertices), 0.5, 1e-15);
  ASSERT_EQ(mesh.materials.size(), 2u);
  EXPECT_EQ(mesh.materials[1].name, "steel");
  EXPECT_EQ(mesh.materials[1].location.line, 16);
  EXPECT_EQ(mesh.materials[1].location.column, 8);
}

TEST(ObjReader, MalformedObjGivesLocatedErrors) {
  const std::string text =
      "v 0 0 0\n"           // 1
      "v 1 0 0\n"           // 2
      "v 1 1 x\n"           // 3: not a number, column 7
      "v 0 1\n"             // 4: two values; caret after the last, column 6
      "f 1 2 5\n"           // 5: vertex 5 out of range, column 7
      "f 1 0 2\n"           // 6: index 0, column 5
      "f 1 2\n"             // 7: two vertices
      "curv 0 1 1 2\n"      // 8: free-form
      "  bogus 1 2\n"       // 9: unknown statement, column 3
      "f 1/1/1 2 -1\n"      // 10: no vt (col 5), no vn (col 7), -1 is the bad v4 (col 11)
      "v nan 0 0\n"         // 11: not finite, column 3
      "f 1 2 5\n"           // 12: uses the invalid vertex 5
      "f 1 2 2/x\n"         // 13: bad texture index, column 9
      "usemtl\n"            // 14: no name
      "f 1 2 4\n";          // 15: v4 counted (bad) -> reported
  Diagnostics diag;
  const ObjMesh mesh = read_obj_from_string(text, "bad.obj", diag);
  const std::string out = diag.format();
  const char* const expected[] = {
      "bad.obj:3:7: error: expected a number, found 'x'\n    v 1 1 x\n          ^\n",
      "bad.obj:4:6: error: a vertex needs x y z (optionally w, or r g b), found 2 value(s)\n",
      "bad.obj:5:7: error: vertex index 5 is out of range (4 vertices defined so far)",
      "bad.obj:6:5: error: vertex index 0 is invalid (OBJ indices start at 1)\n",
      "bad.obj:7:1: error: a face needs at least 3 vertices, found 2\n",
      "bad.obj:8:1: error: free-form geometry ('curv') is not supported",
      "bad.obj:9:3: error: unknown OBJ statement 'bogus'\n      bogus 1 2\n      ^\n",
      "bad.obj:10:5: error: texture coordinate index 1 is out of range (0 texture coordinates defined so far)",
      "bad.obj:10:7: error: normal index 1 is out of range (0 normals defined so far)",
      "bad.obj:10:11: error: face uses vertex -1, which is invalid\n    f 1/1/1 2 -1\n              ^\n",
      "bad.obj:11:3: error: vertex coordinate is not finite ('nan')\n",
      "bad.obj:12:7: error: face uses vertex 5, which is invalid\n",
      "bad.obj:13:9: error: expected a texture coordinate index, found 'x'\n",
      "bad.obj:14:7: error: usemtl needs a material name\n",
      "bad.obj:15:7: error: face uses vertex 4, which is invalid\n",
  };
  for (const char* e : expected) EXPECT_NE(out.find(e), std::string::npos) << "missing: " << e << "\nin:\n" << out;
  EXPECT_EQ(diag.error_count(), sizeof(expected) / sizeof(expected[0])) << out;
  EXPECT_TRUE(mesh.faces.empty());
}

TEST(ObjReader, MeshThroughSceneBuilder) {
  TempFile obj("obj_reader_test_mesh.obj", UnitCubeTopAndSide);
  Project p;
  p.materials = {testing::lambertian("white_paint", 0.8), testing::lambertian("grey", 0.4)};
  MeshSpec mesh;
  mesh.name = "shelf";
  mesh.path = obj.path();
  mesh.material_map = {{"white", "white_paint"}};
  mesh.default_material = "grey";
  mesh.scale = 2;
  mesh.rotation_deg = 90;
  mesh.translate = {10, 0, 0};
  mesh.port = false;
  mesh.location = {"p.yaml", 12, 5};
  p.geometry.meshes.push_back(mesh);
  const SceneDescription scene = build_scene_description(p);
  ASSERT_EQ(scene.surfaces.size(), 3u);
  const Surface& top = scene.surfaces[0];
  EXPECT_EQ(top.name, "shelf:15");
  EXPECT_EQ(scene.materials[top.material].name, "white_paint");
  EXPECT_EQ(scene.materials[scene.surfaces[1].material].name, "grey");  // 'steel' unmapped -> default
  EXPECT_EQ(top.location.file, obj.path());
  EXPECT_EQ(top.location.line, 15);
  // (1,0,1) scaled by 2 -> (2,0,2), turned +90 degrees -> (0,2,2), moved -> (10,2,2).
  EXPECT_NEAR(length(top.vertices[1] - Vec3{10, 2, 2}), 0, 1e-12);
  EXPECT_NEAR(polygon_area_m2(top.vertices), 4, 1e-12);
  // The side's normal (0,-1,0) turns to (1,0,0).
  EXPECT_NEAR(length(polygon_normal(scene.surfaces[1].vertices) - Vec3{1, 0, 0}), 0, 1e-12);

  // No default: the unmapped usemtl is reported at its line in the OBJ file.
  p.geometry.meshes[0].default_material.clear();
  std::string text = build_error(p);
  EXPECT_NE(text.find(obj.path() + ":16:8: error: OBJ material 'steel' is not in the material_map of mesh 'shelf'"),
            std::string::npos) << text;
  // Unknown project material in the map.
  p.geometry.meshes[0].material_map = {{"white", "white_pain"}, {"steel", "grey"}};
  text = build_error(p);
  EXPECT_NE(text.find("p.yaml:12:5: error: unknown material 'white_pain' for OBJ material 'white' of mesh 'shelf' "
                      "(did you mean 'white_paint'?)"),
            std::string::npos) << text;
  // Missing file: reported at the mesh entry.
  p.geometry.meshes[0].material_map = {{"white", "white_paint"}, {"steel", "grey"}};
  p.geometry.meshes[0].path = obj.path() + ".missing";
  EXPECT_NE(build_error(p).find("p.yaml:12:5: error: OBJ file '" + obj.path() + ".missing' not found"), std::string::npos);
  // Bad scale.
  p.geometry.meshes[0].path = obj.path();
  p.geometry.meshes[0].scale = -1;
  EXPECT_NE(build_error(p).find("scale must be positive"), std::string::npos);
}

TEST(ObjReader, DegenerateAndNonPlanarFacesPointIntoTheObj) {
  TempFile obj("obj_reader_test_bad_faces.obj",
               "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 1 1 0\nv 0 1 0.5\n"
               "f 1 2 3\n"      // 6: collinear -> zero area
               "f 1 2 4 5\n");  // 7: 0.5 m out of plane
  Project p;
  p.materials = {testing::lambertian("grey", 0.4)};
  MeshSpec mesh;
  mesh.name = "junk";
  mesh.path = obj.path();
  mesh.default_material = "grey";
  mesh.location = {"p.yaml", 3, 3};
  p.geometry.meshes.push_back(mesh);
  const std::string text = build_error(p);
  EXPECT_NE(text.find(obj.path() + ":6:1: error: surface 'junk:6' is degenerate (zero area)\n    f 1 2 3\n    ^\n"),
            std::string::npos) << text;
  EXPECT_NE(text.find(obj.path() + ":7:1: error: surface 'junk:7' is not planar"), std::string::npos) << text;
}

}  // namespace
}  // namespace dayphoton::project
