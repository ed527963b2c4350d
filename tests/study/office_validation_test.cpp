// The reference office against RADIANCE, end to end: `run_study` on projects/office (the
// project as shipped: its photon counts, bandwidth, ground factor and direct samples; annual
// outputs off, another seed), then what scripts/validate_office.py and
// bench/office_daylight_factor.cpp compare:
//   - the daylight factor per sensor, the run's sky coefficients times RADIANCE's own overcast
//     sky vector (gensky -c -B 55.866 -g 0.2 | genskyvec -m 1), against rtrace's converged DF
//     (tests/data/radiance/df_office.csv, DF_main_pct);
//   - per sky bin, the sum over sensors of the coefficients against rfluxmtx's classic
//     daylight-coefficient matrix (office_dc_classic.mtx), bins above 0.2 % of the total.
// Seven aggregates of those per-sensor and per-bin differences, whose run-to-run noise was
// measured over 10 seeds (docs/validation.md, "The reference office in CI"): the RMS and the
// largest of the per-sensor relative DF differences, the DF ratio of the whole grid and of its
// back half (y >= 4.5 m, where the light is mostly indirect), the ground bin, the sum of the
// other compared bins, and the largest of those bins' differences. Each must lie within the
// prediction interval of the measured mean, t x sd x sqrt(1 + 1/n), t the Student quantile
// for n - 1 = 9 degrees of freedom at a Sidak-corrected two-sided 1e-3 for the 7 (t = 6.29),
// so a correct build fails with probability about 1e-3 whatever its seed. A change that moves
// the office's light by about a percent (ground reflectance, bandwidth wiring, density
// estimate, photon flux) leaves the grid or sky-bin intervals (+-0.4 %). The issue-5 goals
// (every sensor within 5 %, every bin within 3 %) are not asserted: the measured seeds break
// them by noise alone (largest sensor 5.7 %, ground bin -3.26 %).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "fresh_run.h"
#include "../reference_data.h"
#include "dayphoton/core/radiance_matrix.h"
#include "dayphoton/core/units.h"
#include "dayphoton/project/project.h"
#include "dayphoton/study/progress.h"
#include "dayphoton/study/study_runner.h"
#include "../temp_folder.h"

namespace dayphoton::study {
namespace {

namespace fs = std::filesystem;

const std::string Radiance = std::string(DAYPHOTON_TEST_DATA_DIR) + "/radiance";

/// The seed of the CI run: not one of the seeds the noise was measured with.
constexpr unsigned long long TestSeed = 11;

/// A measured aggregate (docs/validation.md, "The reference office in CI"): mean and sample
/// standard deviation over the runs with seeds 1..10 (measured, 40 000 photons per bin).
struct MeasuredAggregate {
  const char* name;
  double mean, sd;
};
constexpr int MeasuredRuns = 10;
/// Student t quantile, 9 degrees of freedom, two-sided 1 - (1 - 1e-3)^(1/7) = 1.43e-4.
constexpr double StudentT = 6.29;
constexpr MeasuredAggregate SensorRms{"RMS of sensor DF / rtrace - 1", 0.01339, 0.00076};
constexpr MeasuredAggregate SensorMax{"largest |sensor DF / rtrace - 1|", 0.04422, 0.00608};
constexpr MeasuredAggregate GridRatio{"grid DF / rtrace - 1", -0.00412, 0.00035};
constexpr MeasuredAggregate BackRatio{"back half DF / rtrace - 1", -0.00844, 0.00144};
constexpr MeasuredAggregate GroundBin{"ground bin / rfluxmtx - 1", -0.02911, 0.00191};
constexpr MeasuredAggregate SkyBins{"other bins' sum / rfluxmtx - 1", 0.00314, 0.00036};
constexpr MeasuredAggregate SkyBinMax{"largest |other bin / rfluxmtx - 1|", 0.02610, 0.00302};

void expect_within_prediction_interval(const MeasuredAggregate& m, double value) {
  const double half_width = StudentT * m.sd * std::sqrt(1.0 + 1.0 / MeasuredRuns);
  std::printf("[ office ] %-40s %+.5f (measured %+.5f +- %.5f over %d seeds; interval +- %.5f)\n", m.name, value,
              m.mean, m.sd, MeasuredRuns, half_width);
  EXPECT_NEAR(value, m.mean, half_width) << m.name;
}

double photometric(const RadianceMatrix& m, std::size_t row, std::size_t column) {
  return rgb_to_photometric({m.at(row, column, 0), m.at(row, column, 1), m.at(row, column, 2)});
}

TEST(OfficeValidation, DaylightFactorAndBinSumsAgreeWithRadiance) {
  project::Project p = project::load_project(std::string(DAYPHOTON_SOURCE_DIR) + "/projects/office/project.yaml");
  p.simulation.seed = TestSeed;
  p.outputs.annual_illuminance = p.outputs.metrics = p.outputs.images = p.outputs.report = false;
  p.outputs.coefficients = true;
  const fs::path out = test::process_temp_dir() / "office_validation";
  test::run_in_fresh_folder(p, out);

  const RadianceMatrix c = RadianceMatrix::read_file((out / "workplane" / "coefficients_sky.mtx").string());
  const RadianceMatrix sky = RadianceMatrix::read_file(Radiance + "/skyvec_overcast_m1.vec");
  const std::vector<double> rtrace = test::read_reference_df(Radiance + "/df_office.csv");
  const RadianceMatrix rflux = test::read_gzip_matrix(Radiance + "/office_dc_classic.mtx.gz");
  ASSERT_EQ(c.rows(), 165u);
  ASSERT_EQ(c.columns(), 146u);
  ASSERT_EQ(rtrace.size(), 165u);

  // Daylight factor per sensor (%): E / 10 000 lux x 100 for the 10 000 lux overcast sky.
  std::vector<double> df(165, 0.0);
  double sum2 = 0, largest = 0, ours = 0, ref = 0, ours_back = 0, ref_back = 0;
  for (std::size_t s = 0; s < 165; ++s) {
    for (std::size_t b = 0; b < 146; ++b)
      df[s] += rgb_to_photometric({c.at(s, b, 0) * sky.at(b, 0, 0), c.at(s, b, 1) * sky.at(b, 0, 1),
                                   c.at(s, b, 2) * sky.at(b, 0, 2)}) / 100.0;
    const double rel = df[s] / rtrace[s] - 1;
    sum2 += rel * rel;
    largest = std::max(largest, std::abs(rel));
    ours += df[s];
    ref += rtrace[s];
    if (s / 11 >= 8) {  // rows y = 4.5 .. 7.5 m
      ours_back += df[s];
      ref_back += rtrace[s];
    }
  }

  // Per-bin sums over the sensors against rfluxmtx, bins above 0.2 % of the total.
  std::vector<double> bin_ours(146, 0.0), bin_ref(146, 0.0);
  double total = 0;
  for (std::size_t b = 0; b < 146; ++b) {
    for (std::size_t s = 0; s < 165; ++s) {
      bin_ours[b] += photometric(c, s, b);
      bin_ref[b] += photometric(rflux, s, b);
    }
    total += bin_ref[b];
  }
  double sky_ours = 0, sky_ref = 0, sky_largest = 0;
  std::size_t compared = 0;
  for (std::size_t b = 0; b < 146; ++b) {
    if (bin_ref[b] <= 0.002 * total) continue;
    ++compared;
    if (b > 0) {
      sky_ours += bin_ours[b];
      sky_ref += bin_ref[b];
      sky_largest = std::max(sky_largest, std::abs(bin_ours[b] / bin_ref[b] - 1));
    }
  }
  EXPECT_EQ(compared, 55u);

  expect_within_prediction_interval(SensorRms, std::sqrt(sum2 / 165));
  expect_within_prediction_interval(SensorMax, largest);
  expect_within_prediction_interval(GridRatio, ours / ref - 1);
  expect_within_prediction_interval(BackRatio, ours_back / ref_back - 1);
  expect_within_prediction_interval(GroundBin, bin_ours[0] / bin_ref[0] - 1);
  expect_within_prediction_interval(SkyBins, sky_ours / sky_ref - 1);
  expect_within_prediction_interval(SkyBinMax, sky_largest);
  fs::remove_all(out);
}

}  // namespace
}  // namespace dayphoton::study
