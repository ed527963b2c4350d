// The registered `bsdf` material (engine/src/bsdf_material.cpp; docs/materials.md "Measured
// BSDF (Klems)") through engine::Material: the sampling harness' consistency checks (weight ==
// eval |cos| / pdf to 1e-9, E[weight] == albedo within 4 sigma), the window factors on
// transmitted light only, no straight component; and the scene's checks (an up vector parallel
// to a surface's normal; a BSDF port whose front would face the room), both located. The
// harness' chi-square is not used: its cells in (cos theta, phi) about the normal cut across
// the Klems patches, whose density jumps at every patch edge, and its cell integration assumes
// a smooth density; the patch-level chi-square of klems_bsdf_test.cpp (exact for a piecewise
// constant density) tests the distribution instead.
#include "dayphoton/engine/bsdf_material.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <string>

#include "../bsdf_xml_writer.h"
#include "dayphoton/core/diagnostics.h"
#include "dayphoton/engine/material.h"
#include "dayphoton/engine/scene.h"
#include "material_test_harness.h"

namespace dayphoton::engine {
namespace {

// Forward peak plus a spread part, different per side.
std::shared_ptr<const KlemsBsdfData> peaked() {
  const KlemsBasis b = KlemsBasis::full();
  return std::make_shared<KlemsBsdfData>(dayphoton::test::klems_from(
      b, [b](int i, int o) { return (i == o ? 0.4 / b.projected_solid_angle(o) : 0.0) + 0.1 / Pi; },
      [](int, int o) { return o < 40 ? 0.5 / Pi : 0.1 / Pi; }, [](int, int) { return 0.15 / Pi; },
      [b](int i, int o) { return i == o ? 0.2 / b.projected_solid_angle(o) : 0.0; }));
}

void consistency(const Material& m, const Vec3& in, const Vec3& n, std::uint64_t seed, const std::string& label) {
  const test::SamplingReport r = test::measure_sampling(m, m, in, n, seed, label, 40000);
  EXPECT_LT(r.max_consistency_error, 1e-9) << label;
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(r.mean_weight[c], r.albedo[c], 4.0 * r.weight_sigma_of_mean[c] + 1e-10) << label;
    EXPECT_LE(r.albedo[c], 1.0 + 1e-12) << label;
  }
}

TEST(BsdfMaterial, SamplingHarness) {
  MaterialSpec spec = bsdf_material_spec("blind", peaked(), Vec3{0, 0, 1});
  const Material m = Material::from_spec(spec);
  const Vec3 n = test::tilted_normal();
  std::uint64_t seed = 1;
  for (double theta : {0.0, 35.0, 70.0, 86.0})
    for (bool back : {false, true})
      consistency(m, test::incident_direction(n, theta, 30.0, back), n, seed++,
                  "bsdf theta " + std::to_string(int(theta)) + (back ? " back" : " front"));
  EXPECT_EQ(m.straight_transmittance(Vec3{0, 0, -1}, Vec3{0, 0, 1}), Vec3(0, 0, 0));
  EXPECT_FALSE(m.model().stores_photons());
}

TEST(BsdfMaterial, WindowFactorScalesTheTransmittedLightOnly) {
  MaterialSpec spec = bsdf_material_spec("blind", peaked(), Vec3{0, 0, 1});
  const Material plain = Material::from_spec(spec);
  spec.transmittance_factor = 0.6;
  const Material framed = Material::from_spec(spec);
  const Vec3 n = test::tilted_normal();
  const Vec3 in = test::incident_direction(n, 20.0, 10.0, true);  // moving along n: front incidence
  // Front: T = 0.4 + 0.1 = 0.5 (hemispherical), R = 0.15: plain 0.65, framed 0.6 x 0.5 + 0.15.
  EXPECT_NEAR(plain.albedo(in, n).y, 0.65, 1e-9);
  EXPECT_NEAR(framed.albedo(in, n).y, 0.45, 1e-9);
  consistency(framed, in, n, 99, "bsdf with a window factor");
}

SceneDescription one_window(const Vec3& up, bool reversed) {
  SceneDescription d;
  d.materials.push_back(bsdf_material_spec("blind", peaked(), up));
  d.materials.back().location = {"project.yaml", 3, 5};
  MaterialSpec wall;
  wall.name = "wall";
  wall.reflectance = {0.5, 0.5, 0.5};
  d.materials.push_back(wall);
  // A closed 4 x 4 x 3 room, the window in its south wall (y = 0), normal into the room (+y).
  auto quad = [&](const std::string& name, int material, std::vector<Vec3> v) {
    Surface s;
    s.name = name;
    s.material = material;
    s.vertices = std::move(v);
    s.location = {"project.yaml", 10 + static_cast<int>(d.surfaces.size()), 7};
    d.surfaces.push_back(s);
  };
  std::vector<Vec3> window = {{1, 0, 1}, {1, 0, 2}, {3, 0, 2}, {3, 0, 1}};  // normal +y
  if (reversed) std::reverse(window.begin(), window.end());
  quad("window", 0, window);
  d.surfaces.back().port = true;
  d.surfaces.back().facing = PortFacing::Auto;
  quad("floor", 1, {{0, 0, 0}, {0, 4, 0}, {4, 4, 0}, {4, 0, 0}});
  quad("ceiling", 1, {{0, 0, 3}, {4, 0, 3}, {4, 4, 3}, {0, 4, 3}});
  quad("north", 1, {{0, 4, 0}, {0, 4, 3}, {4, 4, 3}, {4, 4, 0}});
  quad("east", 1, {{4, 0, 0}, {4, 4, 0}, {4, 4, 3}, {4, 0, 3}});
  quad("west", 1, {{0, 0, 0}, {0, 0, 3}, {0, 4, 3}, {0, 4, 0}});
  return d;
}

std::string build_error(const SceneDescription& d) {
  try {
    Scene::build(d);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(BsdfMaterial, SceneRefusesAnUndefinedFrameAndAFrontFacingTheRoom) {
  EXPECT_EQ(build_error(one_window({0, 0, 1}, false)), "no error");
  EXPECT_NE(build_error(one_window({0, 1, 0}, false))
                .find("project.yaml:10:7: error: surface 'window': the up vector (0, 1, 0) of its BSDF material 'blind' "
                      "is parallel to the surface's normal"),
            std::string::npos)
      << build_error(one_window({0, 1, 0}, false));
  // Drawn the other way round, the port's room side is against its winding: the BSDF's front
  // (the side the normal points away from) would be indoors.
  EXPECT_NE(build_error(one_window({0, 0, 1}, true))
                .find("project.yaml:10:7: error: surface 'window' is a port of BSDF material 'blind' whose normal "
                      "points out of the room"),
            std::string::npos)
      << build_error(one_window({0, 0, 1}, true));
}

}  // namespace
}  // namespace dayphoton::engine
