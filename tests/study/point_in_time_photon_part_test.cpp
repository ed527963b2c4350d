// A CIE point-in-time case's photon part on the sub-patches of its own sky
// (point_in_time_cie_quadrant_deltas, sub_patch_shares(SharesOf::PhotonPart),
// sub_patch_correction_lux; docs/photon-map.md, "The point-in-time photon part").
//
// The closed-form case of tests/engine/photon_part_on_sky_test.cpp: a black room lit only
// through a vertical Lambertian diffuser (window at y = 2, x [-1, 1], z [0.5, 1.5], facing +y)
// that faces the sky above a distant black wall hiding the sky below 6 degrees (half of the
// lowest Tregenza band). Every photon leaves the diffuser in a direction independent of where
// it came from and the room returns none, so the photon part on the work plane is
// proportional to the diffuser's vertical irradiance whatever the sky. Under a CIE clear sky
// (type 12) with the sun at 9 degrees in front of the window, in the visible upper half of the
// lowest band, the bins around the sun vary steeply within themselves: the patch-uniform sum
// (each bin at its mean) misses the light the pane sees, the sky of quadrant means sees most of
// it. The photon part with the shares over its basis sum must be the diffuser's irradiance
// from the quadrant sky over that from the bin means, both by midpoint quadrature from the
// case's own column and deltas, within 4 standard errors over 16 seeds (|t| > 4 has
// probability 1e-3 with 15 degrees of freedom), and the basis's ratio, 1, must lie outside them.
// The quadrant sky's ratio lies closer to the continuous sky's than the basis does (reported).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "../engine/diffuser_room.h"
#include "../engine/estimate_statistics.h"
#include "../engine/test_scenes.h"
#include "dayphoton/core/units.h"
#include "dayphoton/engine/daylight_coefficients.h"
#include "dayphoton/engine/estimate_variance.h"
#include "dayphoton/engine/photon_tracer.h"
#include "dayphoton/engine/scene.h"
#include "dayphoton/sky/patch_basis.h"
#include "dayphoton/sky/sky_matrix.h"
#include "dayphoton/sky/sky_model.h"
#include "dayphoton/study/annual_illuminance.h"
#include "dayphoton/study/point_in_time.h"
#include "dayphoton/study/sub_patch_shares.h"

namespace dayphoton::study {
namespace {


constexpr double GroundRadiance = 0.0;  // the ground plays no part: only the sky's shape
using engine::test::diffuser_room;
bool hidden(const Vec3& w) { return engine::test::hidden_by_opposing_wall(w); }

/// The sun 9 degrees high, 5 degrees east of the window's normal (off the bins' borders).
Vec3 sun_direction() {
  const double a = 9.0 * Pi / 180.0, az = 5.0 * Pi / 180.0;
  return {std::cos(a) * std::sin(az), std::cos(a) * std::cos(az), std::sin(a)};
}

double lum(const RadianceMatrix& m, std::size_t row) {
  return dot(RgbLuminanceWeights, Vec3{m.at(row, 0, 0), m.at(row, 0, 1), m.at(row, 0, 2)});
}

/// The diffuser's irradiance (normal +y) from the bin means, the quadrant sky and the
/// continuous sky, the hidden directions left out, by midpoint quadrature over sin(altitude)
/// and azimuth (equal solid angles).
struct PaneIrradiance {
  double bin_means = 0, quadrants = 0, continuous = 0;
};
PaneIrradiance pane_irradiance(const sky::PatchBasis& basis, const sky::SkyModel& model, const RadianceMatrix& column,
                               const RadianceMatrix& deltas) {
  constexpr int Nu = 1500, Nphi = 3000;
  const double du = 1.0 / Nu, dphi = 2 * Pi / Nphi;
  PaneIrradiance e;
  for (int i = 0; i < Nu; ++i) {
    const double z = (i + 0.5) * du, rho = std::sqrt(1 - z * z);
    for (int j = 0; j < Nphi; ++j) {
      const double phi = (j + 0.5) * dphi;
      const Vec3 w{rho * std::cos(phi), rho * std::sin(phi), z};
      if (w.y <= 0 || hidden(w)) continue;
      const int p = basis.find_bin(w);
      const double mean = lum(column, std::size_t(p));
      e.bin_means += mean * w.y;
      e.quadrants += (mean + deltas.at(std::size_t(4 * p + basis.quadrant(p, w)), 0, 0)) * w.y;
      e.continuous += dot(RgbLuminanceWeights, model.radiance_rgb(w)) * w.y;
    }
  }
  return e;
}

TEST(PointInTimePhotonPart, ACieClearSkysPhotonPartSeesTheQuadrantsOfItsSky) {
  constexpr int Seeds = 16;
  const SceneDescription d = diffuser_room();
  const engine::Scene scene = engine::Scene::build(d);
  std::vector<engine::Material> materials;
  for (const MaterialSpec& m : d.materials) materials.push_back(engine::Material::from_spec(m));
  const sky::PatchBasis basis = sky::PatchBasis::tregenza();
  const engine::SourceSet sources = engine::SourceSet::sky_bins(basis);
  const std::unique_ptr<sky::SkyModel> model =
      sky::make_cie_general_sky(12, sun_direction(), sky::SkyScale::horizontal_illuminance_lux(10000));
  const RadianceMatrix column = sky::sky_vector(*model, basis, Vec3{GroundRadiance, GroundRadiance, GroundRadiance});
  const RadianceMatrix deltas = sky::sky_vector_quadrant_deltas(*model, basis, column);
  const PaneIrradiance e = pane_irradiance(basis, *model, column, deltas);
  const double expected = e.quadrants / e.bin_means;
  RecordProperty("quadrants_over_bin_means", std::to_string(expected));
  RecordProperty("continuous_over_bin_means", std::to_string(e.continuous / e.bin_means));
  // The quadrant sky is nearer the continuous one than the patch-uniform sky is.
  EXPECT_LT(std::fabs(e.continuous - e.quadrants), 0.5 * std::fabs(e.continuous - e.bin_means));

  const std::vector<engine::ReceiverPlane> planes = {
      engine::ReceiverPlane(0.0, true, {{-3, -3}, {3, -3}, {3, 2}, {-3, 2}})};
  const std::vector<SensorPoint> sensors = {
      {{0, 0, 0}, {0, 0, 1}}, {{-2, -2, 0}, {0, 0, 1}}, {{1.5, 1.2, 0}, {0, 0, 1}}};
  std::vector<engine::test::Stats> ratio(sensors.size());
  for (int k = 0; k < Seeds; ++k) {
    engine::TracingOptions t;
    t.photons_per_source = 1500;
    t.seed = 7300 + std::uint64_t(k);
    t.keep_surface_photons = false;
    engine::TracedPhotons photons = engine::trace_photons(scene, materials, sources, planes, t);
    const engine::GridPhotons grid =
        engine::GridPhotons::for_plane(planes[0], std::move(photons.planes[0]), sources.size());
    engine::CoefficientOptions o;
    o.seed = t.seed;
    o.direct.seed = t.seed;
    o.direct.samples_per_source = 1;  // the direct part plays no role here
    o.photon_quadrants = true;
    const engine::DaylightCoefficients c =
        engine::daylight_coefficients(scene, materials, sources, grid, sensors, o);
    const SubPatchShares shares = sub_patch_shares(c, SharesOf::PhotonPart);
    ASSERT_FALSE(shares.empty());
    const std::vector<double> correction = sub_patch_correction_lux(shares, deltas, 0);
    for (std::size_t s = 0; s < sensors.size(); ++s) {
      double basis_lux = 0;
      for (std::size_t p = 0; p < c.sources; ++p)
        basis_lux += engine::luminance_of(c.caustic[s * c.sources + p] + c.global[s * c.sources + p]) * lum(column, p);
      basis_lux *= RadianceWhiteEfficacy_lm_per_W;
      ratio[s].add((basis_lux + correction[s]) / basis_lux);
    }
  }
  for (std::size_t s = 0; s < sensors.size(); ++s) {
    RecordProperty("sensor_" + std::to_string(s) + "_ratio", std::to_string(ratio[s].mean()));
    EXPECT_NEAR(ratio[s].mean(), expected, ratio[s].tolerance()) << "sensor " << s;
    EXPECT_GT(std::fabs(1.0 - expected), ratio[s].tolerance()) << "sensor " << s << ": the basis would pass";
  }
}

// The quadrant deltas of one sky's vector against a fine quadrature of the same sky: each
// quadrant's mean luminance by a 40 x 40 midpoint rule, normalised as the vector is (to the
// model's horizontal illuminance), less the vector's bin value. The production rule's 3 x 3
// midpoints per quadrant differ from it by the midpoint rule's error, 0.4 % at most here (below 1 %) of the
// quadrant's luminance for the CIE clear sky with a low sun (largest in the circumsolar bins);
// the deltas themselves reach 10-40 % of the bin there, so the check is not vacuous.
TEST(PointInTimePhotonPart, TheQuadrantDeltasAreTheSkysQuadrantMeans) {
  const sky::PatchBasis basis = sky::PatchBasis::tregenza();
  const std::unique_ptr<sky::SkyModel> model =
      sky::make_cie_general_sky(12, sun_direction(), sky::SkyScale::horizontal_illuminance_lux(10000));
  const RadianceMatrix column = sky::sky_vector(*model, basis, Vec3{0.3, 0.3, 0.3});
  const RadianceMatrix deltas = sky::sky_vector_quadrant_deltas(*model, basis, column);
  ASSERT_EQ(deltas.rows(), std::size_t(4 * basis.bin_count()));
  for (int q = 0; q < 4; ++q) EXPECT_EQ(deltas.at(std::size_t(q), 0, 0), 0.0f) << "the ground";
  constexpr int N = 40;
  double largest_relative_delta = 0, largest_error = 0, largest_mean_shift = 0;
  for (int p = 1; p < basis.bin_count(); ++p) {
    double mean_of_quadrants = 0;
    for (int q = 0; q < 4; ++q) {
      double sum = 0;
      for (int i = 0; i < N; ++i)
        for (int j = 0; j < N; ++j)
          sum += dot(RgbLuminanceWeights, model->radiance_rgb(basis.sample_direction(
                                              p, 0.5 * (q / 2) + 0.5 * (i + 0.5) / N, 0.5 * (q % 2) + 0.5 * (j + 0.5) / N)));
      const double fine = sum / (N * N);
      const double got = lum(column, std::size_t(p)) + deltas.at(std::size_t(4 * p + q), 0, 0);
      EXPECT_NEAR(got, fine, 0.01 * fine) << "bin " << p << ", quadrant " << q;
      mean_of_quadrants += 0.25 * got;
      largest_error = std::max(largest_error, std::fabs(got / fine - 1));
      largest_relative_delta =
          std::max(largest_relative_delta, std::fabs(deltas.at(std::size_t(4 * p + q), 0, 0)) / fine);
    }
    largest_mean_shift = std::max(largest_mean_shift, std::fabs(mean_of_quadrants / lum(column, std::size_t(p)) - 1));
  }
  RecordProperty("largest_quadrant_error", std::to_string(largest_error));
  RecordProperty("largest_relative_delta", std::to_string(largest_relative_delta));
  // The quadrants' mean need not be the vector's value: each is normalised to the horizontal
  // illuminance by its own rule (the quadrants' is the finer), about 1 % apart for this sky.
  RecordProperty("largest_mean_shift", std::to_string(largest_mean_shift));
  EXPECT_GT(largest_relative_delta, 0.1);
}

// The cases' deltas: a CIE general case's column is its sky's, an overcast or weather case's
// zero (their photon parts take the DF's continuous correction and the hour's deltas).
TEST(PointInTimePhotonPart, OnlyTheCieGeneralCasesGetTheirSkysDeltas) {
  const sky::SolarSite site{37.72, -122.22, -8, 0};
  const sky::PatchBasis basis = sky::PatchBasis::tregenza();
  std::vector<project::PointInTimeSpec> cases(3);
  for (project::PointInTimeSpec& c : cases) {
    c.month = 12;
    c.day = 21;
    c.hour_lst = 9.0;
    c.diffuse_horizontal_illuminance_lux = 10000;
  }
  cases[0].sky = project::PointSky::CieGeneral;
  cases[0].cie_type = 12;
  cases[1].sky = project::PointSky::CieOvercast;
  cases[2].sky = project::PointSky::Weather;
  const RadianceMatrix d = point_in_time_cie_quadrant_deltas(cases, site, basis, 0.2);
  ASSERT_EQ(d.columns(), 3u);
  double general = 0;
  for (std::size_t r = 0; r < d.rows(); ++r) {
    general += std::fabs(d.at(r, 0, 0));
    EXPECT_EQ(d.at(r, 1, 0), 0.0f);
    EXPECT_EQ(d.at(r, 2, 0), 0.0f);
  }
  EXPECT_GT(general, 0.0);
}

// The scalar correction is the one annual_illuminance adds with the same shares and deltas.
TEST(PointInTimePhotonPart, TheCorrectionIsTheAnnualProducts) {
  const std::size_t sensors = 2, bins = 3;
  SubPatchShares shares;
  shares.sensors = sensors;
  shares.bins = bins;
  RadianceMatrix coefficients(sensors, bins, 1);
  for (std::size_t i = 0; i < sensors * bins; ++i) {
    coefficients.data()[i] = 0.1f * float(i + 1);
    shares.values.insert(shares.values.end(), {0.1f * float(i + 1), 0.01f * float(i), 0.02f, 0.03f * float(i % 2)});
  }
  RadianceMatrix sky(bins, 2, 1), deltas(4 * bins, 2, 1);
  for (std::size_t p = 0; p < bins; ++p)
    for (std::size_t t = 0; t < 2; ++t) sky.at(p, t, 0) = 1.0f + float(p + t);
  for (std::size_t r = 4; r < 4 * bins; ++r)
    for (std::size_t t = 0; t < 2; ++t) deltas.at(r, t, 0) = 0.1f * float(r % 5) - 0.2f + 0.05f * float(t);
  const std::vector<metrics::TimeStamp> steps = {{1, 1, 10.5}, {1, 1, 11.5}};
  const metrics::IlluminanceTable with = annual_illuminance(coefficients, sky, steps, 0, &shares, &deltas);
  const metrics::IlluminanceTable without = annual_illuminance(coefficients, sky, steps);
  for (std::size_t t = 0; t < 2; ++t) {
    const std::vector<double> correction = sub_patch_correction_lux(shares, deltas, t);
    for (std::size_t s = 0; s < sensors; ++s)
      EXPECT_NEAR(double(with.lux(t, s)) - double(without.lux(t, s)), correction[s], 1e-4 * (1 + std::fabs(correction[s])))
          << "step " << t << ", sensor " << s;
  }
}

}  // namespace
}  // namespace dayphoton::study
