// The accuracy target of the sun bins (study/sun_accuracy_rounds.h): the year's weights and
// the annual measure against their closed forms, and whole rounds on the reference office
// (48 sensors, reference 2000 photons per sun bin, bandwidth 8, 72 suns on Reinhart MF 1):
// the target is met and the spread of three seeds agrees with the reported variances, bins
// that send nothing keep their pilot, one and two threads give the same bytes, as do 1 to 3
// in-process ranks sharing the rounds (round_work.h), and a grid estimated by final gather
// gets the sky's gather rounds (gather_accuracy_rounds.h) on the annual measure: more gather
// rays, and more photons of the bins for the gather's photon part; its stated annual error
// agrees with the spread of 20 seeds.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <tbb/global_control.h>

#include "dayphoton/core/units.h"
#include "dayphoton/engine/material.h"
#include "dayphoton/engine/scene.h"
#include "dayphoton/project/project.h"
#include "dayphoton/sky/patch_basis.h"
#include "dayphoton/sky/sky_model.h"
#include "dayphoton/study/accuracy_policy.h"
#include "dayphoton/study/annual_sun.h"
#include "dayphoton/study/artifact_codec.h"
#include "dayphoton/study/artifact_store.h"
#include "dayphoton/study/distributed_executor.h"
#include "dayphoton/study/sun_accuracy_rounds.h"
#include "counting_round_work.h"
#include "in_process_study.h"
#include "office_rounds.h"

namespace dayphoton::study {
namespace {

std::vector<sky::SunRecord> test_suns() {
  std::vector<sky::SunRecord> suns;
  std::size_t step = 0;
  for (double altitude : {15.0, 30.0, 45.0, 60.0})
    for (int a = 0; a < 18; ++a) {
      const double alt = altitude * Pi / 180.0, az = double(a) * 20.0 * Pi / 180.0;
      const Vec3 d{std::cos(alt) * std::sin(az), std::cos(alt) * std::cos(az), std::sin(alt)};
      suns.push_back(sky::sun_record(step++, d, 20000.0 + 1000.0 * double(a)));
    }
  return suns;
}

engine::SunBins bins_of(const std::vector<sky::SunRecord>& suns) {
  std::vector<Vec3> d;
  for (const sky::SunRecord& s : suns) d.push_back(s.direction);
  return engine::SunBins::for_suns(d, 1);
}

// ---- closed forms ---------------------------------------------------------------------------

// The stencil's weights sum to 1, so sum_k A_k = sum_h L_h; and B_k <= A_k^2 (each term of A_k
// is positive).
TEST(SunAccuracy, YearWeightsSumToTheSunsRadiance) {
  const std::vector<sky::SunRecord> suns = test_suns();
  const engine::SunBins bins = bins_of(suns);
  const SunYearWeights w = sun_year_weights(bins, suns);
  double total = 0, expected = 0;
  for (double a : w.annual) total += a;
  for (const sky::SunRecord& s : suns) expected += s.disc_radiance;
  EXPECT_NEAR(total, expected, 1e-9 * expected);
  for (std::size_t k = 0; k < bins.size(); ++k) EXPECT_LE(w.squared[k], w.annual[k] * w.annual[k] * (1 + 1e-12));
}

// One sensor, two bins of luminance 2 and 3 (grey RGB), variances 0.04 and 0.09, weights
// A = (10, 20): the annual value is 10 x 2 + 20 x 3 = 80 and its variance
// 100 x 0.04 + 400 x 0.09 = 40.
TEST(SunAccuracy, AnnualMeasureIsTheWeightedSumAndItsVariance) {
  RadianceMatrix c(1, 2, 3);
  for (int k = 0; k < 3; ++k) {
    c.at(0, 0, k) = 2.0f;
    c.at(0, 1, k) = 3.0f;
  }
  SunYearWeights w;
  w.annual = {10.0, 20.0};
  w.squared = {50.0, 200.0};
  const GridVariance g = sun_annual_variance(c, {0.04, 0.09}, w);
  const double lum = RgbLuminanceWeights.x + RgbLuminanceWeights.y + RgbLuminanceWeights.z;
  EXPECT_NEAR(g.df_percent[0], 80.0 * lum, 1e-5);
  EXPECT_NEAR(g.photon_variance[0] + g.photon_variance[1], 40.0, 1e-12);
  EXPECT_EQ(g.direct_variance[0], 0.0);
}

// The gather's variance weights of the annual measure are the bins' A_k (one per bin, whatever
// the options had), and nothing else of the options changes.
TEST(SunAccuracy, AnnualEstimatingWeighsTheGatherRaysByTheYearsWeights) {
  const std::vector<sky::SunRecord> suns = test_suns();
  const engine::SunBins bins = bins_of(suns);
  const SunYearWeights w = sun_year_weights(bins, suns);
  engine::CoefficientOptions o;
  o.density.bandwidth = 8;
  o.gather.rays_per_sensor = 64;
  o.gather.variance_weights = {1.0, 2.0};  // replaced
  const engine::CoefficientOptions a = sun_annual_estimating(o, w);
  ASSERT_EQ(a.gather.variance_weights.size(), bins.size());
  EXPECT_EQ(a.gather.variance_weights, w.annual);
  EXPECT_EQ(a.density.bandwidth, 8u);
  EXPECT_EQ(a.gather.rays_per_sensor, 64);
}

TEST(AccuracyPolicy, GatheredGridsAreNotChased) {
  const std::vector<int> plane_of_grid = {0, -1};
  EXPECT_TRUE(grid_chased_by_photons(plane_of_grid, true, 0));
  EXPECT_FALSE(grid_chased_by_photons(plane_of_grid, true, 1));
  EXPECT_TRUE(grid_chased_by_photons(plane_of_grid, false, 1));
  EXPECT_EQ(accuracy_grid_status(false, 1.2, 1.0), "not reachable by photons");
  EXPECT_EQ(accuracy_grid_status(true, 1.2, 1.0), "above target");
  EXPECT_EQ(accuracy_grid_status(false, 0.8, 1.0), "met");
  EXPECT_EQ(met_stop_reason({"met", "met"}), "target met");
  EXPECT_EQ(met_stop_reason({"met", "not reachable by photons"}), "not reachable by photons");
}

// ---- whole rounds on the office -------------------------------------------------------------

struct Office : test::OfficeRounds {
  std::vector<sky::SunRecord> suns = test_suns();
  engine::SunBins bins = bins_of(suns);

  explicit Office(bool wall_grid = false) {
    if (wall_grid) add_gathered_grid();
  }
  SunAccuracyCase accuracy_case(std::uint64_t seed) const {
    SunAccuracyCase c;
    c.scene = scene.get();
    c.materials = &materials;
    c.bins = &bins;
    c.suns = &suns;
    c.planes = &planes;
    c.plane_of_grid = &plane_of_grid;
    c.grids = &description.grids;
    c.gather = true;
    c.tracing.seed = seed;
    c.tracing.photons_per_source = 2000;
    c.tracing.keep_surface_photons = plane_of_grid.back() < 0;
    c.estimating.density.bandwidth = 8;
    c.estimating.gather.rays_per_sensor = 64;
    return c;
  }
};

SunAccuracyResult run(const Office& office, std::uint64_t seed, const AccuracyGoal& goal, int threads = 0) {
  std::unique_ptr<tbb::global_control> limit;
  if (threads > 0) limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, threads);
  return run_sun_accuracy_rounds(office.accuracy_case(seed), goal,
                                 [](const std::string& line) { std::printf("%s\n", line.c_str()); });
}

constexpr double Target = 3.0;  // percent: the pilot (about 11 %) does not reach it

// As AccuracyTarget.MetAndConsistentWithTheSpreadOfThreeSeeds (accuracy_rounds_test.cpp): the
// target is met, and for the sensors at or below the percentile the mean of S_s^2 / sigma_s^2
// over three seeds (each term chi^2(2) / 2 for honest variances) is below 9.21, the upper 1e-4
// quantile of chi^2(2) / 2 (all sensors fully correlated, the worst case).
TEST(SunAccuracyTarget, MetAndConsistentWithTheSpreadOfThreeSeeds) {
  const Office office;
  const SunYearWeights w = sun_year_weights(office.bins, office.suns);
  AccuracyGoal goal;
  goal.target_percent = Target;
  std::vector<GridVariance> v;
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    const SunAccuracyResult r = run(office, seed, goal);
    ASSERT_EQ(r.outcome.stop_reason, "target met");
    EXPECT_LE(r.outcome.reached_percent[0], Target);
    EXPECT_GE(r.outcome.rounds, 2u) << "the pilot alone met the target: the test checks no round";
    EXPECT_GT(r.outcome.hourly_percent[0], 0.0);
    v.push_back(sun_annual_variance(r.coefficients[0], r.variance[0], w));
    if (seed == 1) {
      std::size_t grown = 0, kept_dark = 0;
      for (std::size_t k = 0; k < office.bins.size(); ++k) {
        grown += r.outcome.final_attempts[k] > r.outcome.pilot_attempts[k];
        bool lit = false;
        for (std::size_t s = 0; s < r.coefficients[0].rows() && !lit; ++s) lit = r.coefficients[0].at(s, k, 1) > 0;
        if (!lit) {
          ++kept_dark;
          EXPECT_EQ(r.outcome.final_attempts[k], r.outcome.pilot_attempts[k]) << "bin " << k;
        }
      }
      EXPECT_GT(grown, 0u);
      EXPECT_GT(kept_dark, 0u) << "some sun bins behind the office bring no photon";
    }
  }
  const std::size_t m = v[0].df_percent.size(), n = office.bins.size();
  std::vector<double> sigma2(m, 0.0), relative(m, 0.0);
  std::vector<std::size_t> order;
  for (std::size_t s = 0; s < m; ++s) {
    for (int k = 0; k < 3; ++k)
      for (std::size_t b = 0; b < n; ++b) sigma2[s] += v[k].photon_variance[s * n + b] / 3;
    if (v[0].df_percent[s] > 0) {
      relative[s] = std::sqrt(sigma2[s]) / v[0].df_percent[s];
      order.push_back(s);
    }
  }
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return relative[a] < relative[b]; });
  order.resize(static_cast<std::size_t>(std::ceil(0.95 * double(order.size()))));
  double ratio = 0;
  for (std::size_t s : order) {
    const double mean = (v[0].df_percent[s] + v[1].df_percent[s] + v[2].df_percent[s]) / 3;
    double ss = 0;
    for (int k = 0; k < 3; ++k) ss += (v[k].df_percent[s] - mean) * (v[k].df_percent[s] - mean);
    ratio += ss / 2 / sigma2[s] / double(order.size());
  }
  std::printf("mean observed / reported variance of the annual sun-bin value over %zu sensors: %.3f (bound 9.21)\n",
              order.size(), ratio);
  EXPECT_LT(ratio, 9.21);
  EXPECT_GT(ratio, 0.0);
}

TEST(SunAccuracyTarget, OneAndTwoThreadsGiveTheSameBytes) {
  const Office office;
  AccuracyGoal goal;
  goal.target_percent = Target;
  const SunAccuracyResult a = run(office, 4, goal, 1), b = run(office, 4, goal, 2);
  ASSERT_EQ(a.outcome.rounds, b.outcome.rounds);
  EXPECT_GE(a.outcome.rounds, 2u);
  EXPECT_EQ(a.outcome.final_attempts, b.outcome.final_attempts);
  EXPECT_EQ(a.outcome.reached_percent, b.outcome.reached_percent);
  ASSERT_EQ(a.coefficients[0].data().size(), b.coefficients[0].data().size());
  EXPECT_EQ(0, std::memcmp(a.coefficients[0].data().data(), b.coefficients[0].data().data(),
                           a.coefficients[0].data().size() * sizeof(float)));
  EXPECT_EQ(a.variance[0], b.variance[0]);
}

using test::CountingWork;

// The sun rounds on 1, 2 and 3 in-process ranks (the distributed executor's RoundWork, sensor
// blocks of 8 of the 48 sensors) give every rank the one-process rounds' bytes: outcome,
// attempts per bin, coefficients and variances. With several ranks each range is traced by one
// rank, some bin's request is cut into ranges, and every round's estimate goes in 6 blocks.
TEST(SunAccuracyTarget, OneToThreeRanksGiveTheOneProcessBytes) {
  const Office office;
  AccuracyGoal goal;
  goal.target_percent = Target;
  const SunAccuracyResult one = run(office, 5, goal);
  ASSERT_GE(one.outcome.rounds, 2u);
  const std::string expected = encode_matrix(one.coefficients[0]);
  for (int ranks : {1, 2, 3}) {
    SCOPED_TRACE(std::to_string(ranks) + " ranks");
    std::vector<SunAccuracyResult> results(static_cast<std::size_t>(ranks));
    std::vector<int> ranges(results.size());
    std::vector<std::size_t> requests(results.size()), blocks(results.size());
    test::run_ranks_expecting_no_error(ranks, [&](dist::Communicator& comm) {
      const std::filesystem::path dir =
          test::fresh_dir("sun_accuracy_ranks_" + std::to_string(ranks) + "_" + std::to_string(comm.rank()));
      const ArtifactStore store(dir.string());
      const auto executor = make_distributed_executor(comm, store, false, 8);
      CountingWork work(executor->round_work());
      const auto r = static_cast<std::size_t>(comm.rank());
      results[r] = run_sun_accuracy_rounds(office.accuracy_case(5), goal, [](const std::string&) {}, work);
      requests[r] = work.requests_total;
      ranges[r] = work.ranges;
      blocks[r] = work.blocks;
    });
    int all_ranges = 0;
    for (std::size_t r = 0; r < results.size(); ++r) {
      const SunAccuracyResult& x = results[r];
      EXPECT_EQ(x.outcome.rounds, one.outcome.rounds);
      EXPECT_EQ(x.outcome.photons, one.outcome.photons);
      EXPECT_EQ(x.outcome.stop_reason, one.outcome.stop_reason);
      EXPECT_EQ(x.outcome.pilot_attempts, one.outcome.pilot_attempts);
      EXPECT_EQ(x.outcome.final_attempts, one.outcome.final_attempts);
      EXPECT_EQ(x.outcome.reached_percent, one.outcome.reached_percent);
      EXPECT_EQ(x.outcome.hourly_percent, one.outcome.hourly_percent);
      ASSERT_EQ(x.coefficients.size(), 1u);
      EXPECT_TRUE(encode_matrix(x.coefficients[0]) == expected) << "rank " << r;
      EXPECT_EQ(x.variance[0], one.variance[0]) << "rank " << r;
      EXPECT_EQ(requests[r], requests[0]);
      all_ranges += ranges[r];
    }
    if (ranks > 1) {
      EXPECT_GT(ranges[0], 0);
      EXPECT_LT(ranges[0], all_ranges) << "rank 0 traced every range";
      EXPECT_GT(std::size_t(all_ranges), requests[0]) << "no request was split";
      EXPECT_EQ(blocks[0], one.outcome.rounds * 6u);  // each round's estimate in 6 blocks
    } else {
      EXPECT_EQ(std::size_t(all_ranges), requests[0]);
      EXPECT_EQ(blocks[0], one.outcome.rounds);  // one block per round
    }
  }
}

// ---- gathered grids: the sky's gather rounds on the annual measure ---------------------------

SunAccuracyResult run_logged(const SunAccuracyCase& c, const AccuracyGoal& goal, std::vector<std::string>* log = nullptr,
                             int threads = 0) {
  std::unique_ptr<tbb::global_control> limit;
  if (threads > 0) limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, threads);
  return run_sun_accuracy_rounds(c, goal, [&](const std::string& line) {
    std::printf("%s\n", line.c_str());
    if (log) log->push_back(line);
  });
}

bool has_line(const std::vector<std::string>& log, const std::string& words) {
  for (const std::string& line : log)
    if (line.find(words) != std::string::npos) return true;
  return false;
}

/// The annual measure at the percentile from a grid's final coefficients and variances.
double reached_from(const SunAccuracyResult& r, std::size_t g, const SunYearWeights& w) {
  const GridVariance v = sun_annual_variance(r.coefficients[g], r.variance[g], w);
  const std::size_t n = r.coefficients[g].columns();
  std::vector<double> se(v.df_percent.size(), 0.0);
  for (std::size_t s = 0; s < se.size(); ++s) {
    for (std::size_t k = 0; k < n; ++k) se[s] += v.photon_variance[s * n + k];
    se[s] = std::sqrt(se[s]);
  }
  return percentile_relative_stderr_percent(v.df_percent, se, AccuracyPercentile);
}

/// Mean over the sensors of z^2 = (E - E_ref)^2 / (se^2 + se_ref^2) of grid g's annual sun-bin
/// values: at most 15.1, the upper 1e-4 quantile of chi^2(1), however correlated the sensors
/// are (fully correlated, the mean is one chi^2(1) draw; independent, chi^2(m) / m).
double mean_z2(const SunAccuracyResult& r, const SunAccuracyResult& ref, std::size_t g, const SunYearWeights& w) {
  const GridVariance a = sun_annual_variance(r.coefficients[g], r.variance[g], w);
  const GridVariance b = sun_annual_variance(ref.coefficients[g], ref.variance[g], w);
  const std::size_t n = r.coefficients[g].columns(), m = a.df_percent.size();
  double z2 = 0;
  for (std::size_t s = 0; s < m; ++s) {
    double va = 0, vb = 0;
    for (std::size_t k = 0; k < n; ++k) {
      va += a.photon_variance[s * n + k];
      vb += b.photon_variance[s * n + k];
    }
    z2 += (a.df_percent[s] - b.df_percent[s]) * (a.df_percent[s] - b.df_percent[s]) / (va + vb);
  }
  return z2 / double(m);
}

// A gathered grid takes no part in the photons' allocation; when the rounds would stop it gets
// the gather rounds of the sky's gathered grids on the annual measure. With one gather ray per
// sensor its error (mostly the ray's) is far above the target after the pilot, at which the
// work plane (11 %) meets it; the gather rounds raise its rays until it meets the target, and
// its annual values agree with a reference of another seed at 1024 rays within their stated
// standard errors.
TEST(SunAccuracyTarget, GatheredGridIsChasedByGatherRays) {
  const Office office(true);
  const SunYearWeights w = sun_year_weights(office.bins, office.suns);
  SunAccuracyCase c = office.accuracy_case(2);
  c.estimating.gather.rays_per_sensor = 1;
  AccuracyGoal goal;
  goal.target_percent = 20.0;
  std::vector<std::string> log;
  const SunAccuracyResult r = run_logged(c, goal, &log);
  ASSERT_EQ(r.outcome.reached_percent.size(), 2u);
  ASSERT_LE(r.outcome.reached_percent[0], goal.target_percent);
  EXPECT_EQ(r.outcome.rounds, 1u);
  EXPECT_EQ(r.outcome.final_attempts, r.outcome.pilot_attempts);
  EXPECT_TRUE(has_line(log, "gathered: its gather rays follow"));
  // Above the target after the pilot, at the project's one ray.
  EXPECT_TRUE(has_line(log, "sun accuracy gather round 1, grid gathered"));
  ASSERT_EQ(r.outcome.gather.size(), 2u);
  EXPECT_FALSE(r.outcome.gather[0].gathered);
  EXPECT_TRUE(r.outcome.gather[1].gathered);
  EXPECT_EQ(r.outcome.gather[1].first_rays, 1);
  EXPECT_GE(r.outcome.gather[1].rounds, 1u);
  EXPECT_GT(r.outcome.gather[1].rays, 1);
  EXPECT_EQ(r.outcome.gather[1].stop_reason, "target met");
  EXPECT_LE(r.outcome.reached_percent[1], goal.target_percent);
  EXPECT_EQ(r.outcome.grid_status[0], "met");
  EXPECT_EQ(r.outcome.grid_status[1], "met");
  EXPECT_EQ(r.outcome.stop_reason, "target met");
  // The reported value is the final estimate's own, and the coefficients are that estimate's.
  EXPECT_NEAR(r.outcome.reached_percent[1], reached_from(r, 1, w), 1e-6 * r.outcome.reached_percent[1]);
  EXPECT_NE(sun_accuracy_sentence(r.outcome, 1).find("gather round(s) from 1"), std::string::npos);

  SunAccuracyCase rc = office.accuracy_case(1002);
  rc.estimating.gather.rays_per_sensor = 1024;
  const SunAccuracyResult ref = run_logged(rc, goal);
  const double z2 = mean_z2(r, ref, 1, w);
  std::printf("mean z^2 of the gathered grid's annual sun-bin values against the reference: %.3g\n", z2);
  EXPECT_LE(z2, 15.1);
  EXPECT_GT(z2, 0.0);
}

// The gathered grid alone, from few photons (100 per bin at the reference count) and 64 rays:
// after the pilot its gather rounds stop on the photon part, which more rays do not lower; the
// sun rounds trace more photons of the bins for it and the gather rounds go on from the rays
// reached, to the target. Against a reference of another seed at a 4 times tighter target the
// mean z^2 of the annual values is below the chi^2(1) bound.
constexpr double SunPhotonPartTarget = 5.0;
constexpr std::size_t SunPhotonPartReference = 100;

struct GatheredOffice : Office {
  GatheredOffice() : Office(true) { drop_work_plane_grid(); }
  SunAccuracyCase gathered_case(std::uint64_t seed) const {
    SunAccuracyCase c = accuracy_case(seed);
    c.tracing.photons_per_source = SunPhotonPartReference;
    c.estimating.gather.rays_per_sensor = 64;
    return c;
  }
};

TEST(SunAccuracyTarget, GatheredPhotonPartGetsMorePhotons) {
  const GatheredOffice office;
  const SunYearWeights w = sun_year_weights(office.bins, office.suns);
  AccuracyGoal tight;
  tight.target_percent = SunPhotonPartTarget / 4;
  const SunAccuracyResult ref = run_logged(office.gathered_case(1003), tight);
  ASSERT_EQ(ref.outcome.stop_reason, "target met");
  for (const std::uint64_t seed : {3u, 4u}) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    AccuracyGoal goal;
    goal.target_percent = SunPhotonPartTarget;
    std::vector<std::string> log;
    const SunAccuracyResult r = run_logged(office.gathered_case(seed), goal, &log);
    const SunAccuracyOutcome& o = r.outcome;
    ASSERT_EQ(o.gather.size(), 1u);
    EXPECT_TRUE(has_line(log, "ask for more photons for the gather's photon part"));
    EXPECT_TRUE(has_line(log, "sun accuracy: round 2 traces more photons for the gathered grids' photon part"));
    EXPECT_GE(o.rounds, 2u);
    for (std::size_t k = 0; k < o.final_attempts.size(); ++k) EXPECT_GE(o.final_attempts[k], o.pilot_attempts[k]);
    EXPECT_NE(o.final_attempts, o.pilot_attempts);
    EXPECT_EQ(o.gather[0].stop_reason, "target met");
    EXPECT_EQ(o.grid_status[0], "met");
    EXPECT_EQ(o.stop_reason, "target met");
    EXPECT_LE(o.reached_percent[0], SunPhotonPartTarget);
    EXPECT_NEAR(o.reached_percent[0], reached_from(r, 0, w), 1e-6 * o.reached_percent[0]);
    const double z2 = mean_z2(r, ref, 0, w);
    std::printf("seed %u: mean z^2 against the reference %.3g\n", unsigned(seed), z2);
    EXPECT_LE(z2, 15.1);
  }
}

// A photon budget at the pilot's photons: no photon round for the photon part, and the grid's
// stop (and the rounds') names the budget.
TEST(SunAccuracyTarget, GatheredPhotonPartPhotonBudgetIsTheNamedStop) {
  const GatheredOffice office;
  AccuracyGoal goal;
  goal.target_percent = SunPhotonPartTarget;
  goal.max_photons = 1;
  std::vector<std::string> log;
  const SunAccuracyResult r = run_logged(office.gathered_case(3), goal, &log);
  EXPECT_EQ(r.outcome.rounds, 1u);
  EXPECT_EQ(r.outcome.final_attempts, r.outcome.pilot_attempts);
  ASSERT_EQ(r.outcome.gather.size(), 1u);
  EXPECT_TRUE(has_line(log, "no round 2: the photon budget"));
  EXPECT_EQ(r.outcome.gather[0].stop_reason, "photon budget");
  EXPECT_EQ(r.outcome.grid_status[0], "above target");
  EXPECT_EQ(r.outcome.stop_reason, "photon budget");
}

// The stated annual sun-bin variance of a gathered grid against the spread of 20 independent
// runs (photon and gather seeds both changed; 2000 photons per bin at the reference count, 16
// gather rays, a target so loose that the pilot's estimate at the project's rays stands): per
// sensor S_s^2 / sigma_s^2 (the sample variance over the runs over the mean stated variance)
// is chi^2(19) / 19 for an honest statement, and the mean over the 8 sensors lies within that
// distribution's 1e-4 and 1 - 1e-4 quantiles, 0.209 and 2.67, in the fully correlated case,
// the widest (a mean over sensors is less spread than one sensor's term, in convex order). So
// the stated error is neither too small nor too large (the z^2 tests above bound it from one
// side only). The mean is 0.81 with the bins' yearly weights in the gather's variance and was
// 0.61 with unit weights: the bounds hold both, this case does not tell them apart.
TEST(SunAccuracyTarget, GatheredGridsStatedErrorMatchesTheSpreadOfSeeds) {
  const GatheredOffice office;
  const SunYearWeights w = sun_year_weights(office.bins, office.suns);
  AccuracyGoal loose;
  loose.target_percent = 1000.0;  // the pilot's estimate at the project's rays
  constexpr int Seeds = 20;
  std::vector<std::vector<double>> value(Seeds), variance(Seeds);
  for (int i = 0; i < Seeds; ++i) {
    SunAccuracyCase c = office.gathered_case(100 + std::uint64_t(i));
    c.tracing.photons_per_source = 2000;
    c.estimating.gather.rays_per_sensor = 16;
    c.estimating.gather.seed = 100 + std::uint64_t(i);
    const SunAccuracyResult r = run_logged(c, loose);
    ASSERT_EQ(r.outcome.gather.at(0).rounds, 0u);
    const GridVariance v = sun_annual_variance(r.coefficients[0], r.variance[0], w);
    const std::size_t n = r.coefficients[0].columns();
    value[i] = v.df_percent;
    variance[i].assign(v.df_percent.size(), 0.0);
    for (std::size_t s = 0; s < v.df_percent.size(); ++s)
      for (std::size_t k = 0; k < n; ++k) variance[i][s] += v.photon_variance[s * n + k];
  }
  const std::size_t m = value[0].size();
  double ratio = 0;
  for (std::size_t s = 0; s < m; ++s) {
    double mean = 0, claimed = 0, spread = 0;
    for (int i = 0; i < Seeds; ++i) {
      mean += value[i][s] / Seeds;
      claimed += variance[i][s] / Seeds;
    }
    for (int i = 0; i < Seeds; ++i) spread += (value[i][s] - mean) * (value[i][s] - mean) / (Seeds - 1);
    ASSERT_GT(claimed, 0.0) << "sensor " << s;
    ratio += spread / claimed / double(m);
  }
  std::printf("mean over the sensors of S^2 / sigma^2 over %d runs: %.3g\n", Seeds, ratio);
  EXPECT_GE(ratio, 0.209);
  EXPECT_LE(ratio, 2.67);
}

// The gather's variance weights of a run with photon counts (no rounds: sun_bin_steps.cpp),
// measured: the office's gathered grid traced as such a run traces it (every lit bin at a fixed
// count, Direct photons on surfaces, the bins' photons of one seed), each grid's coefficients
// gathered once and their variances split over the bins with unit weights and with the year's
// A_k (sun_annual_estimating), against the spread of the values over Seeds seeds. Weights move
// only the split of the rays' variance, never a coefficient. The two measures that read the
// split: the annual sun-bin value (sum_k A_k C_k: the sun rounds' target) and the hours' RMS
// (sum_h var E_h over sum_h of the claimed variances: what the run's illuminance_rms_stderr_lux
// and DA verdicts within 2 sigma read, verdict_uncertainty.h, and the rounds' hourly_percent).
// For each the mean over the 8 sensors of S^2 / sigma^2 is printed (1 for an honest statement)
// and bounded as in the test above (chi^2(Seeds - 1) / (Seeds - 1) quantiles, the widest,
// fully correlated case: 0.209 and 2.67 for 20 seeds), and the year's weights' must be the
// nearer to 1 (docs/photon-tracing.md, "The same weights with photon counts").
TEST(SunAccuracy, GatherWeightsOfARunWithPhotonCountsAgainstTheSpreadOfSeeds) {
  const GatheredOffice office;
  const SunYearWeights year = sun_year_weights(office.bins, office.suns);
  const engine::SourceSet discs = office.bins.sources(sky::SunHalfAngle_rad);
  const std::vector<SensorPoint>& points = office.description.grids.at(0).points;
  constexpr int Seeds = 20;
  constexpr std::size_t Photons = 1000;  // per bin: the rays' part a large share of the variance
  constexpr int Rays = 16;
  const std::size_t n_sensors = points.size(), n_suns = office.suns.size();
  // [weighting][seed]: per sensor the annual value and its claimed variance; per sensor x sun
  // the hour's value and its claimed variance.
  struct Measures {
    std::vector<double> annual, annual_variance, hourly, hourly_variance;
  };
  std::vector<Measures> unit(Seeds), yearly(Seeds);
  auto measures = [&](const RadianceMatrix& c, const std::vector<double>& variance) {
    Measures m;
    const GridVariance a = sun_annual_variance(c, variance, year);
    const std::size_t n = c.columns();
    m.annual = a.df_percent;
    m.annual_variance.assign(n_sensors, 0.0);
    for (std::size_t s = 0; s < n_sensors; ++s)
      for (std::size_t k = 0; k < n; ++k) m.annual_variance[s] += a.photon_variance[s * n + k];
    for (std::size_t h = 0; h < n_suns; ++h) {
      // One hour's value is the annual measure of a year of that hour alone (A_k = w_hk L_h).
      const GridVariance e = sun_annual_variance(c, variance, sun_year_weights(office.bins, {office.suns[h]}));
      for (std::size_t s = 0; s < n_sensors; ++s) {
        double v = 0;
        for (std::size_t k = 0; k < n; ++k) v += e.photon_variance[s * n + k];
        m.hourly.push_back(e.df_percent[s]);
        m.hourly_variance.push_back(v);
      }
    }
    return m;
  };
  for (int i = 0; i < Seeds; ++i) {
    SunAccuracyCase c = office.gathered_case(200 + std::uint64_t(i));
    engine::TracingOptions tracing = c.tracing;
    tracing.photons_per_source = Photons;
    tracing.keep_surface_photons = true;
    tracing.store_direct_on_surfaces = true;  // as SimulationPlan::tracing_for for a gathered grid
    engine::TracedPhotons photons = trace_sun_bins(*office.scene, office.materials, office.bins, office.planes, tracing);
    const engine::GridPhotons gp = engine::GridPhotons::for_gather(std::move(photons.surface), office.bins.size());
    engine::CoefficientOptions o = c.estimating;
    o.gather.rays_per_sensor = Rays;
    o.gather.seed = 200 + std::uint64_t(i);
    o.gather.variance_weights.clear();
    std::vector<double> unit_variance, yearly_variance;
    const RadianceMatrix cu = sun_bin_coefficients(*office.scene, office.materials, discs, gp, points, o, &unit_variance);
    const RadianceMatrix cy = sun_bin_coefficients(*office.scene, office.materials, discs, gp, points,
                                                   sun_annual_estimating(o, year), &yearly_variance);
    ASSERT_EQ(cu.data(), cy.data()) << "the weights changed a coefficient";
    unit[i] = measures(cu, unit_variance);
    yearly[i] = measures(cy, yearly_variance);
  }
  // Mean over the sensors of S^2 / sigma^2: the annual value's, and the hours' (summed over
  // the hours before the ratio, as the RMS over the hours sums them).
  auto ratios = [&](const std::vector<Measures>& m) {
    double annual = 0, hourly = 0;
    for (std::size_t s = 0; s < n_sensors; ++s) {
      auto spread_and_claim = [&](auto value, auto claim) {
        double mean = 0, claimed = 0, spread = 0;
        for (int i = 0; i < Seeds; ++i) {
          mean += value(m[i]) / Seeds;
          claimed += claim(m[i]) / Seeds;
        }
        for (int i = 0; i < Seeds; ++i) spread += (value(m[i]) - mean) * (value(m[i]) - mean) / (Seeds - 1);
        return std::pair<double, double>{spread, claimed};
      };
      const auto [sa, ca] = spread_and_claim([s](const Measures& x) { return x.annual[s]; },
                                             [s](const Measures& x) { return x.annual_variance[s]; });
      EXPECT_GT(ca, 0.0) << "sensor " << s;
      annual += sa / ca / double(n_sensors);
      double sh = 0, ch = 0;
      for (std::size_t h = 0; h < n_suns; ++h) {
        const std::size_t at = h * n_sensors + s;
        const auto [spread, claimed] = spread_and_claim([at](const Measures& x) { return x.hourly[at]; },
                                                        [at](const Measures& x) { return x.hourly_variance[at]; });
        sh += spread;
        ch += claimed;
      }
      hourly += sh / ch / double(n_sensors);
    }
    return std::pair<double, double>{annual, hourly};
  };
  const auto [unit_annual, unit_hourly] = ratios(unit);
  const auto [yearly_annual, yearly_hourly] = ratios(yearly);
  std::printf("mean over the sensors of S^2 / sigma^2 over %d seeds, %zu photons per bin, %d rays: annual value "
              "unit %.3g, A_k %.3g; hours unit %.3g, A_k %.3g\n",
              Seeds, Photons, Rays, unit_annual, yearly_annual, unit_hourly, yearly_hourly);
  for (const double r : {unit_annual, yearly_annual, unit_hourly, yearly_hourly}) {
    EXPECT_GE(r, 0.209);
    EXPECT_LE(r, 2.67);
  }
  // The reason the run takes the year's weights: on both measures their statement is the nearer
  // to the spread (measured 0.66 against 0.44, 0.38 against 0.26; the same seeds for both, so
  // the comparison is paired).
  EXPECT_LT(std::abs(std::log(yearly_annual)), std::abs(std::log(unit_annual)));
  EXPECT_LT(std::abs(std::log(yearly_hourly)), std::abs(std::log(unit_hourly)));
}

// The gathered grid's gather rounds and photon round give the same bytes at 1 and 2 threads and
// on 1 to 3 in-process ranks (sensor blocks of 3 of its 8 sensors).
TEST(SunAccuracyTarget, GatheredGridOneAndTwoThreadsAndOneToThreeRanksGiveTheSameBytes) {
  const GatheredOffice office;
  AccuracyGoal goal;
  goal.target_percent = SunPhotonPartTarget;
  const SunAccuracyResult one = run_logged(office.gathered_case(5), goal, nullptr, 1);
  ASSERT_GE(one.outcome.rounds, 2u);
  ASSERT_GE(one.outcome.gather.at(0).rounds, 1u);
  const std::string expected = encode_matrix(one.coefficients.at(0));
  const SunAccuracyResult two = run_logged(office.gathered_case(5), goal, nullptr, 2);
  EXPECT_TRUE(encode_matrix(two.coefficients.at(0)) == expected);
  EXPECT_EQ(two.variance.at(0), one.variance.at(0));
  EXPECT_EQ(two.outcome.final_attempts, one.outcome.final_attempts);
  for (int ranks : {1, 2, 3}) {
    SCOPED_TRACE(std::to_string(ranks) + " ranks");
    std::vector<SunAccuracyResult> results(static_cast<std::size_t>(ranks));
    test::run_ranks_expecting_no_error(ranks, [&](dist::Communicator& comm) {
      const std::filesystem::path dir =
          test::fresh_dir("sun_gather_ranks_" + std::to_string(ranks) + "_" + std::to_string(comm.rank()));
      const ArtifactStore store(dir.string());
      const auto executor = make_distributed_executor(comm, store, false, 3);
      results[static_cast<std::size_t>(comm.rank())] =
          run_sun_accuracy_rounds(office.gathered_case(5), goal, [](const std::string&) {}, executor->round_work());
    });
    for (const SunAccuracyResult& x : results) {
      EXPECT_EQ(x.outcome.rounds, one.outcome.rounds);
      EXPECT_EQ(x.outcome.final_attempts, one.outcome.final_attempts);
      EXPECT_EQ(x.outcome.gather.at(0).rays, one.outcome.gather.at(0).rays);
      EXPECT_EQ(x.outcome.gather.at(0).rounds, one.outcome.gather.at(0).rounds);
      EXPECT_EQ(x.outcome.reached_percent, one.outcome.reached_percent);
      EXPECT_EQ(x.outcome.hourly_percent, one.outcome.hourly_percent);
      EXPECT_TRUE(encode_matrix(x.coefficients.at(0)) == expected);
      EXPECT_EQ(x.variance.at(0), one.variance.at(0));
    }
  }
}

// The same for the sky's photon rounds (accuracy_rounds.h): the office's work plane (reference
// 2000 photons per bin, bandwidth 20: about 7 % at the pilot) and 8 of its sensors again as a
// grid estimated by final gather with one ray each; target 10 %. The photons stop after the
// pilot; the gather rounds (gather_accuracy_rounds.h) then raise the gathered grid's rays.
TEST(AccuracyTarget, GatheredGridIsChasedByRaysNotPhotons) {
  const Office office(true);
  AccuracyCase c;
  c.scene = office.scene.get();
  c.materials = &office.materials;
  c.sources = &office.sources;
  c.planes = &office.planes;
  c.plane_of_grid = &office.plane_of_grid;
  c.grids = &office.description.grids;
  c.gather = true;
  c.tracing.seed = 3;
  c.tracing.photons_per_source = 2000;
  c.tracing.source_photon_factor.assign(office.sources.size(), 1.0);
  c.tracing.source_photon_factor[0] = 16.0;
  c.tracing.keep_surface_photons = true;
  c.estimating.density.bandwidth = 20;
  c.estimating.direct.samples_per_source = 16;
  c.estimating.gather.rays_per_sensor = 1;
  c.overcast_vector = &office.overcast;
  c.horizontal_illuminance_lux = Office::OvercastLux;
  AccuracyGoal goal;
  goal.target_percent = 10.0;
  const AccuracyResult r = run_accuracy_rounds(c, goal, [](const std::string& line) { std::printf("%s\n", line.c_str()); });
  ASSERT_EQ(r.outcome.reached_percent.size(), 2u);
  ASSERT_LE(r.outcome.reached_percent[0], goal.target_percent);
  EXPECT_EQ(r.outcome.rounds, 1u);
  EXPECT_EQ(r.outcome.final_attempts, r.outcome.pilot_attempts);
  EXPECT_EQ(r.outcome.grid_status[0], "met");
  ASSERT_EQ(r.outcome.gather.size(), 2u);
  EXPECT_GE(r.outcome.gather[1].rounds, 1u);
  EXPECT_GT(r.outcome.gather[1].rays, 1);
  EXPECT_EQ(r.outcome.gather[1].stop_reason, "target met");
  EXPECT_LE(r.outcome.reached_percent[1], goal.target_percent);
  EXPECT_EQ(r.outcome.grid_status[1], "met");
  EXPECT_EQ(r.outcome.stop_reason, "target met");
  EXPECT_NE(accuracy_sentence(r.outcome, 1).find("gather round(s) from 1"), std::string::npos);
}

}  // namespace
}  // namespace dayphoton::study
