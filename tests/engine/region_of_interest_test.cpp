// Region of interest (TracingOptions::region_of_interest, issue 6 "photons concentrated where
// they matter"): photons are stored only inside a box, and the photon-count control counts
// only those, so the same target puts more photons where the estimates are made. Storing
// fewer photons must not change the flux of those that are stored.
//
// Scene: the reference office (test::office_room), a sun due south at 40 degrees through the
// window; region of interest = the back half of the room (y >= 4 m), receiver plane at the
// work plane. Tolerances: R independent replicates (own seeds) per configuration; the
// replicate is the unit because crossings of one path are correlated. 4 sigma of the
// difference of the two means.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "dayphoton/engine/photon_tracer.h"
#include "estimate_statistics.h"
#include "test_scenes.h"

namespace dayphoton::engine {
namespace {

constexpr double Pi = 3.14159265358979323846;
constexpr double SunHalfAngle_rad = 0.2665 * Pi / 180;

struct BackHalf {
  double flux = 0;        ///< flux (mean of RGB) crossing the plane at y >= 4 m
  std::size_t count = 0;  ///< plane photons stored there
};

BackHalf back_half(const TracedPhotons& traced) {
  BackHalf b;
  for (const Photon& p : traced.planes[0]) {
    if (p.position[1] < 4.0) continue;
    b.flux += (double(p.flux[0]) + p.flux[1] + p.flux[2]) / 3;
    ++b.count;
  }
  return b;
}

TEST(RegionOfInterest, StoresOnlyInsideAndKeepsTheFluxUnbiased) {
  const SceneDescription d = test::office_room();
  const Scene scene = Scene::build(d);
  std::vector<Material> materials;
  for (const MaterialSpec& m : d.materials) materials.push_back(Material::from_spec(m));
  SourceSet sun;
  const double alt = 40 * Pi / 180;
  sun.add_sun_disc({0, -std::cos(alt), std::sin(alt)}, SunHalfAngle_rad);
  const ReceiverPlane plane(0.8, true, {{0, 0}, {6, 0}, {6, 8}, {0, 8}});
  const Bounds3 roi{{-0.01, 4.0, -0.01}, {6.01, 8.01, 3.01}};

  constexpr int Replicates = 10;
  test::Stats full_flux, roi_flux, full_count, roi_count;
  for (int r = 0; r < Replicates; ++r) {
    TracingOptions o;
    o.photons_per_source = 20000;
    o.seed = 100 + r;
    const TracedPhotons full = trace_photons(scene, materials, sun, {plane}, o);
    o.region_of_interest = roi;
    const TracedPhotons inside = trace_photons(scene, materials, sun, {plane}, o);
    for (const Photon& p : inside.surface) {
      ASSERT_GE(p.position[1], roi.lower.y);
      ASSERT_LE(p.position[1], roi.upper.y);
    }
    for (const Photon& p : inside.planes[0]) ASSERT_GE(p.position[1], roi.lower.y);
    const BackHalf a = back_half(full), b = back_half(inside);
    full_flux.add(a.flux);
    roi_flux.add(b.flux);
    full_count.add(double(a.count));
    roi_count.add(double(b.count));
  }
  const double tolerance =
      4 * std::sqrt((full_flux.sigma() * full_flux.sigma() + roi_flux.sigma() * roi_flux.sigma()) / Replicates);
  EXPECT_NEAR(roi_flux.mean(), full_flux.mean(), tolerance);
  // The back half holds a minority of the full run's photons (the sun patch and the front
  // of the room take most); with the region, the whole target lands there.
  EXPECT_GT(roi_count.mean(), 1.5 * full_count.mean());
  RecordProperty("back_half_photons_full", std::to_string(full_count.mean()));
  RecordProperty("back_half_photons_roi", std::to_string(roi_count.mean()));
  RecordProperty("flux_ratio_roi_over_full", std::to_string(roi_flux.mean() / full_flux.mean()));
}

}  // namespace
}  // namespace dayphoton::engine
