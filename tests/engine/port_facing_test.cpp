// Ports face either way (engine/port_facing.h): Scene::build points Port::normal into the
// room whichever way the port polygon was drawn, so a roof light drawn facing the sky (its
// natural winding) brings in the same light as one drawn facing the room. A port whose room
// side the rays cannot tell is marked Ambiguous, a declared facing the rays refute
// Contradicted (the project's placement check turns both into located errors).
#include <gtest/gtest.h>

#include <cmath>

#include "dayphoton/core/units.h"
#include "dayphoton/engine/photon_tracer.h"
#include "dayphoton/engine/port_emission.h"
#include "dayphoton/engine/port_facing.h"
#include "dayphoton/engine/scene.h"
#include "dayphoton/sky/patch_basis.h"
#include "dayphoton/sky/solar_position.h"
#include "estimate_statistics.h"
#include "test_scenes.h"

namespace dayphoton::engine {
namespace {

/// A 4 x 4 x 3 m room of polygons (normals inward) with a 1 x 1 m glazed roof light in the
/// middle of its ceiling, wound facing the sky (`sky_side` true, normal +z) or the room, and
/// declared `facing`. Nothing above the roof: the sky side sees the whole sky.
SceneDescription roof_light_room(bool sky_side, PortFacing facing) {
  SceneDescription d;
  const int grey = test::add_material(d, "grey", MaterialType::Lambertian, 0.5);
  const int glass = test::add_material(d, "glass", MaterialType::Glass, 0.0);
  using test::add_surface;
  add_surface(d, "floor", grey, {{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {0, 4, 0}});
  add_surface(d, "wall_x0", grey, {{0, 0, 0}, {0, 4, 0}, {0, 4, 3}, {0, 0, 3}});
  add_surface(d, "wall_x1", grey, {{4, 0, 0}, {4, 0, 3}, {4, 4, 3}, {4, 4, 0}});
  add_surface(d, "wall_y0", grey, {{0, 0, 0}, {0, 0, 3}, {4, 0, 3}, {4, 0, 0}});
  add_surface(d, "wall_y1", grey, {{0, 4, 0}, {4, 4, 0}, {4, 4, 3}, {0, 4, 3}});
  // The ceiling around the opening x, y in [1.5, 2.5], facing down.
  auto ceiling = [&](const char* name, double x0, double x1, double y0, double y1) {
    add_surface(d, name, grey, {{x0, y0, 3}, {x0, y1, 3}, {x1, y1, 3}, {x1, y0, 3}});
  };
  ceiling("ceiling_s", 0, 4, 0, 1.5);
  ceiling("ceiling_n", 0, 4, 2.5, 4);
  ceiling("ceiling_w", 0, 1.5, 1.5, 2.5);
  ceiling("ceiling_e", 2.5, 4, 1.5, 2.5);
  std::vector<Vec3> light = {{1.5, 1.5, 3}, {2.5, 1.5, 3}, {2.5, 2.5, 3}, {1.5, 2.5, 3}};  // +z
  if (!sky_side) std::reverse(light.begin(), light.end());
  add_surface(d, "roof_light", glass, light, /*port=*/true);
  d.surfaces.back().facing = facing;
  return d;
}

std::vector<Material> models_of(const SceneDescription& d) {
  std::vector<Material> m;
  for (const MaterialSpec& spec : d.materials) m.push_back(Material::from_spec(spec));
  return m;
}

TEST(PortFacing, ARoofLightPointsIntoTheRoomWhicheverWayItIsDrawn) {
  for (bool sky_side : {true, false}) {
    SCOPED_TRACE(sky_side ? "drawn facing the sky" : "drawn facing the room");
    const Scene scene = Scene::build(roof_light_room(sky_side, PortFacing::Auto));
    ASSERT_EQ(scene.ports().size(), 1u);
    const Port& port = scene.ports()[0];
    EXPECT_EQ(port.side_reason, PortSideReason::Sky);
    EXPECT_NEAR(port.normal.z, -1.0, 1e-12);
    EXPECT_EQ(port.against_winding, sky_side);
    // The sky side sees the whole sky, the room side none of it.
    const double sky = sky_side ? port.sky_fraction_winding : port.sky_fraction_opposite;
    const double room = sky_side ? port.sky_fraction_opposite : port.sky_fraction_winding;
    EXPECT_EQ(sky, 1.0);
    EXPECT_EQ(room, 0.0);
  }
}

TEST(PortFacing, GeneratedPortsKeepTheirWindingUntested) {
  // PortFacing::Winding (the default of a Surface): the generator's word, no rays cast.
  const Scene scene = Scene::build(roof_light_room(true, PortFacing::Winding));
  const Port& port = scene.ports()[0];
  EXPECT_EQ(port.side_reason, PortSideReason::Generated);
  EXPECT_NEAR(port.normal.z, 1.0, 1e-12);
  EXPECT_FALSE(port.against_winding);
}

TEST(PortFacing, ADeclaredFacingIsKeptAndCheckedAgainstTheSky) {
  // Declared right: "out" for a polygon wound toward the sky, "in" for one wound into the room.
  for (const auto& [sky_side, facing] : {std::pair<bool, PortFacing>{true, PortFacing::Out}, {false, PortFacing::In}}) {
    const Port port = Scene::build(roof_light_room(sky_side, facing)).ports()[0];
    EXPECT_EQ(port.side_reason, PortSideReason::Declared);
    EXPECT_NEAR(port.normal.z, -1.0, 1e-12);
  }
  // Declared wrong: the room would be the side that sees the sky. The declared side is kept
  // (the placement check refuses the project).
  for (const auto& [sky_side, facing] : {std::pair<bool, PortFacing>{true, PortFacing::In}, {false, PortFacing::Out}}) {
    const Port port = Scene::build(roof_light_room(sky_side, facing)).ports()[0];
    EXPECT_EQ(port.side_reason, PortSideReason::Contradicted);
    EXPECT_NEAR(port.normal.z, 1.0, 1e-12);
  }
}

TEST(PortFacing, APortTheRaysCannotPlaceIsAmbiguous) {
  // A free-standing port: both sides see the sky alike.
  SceneDescription open;
  const int glass = test::add_material(open, "glass", MaterialType::Glass, 0.0);
  test::add_surface(open, "pane", glass, {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, true);
  open.surfaces.back().facing = PortFacing::Auto;
  const Port free_port = Scene::build(open).ports()[0];
  EXPECT_EQ(free_port.side_reason, PortSideReason::Ambiguous);
  EXPECT_NEAR(free_port.sky_fraction_winding, 1.0, 1e-12);
  EXPECT_NEAR(free_port.sky_fraction_opposite, 1.0, 1e-12);
  // A port between two closed rooms (a 1 m cube split by a glazed partition): neither side
  // sees the sky.
  SceneDescription closed = test::box_room({2, 1, 1});
  const int pane = test::add_material(closed, "glass", MaterialType::Glass, 0.0);
  test::add_surface(closed, "partition", pane, {{1, 0, 0}, {1, 1, 0}, {1, 1, 1}, {1, 0, 1}}, true);
  closed.surfaces.back().facing = PortFacing::Auto;
  const Port inner = Scene::build(closed).ports()[0];
  EXPECT_EQ(inner.side_reason, PortSideReason::Ambiguous);
  EXPECT_EQ(inner.sky_fraction_winding, 0.0);
  EXPECT_EQ(inner.sky_fraction_opposite, 0.0);
}

TEST(PortFacing, TheDecisionRule) {
  // Decisive: at least PortFacingMinSkyFraction and PortFacingSkyRatio times the other side.
  EXPECT_EQ(decide_port_side(PortFacing::Auto, {0.02, 0.0}).reason, PortSideReason::Sky);
  EXPECT_TRUE(decide_port_side(PortFacing::Auto, {0.02, 0.0}).against_winding);
  EXPECT_FALSE(decide_port_side(PortFacing::Auto, {0.0, 0.5}).against_winding);
  EXPECT_EQ(decide_port_side(PortFacing::Auto, {0.005, 0.0}).reason, PortSideReason::Ambiguous);
  EXPECT_EQ(decide_port_side(PortFacing::Auto, {0.6, 0.4}).reason, PortSideReason::Ambiguous);
  EXPECT_EQ(decide_port_side(PortFacing::In, {0.6, 0.4}).reason, PortSideReason::Declared);
  EXPECT_EQ(decide_port_side(PortFacing::Out, {0.0, 0.0}).reason, PortSideReason::Declared);
  EXPECT_TRUE(decide_port_side(PortFacing::Out, {0.0, 0.0}).against_winding);
  EXPECT_EQ(decide_port_side(PortFacing::Winding, {1.0, 0.0}).reason, PortSideReason::Generated);
}

TEST(PortFacing, EveryPortsFluxIsTheSameWhicheverWayItIsDrawn) {
  // The flux the sky bins send through the roof light (the port emitter's quadrature, as
  // the energy-balance tests use it): one Tregenza sky, the roof light wound either way.
  // A deterministic 256 x 256 quadrature of the same integrand: equal to rounding.
  const sky::PatchBasis basis = sky::PatchBasis::tregenza();
  const SourceSet sources = SourceSet::sky_bins(basis);
  const Scene up = Scene::build(roof_light_room(true, PortFacing::Auto));
  const Scene down = Scene::build(roof_light_room(false, PortFacing::Auto));
  const PortEmitter from_up(up, sources), from_down(down, sources);
  double total = 0;
  for (std::size_t p = 0; p < sources.size(); ++p) {
    const double a = from_up.port_flux(p, 32), b = from_down.port_flux(p, 32);
    EXPECT_NEAR(a, b, 1e-12 * (1 + b)) << "bin " << p;
    total += b;
  }
  // The sky bins (not the ground) bring light through a horizontal opening of 1 m^2:
  // the integral of cos over the upper hemisphere is pi.
  EXPECT_NEAR(total, Pi, 0.01 * Pi);
}

TEST(PortFacing, ARoofLightLightsTheRoomTheSameWhicheverWayItIsDrawn) {
  // The photons a sun 60 degrees high sends through the roof light onto the work plane
  // (global photons crossing z = 0.8 m downward), in Trials independent runs per winding.
  // The two means must agree within 4 standard errors of their difference,
  // 4 sqrt(s_a^2 / n + s_b^2 / n), with s the trials' own standard deviations.
  const Vec3 sun_dir = normalize(Vec3{0.3, -0.4, std::tan(60 * Pi / 180) * 0.5});
  SourceSet sun;
  sun.add_sun_disc(sun_dir, sky::SunHalfAngle_rad);
  const ReceiverPlane plane(0.8, true, {{0, 0}, {4, 0}, {4, 4}, {0, 4}});
  constexpr int Trials = 12;
  test::Stats drawn[2];
  for (int w = 0; w < 2; ++w) {
    const SceneDescription d = roof_light_room(w == 0, PortFacing::Auto);
    const Scene scene = Scene::build(d);
    const std::vector<Material> materials = models_of(d);
    for (int t = 0; t < Trials; ++t) {
      TracingOptions o;
      o.photons_per_source = 20000;
      o.seed = 100 + static_cast<std::uint64_t>(t);
      const TracedPhotons traced = trace_photons(scene, materials, sun, {plane}, o);
      double flux = 0;
      for (const Photon& p : traced.planes[0]) flux += (p.flux_rgb().x + p.flux_rgb().y + p.flux_rgb().z) / 3;
      drawn[w].add(flux);
    }
  }
  ASSERT_GT(drawn[1].mean(), 0.0);
  const double bound = 4 * std::sqrt((drawn[0].sigma() * drawn[0].sigma() + drawn[1].sigma() * drawn[1].sigma()) /
                                     Trials);
  EXPECT_NEAR(drawn[0].mean(), drawn[1].mean(), bound)
      << "facing the sky " << drawn[0].mean() << ", facing the room " << drawn[1].mean();
  RecordProperty("relative_difference", std::to_string(drawn[0].mean() / drawn[1].mean() - 1));
  RecordProperty("relative_bound", std::to_string(bound / drawn[1].mean()));
}

}  // namespace
}  // namespace dayphoton::engine
