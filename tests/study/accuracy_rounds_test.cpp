// The accuracy target (study/accuracy_rounds.h): the allocation of a round against its closed
// form, the percentile, and whole rounds on the reference office with a small reference count
// (2000 photons per bin, bandwidth 20, 16 direct samples, sensors 1 m apart): the target
// is met and the spread of three seeds agrees with it, sources that bring nothing get no
// photons after the pilot, the budgets stop the rounds and say so, and one and two threads
// give the same bytes, as do 1 to 3 ranks (in-process, tests/dist/in_process_ranks.h) sharing
// the rounds' tracing and estimates through the distributed executor's RoundWork.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <tbb/global_control.h>

#include "dayphoton/engine/daylight_coefficients.h"
#include "dayphoton/engine/direct_component.h"
#include "dayphoton/engine/material.h"
#include "dayphoton/engine/scene.h"
#include "dayphoton/project/project.h"
#include "dayphoton/sky/patch_basis.h"
#include "dayphoton/sky/sky_matrix.h"
#include "dayphoton/sky/sky_model.h"
#include "dayphoton/study/accuracy_rounds.h"
#include "dayphoton/study/artifact_codec.h"
#include "dayphoton/study/artifact_store.h"
#include "dayphoton/study/daylight_factor.h"
#include "dayphoton/study/simulation_plan.h"
#include "dayphoton/study/distributed_executor.h"
#include "dayphoton/study/plan_policy.h"
#include "counting_round_work.h"
#include "in_process_study.h"
#include "office_rounds.h"

namespace dayphoton::study {
namespace {

// ---- the allocation -----------------------------------------------------------------------

TEST(AccuracyRounds, PercentileIsTheNearestRankOverLitSensors) {
  const std::vector<double> df = {1, 1, 1, 1, 0};
  const std::vector<double> se = {0.01, 0.02, 0.03, 0.04, 0.5};  // 1, 2, 3, 4 %; the dark one left out
  EXPECT_DOUBLE_EQ(percentile_relative_stderr_percent(df, se, 95), 4.0);
  EXPECT_DOUBLE_EQ(percentile_relative_stderr_percent(df, se, 50), 2.0);
  EXPECT_DOUBLE_EQ(percentile_relative_stderr_percent(df, se, 25), 1.0);
  EXPECT_DOUBLE_EQ(percentile_relative_stderr_percent({0, 0}, {1, 1}, 95), 0.0);
}

// One sensor (DF 1 %), photon variances 4e-4 and 1e-4 (%^2) from two sources costing 1 and 4
// per photon-count unit, no direct variance, aim 1 %: the budget is 1e-4 and Neyman's
// allocation s_p = sqrt(a_p / c_p) sum_q sqrt(a_q c_q) / budget gives 8 and 2 (cost 16;
// equal factors meeting the budget need 5 each, cost 25). A third source brings no variance
// (no light) and gets nothing.
TEST(AccuracyRounds, OneSensorGetsNeymansAllocation) {
  GridVariance g;
  g.df_percent = {1.0};
  g.direct_variance = {0.0};
  g.photon_variance = {4e-4, 1e-4, 0.0};
  const RoundPlan plan = next_round_scale({g}, {1.0, 4.0, 2.0}, 1.0, AccuracyPercentile);
  ASSERT_EQ(plan.scale.size(), 3u);
  EXPECT_NEAR(plan.scale[0], 8.0, 1e-12);
  EXPECT_NEAR(plan.scale[1], 2.0, 1e-12);
  EXPECT_EQ(plan.scale[2], 1.0);
  EXPECT_NEAR(4e-4 / plan.scale[0] + 1e-4 / plan.scale[1], 1e-4, 1e-16);
  EXPECT_EQ(plan.sensors_constrained, 1u);
}

TEST(AccuracyRounds, DirectVarianceAboveTheBudgetIsCountedNotChased) {
  GridVariance g;
  g.df_percent = {1.0};
  g.direct_variance = {2e-4};  // 1.41 % from the shadow rays alone, aim 1 %
  g.photon_variance = {4e-4};
  const RoundPlan plan = next_round_scale({g}, {1.0}, 1.0, AccuracyPercentile);
  EXPECT_EQ(plan.sensors_direct_limited, 1u);
  EXPECT_EQ(plan.scale[0], 1.0);
}

// ---- the direct part's round (next_direct_round) --------------------------------------------

/// One sensor at DF 1 % with direct variance `direct` and photon variance `photon` from one
/// source whose rays so far cost `cost`; aim 1 %, so the budget is 1e-4 (%^2).
DirectRoundPlan one_sensor_direct_round(double direct, double photon, double cost, int samples) {
  GridVariance g;
  g.df_percent = {1.0};
  g.direct_variance = {direct};
  g.photon_variance = {photon};
  const RoundPlan photons = next_round_scale({g}, {cost}, 1.0, AccuracyPercentile);
  return next_direct_round({g}, {samples}, {1}, {cost}, photons, 1.0, AccuracyPercentile, 1, false);
}

// The shadow rays alone exceed the budget (2e-4 > 1e-4): the raise is needed. At 2k the
// predicted variance 2e-4 / 2^3 = 2.5e-5 is under half the budget, so 16 -> 64 (8 x 8); with
// 5e-3 neither 2k (6.3e-4) nor 4k (7.8e-5) is, and 4k = 16 (256, the limit) is the most a round
// takes. At the limit nothing is raised and the sensor is counted; a project's count above
// the limit is kept.
TEST(AccuracyRounds, DirectRoundRaisesWhatPhotonsCannotReduce) {
  const DirectRoundPlan a = one_sensor_direct_round(2e-4, 1e-5, 100.0, 16);
  ASSERT_TRUE(a.raised());
  EXPECT_EQ(a.samples_per_bin, std::vector<int>{64});
  EXPECT_DOUBLE_EQ(a.rays, direct_rays_per_sensor(64, 1, false));
  EXPECT_DOUBLE_EQ(a.rays, 64.0);
  EXPECT_EQ(a.sensors_at_limit, 0u);
  const DirectRoundPlan b = one_sensor_direct_round(5e-3, 1e-5, 100.0, 16);
  EXPECT_EQ(b.samples_per_bin, std::vector<int>{MaxDirectSamplesPerBin});
  const DirectRoundPlan c = one_sensor_direct_round(2e-4, 1e-5, 100.0, MaxDirectSamplesPerBin);
  EXPECT_FALSE(c.raised());
  EXPECT_EQ(c.sensors_at_limit, 1u);
  EXPECT_EQ(c.samples_at_limit, MaxDirectSamplesPerBin);
  const DirectRoundPlan d = one_sensor_direct_round(2e-4, 1e-5, 100.0, 400);
  EXPECT_FALSE(d.raised());
  EXPECT_EQ(d.samples_per_bin, std::vector<int>{400});
  EXPECT_EQ(d.sensors_at_limit, 1u);
  EXPECT_EQ(d.samples_at_limit, 400);  // the count the sensor is at, not the rounds' limit
  EXPECT_EQ(a.samples_at_limit, 0);
}

// Direct 0.6e-4 and photons 0.6e-4 (1.1 % against the aim of 1 %): photons alone need
// 0.6e-4 / (1e-4 - 0.6e-4) = 1.5 times the source's rays (0.5 x cost more); after a raise to
// 8 x 8 the direct part is 0.6e-4 / 8 and the photons already fit, for 64 shadow rays. So the
// raise is made when 64 < 0.5 x cost (cost 1000) and not when it is dearer (cost 100).
TEST(AccuracyRounds, DirectRoundRaisesWhenCheaperThanPhotons) {
  const DirectRoundPlan cheap = one_sensor_direct_round(0.6e-4, 0.6e-4, 1000.0, 16);
  ASSERT_TRUE(cheap.raised());
  EXPECT_EQ(cheap.samples_per_bin, std::vector<int>{64});
  EXPECT_EQ(cheap.photons.scale, std::vector<double>{1.0});
  const DirectRoundPlan dear = one_sensor_direct_round(0.6e-4, 0.6e-4, 100.0, 16);
  EXPECT_FALSE(dear.raised());
  EXPECT_EQ(dear.samples_per_bin, std::vector<int>{16});
  EXPECT_NEAR(dear.photons.scale[0], 1.5, 1e-12);
  // The direct part under half the budget: not what keeps the sensor above; not raised.
  EXPECT_FALSE(one_sensor_direct_round(0.4e-4, 1e-4, 1e9, 16).raised());
  // The port points count: 2 sides x (8 x 8)^2 at 64 rays per bin, besides 64 per source.
  EXPECT_DOUBLE_EQ(direct_rays_per_sensor(64, 146, true), 64.0 * 146 + 2.0 * 64 * 64);
  EXPECT_DOUBLE_EQ(direct_rays_per_sensor(10, 1, false), 16.0);  // rounded up to 4 x 4
}

// 20 sensors at 0.5 % and one at 10 %: the worst is beyond the 95th percentile (rank 20 of
// 21 kept), so nothing is traced for it.
TEST(AccuracyRounds, SensorsBeyondThePercentileAreNotChased) {
  GridVariance g;
  for (int i = 0; i < 21; ++i) {
    g.df_percent.push_back(1.0);
    g.direct_variance.push_back(0.0);
    g.photon_variance.push_back(i == 7 ? 1e-2 : 0.25e-4);
  }
  const RoundPlan plan = next_round_scale({g}, {1.0}, 1.0, AccuracyPercentile);
  EXPECT_EQ(plan.sensors_constrained, 0u);
  EXPECT_EQ(plan.scale[0], 1.0);
}

// ---- whole rounds on the office ------------------------------------------------------------

/// The reference office as run_study sets it up, DF only, with test settings.
struct Office : test::OfficeRounds {
  explicit Office(std::uint64_t seed) { this->seed = seed; }
  AccuracyCase accuracy_case() const {
    AccuracyCase c;
    c.scene = scene.get();
    c.materials = &materials;
    c.sources = &sources;
    c.planes = &planes;
    c.plane_of_grid = &plane_of_grid;
    c.grids = &description.grids;
    c.tracing.seed = seed;
    c.tracing.photons_per_source = 2000;  // the reference count
    c.tracing.source_photon_factor.assign(sources.size(), 1.0);
    c.tracing.source_photon_factor[0] = 16.0;  // the ground, as the pipeline
    c.tracing.keep_surface_photons = false;
    c.estimating.density.bandwidth = 20;
    c.estimating.direct.samples_per_source = direct_samples;
    c.estimating.direct.seed = seed;
    c.overcast_vector = &overcast;
    c.horizontal_illuminance_lux = 10000.0;
    return c;
  }
  std::uint64_t seed = 1;
  int direct_samples = 16;
};

AccuracyResult run(std::uint64_t seed, const AccuracyGoal& goal, int threads = 0) {
  const Office office(seed);
  std::unique_ptr<tbb::global_control> limit;
  if (threads > 0) limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, threads);
  return run_accuracy_rounds(office.accuracy_case(), goal, [](const std::string& line) { std::printf("%s\n", line.c_str()); });
}

std::vector<double> df_of(const engine::DaylightCoefficients& c, const RadianceMatrix& sky) {
  return daylight_factor_percent(c.to_matrix(), sky, 10000.0);
}

constexpr double Target = 3.0;  // percent: the pilot (about 6 %) does not reach it

// The target is met (the reported 95th percentile, recomputed here from the coefficients'
// own variances, is at most 3 %), and three seeds' DF spread agrees with it. For the sensors
// at or below the percentile, the mean of S_s^2 / sigma_s^2 (S_s the sample standard deviation
// over the seeds, sigma_s^2 the mean reported variance) has mean 1 if the errors are honest;
// with 3 seeds each term is chi^2(2) / 2, and since neighbouring sensors share photons the
// mean is bounded by the fully correlated case, chi^2(2) / 2 itself: its upper 1e-4 quantile
// is ln(1e4) = 9.21, which the test uses (a spread 3 times the claim fails). The
// calibration itself is measured over 20 seeds by UncertaintyHonesty.*.
// Sources whose pilot stored no photon (the sky behind the office) bring nothing: they get no
// attempts after the pilot.
TEST(AccuracyTarget, MetAndConsistentWithTheSpreadOfThreeSeeds) {
  AccuracyGoal goal;
  goal.target_percent = Target;
  const Office office(1);
  std::vector<std::vector<double>> df, variance;
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    const AccuracyResult r = run(seed, goal);
    ASSERT_EQ(r.outcome.stop_reason, "target met");
    ASSERT_EQ(r.outcome.reached_percent.size(), 1u);
    EXPECT_LE(r.outcome.reached_percent[0], Target);
    EXPECT_GE(r.outcome.rounds, 2u) << "the pilot alone met the target: the test checks no round";
    const engine::DaylightCoefficients& c = r.coefficients[0];
    // As the study writes daylight_factor.csv (study_runner.cpp).
    const DaylightFactorParts parts = daylight_factor_parts(c, office.overcast, 10000.0, DaylightFactorSkyIndex);
    const std::vector<double> se = parts.stderr_percent();
    df.push_back(parts.df_percent);
    EXPECT_NEAR(percentile_relative_stderr_percent(df.back(), se, AccuracyPercentile), r.outcome.reached_percent[0], 1e-9);
    std::vector<double> se2(se.size());
    for (std::size_t i = 0; i < se.size(); ++i) se2[i] = se[i] * se[i];
    variance.push_back(se2);
    if (seed == 1) {
      std::size_t dark = 0;
      for (std::size_t p = 0; p < c.sources; ++p) {
        bool lit = false;
        for (std::size_t s = 0; s < c.sensors && !lit; ++s) lit = c.global[s * c.sources + p].y > 0 || c.caustic[s * c.sources + p].y > 0;
        if (lit) continue;
        ++dark;
        EXPECT_EQ(r.outcome.final_attempts[p], r.outcome.pilot_attempts[p]) << "source " << p;
      }
      EXPECT_GT(dark, 20u) << "the office's north sky brings no photon";
      std::uint64_t grown = 0;
      for (std::size_t p = 0; p < c.sources; ++p) grown += r.outcome.final_attempts[p] > r.outcome.pilot_attempts[p];
      EXPECT_GT(grown, 0u);
    }
  }
  const std::size_t m = df[0].size();
  std::vector<double> relative(m);
  for (std::size_t s = 0; s < m; ++s) relative[s] = std::sqrt((variance[0][s] + variance[1][s] + variance[2][s]) / 3) / std::max(1e-30, df[0][s]);
  std::vector<std::size_t> order;
  for (std::size_t s = 0; s < m; ++s)
    if (df[0][s] > 0) order.push_back(s);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return relative[a] < relative[b]; });
  order.resize(static_cast<std::size_t>(std::ceil(0.95 * double(order.size()))));
  double ratio = 0;
  for (std::size_t s : order) {
    const double mean = (df[0][s] + df[1][s] + df[2][s]) / 3;
    double ss = 0;
    for (int k = 0; k < 3; ++k) ss += (df[k][s] - mean) * (df[k][s] - mean);
    const double sigma2 = (variance[0][s] + variance[1][s] + variance[2][s]) / 3;
    ratio += ss / 2 / sigma2 / double(order.size());
  }
  std::printf("mean observed / reported variance over %zu sensors: %.3f (bound 9.21)\n", order.size(), ratio);
  EXPECT_LT(ratio, 9.21);
  EXPECT_GT(ratio, 0.0);
}

TEST(AccuracyTarget, OneAndTwoThreadsGiveTheSameBytes) {
  AccuracyGoal goal;
  goal.target_percent = Target;
  const AccuracyResult a = run(5, goal, 1), b = run(5, goal, 2);
  ASSERT_EQ(a.outcome.rounds, b.outcome.rounds);
  EXPECT_GE(a.outcome.rounds, 2u);
  EXPECT_EQ(a.outcome.photons, b.outcome.photons);
  EXPECT_EQ(a.outcome.final_attempts, b.outcome.final_attempts);
  EXPECT_EQ(a.outcome.reached_percent, b.outcome.reached_percent);
  const engine::DaylightCoefficients& x = a.coefficients[0];
  const engine::DaylightCoefficients& y = b.coefficients[0];
  ASSERT_EQ(x.global.size(), y.global.size());
  EXPECT_EQ(0, std::memcmp(x.global.data(), y.global.data(), x.global.size() * sizeof(Vec3)));
  EXPECT_EQ(0, std::memcmp(x.direct.data(), y.direct.data(), x.direct.size() * sizeof(Vec3)));
  EXPECT_EQ(0, std::memcmp(x.photon_variance.data(), y.photon_variance.data(), x.photon_variance.size() * sizeof(double)));
}

// The direct part dominates after the pilot: at 1 shadow ray per bin (and 8 x 8 port points
// per side) the office's direct variance alone exceeds many sensors' budget at a 3 % target, so
// a round raises the grid's shadow rays (the log says so) and the rounds then meet the target
// ("target met", the count raised, the same bytes on one and two threads). The raised direct
// part's reported variance is checked against an independent direct component (another seed,
// 256 rays per bin): per sensor z = (D - D_ref) / sqrt(s^2 + s_ref^2) of the direct DF, the
// sensors independent (each draws its own random streams), so sum z^2 over the N lit sensors
// is at most chi^2(N) if the variances are honest; the test bounds it by chi^2(N)'s upper
// 1e-4 quantile (Wilson-Hilferty), a variance understated by a factor 2 fails.
TEST(AccuracyTarget, DirectPartDominatesThenTheRoundsRaiseItsRaysAndMeetTheTarget) {
  AccuracyGoal goal;
  goal.target_percent = Target;
  Office office(7);
  office.direct_samples = 1;
  std::vector<std::string> lines;
  auto run_direct = [&](int threads) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    lines.clear();
    return run_accuracy_rounds(office.accuracy_case(), goal, [&](const std::string& line) {
      std::printf("%s\n", line.c_str());
      lines.push_back(line);
    });
  };
  const AccuracyResult r = run_direct(2);
  std::size_t raises = 0;
  for (const std::string& l : lines) raises += l.find("raises grid") != std::string::npos;
  EXPECT_GE(raises, 1u) << "no round raised the shadow rays";
  ASSERT_EQ(r.outcome.stop_reason, "target met");
  ASSERT_EQ(r.outcome.direct_samples_per_bin.size(), 1u);
  const int raised = r.outcome.direct_samples_per_bin[0];
  EXPECT_GT(raised, 1);
  EXPECT_LE(raised, MaxDirectSamplesPerBin);
  EXPECT_LE(r.outcome.reached_percent[0], Target);
  const AccuracyResult one = run_direct(1);
  EXPECT_EQ(one.outcome.direct_samples_per_bin, r.outcome.direct_samples_per_bin);
  EXPECT_EQ(one.outcome.final_attempts, r.outcome.final_attempts);
  EXPECT_TRUE(encode_coefficients(one.coefficients[0]) == encode_coefficients(r.coefficients[0]));
  // Two in-process ranks (the distributed executor's RoundWork, blocks of 8 sensors): every
  // rank raises alike and holds the one-process bytes.
  std::vector<AccuracyResult> ranked(2);
  test::run_ranks_expecting_no_error(2, [&](dist::Communicator& comm) {
    const ArtifactStore store(test::fresh_dir("accuracy_direct_" + std::to_string(comm.rank())).string());
    const auto executor = make_distributed_executor(comm, store, false, 8);
    ranked[static_cast<std::size_t>(comm.rank())] =
        run_accuracy_rounds(office.accuracy_case(), goal, [](const std::string&) {}, executor->round_work());
  });
  for (const AccuracyResult& x : ranked) {
    EXPECT_EQ(x.outcome.direct_samples_per_bin, r.outcome.direct_samples_per_bin);
    EXPECT_EQ(x.outcome.stop_reason, r.outcome.stop_reason);
    ASSERT_EQ(x.coefficients.size(), 1u);
    EXPECT_TRUE(encode_coefficients(x.coefficients[0]) == encode_coefficients(r.coefficients[0]));
  }

  // The direct part of the result against an independent one.
  const engine::DaylightCoefficients& c = r.coefficients[0];
  const std::vector<SensorPoint>& sensors = office.description.grids.at(0).points;
  engine::DirectOptions reference;
  reference.samples_per_source = MaxDirectSamplesPerBin;
  reference.seed = 1007;
  engine::DaylightCoefficients ref = c;
  ref.direct = engine::direct_coefficients(*office.scene, office.materials, office.sources, sensors, reference,
                                           &ref.direct_variance);
  auto direct_df = [&](const engine::DaylightCoefficients& x, std::vector<double>& se) {
    engine::DaylightCoefficients d = x;
    d.global.assign(d.global.size(), Vec3{0, 0, 0});
    d.caustic.assign(d.caustic.size(), Vec3{0, 0, 0});
    se = daylight_factor_stderr_percent(d.direct_variance, d.sensors, office.overcast, 10000.0);
    return df_of(d, office.overcast);
  };
  std::vector<double> se, se_ref;
  const std::vector<double> df = direct_df(c, se), df_ref = direct_df(ref, se_ref);
  double sum = 0;
  std::size_t lit = 0;
  for (std::size_t i = 0; i < df.size(); ++i) {
    if (!(df_ref[i] > 0)) continue;
    ++lit;
    const double e = df[i] - df_ref[i];
    sum += e * e / (se[i] * se[i] + se_ref[i] * se_ref[i]);
  }
  ASSERT_GT(lit, 20u);
  const double nu = double(lit), z = 3.719;  // the standard normal's upper 1e-4 quantile
  const double bound = nu * std::pow(1.0 - 2.0 / (9.0 * nu) + z * std::sqrt(2.0 / (9.0 * nu)), 3.0);
  std::printf("direct part at %d rays per bin against the reference: sum z^2 %.1f over %zu sensors (bound %.1f)\n",
              raised, sum, lit, bound);
  EXPECT_LT(sum, bound);
}

// The photon budget spent does not end the shadow rays' rounds: at a 1 % target the direct
// part still keeps some sensors above after the first raise (1 -> 16), and round 3 raises it
// again (16 -> 64), shadow rays alone; the estimate is then the pilot's at 64 shadow rays.
TEST(AccuracyTarget, APhotonBudgetSpentLeavesTheShadowRaysTheirFurtherRaises) {
  AccuracyGoal goal;
  goal.target_percent = 1.0;
  goal.max_photons = 1000;
  Office office(7);
  office.direct_samples = 1;
  std::vector<std::string> lines;
  const AccuracyResult r = run_accuracy_rounds(office.accuracy_case(), goal, [&](const std::string& line) {
    std::printf("%s\n", line.c_str());
    lines.push_back(line);
  });
  std::size_t raise_only = 0;
  for (const std::string& l : lines) raise_only += l.find("raises the shadow rays only: the photon budget") != std::string::npos;
  EXPECT_EQ(raise_only, 2u);
  EXPECT_EQ(r.outcome.stop_reason, "photon budget");
  EXPECT_EQ(r.outcome.rounds, 3u);
  EXPECT_EQ(r.outcome.final_attempts, r.outcome.pilot_attempts);
  EXPECT_EQ(r.outcome.direct_samples_per_bin, std::vector<int>({64}));
  office.direct_samples = 64;
  goal.max_photons = 0;  // the pilot alone at the raised count: the same estimate
  goal.target_percent = 100.0;
  const AccuracyResult pilot = run_accuracy_rounds(office.accuracy_case(), goal, [](const std::string&) {});
  EXPECT_EQ(pilot.outcome.rounds, 1u);
  EXPECT_TRUE(encode_coefficients(pilot.coefficients[0]) == encode_coefficients(r.coefficients[0]));
}

// A photon budget below the pilot's photons leaves no room for photons after it, but the
// shadow rays are no photons: round 2 raises them alone (no attempt after the pilot) and, the
// direct part no longer keeping the grid above, is the last, stopping on the photon budget
// with the error the raise brought down.
TEST(AccuracyTarget, APhotonBudgetLeavesTheShadowRaysTheirRound) {
  AccuracyGoal goal;
  goal.target_percent = Target;
  goal.max_photons = 1000;
  Office office(7);
  office.direct_samples = 1;
  const AccuracyResult r =
      run_accuracy_rounds(office.accuracy_case(), goal, [](const std::string& line) { std::printf("%s\n", line.c_str()); });
  EXPECT_EQ(r.outcome.stop_reason, "photon budget");
  EXPECT_EQ(r.outcome.rounds, 2u);
  EXPECT_EQ(r.outcome.final_attempts, r.outcome.pilot_attempts);
  ASSERT_EQ(r.outcome.direct_samples_per_bin.size(), 1u);
  EXPECT_GT(r.outcome.direct_samples_per_bin[0], 1);
  office.direct_samples = r.outcome.direct_samples_per_bin[0];
  goal.max_photons = 0;  // the pilot alone at the raised count: the same estimate
  goal.target_percent = 100.0;
  const AccuracyResult pilot = run_accuracy_rounds(office.accuracy_case(), goal, [](const std::string&) {});
  EXPECT_EQ(pilot.outcome.rounds, 1u);
  EXPECT_TRUE(encode_coefficients(pilot.coefficients[0]) == encode_coefficients(r.coefficients[0]));
}

using test::CountingWork;

// The rounds on 1, 2 and 3 in-process ranks (the distributed executor's RoundWork, sensor
// blocks of 8 of the 48 sensors, a time budget checked) give every rank the one-process rounds' bytes: outcome,
// attempts per source, coefficients with their variances. With several ranks the requests

// go out in more ranges than there are requests (a big source split) and the grid in 6 blocks.
TEST(AccuracyTarget, OneToThreeRanksGiveTheOneProcessBytes) {
  AccuracyGoal goal;
  goal.target_percent = Target;
  goal.max_seconds = 1e6;  // never reached, but every round's check agrees on rank 0's clock
  const AccuracyResult one = run(5, goal);
  ASSERT_GE(one.outcome.rounds, 2u);
  const std::string expected = encode_coefficients(one.coefficients[0]);
  const Office office(5);
  for (int ranks : {1, 2, 3}) {
    SCOPED_TRACE(std::to_string(ranks) + " ranks");
    std::vector<AccuracyResult> results(static_cast<std::size_t>(ranks));
    std::vector<int> calls(results.size()), ranges(results.size());
    std::vector<std::size_t> requests(results.size());
    std::vector<std::size_t> blocks(results.size());
    test::run_ranks_expecting_no_error(ranks, [&](dist::Communicator& comm) {
      const std::filesystem::path dir =
          test::fresh_dir("accuracy_ranks_" + std::to_string(ranks) + "_" + std::to_string(comm.rank()));
      const ArtifactStore store(dir.string());
      const auto executor = make_distributed_executor(comm, store, false, 8);
      CountingWork work(executor->round_work());
      const auto r = static_cast<std::size_t>(comm.rank());
      results[r] = run_accuracy_rounds(office.accuracy_case(), goal, [](const std::string&) {}, work);
      calls[r] = work.calls;
      requests[r] = work.requests_total;
      ranges[r] = work.ranges;
      blocks[r] = work.blocks;
    });
    int all_ranges = 0;
    for (std::size_t r = 0; r < results.size(); ++r) {
      const AccuracyResult& x = results[r];
      EXPECT_EQ(x.outcome.rounds, one.outcome.rounds);
      EXPECT_EQ(x.outcome.photons, one.outcome.photons);
      EXPECT_EQ(x.outcome.stop_reason, one.outcome.stop_reason);
      EXPECT_EQ(x.outcome.pilot_attempts, one.outcome.pilot_attempts);
      EXPECT_EQ(x.outcome.final_attempts, one.outcome.final_attempts);
      EXPECT_EQ(x.outcome.reached_percent, one.outcome.reached_percent);
      ASSERT_EQ(x.coefficients.size(), 1u);
      EXPECT_TRUE(encode_coefficients(x.coefficients[0]) == expected) << "rank " << r;
      EXPECT_EQ(calls[r], calls[0]);
      EXPECT_EQ(requests[r], requests[0]);
      all_ranges += ranges[r];
    }
    // Every rank receives every range; each range is traced by one rank only.
    if (ranks > 1) {
      EXPECT_GT(ranges[0], 0);
      EXPECT_LT(ranges[0], all_ranges) << "rank 0 traced every range";
      EXPECT_GT(std::size_t(all_ranges), requests[0]) << "no request was split";
      EXPECT_EQ(blocks[0], (1 + one.outcome.rounds) * 6u);  // the direct part, then each round, in 6 blocks
    } else {
      EXPECT_EQ(std::size_t(all_ranges), requests[0]);
      EXPECT_EQ(blocks[0], 1 + one.outcome.rounds);  // one block per grid and round
    }
  }
}

// A photon budget below the pilot's photons and a time budget shorter than the pilot stop the
// rounds after the pilot, and the outcome says which; a budget between the pilot and the
// second round's plan cuts that round and stops after it.
TEST(AccuracyTarget, BudgetsStopTheRoundsWithTheirReason) {
  AccuracyGoal photons;
  photons.target_percent = Target;
  photons.max_photons = 1000;
  const AccuracyResult p = run(2, photons);
  EXPECT_EQ(p.outcome.stop_reason, "photon budget");
  EXPECT_EQ(p.outcome.rounds, 1u);
  EXPECT_GT(p.outcome.reached_percent[0], Target);
  AccuracyGoal seconds;
  seconds.target_percent = Target;
  seconds.max_seconds = 1e-6;
  const AccuracyResult s = run(2, seconds);
  EXPECT_EQ(s.outcome.stop_reason, "time budget");
  EXPECT_EQ(s.outcome.rounds, 1u);
  EXPECT_EQ(s.outcome.final_attempts, p.outcome.final_attempts);  // both the pilot alone

  // A budget 20 000 photons above the pilot's: round 2 is cut to fit and is the last. Its
  // photons are planned from each source's yield so far, whose relative error is about
  // 1 / sqrt(its photons); with at most 16 times a source's photons added, the plan's standard
  // error is below sqrt(16 x budget), and the test allows 4 of them.
  AccuracyGoal cut;
  cut.target_percent = Target;
  cut.max_photons = p.outcome.photons + 20000;
  const AccuracyResult c = run(2, cut);
  EXPECT_EQ(c.outcome.stop_reason, "photon budget");
  EXPECT_EQ(c.outcome.rounds, 2u);
  EXPECT_GT(c.outcome.photons, p.outcome.photons);
  EXPECT_LE(double(c.outcome.photons), double(cut.max_photons) + 4.0 * std::sqrt(16.0 * double(cut.max_photons)));
  std::printf("photon budget %llu: %llu photons stored\n", static_cast<unsigned long long>(cut.max_photons),
              static_cast<unsigned long long>(c.outcome.photons));
}

}  // namespace
}  // namespace dayphoton::study
