// Scene::build validates geometry before Embree sees it (Embree drops bad primitives
// silently): every problem is a located InputError naming the surface, all are reported at
// once, and nothing crashes.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/engine/scene.h"
#include "test_scenes.h"

namespace dayphoton::engine {
namespace {

using test::add_surface;
using test::office_room;

/// Build `d`, expect an InputError, return it.
InputError build_error(const SceneDescription& d) {
  try {
    Scene::build(d);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "Scene::build accepted invalid geometry";
  return InputError(SourceLocation{}, "none");
}

void expect_single_located_error(const SceneDescription& d, const std::string& surface_name,
                                 const std::string& fragment) {
  const InputError e = build_error(d);
  ASSERT_EQ(e.diagnostics().size(), 1u) << e.what();
  const Diagnostic& diag = e.diagnostics()[0];
  EXPECT_EQ(diag.location.file, "test.yaml");
  EXPECT_EQ(diag.location.line, d.surfaces.back().location.line);
  EXPECT_EQ(diag.location.column, 3);
  EXPECT_NE(diag.message.find("'" + surface_name + "'"), std::string::npos) << diag.message;
  EXPECT_NE(diag.message.find(fragment), std::string::npos) << diag.message;
  const std::string where = d.surfaces.back().location.to_string() + ": error: ";
  EXPECT_EQ(std::string(e.what()).rfind(where, 0), 0u) << e.what();
}

TEST(SceneValidation, NanVertexIsALocatedError) {
  SceneDescription d = office_room();
  add_surface(d, "bad_nan", 0, {{0, 0, 1}, {1, 0, 1}, {std::nan(""), 1, 1}});
  expect_single_located_error(d, "bad_nan", "vertex 3 has a NaN or infinite coordinate");
}

TEST(SceneValidation, InfiniteVertexIsALocatedError) {
  SceneDescription d = office_room();
  add_surface(d, "bad_inf", 0,
              {{0, 0, 1}, {std::numeric_limits<double>::infinity(), 0, 1}, {1, 1, 1}});
  expect_single_located_error(d, "bad_inf", "vertex 2 has a NaN or infinite coordinate");
}

TEST(SceneValidation, MaterialIndexOutOfRange) {
  for (int material : {-1, 4, 1000}) {
    SceneDescription d = office_room();  // 4 materials
    add_surface(d, "shelf", material, {{1, 1, 1}, {2, 1, 1}, {2, 2, 1}});
    expect_single_located_error(d, "shelf", "material index " + std::to_string(material) +
                                                " is out of range (4 materials)");
  }
}

TEST(SceneValidation, TooFewVertices) {
  SceneDescription d = office_room();
  add_surface(d, "line", 0, {{1, 1, 1}, {2, 1, 1}});
  expect_single_located_error(d, "line", "has 2 vertices");
}

TEST(SceneValidation, CollinearPolygonIsDegenerate) {
  SceneDescription d = office_room();
  add_surface(d, "flat", 0, {{1, 1, 1}, {2, 1, 1}, {3, 1, 1}, {4, 1, 1}});
  expect_single_located_error(d, "flat", "degenerate");
}

TEST(SceneValidation, RepeatedVertexPolygonIsDegenerate) {
  SceneDescription d = office_room();
  add_surface(d, "dot", 0, {{1, 1, 1}, {1, 1, 1}, {1, 1, 1}});
  expect_single_located_error(d, "dot", "degenerate");
}

TEST(SceneValidation, SliverBelowTheScaledThresholdIsDegenerate) {
  // Office diagonal ~10.4 m: threshold 1e-12 * 10.4^2 ~ 1.1e-10 m^2; this sliver has 5e-11.
  SceneDescription d = office_room();
  add_surface(d, "sliver", 0, {{1, 1, 1}, {2, 1, 1}, {1.5, 1 + 1e-10, 1}});
  expect_single_located_error(d, "sliver", "degenerate");
}

TEST(SceneValidation, SmallButRealPolygonIsAccepted) {
  SceneDescription d = office_room();  // a 1 mm^2 tag on the floor is real geometry
  add_surface(d, "tag", 0, {{1, 1, 0.5}, {1.001, 1, 0.5}, {1.001, 1.001, 0.5}, {1, 1.001, 0.5}});
  const Scene scene = Scene::build(d);
  const auto hit = scene.intersect({{1.0005, 1.0005, 1}, {0, 0, -1}});
  ASSERT_TRUE(hit.has_value());
  EXPECT_EQ(scene.description().surfaces[static_cast<std::size_t>(hit->surface)].name, "tag");
}

TEST(SceneValidation, AllProblemsAreReportedAtOnce) {
  SceneDescription d = office_room();
  add_surface(d, "a", 0, {{0, 0, 1}, {1, 0, 1}, {std::nan(""), 1, 1}});
  add_surface(d, "b", 17, {{1, 1, 1}, {2, 1, 1}, {2, 2, 1}});
  add_surface(d, "c", 0, {{1, 1, 1}, {2, 1, 1}, {3, 1, 1}});
  const InputError e = build_error(d);
  ASSERT_EQ(e.diagnostics().size(), 3u) << e.what();
  EXPECT_EQ(e.diagnostics()[0].location.line, d.surfaces[10].location.line);
  EXPECT_EQ(e.diagnostics()[1].location.line, d.surfaces[11].location.line);
  EXPECT_EQ(e.diagnostics()[2].location.line, d.surfaces[12].location.line);
  EXPECT_NE(std::string(e.what()).find("3 errors generated."), std::string::npos);
}

TEST(SceneValidation, SelfIntersectingPolygonDoesNotCrash) {
  // A bow-tie with unequal lobes: non-zero vector area, but not a simple polygon. Whatever
  // the triangulator makes of it, build must either give a located error or a usable scene.
  SceneDescription d = office_room();
  add_surface(d, "bowtie", 0, {{1, 1, 1}, {3, 2, 1}, {3, 1, 1}, {1, 3, 1}});
  try {
    const Scene scene = Scene::build(d);
    EXPECT_GE(scene.triangle_count(), 21u);
  } catch (const InputError& e) {
    ASSERT_EQ(e.diagnostics().size(), 1u);
    EXPECT_EQ(e.diagnostics()[0].location.line, d.surfaces.back().location.line);
  }
}

}  // namespace
}  // namespace dayphoton::engine
