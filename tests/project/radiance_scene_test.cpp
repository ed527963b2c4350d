// RADIANCE scene reader (project/radiance_scene.h): the reference office's files, the token
// syntax, xform, tessellation against closed forms, and every refusal with its location.
#include "dayphoton/project/radiance_scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "dayphoton/core/polygon.h"
#include "dayphoton/core/units.h"
#include "dayphoton/engine/bsdf_material.h"
#include "../tensor_tree_xml_writer.h"

namespace dayphoton::project {
namespace {

namespace fs = std::filesystem;
const std::string Radiance = std::string(DAYPHOTON_TEST_DATA_DIR) + "/radiance";

RadianceScene read(const std::string& text, Diagnostics& diag, bool skip = false) {
  RadianceSceneOptions options;
  options.skip_unsupported = skip;
  return read_radiance_scene_from_string(text, "scene.rad", options, diag);
}

/// The first error's text ("file:line:col: error: message" and the caret lines).
std::string first_error(const Diagnostics& diag) {
  for (const Diagnostic& d : diag.entries())
    if (d.severity == Severity::Error) return d.format();
  return "";
}

std::size_t warnings(const Diagnostics& diag) {
  std::size_t n = 0;
  for (const Diagnostic& d : diag.entries()) n += d.severity == Severity::Warning;
  return n;
}

TEST(RadianceScene, ReadsTheReferenceOffice) {
  Diagnostics diag;
  const RadianceScene scene =
      read_radiance_scene({Radiance + "/materials.rad", Radiance + "/office.rad"}, {}, diag);
  ASSERT_FALSE(diag.has_errors()) << diag.format();
  EXPECT_EQ(warnings(diag), 0u) << diag.format();
  ASSERT_EQ(scene.materials.size(), 4u);
  ASSERT_EQ(scene.surfaces.size(), 10u);
  const RadianceSurface& window = scene.surfaces.back();
  EXPECT_EQ(window.name, "window");
  EXPECT_EQ(window.modifier, "glass_mat");
  const MaterialSpec& glass = scene.materials[static_cast<std::size_t>(window.material)];
  EXPECT_EQ(glass.type, MaterialType::Glass);
  EXPECT_NEAR(glass.transmittance.y, 0.60, 1e-4);
  ASSERT_EQ(window.vertices.size(), 4u);
  EXPECT_EQ(window.vertices[1], Vec3(1, 0, 2.4));
  EXPECT_NEAR(polygon_area_m2(window.vertices), 6.0, 1e-12);
  // Normals face into the room, as the file says: the window's toward +y.
  EXPECT_GT(polygon_normal(window.vertices).y, 0.99);
  EXPECT_EQ(window.location.line, 53);
  EXPECT_EQ(window.location.column, 1);
  const MaterialSpec& floor = scene.materials[static_cast<std::size_t>(scene.surfaces[0].material)];
  EXPECT_EQ(floor.name, "floor_mat");
  EXPECT_EQ(floor.reflectance, Vec3(0.2, 0.2, 0.2));
}

TEST(RadianceScene, FreeFormatCommentsAndQuotedStrings) {
  Diagnostics diag;
  const RadianceScene scene = read(
      "# a comment\n"
      "void plastic   grey 0 0 5 .5 .5 .5 0 0   # after a primitive\n"
      "void mirror m 1 \"white paint\" 0 3 0.9 0.9 0.9\n"
      "grey polygon\tp 0 0 12\n 0 0 0  1 0 0\n 1 1 0\n 0 1 0\n",
      diag);
  // The mirror's alternate material is noted (and ignored), nothing else.
  EXPECT_FALSE(diag.has_errors()) << diag.format();
  EXPECT_EQ(warnings(diag), 1u) << diag.format();
  ASSERT_EQ(scene.surfaces.size(), 1u);
  EXPECT_EQ(scene.surfaces[0].vertices.size(), 4u);
}

TEST(RadianceScene, CommandsAreNeverRunButLocated) {
  Diagnostics diag;
  read("void plastic grey 0 0 5 .5 .5 .5 0 0\n"
       "  !genbox grey box 1 1 1\n",
       diag);
  const std::string e = first_error(diag);
  EXPECT_NE(e.find("scene.rad:2:3: error: command '!genbox'"), std::string::npos) << e;
  EXPECT_NE(e.find("never runs commands"), std::string::npos) << e;
  EXPECT_NE(e.find("xform -e scene.rad"), std::string::npos) << e;
}

TEST(RadianceScene, UndefinedModifierAndBadArgumentsAreLocated) {
  {
    Diagnostics diag;
    read("void plastic grey 0 0 5 .5 .5 .5 0 0\ngray polygon p 0 0 9 0 0 0 1 0 0 0 1 0\n", diag);
    const std::string e = first_error(diag);
    EXPECT_NE(e.find("scene.rad:2:1: error: polygon 'p': modifier 'gray' is not defined"), std::string::npos) << e;
    EXPECT_NE(e.find("did you mean 'grey'?"), std::string::npos) << e;
  }
  {
    Diagnostics diag;
    read("void plastic grey 0 0 5 .5 .5 .5 0 0\ngrey polygon p 0 0 8 0 0 0 1 0 0 0 1\n", diag);
    EXPECT_NE(first_error(diag).find("scene.rad:2:6: error: polygon 'p': needs 3 coordinates per vertex"),
              std::string::npos)
        << first_error(diag);
  }
  {
    Diagnostics diag;
    read("void plastic grey 0 0 5 .5 .5 x 0 0\n", diag);
    EXPECT_NE(first_error(diag).find("scene.rad:1:31: error: plastic 'grey': real argument 3 'x' is not a number"),
              std::string::npos)
        << first_error(diag);
  }
  {
    Diagnostics diag;
    read("void plastic grey 0 0 5 .5 .5 .5 0 0\ngrey polgon p 0 0 9 0 0 0 1 0 0 0 1 0\n", diag);
    EXPECT_NE(first_error(diag).find("scene.rad:2:6: error: unknown RADIANCE primitive type 'polgon'"),
              std::string::npos)
        << first_error(diag);
    EXPECT_NE(first_error(diag).find("did you mean 'polygon'?"), std::string::npos);
  }
  {
    Diagnostics diag;
    read("void glass g 0 0 3 1.2 0.9 0.9\n", diag);
    EXPECT_NE(first_error(diag).find("scene.rad:1:6: error: glass 'g': transmissivity 1.2 (red) is above 1"),
              std::string::npos)
        << first_error(diag);
  }
}

TEST(RadianceScene, UnsupportedModifiersAreErrorsOrSkippedOnRequest) {
  const std::string text =
      "void brightfunc dirt 2 dirt dirt.cal 0 0\n"
      "dirt plastic dirty 0 0 5 .5 .5 .5 0 0\n"
      "void plastic2 blind 4 0 0 1 . 0 6 .5 .5 .5 0 .1 .1\n"
      "void plastic grey 0 0 5 .5 .5 .5 0 0\n"
      "dirty polygon a 0 0 9 0 0 0 1 0 0 0 1 0\n"
      "blind polygon b 0 0 9 0 0 0 1 0 0 0 1 0\n"
      "grey polygon c 0 0 9 0 0 0 1 0 0 0 1 0\n";
  {
    Diagnostics diag;
    read(text, diag);
    ASSERT_EQ(diag.error_count(), 2u) << diag.format();
    EXPECT_NE(diag.format().find("scene.rad:5:1: error: polygon 'a': plastic 'dirty' is modified by brightfunc "
                                 "'dirt': patterns"),
              std::string::npos)
        << diag.format();
    EXPECT_NE(diag.format().find("scene.rad:6:1: error: polygon 'b': plastic2 'blind': anisotropic reflection "
                                 "is not modelled (use plastic, metal or trans) (defined at scene.rad:3:15)"),
              std::string::npos)
        << diag.format();
  }
  {
    Diagnostics diag;
    const RadianceScene scene = read(text, diag, /*skip=*/true);
    EXPECT_FALSE(diag.has_errors()) << diag.format();
    ASSERT_EQ(scene.surfaces.size(), 1u);
    EXPECT_EQ(scene.surfaces[0].name, "c");
    EXPECT_NE(diag.format().find("warning: polygon 'b': plastic2 'blind'"), std::string::npos) << diag.format();
  }
}

TEST(RadianceScene, LightSourcesAndVoidAreLeftOutWithANote) {
  Diagnostics diag;
  const RadianceScene scene = read(
      "void glow sky_glow 0 0 4 1 1 1 0\n"
      "sky_glow source sky 0 0 4 0 0 1 180\n"
      "void light lamp 0 0 3 100 100 100\n"
      "lamp sphere bulb 0 0 4 0 0 2 0.05\n"
      "void polygon hole 0 0 9 0 0 0 1 0 0 0 1 0\n"
      "void glass g 0 0 3 0.654 0.654 0.654\n"
      "void illum window_illum 1 g 0 3 1 1 1\n"
      "window_illum polygon w 0 0 9 0 0 0 1 0 0 0 1 0\n",
      diag);
  EXPECT_FALSE(diag.has_errors()) << diag.format();
  ASSERT_EQ(scene.surfaces.size(), 1u);
  EXPECT_EQ(scene.surfaces[0].name, "w");
  EXPECT_EQ(scene.materials[static_cast<std::size_t>(scene.surfaces[0].material)].type, MaterialType::Glass);
  const std::string text = diag.format();
  EXPECT_NE(text.find("light 'lamp' is a light source: 1 surface using it left out"), std::string::npos) << text;
  EXPECT_NE(text.find("1 surface with modifier 'void' left out"), std::string::npos) << text;
  EXPECT_NE(text.find("1 distant 'source' primitive left out"), std::string::npos) << text;
  EXPECT_NE(text.find("take its alternate material 'g'"), std::string::npos) << text;
}

TEST(RadianceScene, AliasAndRedefinition) {
  Diagnostics diag;
  const RadianceScene scene = read(
      "void plastic grey 0 0 5 .5 .5 .5 0 0\n"
      "void alias wall grey\n"
      "wall polygon a 0 0 9 0 0 0 1 0 0 0 1 0\n"
      "void plastic grey 0 0 5 .3 .3 .3 0 0\n"
      "grey polygon b 0 0 9 0 0 0 1 0 0 0 1 0\n",
      diag);
  ASSERT_FALSE(diag.has_errors()) << diag.format();
  ASSERT_EQ(scene.surfaces.size(), 2u);
  const MaterialSpec& a = scene.materials[static_cast<std::size_t>(scene.surfaces[0].material)];
  const MaterialSpec& b = scene.materials[static_cast<std::size_t>(scene.surfaces[1].material)];
  EXPECT_EQ(a.name, "grey");
  EXPECT_DOUBLE_EQ(a.reflectance.x, 0.5);
  EXPECT_EQ(b.name, "grey@scene.rad:4:14");
  EXPECT_DOUBLE_EQ(b.reflectance.x, 0.3);
}

TEST(RadianceScene, MeshesAndInstancesAreRefused) {
  Diagnostics diag;
  read("void plastic grey 0 0 5 .5 .5 .5 0 0\ngrey mesh chair 1 chair.rtm 0 0\n", diag);
  EXPECT_NE(first_error(diag).find("scene.rad:2:1: error: mesh 'chair': compiled RADIANCE meshes"),
            std::string::npos)
      << first_error(diag);
}

// ---- tessellation ---------------------------------------------------------------------------

TEST(RadianceScene, SegmentsKeepTheSagittaWithinTheTolerance) {
  for (double r : {0.05, 0.5, 1.0, 3.0, 10.0}) {
    const int n = radiance_circle_segments(r);
    EXPECT_GE(n, RadianceMinSegments);
    if (n < RadianceMaxSegments) {
      EXPECT_LE(r * (1 - std::cos(Pi / n)), RadianceTessellationTolerance_m * (1 + 1e-12)) << r;
      if (n > RadianceMinSegments) {  // the fewest that do
        EXPECT_GT(r * (1 - std::cos(Pi / (n - 1))), RadianceTessellationTolerance_m) << r;
      }
    }
  }
  EXPECT_EQ(radiance_circle_segments(1000.0), RadianceMaxSegments);
}

TEST(RadianceScene, SphereFacetsLieOnAndJustInsideTheSphere) {
  for (const char* type : {"sphere", "bubble"}) {
    Diagnostics diag;
    const std::string text = std::string("void plastic grey 0 0 5 .5 .5 .5 0 0\ngrey ") + type +
                             " ball 0 0 4 1 2 3 1.5\n";
    const RadianceScene scene = read(text, diag);
    ASSERT_FALSE(diag.has_errors()) << diag.format();
    const Vec3 c{1, 2, 3};
    double area_m2 = 0;
    for (const RadianceSurface& s : scene.surfaces) {
      for (const Vec3& p : s.vertices) EXPECT_NEAR(length(p - c), 1.5, 1e-12);
      const Vec3 n = polygon_normal(s.vertices);
      // The facet's plane is within the tolerance of the sphere, and faces out (sphere) or in.
      const double plane_distance = dot(s.vertices[0] - c, n);
      EXPECT_GE(std::fabs(plane_distance), 1.5 - RadianceTessellationTolerance_m);
      EXPECT_EQ(plane_distance > 0, std::string(type) == "sphere");
      EXPECT_LT(planarity_deviation_m(s.vertices), 1e-12);
      EXPECT_EQ(s.solid_face, std::string(type) == "sphere");
      area_m2 += polygon_area_m2(s.vertices);
    }
    // Inscribed facets: a little less than 4 pi r^2, by about the relative tolerance.
    EXPECT_LT(area_m2, 4 * Pi * 1.5 * 1.5);
    EXPECT_GT(area_m2, 4 * Pi * 1.5 * 1.5 * (1 - 2 * RadianceTessellationTolerance_m / 1.5));
  }
}

TEST(RadianceScene, RingCylinderAndConeFaceAsRadianceSays) {
  Diagnostics diag;
  const RadianceScene scene = read(
      "void plastic grey 0 0 5 .5 .5 .5 0 0\n"
      "grey ring disc 0 0 8 0 0 1 0 0 1 0 2\n"
      "grey ring annulus 0 0 8 0 0 0 0 0 -1 1 2\n"
      "grey cylinder post 0 0 7 5 5 0 5 5 3 0.2\n"
      "grey tube pipe 0 0 7 5 5 0 5 5 3 0.2\n"
      "grey cone lamp 0 0 8 0 0 0 0 0 1 0.5 0\n"
      "grey cup bowl 0 0 8 0 0 0 0 0 1 0 0.5\n",
      diag);
  ASSERT_FALSE(diag.has_errors()) << diag.format();
  double disc_m2 = 0, annulus_m2 = 0;
  int disc = 0;
  for (const RadianceSurface& s : scene.surfaces) {
    const Vec3 n = polygon_normal(s.vertices);
    const Vec3 centroid = polygon_centroid(s.vertices);
    if (s.name == "disc") {
      ++disc;
      disc_m2 += polygon_area_m2(s.vertices);
      EXPECT_GT(n.z, 0.999);
    } else if (s.name.rfind("annulus.", 0) == 0) {
      annulus_m2 += polygon_area_m2(s.vertices);
      EXPECT_LT(n.z, -0.999);
    } else {
      const bool at_5 = s.name.rfind("post", 0) == 0 || s.name.rfind("pipe", 0) == 0;
      const Vec3 axis_point{at_5 ? 5.0 : 0.0, at_5 ? 5.0 : 0.0, centroid.z};
      const double outward = dot(n, centroid - axis_point);
      const bool inward = s.name.rfind("pipe", 0) == 0 || s.name.rfind("bowl", 0) == 0;
      EXPECT_EQ(outward < 0, inward) << s.name;
    }
  }
  EXPECT_EQ(disc, 1);
  // An inscribed regular n-gon: n/2 sin(2 pi / n) r^2.
  const int n = radiance_circle_segments(2.0);
  const double ngon = 0.5 * n * std::sin(2 * Pi / n);
  EXPECT_NEAR(disc_m2, ngon * 4, 1e-12);
  EXPECT_NEAR(annulus_m2, ngon * (4 - 1), 1e-12);
}

// ---- xform ----------------------------------------------------------------------------------

class RadianceXform : public ::testing::Test {
 protected:
  void SetUp() override {
    // A folder per test: ctest runs the tests of this fixture in parallel processes.
    m_dir = fs::path(::testing::TempDir()) /
            ("radiance_xform_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(m_dir);
    fs::create_directories(m_dir / "parts");
    write("parts/tri.rad", "grey polygon tri 0 0 9 0 0 0 1 0 0 0 1 0\n");
  }
  void TearDown() override { fs::remove_all(m_dir); }
  void write(const std::string& name, const std::string& text) { std::ofstream(m_dir / name) << text; }
  RadianceScene read_main(const std::string& text, Diagnostics& diag) {
    write("main.rad", "void plastic grey 0 0 5 .5 .5 .5 0 0\n" + text);
    return read_radiance_scene({(m_dir / "main.rad").string()}, {}, diag);
  }
  fs::path m_dir;
};

TEST_F(RadianceXform, PlainTransformsApplyInOrder) {
  Diagnostics diag;
  // Rotate 90 deg about z, then translate: (1, 0, 0) -> (0, 1, 0) -> (10, 1, 0).
  const RadianceScene scene = read_main("!xform -rz 90 -t 10 0 0 parts/tri.rad\n", diag);
  ASSERT_FALSE(diag.has_errors()) << diag.format();
  ASSERT_EQ(scene.surfaces.size(), 1u);
  const auto& v = scene.surfaces[0].vertices;
  EXPECT_NEAR(length(v[0] - Vec3(10, 0, 0)), 0, 1e-12);
  EXPECT_NEAR(length(v[1] - Vec3(10, 1, 0)), 0, 1e-12);
  EXPECT_NEAR(length(v[2] - Vec3(9, 0, 0)), 0, 1e-12);
  EXPECT_EQ(scene.surfaces[0].location.file, (m_dir / "parts/tri.rad").lexically_normal().string());
}

TEST_F(RadianceXform, IterationScaleAndNesting) {
  // -i 3 repeats the translation; -s scales about the origin; the nested file's own xform
  // applies first, then the outer one.
  write("parts/twice.rad", "!xform -rx 90 tri.rad\n");
  Diagnostics diag;
  const RadianceScene scene = read_main("!xform -s 2 -i 3 -t 1 0 0 parts/twice.rad\n", diag);
  ASSERT_FALSE(diag.has_errors()) << diag.format();
  ASSERT_EQ(scene.surfaces.size(), 1u);
  const auto& v = scene.surfaces[0].vertices;
  // (0, 1, 0) -rx 90-> (0, 0, 1) -s 2-> (0, 0, 2) -3 x t-> (3, 0, 2).
  EXPECT_NEAR(length(v[2] - Vec3(3, 0, 2)), 0, 1e-12);
  EXPECT_NEAR(length(v[1] - Vec3(5, 0, 0)), 0, 1e-12);
}

// xform's -n NAME (a prefix for the identifiers it writes, common in scenes that place
// copies: "!xform -n win.0 -t 5 0 0 pane.rad") changes no geometry: it is read, and the
// transforms around it apply. It was refused as an option not read.
TEST_F(RadianceXform, NamePrefixIsReadAndChangesNoGeometry) {
  Diagnostics diag;
  const RadianceScene scene = read_main("!xform -n copy.0 -t 10 0 0 parts/tri.rad\n", diag);
  ASSERT_FALSE(diag.has_errors()) << diag.format();
  ASSERT_EQ(scene.surfaces.size(), 1u);
  EXPECT_NEAR(length(scene.surfaces[0].vertices[1] - Vec3(11, 0, 0)), 0, 1e-12);
  Diagnostics missing;
  read_main("!xform -n -t 10 0 0 parts/tri.rad\n", missing);
  EXPECT_NE(first_error(missing).find("option -n needs a name"), std::string::npos) << first_error(missing);
}

TEST_F(RadianceXform, AnythingButPlainXformIsRefused) {
  {
    Diagnostics diag;
    read_main("!xform -a 4 -t 1 0 0 parts/tri.rad\n", diag);
    EXPECT_NE(first_error(diag).find("main.rad:2:1: error: '!xform' option '-a' is not read"), std::string::npos)
        << first_error(diag);
  }
  {
    Diagnostics diag;
    read_main("!xform -t 1 0 0 parts/tri.rad | grep x\n", diag);
    EXPECT_NE(first_error(diag).find("shell syntax"), std::string::npos) << first_error(diag);
  }
  {
    write("loop.rad", "!xform loop.rad\n");
    Diagnostics diag;
    read_main("!xform loop.rad\n", diag);
    EXPECT_NE(first_error(diag).find("already being read"), std::string::npos) << first_error(diag);
  }
  {
    Diagnostics diag;
    read_main("!xform -t 1 0 0 parts/missing.rad\n", diag);
    EXPECT_NE(first_error(diag).find("main.rad:2:1: error: RADIANCE scene file"), std::string::npos)
        << first_error(diag);
  }
}

}  // namespace
}  // namespace dayphoton::project

namespace dayphoton::project {
namespace {

TEST_F(RadianceXform, BsdfModifiersReadTheirFileAndTurnTheirUpVector) {
  // The file is relative to the .rad file that names it; the up vector turns with the xform
  // of that file (-rz 90: x -> y); surfaces of a BSDF are port candidates under ports: auto.
  fs::copy_file(std::string(DAYPHOTON_SOURCE_DIR) + "/projects/bsdf_blind/blind_45deg.xml", m_dir / "parts/blind.xml");
  write("parts/window.rad", "void BSDF blind 6 0 blind.xml 1 0 0 . 0 0\nblind polygon w 0 0 9 0 0 0 1 0 0 1 0 1\n");
  Diagnostics diag;
  const RadianceScene scene = read_main("!xform -rz 90 parts/window.rad\n", diag);
  ASSERT_FALSE(diag.has_errors()) << diag.format();
  ASSERT_EQ(scene.surfaces.size(), 1u);
  const MaterialSpec& m = scene.materials.at(static_cast<std::size_t>(scene.surfaces[0].material));
  const engine::BsdfMaterialParameters* bsdf = engine::bsdf_parameters(m);
  ASSERT_NE(bsdf, nullptr);
  EXPECT_EQ(bsdf->data->basis.size(), 145);
  EXPECT_NEAR(length(bsdf->up - Vec3(0, 1, 0)), 0, 1e-12);
  {
    // A tensor-tree file (TensorTree3) is taken where a Klems file is.
    write("parts/film.xml", dayphoton::test::tensor_tree_xml({"{ 0.2 }", "{ 0.2 }", "{ 0.05 }", "{ 0.05 }"}));
    Diagnostics d3;
    const RadianceScene film = read_main("void BSDF film 6 0 parts/film.xml 0 0 1 . 0 0\nfilm polygon f 0 0 9 0 0 0 1 0 0 1 0 1\n", d3);
    ASSERT_FALSE(d3.has_errors()) << d3.format();
    const engine::BsdfMaterialParameters* tt = engine::bsdf_parameters(film.materials.at(static_cast<std::size_t>(film.surfaces[0].material)));
    ASSERT_NE(tt, nullptr);
    ASSERT_TRUE(tt->data->tensor_tree);
    EXPECT_NEAR(tt->data->tensor_tree->slices[0][0].transmittance, 0.2 * Pi, 1e-6);
  }
  {
    // A missing file is an error at the modifier; an error inside the file is located there.
    write("bad.xml", "<WindowElement><Optical></Optical></WindowElement>\n");
    Diagnostics d2;
    read_main("void BSDF gone 6 0 missing.xml 0 0 1 . 0 0\nvoid BSDF bad 6 0 bad.xml 0 0 1 . 0 0\n", d2);
    EXPECT_NE(d2.format().find("main.rad:2:6: error: BSDF file '"), std::string::npos) << d2.format();
    EXPECT_NE(d2.format().find("bad.xml:1:16: error: <Optical> has no <Layer>"), std::string::npos) << d2.format();
  }
}

}  // namespace
}  // namespace dayphoton::project
