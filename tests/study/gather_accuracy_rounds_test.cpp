// The gather rounds of the accuracy target (study/gather_accuracy_rounds.h): the ray plan
// against its closed forms, and whole rounds on the reference office (48 work-plane sensors on
// a receiver plane, and 8 of them again as a grid estimated by final gather): the gathered
// grid misses the target at the project's rays, its rays are raised until it is met, the
// photons are not touched for it, the outcome says so, and the bytes are the same for 1 and
// 2 threads and for 1, 2 and 3 in-process ranks. And the gather's fixed variance part: within
// the variance, 0 for one ray.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <tbb/global_control.h>

#include "dayphoton/engine/daylight_coefficients.h"
#include "dayphoton/engine/direct_component.h"
#include "dayphoton/engine/final_gather.h"
#include "dayphoton/engine/port_emission.h"
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
#include "dayphoton/study/gather_accuracy_rounds.h"
#include "dayphoton/study/plan_policy.h"
#include "in_process_study.h"
#include "office_rounds.h"

namespace dayphoton::study {
namespace {

// ---- the ray plan ---------------------------------------------------------------------------

// One sensor, DF 10 %, aim 10 % (allowed variance 1), no direct variance, gather variance 4 at
// 16 rays, none of it fixed: it needs 16 x 4 / 1 = 64 rays.
TEST(GatherRayPlan, WithoutAFixedPartTheVarianceFallsAsOneOverN) {
  const GatherRayPlan p = next_gather_rays({10.0}, {0.0}, {4.0}, {0.0}, 16, 10.0, 95.0);
  EXPECT_EQ(p.rays, 64);
  EXPECT_EQ(p.sensors_constrained, 1u);
  EXPECT_EQ(p.sensors_photon_limited, 0u);
}

// The direct variance takes its share of the budget first: direct 0.5 leaves 0.5, so
// 16 x 4 / 0.5 = 128 rays, rounded up to the square 144 (12 x 12 strata).
TEST(GatherRayPlan, DirectVarianceShrinksTheBudgetAndRaysAreSquares) {
  const GatherRayPlan p = next_gather_rays({10.0}, {0.5}, {4.0}, {0.0}, 16, 10.0, 95.0);
  EXPECT_EQ(p.rays, 144);
}

// Gather variance 2.5 at 64 rays of which alpha = 2 stays: beta = 0.5 x 64 = 32. Against the
// budget 1 (aim 10 %) alpha alone is too much: photon-limited, the rays stay. Against 2.25
// (aim 15 %): N = 32 / 0.25 = 128, rounded up to 144. At aim 20 % (budget 4 >= 2.5) the
// sensor is under its aim already.
TEST(GatherRayPlan, TheFixedPartIsNotChasedWithRays) {
  GatherRayPlan p = next_gather_rays({10.0}, {0.0}, {2.5}, {2.0}, 64, 10.0, 95.0);
  EXPECT_EQ(p.rays, 64);
  EXPECT_EQ(p.sensors_photon_limited, 1u);
  p = next_gather_rays({10.0}, {0.0}, {2.5}, {2.0}, 64, 15.0, 95.0);
  EXPECT_EQ(p.rays, 144);
  EXPECT_EQ(p.sensors_photon_limited, 0u);
  p = next_gather_rays({10.0}, {0.0}, {2.5}, {2.0}, 64, 20.0, 95.0);
  EXPECT_EQ(p.rays, 64);
  EXPECT_EQ(p.sensors_constrained, 0u);
}

// A fixed part reported above the variance counts as all of it (photon-limited); a direct
// variance above the budget: direct-limited.
TEST(GatherRayPlan, LimitsAreCounted) {
  GatherRayPlan p = next_gather_rays({10.0}, {0.0}, {3.0}, {5.0}, 64, 10.0, 95.0);
  EXPECT_EQ(p.rays, 64);
  EXPECT_EQ(p.sensors_photon_limited, 1u);
  p = next_gather_rays({10.0}, {2.0}, {3.0}, {0.0}, 64, 10.0, 95.0);
  EXPECT_EQ(p.rays, 64);
  EXPECT_EQ(p.sensors_direct_limited, 1u);
}

// At most GatherMaxGrowth times the rays per round, and GatherMaxRays in all; only sensors at
// or below the percentile count (of 20 sensors the worst is beyond the 95th: nearest rank 19).
TEST(GatherRayPlan, GrowthIsCappedAndTheWorstSensorsBeyondThePercentileIgnored) {
  GatherRayPlan p = next_gather_rays({10.0}, {0.0}, {400.0}, {0.0}, 16, 10.0, 95.0);
  EXPECT_EQ(p.rays, 256);
  p = next_gather_rays({10.0}, {0.0}, {400.0}, {0.0}, 16384, 10.0, 95.0);
  EXPECT_EQ(p.rays, GatherMaxRays);
  std::vector<double> df(20, 10.0), direct(20, 0.0), gather(20, 0.5), fixed(20, 0.0);
  gather[7] = 100.0;  // one sensor far worse: beyond the percentile
  p = next_gather_rays(df, direct, gather, fixed, 16, 10.0, 95.0);
  EXPECT_EQ(p.rays, 16);
  EXPECT_EQ(p.sensors_constrained, 0u);
  gather[3] = 2.0;  // a second one: now the 19th, at the percentile
  p = next_gather_rays(df, direct, gather, fixed, 16, 10.0, 95.0);
  EXPECT_EQ(p.rays, 36);  // 16 x 2 / 1 = 32, rounded up to a square
}

// ---- the photon plan of a gathered grid ------------------------------------------------------

// One sensor, DF 10 %, aim 10 % (budget B = 1), two sources of equal cost with fixed parts 1.5
// and 0.5 (alpha = 2) and a rays' part of 0.5 at 64 rays: the photons get B - 0.5 = 0.5, and
// Neyman's factors are sqrt(a_p) (sqrt 1.5 + sqrt 0.5) / 0.5 = 4.732 and 2.732 (then
// 1.5 / 4.732 + 0.5 / 2.732 = 0.5).
TEST(GatherPhotonPlan, ThePhotonsTakeTheBudgetLeftByTheRays) {
  const double s0 = std::sqrt(1.5) * (std::sqrt(1.5) + std::sqrt(0.5)), s1 = std::sqrt(0.5) * (std::sqrt(1.5) + std::sqrt(0.5));
  GatherPhotonPlan p = next_gather_photons({10.0}, {0.0}, {2.5}, {1.5, 0.5}, 64, {1.0, 1.0}, 10.0, 95.0);
  ASSERT_EQ(p.scale.size(), 2u);
  EXPECT_EQ(p.sensors, 1u);
  EXPECT_NEAR(p.scale[0], s0 / 0.5, 1e-12);
  EXPECT_NEAR(p.scale[1], s1 / 0.5, 1e-12);
  EXPECT_NEAR(1.5 / p.scale[0] + 0.5 / p.scale[1], 0.5, 1e-12);
  // A rays' part of 1 (more than half the budget): the rays keep half (more rays take it down).
  p = next_gather_photons({10.0}, {0.0}, {3.0}, {1.5, 0.5}, 64, {1.0, 1.0}, 10.0, 95.0);
  EXPECT_NEAR(p.scale[0], s0 / 0.5, 1e-12);
  // At the ray limit the rays' part stays: 0.8 of it leaves 0.2 to the photons.
  p = next_gather_photons({10.0}, {0.0}, {2.8}, {1.5, 0.5}, GatherMaxRays, {1.0, 1.0}, 10.0, 95.0);
  EXPECT_NEAR(p.scale[0], s0 / 0.2, 1e-9);
  EXPECT_NEAR(p.scale[1], s1 / 0.2, 1e-9);
  // Cost: a source four times dearer per photon gets half the factor it would (sqrt(c_p)).
  p = next_gather_photons({10.0}, {0.0}, {2.5}, {1.0, 1.0}, 64, {1.0, 4.0}, 10.0, 95.0);
  EXPECT_NEAR(p.scale[0], (1.0 + 2.0) / 0.5, 1e-12);
  EXPECT_NEAR(p.scale[1], 0.5 * (1.0 + 2.0) / 0.5, 1e-12);
}

TEST(GatherPhotonPlan, NoPhotonsWhenTheyCannotHelpOrAreNotTheProblem) {
  // The rays' part alone at the ray limit exceeds the budget: photons cannot bring it under.
  GatherPhotonPlan p = next_gather_photons({10.0}, {0.0}, {3.2}, {1.5, 0.5}, GatherMaxRays, {1.0, 1.0}, 10.0, 95.0);
  EXPECT_EQ(p.sensors, 0u);
  EXPECT_EQ(p.scale, std::vector<double>({1.0, 1.0}));
  // Direct-limited.
  p = next_gather_photons({10.0}, {1.2}, {2.5}, {1.5, 0.5}, 64, {1.0, 1.0}, 10.0, 95.0);
  EXPECT_EQ(p.scale, std::vector<double>({1.0, 1.0}));
  // Above the aim (sqrt(0.3 + 0.9) = 1.095), but the photon part 0.3 is within its share
  // 0.7 - 0.35: the rays are the remedy.
  p = next_gather_photons({10.0}, {0.3}, {0.9}, {0.2, 0.1}, 64, {1.0, 1.0}, 10.0, 95.0);
  EXPECT_EQ(p.sensors, 0u);
  EXPECT_EQ(p.scale, std::vector<double>({1.0, 1.0}));
  // Below the aim.
  p = next_gather_photons({10.0}, {0.0}, {0.9}, {0.8, 0.1}, 64, {1.0, 1.0}, 10.0, 95.0);
  EXPECT_EQ(p.scale, std::vector<double>({1.0, 1.0}));
  // A source without cost (no light traced) is not asked for; growth is capped.
  p = next_gather_photons({10.0}, {0.0}, {400.5}, {400.0, 0.5}, 64, {1.0, 0.0}, 10.0, 95.0);
  EXPECT_EQ(p.scale[0], AccuracyMaxGrowth);
  EXPECT_EQ(p.scale[1], 1.0);
}

// ---- whole rounds on the office -------------------------------------------------------------

struct Office : test::OfficeRounds {
  std::size_t photons_per_source = 2000;  ///< the reference count of the rounds
  std::size_t direct_samples = 16;        ///< shadow rays per source and sensor

  /// `plane_grid` false: the gathered grid alone (no receiver plane, no grid the photons serve).
  explicit Office(bool gathered_grid = true, bool plane_grid = true) {
    if (gathered_grid) add_gathered_grid();
    if (!plane_grid) {
      drop_work_plane_grid();
      planes.clear();
    }
  }
  AccuracyCase accuracy_case(std::uint64_t seed, int gather_rays) const {
    AccuracyCase c;
    c.scene = scene.get();
    c.materials = &materials;
    c.sources = &sources;
    c.planes = &planes;
    c.plane_of_grid = &plane_of_grid;
    c.grids = &description.grids;
    c.gather = true;
    c.tracing.seed = seed;
    c.tracing.photons_per_source = photons_per_source;
    c.tracing.source_photon_factor.assign(sources.size(), 1.0);
    c.tracing.source_photon_factor[0] = 16.0;
    c.tracing.keep_surface_photons = true;
    c.tracing.store_direct_on_surfaces = true;  // as the pipeline does for a gather
    c.estimating.density.bandwidth = 20;
    c.estimating.direct.samples_per_source = direct_samples;
    c.estimating.direct.seed = seed;
    c.estimating.gather.rays_per_sensor = gather_rays;
    c.estimating.gather.seed = seed;
    c.overcast_vector = &overcast;
    c.horizontal_illuminance_lux = 10000.0;
    return c;
  }
};

constexpr double Target = 5.0;  // percent: neither grid meets it after the pilot (about 7.5 and 8 %)
constexpr int FirstRays = 4;    // the gathered grid does not (tens of per cent)

AccuracyResult run(const Office& office, std::uint64_t seed, int threads = 0, double max_seconds = 0) {
  std::unique_ptr<tbb::global_control> limit;
  if (threads > 0) limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, threads);
  AccuracyGoal goal;
  goal.target_percent = Target;
  goal.max_seconds = max_seconds;
  return run_accuracy_rounds(office.accuracy_case(seed, FirstRays), goal,
                             [](const std::string& line) { std::printf("%s\n", line.c_str()); });
}

/// The reported measure recomputed from the coefficients' own variances.
double reached_from_coefficients(const engine::DaylightCoefficients& dc, const Office& office) {
  // As the study writes daylight_factor.csv (study_runner.cpp).
  const DaylightFactorParts parts = daylight_factor_parts(dc, office.overcast, 10000.0, DaylightFactorSkyIndex);
  return percentile_relative_stderr_percent(parts.df_percent, parts.stderr_percent(), AccuracyPercentile);
}

// The work plane takes a photon round, the gathered grid gather rounds (4 rays per sensor at
// first). The photons are those of the work plane alone (the same case without the gathered
// grid traces the same attempts), and the work plane's coefficients are the same bytes.
TEST(GatherAccuracyRounds, GatheredGridMeetsTheTargetWithMoreRays) {
  const Office office;
  const AccuracyResult r = run(office, 3);
  ASSERT_EQ(r.outcome.reached_percent.size(), 2u);
  ASSERT_EQ(r.outcome.gather.size(), 2u);
  const Office plane_only(false);
  const AccuracyResult alone = run(plane_only, 3);
  EXPECT_GE(r.outcome.rounds, 2u);
  EXPECT_EQ(r.outcome.rounds, alone.outcome.rounds);
  EXPECT_EQ(r.outcome.final_attempts, alone.outcome.final_attempts);
  EXPECT_TRUE(encode_coefficients(r.coefficients[0]) == encode_coefficients(alone.coefficients[0]));
  EXPECT_EQ(r.outcome.grid_status[0], "met");
  EXPECT_FALSE(r.outcome.gather[0].gathered);
  const GatherAccuracy& g = r.outcome.gather[1];
  EXPECT_TRUE(g.gathered);
  EXPECT_EQ(g.first_rays, FirstRays);
  EXPECT_GE(g.rounds, 1u);
  EXPECT_GT(g.rays, FirstRays);
  EXPECT_EQ(g.stop_reason, "target met");
  EXPECT_EQ(r.outcome.grid_status[1], "met");
  EXPECT_EQ(r.outcome.stop_reason, "target met");
  EXPECT_LE(r.outcome.reached_percent[1], Target);
  // The reported value is the final estimate's own (not a model's).
  EXPECT_DOUBLE_EQ(r.outcome.reached_percent[1], reached_from_coefficients(r.coefficients[1], office));
  EXPECT_NE(accuracy_sentence(r.outcome, 1).find("final gather, " + std::to_string(g.rays) + " rays per sensor"),
            std::string::npos);
}

// A time budget already spent by the photon rounds stops the gather rounds before the first,
// and the outcome says so (the one stop that depends on the machine).
TEST(GatherAccuracyRounds, TimeBudgetStopsTheGatherRounds) {
  const Office office;
  const AccuracyResult r = run(office, 3, 0, 1e-9);
  const GatherAccuracy& g = r.outcome.gather.at(1);
  EXPECT_EQ(g.rounds, 0u);
  EXPECT_EQ(g.rays, FirstRays);
  EXPECT_EQ(g.stop_reason, "time budget");
  EXPECT_EQ(r.outcome.grid_status[1], "above target");
  EXPECT_EQ(r.outcome.stop_reason, "time budget");
}

TEST(GatherAccuracyRounds, OneAndTwoThreadsAndOneToThreeRanksGiveTheSameBytes) {
  const Office office;
  const AccuracyResult one = run(office, 4, 1);
  ASSERT_GE(one.outcome.gather.at(1).rounds, 1u);
  const std::string expected = encode_coefficients(one.coefficients[1]);
  EXPECT_TRUE(encode_coefficients(run(office, 4, 2).coefficients[1]) == expected);
  for (int ranks : {1, 2, 3}) {
    SCOPED_TRACE(std::to_string(ranks) + " ranks");
    std::vector<AccuracyResult> results(static_cast<std::size_t>(ranks));
    test::run_ranks_expecting_no_error(ranks, [&](dist::Communicator& comm) {
      const std::filesystem::path dir =
          test::fresh_dir("gather_ranks_" + std::to_string(ranks) + "_" + std::to_string(comm.rank()));
      const ArtifactStore store(dir.string());
      const auto executor = make_distributed_executor(comm, store, false, 3);  // blocks of 3 of the 8 sensors
      AccuracyGoal goal;
      goal.target_percent = Target;
      results[static_cast<std::size_t>(comm.rank())] =
          run_accuracy_rounds(office.accuracy_case(4, FirstRays), goal, [](const std::string&) {}, executor->round_work());
    });
    for (const AccuracyResult& x : results) {
      EXPECT_EQ(x.outcome.gather.at(1).rays, one.outcome.gather.at(1).rays);
      EXPECT_EQ(x.outcome.gather.at(1).rounds, one.outcome.gather.at(1).rounds);
      EXPECT_EQ(x.outcome.reached_percent, one.outcome.reached_percent);
      EXPECT_TRUE(encode_coefficients(x.coefficients.at(1)) == expected);
    }
  }
}

// ---- more photons for a gathered grid's photon part ------------------------------------------

// The gathered grid alone (no grid the photons serve), from few photons: after the pilot its
// gather rounds stop on the photon part, which more rays do not lower; the photon rounds then
// trace more photons for it and the gather rounds go on from the rays reached.
constexpr double PhotonPartTarget = 2.0;   // percent
constexpr int PhotonPartRays = 64;         // the project's gather rays
constexpr std::size_t PhotonPartReference = 100;  // photons per source at the reference count
constexpr std::size_t PhotonPartDirectSamples = 256;  // the direct component well below the target

struct PhotonPartRun {
  AccuracyResult result;
  std::vector<std::string> log;
};

PhotonPartRun run_photon_part(std::uint64_t seed, std::uint64_t max_photons = 0, int threads = 0) {
  std::unique_ptr<tbb::global_control> limit;
  if (threads > 0) limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, threads);
  Office office(true, false);
  office.photons_per_source = PhotonPartReference;
  office.direct_samples = PhotonPartDirectSamples;
  AccuracyGoal goal;
  goal.target_percent = PhotonPartTarget;
  goal.max_photons = max_photons;
  PhotonPartRun r;
  r.result = run_accuracy_rounds(office.accuracy_case(seed, PhotonPartRays), goal, [&](const std::string& line) {
    std::printf("%s\n", line.c_str());
    r.log.push_back(line);
  });
  return r;
}

bool logged(const PhotonPartRun& r, const std::string& words) {
  for (const std::string& line : r.log)
    if (line.find(words) != std::string::npos) return true;
  return false;
}

// The reported standard errors against a reference (another seed, a 4 times tighter target):
// per sensor z = (DF - DF_ref) / sqrt(se^2 + se_ref^2), and the mean of z^2 over the 8 sensors
// is at most 15.1, the upper 1e-4 quantile of chi^2(1), which bounds it however correlated the
// sensors are (fully correlated, the mean is one chi^2(1) draw; independent, chi^2(8) / 8).
TEST(GatherPhotonRounds, PhotonPartAboveTheTargetGetsMorePhotons) {
  Office office(true, false);
  office.photons_per_source = PhotonPartReference;
  office.direct_samples = PhotonPartDirectSamples;
  AccuracyGoal tight;
  tight.target_percent = PhotonPartTarget / 4;
  const AccuracyResult reference =
      run_accuracy_rounds(office.accuracy_case(1003, PhotonPartRays), tight, [](const std::string&) {});
  ASSERT_EQ(reference.outcome.stop_reason, "target met");
  auto df_and_variance = [&](const engine::DaylightCoefficients& dc, std::vector<double>& df, std::vector<double>& var) {
    df = daylight_factor_percent(dc.to_matrix(), office.overcast, 10000.0);
    std::vector<double> v(dc.sensors * dc.sources);
    for (std::size_t i = 0; i < v.size(); ++i) v[i] = dc.direct_variance[i] + dc.photon_variance[i];
    const std::vector<double> se = daylight_factor_stderr_percent(v, dc.sensors, office.overcast, 10000.0);
    var.resize(se.size());
    for (std::size_t i = 0; i < se.size(); ++i) var[i] = se[i] * se[i];
  };
  std::vector<double> df_ref, var_ref;
  df_and_variance(reference.coefficients.at(0), df_ref, var_ref);
  for (const std::uint64_t seed : {3u, 4u}) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const PhotonPartRun r = run_photon_part(seed);
    const AccuracyOutcome& o = r.result.outcome;
    ASSERT_EQ(o.gather.size(), 1u);
    // After the pilot the gather rounds asked for photons for the photon part.
    EXPECT_TRUE(logged(r, "ask for more photons for the gather's photon part"));
    EXPECT_TRUE(logged(r, "accuracy: round 2 traces more photons for the gathered grids' photon part"));
    EXPECT_GE(o.rounds, 2u);
    for (std::size_t p = 0; p < o.final_attempts.size(); ++p) EXPECT_GE(o.final_attempts[p], o.pilot_attempts[p]);
    EXPECT_NE(o.final_attempts, o.pilot_attempts);
    EXPECT_EQ(o.gather[0].stop_reason, "target met");
    EXPECT_EQ(o.grid_status[0], "met");
    EXPECT_EQ(o.stop_reason, "target met");
    EXPECT_LE(o.reached_percent[0], PhotonPartTarget);
    // The reported value is the final estimate's own.
    EXPECT_DOUBLE_EQ(o.reached_percent[0], reached_from_coefficients(r.result.coefficients[0], office));
    std::vector<double> df, var;
    df_and_variance(r.result.coefficients[0], df, var);
    double z2 = 0;
    for (std::size_t i = 0; i < df.size(); ++i) z2 += (df[i] - df_ref[i]) * (df[i] - df_ref[i]) / (var[i] + var_ref[i]);
    z2 /= double(df.size());
    std::printf("seed %u: mean z^2 against the reference %.3g\n", unsigned(seed), z2);
    EXPECT_LE(z2, 15.1);
  }
}

// A photon budget below the pilot's photons: no photon round for the photon part, and the
// grid's stop (and the case's) names the budget.
TEST(GatherPhotonRounds, PhotonBudgetIsTheNamedStop) {
  const PhotonPartRun pilot_only = run_photon_part(3, 1);
  const AccuracyOutcome& o = pilot_only.result.outcome;
  EXPECT_EQ(o.rounds, 1u);
  EXPECT_EQ(o.final_attempts, o.pilot_attempts);
  ASSERT_EQ(o.gather.size(), 1u);
  EXPECT_TRUE(logged(pilot_only, "no round 2: the photon budget"));
  EXPECT_EQ(o.gather[0].stop_reason, "photon budget");
  EXPECT_EQ(o.grid_status[0], "above target");
  EXPECT_EQ(o.stop_reason, "photon budget");
  EXPECT_GT(o.reached_percent[0], PhotonPartTarget);
  EXPECT_NE(accuracy_sentence(o, 0).find("photon budget"), std::string::npos);
}

TEST(GatherPhotonRounds, OneAndTwoThreadsAndOneToThreeRanksGiveTheSameBytes) {
  const PhotonPartRun one = run_photon_part(5, 0, 1);
  ASSERT_GE(one.result.outcome.rounds, 2u);
  const std::string expected = encode_coefficients(one.result.coefficients.at(0));
  EXPECT_TRUE(encode_coefficients(run_photon_part(5, 0, 2).result.coefficients.at(0)) == expected);
  Office office(true, false);
  office.photons_per_source = PhotonPartReference;
  office.direct_samples = PhotonPartDirectSamples;
  for (int ranks : {1, 2, 3}) {
    SCOPED_TRACE(std::to_string(ranks) + " ranks");
    std::vector<AccuracyResult> results(static_cast<std::size_t>(ranks));
    const auto errors = dist::test::run_ranks(ranks, [&](dist::Communicator& comm) {
      const std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) /
                                        ("gather_photons_ranks_" + std::to_string(ranks) + "_" + std::to_string(comm.rank()));
      std::filesystem::remove_all(dir);
      const ArtifactStore store(dir.string());
      const auto executor = make_distributed_executor(comm, store, false, 3);  // blocks of 3 of the 8 sensors
      AccuracyGoal goal;
      goal.target_percent = PhotonPartTarget;
      results[static_cast<std::size_t>(comm.rank())] = run_accuracy_rounds(
          office.accuracy_case(5, PhotonPartRays), goal, [](const std::string&) {}, executor->round_work());
    });
    for (const std::exception_ptr& e : errors)
      if (e) {
        try {
          std::rethrow_exception(e);
        } catch (const std::exception& x) {
          ADD_FAILURE() << x.what();
        }
      }
    for (const AccuracyResult& x : results) {
      EXPECT_EQ(x.outcome.final_attempts, one.result.outcome.final_attempts);
      EXPECT_EQ(x.outcome.gather.at(0).rays, one.result.outcome.gather.at(0).rays);
      EXPECT_EQ(x.outcome.gather.at(0).rounds, one.result.outcome.gather.at(0).rounds);
      EXPECT_EQ(x.outcome.reached_percent, one.result.outcome.reached_percent);
      EXPECT_TRUE(encode_coefficients(x.coefficients.at(0)) == expected);
    }
  }
}


/// A RoundWork whose clock (agreed, the one measurement the rounds' decisions read) runs as the
/// local one's until an estimate named `after...` (e.g. "accuracy round 3,"): from then on it
/// reads `late_s`, so the time budget is spent at a chosen point of the rounds, on any machine;
/// with `late_readings` > 0 only that many readings are late, then it runs as the local one's.
class LateClockWork final : public RoundWork {
 public:
  LateClockWork(std::string after, double late_s, int late_readings = 0)
      : m_after(std::move(after)), m_late_s(late_s), m_left(late_readings), m_limited(late_readings > 0) {}
  std::vector<engine::AttemptRange> trace(const std::vector<AttemptRequest>& requests, const RangeTracer& t) override {
    return m_inner->trace(requests, t);
  }
  std::vector<std::string> estimate(std::size_t sensors, const RowEstimator& rows, const std::string& name) override {
    if (name.rfind(m_after, 0) == 0) late = true;
    return m_inner->estimate(sensors, rows, name);
  }
  double agreed(double value) override {
    if (!late || (m_limited && m_left == 0)) return m_inner->agreed(value);
    if (m_limited) --m_left;
    return m_late_s;
  }
  bool late = false;

 private:
  std::unique_ptr<RoundWork> m_inner = make_local_round_work();
  std::string m_after;
  double m_late_s;
  int m_left;
  bool m_limited;
};

/// The photon-part office with two gathered grids of 8 work-plane sensors each (sensors 24-31
/// and 32-39, no receiver plane): with seed 3 both ask for photons after the pilot; after that
/// round `near` meets the target at 1024 rays in one gather round while `far` (2.01 %) asks
/// for a third photon round, whose estimate at the project's rays is above the target for both.
/// (With a growth of at most 16 per round, AccuracyGoal::max_growth: at the default 32 the
/// second round's photons bring `far` under the target too.)
Office two_gathered_grids() {
  Office office(true, true);
  office.photons_per_source = PhotonPartReference;
  office.direct_samples = PhotonPartDirectSamples;
  const SensorGrid plane = office.description.grids[0];
  office.description.grids.clear();
  office.plane_of_grid.clear();
  office.planes.clear();
  for (const auto& [name, first] : {std::pair<const char*, std::ptrdiff_t>{"near", 24}, {"far", 32}}) {
    SensorGrid g = plane;
    g.name = name;
    g.points.assign(plane.points.begin() + first, plane.points.begin() + first + 8);
    office.description.grids.push_back(g);
    office.plane_of_grid.push_back(-1);
  }
  return office;
}

// The time budget spent after a later photon round (for the other grid): neither grid is
// gathered again, and each keeps its last gather estimate; its reported accuracy, rays and
// rounds are that estimate's, and the grid that had met the target still meets it.
TEST(GatherPhotonRounds, NoTimeToGatherAgainKeepsTheLastGatherEstimate) {
  const Office office = two_gathered_grids();
  AccuracyGoal goal;
  goal.target_percent = PhotonPartTarget;
  goal.max_growth = 16;  // two_gathered_grids()
  goal.max_seconds = 1e6;  // reached only by the late clock
  LateClockWork work("accuracy round 3,", 1e9);
  std::vector<std::string> lines;
  const AccuracyResult r = run_accuracy_rounds(office.accuracy_case(3, PhotonPartRays), goal, [&](const std::string& line) {
    std::printf("%s\n", line.c_str());
    lines.push_back(line);
  }, work);
  const AccuracyOutcome& o = r.outcome;
  ASSERT_TRUE(work.late) << "no third photon round";
  ASSERT_EQ(o.gather.size(), 2u);
  EXPECT_EQ(o.rounds, 3u);
  for (std::size_t g = 0; g < 2; ++g) {
    SCOPED_TRACE(office.description.grids[g].name);
    const GatherAccuracy& a = o.gather[g];
    // Each grid's estimate is the one of its gather round on the second round's photons.
    EXPECT_EQ(a.rays, 1024);
    EXPECT_EQ(a.rounds, 1u);
    EXPECT_EQ(o.reached_percent[g], reached_from_coefficients(r.coefficients[g], office));
    EXPECT_EQ(o.grid_status[g], o.reached_percent[g] <= PhotonPartTarget ? "met" : "above target");
  }
  EXPECT_EQ(o.gather[0].stop_reason, "target met");
  EXPECT_EQ(o.grid_status[0], "met");
  EXPECT_EQ(o.gather[1].stop_reason, "time budget");
  EXPECT_EQ(o.grid_status[1], "above target");
  EXPECT_EQ(o.stop_reason, "time budget");
}

// A raise of the shadow rays that the time budget has no room for stops the grids the photons
// serve on `time budget`, and the gathered grids' photon round is refused for the same reason.
// The work plane cut to its sensor 0, whose direct part at 1 shadow ray per bin alone is above
// the 2 % target (photons cannot help it: the round is the raise or nothing); the gathered grid
// (the photon-part case) asks for photons after the pilot. The clock reads late exactly once,
// when the rounds predict the raise's time after the pilot, and on time otherwise.
TEST(GatherPhotonRounds, ATimeBudgetRefusingAShadowRayRaiseRefusesTheGatheredGridsPhotonRound) {
  Office office(true, true);
  office.photons_per_source = PhotonPartReference;
  office.direct_samples = 1;
  std::vector<SensorPoint>& plane_points = office.description.grids.at(0).points;
  plane_points.resize(1);
  AccuracyGoal goal;
  goal.target_percent = PhotonPartTarget;
  goal.max_seconds = 1e6;
  LateClockWork work("accuracy round 1, grid gathered", 1e9, 1);
  std::vector<std::string> lines;
  const AccuracyResult r = run_accuracy_rounds(office.accuracy_case(3, PhotonPartRays), goal, [&](const std::string& line) {
    std::printf("%s\n", line.c_str());
    lines.push_back(line);
  }, work);
  auto logged_line = [&](const std::string& words) {
    for (const std::string& l : lines)
      if (l.find(words) != std::string::npos) return true;
    return false;
  };
  const AccuracyOutcome& o = r.outcome;
  EXPECT_TRUE(logged_line("accuracy: no raise of shadow rays in round 2: the time budget leaves no room for it"));
  EXPECT_TRUE(logged_line("ask for more photons for the gather's photon part"));
  EXPECT_TRUE(logged_line("accuracy: no round 2 for the gathered grids' photon part: the time budget"));
  EXPECT_EQ(o.rounds, 1u);
  EXPECT_EQ(o.final_attempts, o.pilot_attempts);
  EXPECT_EQ(o.direct_samples_per_bin.at(0), 1);
  EXPECT_EQ(o.grid_status.at(0), "above target");
  ASSERT_EQ(o.gather.size(), 2u);
  EXPECT_EQ(o.gather[1].stop_reason, "time budget");
  EXPECT_EQ(o.grid_status[1], "above target");
  EXPECT_EQ(o.stop_reason, "time budget");
}

// ---- more shadow rays for a gathered grid's direct part --------------------------------------

// The gathered grid alone at 1 shadow ray per bin: after its gather rounds its sensors are
// above the target by their direct component, which neither rays nor photons lower; the gather
// rounds raise its shadow rays by the photon rounds' rule (next_direct_round) and it meets the
// target, with the same bytes on 1 and 2 threads and on 2 ranks.
constexpr double DirectPartTarget = 3.0;  // percent
constexpr int DirectPartRays = 256;       // the gather's part well below the target
// Percent: some sensors' direct part alone at 256 shadow rays per bin is above it (0.2 % is met).
constexpr double DirectLimitTarget = 0.1;

struct DirectPartRun {
  AccuracyResult result;
  std::vector<std::string> log;
};

TEST(GatherDirectRounds, DirectPartAboveTheTargetGetsMoreShadowRays) {
  Office office(true, false);
  office.direct_samples = 1;
  AccuracyGoal goal;
  goal.target_percent = DirectPartTarget;
  auto run_direct = [&](int threads) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    DirectPartRun r;
    r.result = run_accuracy_rounds(office.accuracy_case(6, DirectPartRays), goal, [&](const std::string& line) {
      std::printf("%s\n", line.c_str());
      r.log.push_back(line);
    });
    return r;
  };
  const DirectPartRun r = run_direct(2);
  const AccuracyOutcome& o = r.result.outcome;
  ASSERT_EQ(o.gather.size(), 1u);
  std::size_t raises = 0;
  for (const std::string& l : r.log) raises += l.find(": shadow rays per bin 1 -> ") != std::string::npos;
  EXPECT_EQ(raises, 1u) << "the gather rounds did not raise the shadow rays";
  ASSERT_EQ(o.direct_samples_per_bin.size(), 1u);
  EXPECT_GT(o.direct_samples_per_bin[0], 1);
  EXPECT_LE(o.direct_samples_per_bin[0], MaxDirectSamplesPerBin);
  EXPECT_EQ(o.gather[0].stop_reason, "target met");
  EXPECT_EQ(o.grid_status[0], "met");
  EXPECT_EQ(o.stop_reason, "target met");
  EXPECT_LE(o.reached_percent[0], DirectPartTarget);
  // The reported value is the final estimate's own, its direct part that of the raised rays.
  EXPECT_DOUBLE_EQ(o.reached_percent[0], reached_from_coefficients(r.result.coefficients[0], office));
  engine::DirectOptions raised = office.accuracy_case(6, DirectPartRays).estimating.direct;
  raised.samples_per_source = o.direct_samples_per_bin[0];
  std::vector<double> variance;
  const std::vector<Vec3> direct = engine::direct_coefficients(
      *office.scene, office.materials, office.sources, office.description.grids.at(0).points, raised, &variance);
  EXPECT_TRUE(direct == r.result.coefficients[0].direct);
  EXPECT_TRUE(variance == r.result.coefficients[0].direct_variance);

  const std::string expected = encode_coefficients(r.result.coefficients[0]);
  const DirectPartRun one = run_direct(1);
  EXPECT_EQ(one.result.outcome.direct_samples_per_bin, o.direct_samples_per_bin);
  EXPECT_TRUE(encode_coefficients(one.result.coefficients.at(0)) == expected);
  std::vector<AccuracyResult> ranked(2);
  test::run_ranks_expecting_no_error(2, [&](dist::Communicator& comm) {
    const ArtifactStore store(test::fresh_dir("gather_direct_" + std::to_string(comm.rank())).string());
    const auto executor = make_distributed_executor(comm, store, false, 3);  // blocks of 3 of the 8 sensors
    ranked[static_cast<std::size_t>(comm.rank())] = run_accuracy_rounds(
        office.accuracy_case(6, DirectPartRays), goal, [](const std::string&) {}, executor->round_work());
  });
  for (const AccuracyResult& x : ranked) {
    EXPECT_EQ(x.outcome.direct_samples_per_bin, o.direct_samples_per_bin);
    EXPECT_EQ(x.outcome.gather.at(0).stop_reason, o.gather[0].stop_reason);
    EXPECT_TRUE(encode_coefficients(x.coefficients.at(0)) == expected);
  }
}

// A grid at the gather ray limit from the start (the project's rays are GatherMaxRays) whose
// direct part, at 1 shadow ray per bin, keeps it above the target: more rays are out of reach,
// so its shadow rays are raised (not the stop `gather ray limit`), and it meets the target at
// the same rays, with no gather round. Two of the gathered grid's sensors, 0 and 5, keep the
// gathers at 65536 rays cheap.
TEST(GatherDirectRounds, AtTheGatherRayLimitTheDirectPartIsStillRaised) {
  Office office(true, false);
  office.direct_samples = 1;
  std::vector<SensorPoint>& points = office.description.grids.at(0).points;
  points = {points.at(0), points.at(5)};
  AccuracyGoal goal;
  goal.target_percent = DirectPartTarget;
  std::vector<std::string> lines;
  const AccuracyResult r = run_accuracy_rounds(office.accuracy_case(6, GatherMaxRays), goal, [&](const std::string& line) {
    std::printf("%s\n", line.c_str());
    lines.push_back(line);
  });
  const AccuracyOutcome& o = r.outcome;
  ASSERT_EQ(o.gather.size(), 1u);
  std::size_t raises = 0;
  for (const std::string& l : lines) raises += l.find(": shadow rays per bin 1 -> ") != std::string::npos;
  EXPECT_GE(raises, 1u) << "the gather rounds did not raise the shadow rays at the ray limit";
  EXPECT_GT(o.direct_samples_per_bin.at(0), 1);
  EXPECT_EQ(o.gather[0].rays, GatherMaxRays);
  EXPECT_EQ(o.gather[0].rounds, 0u);
  EXPECT_EQ(o.gather[0].stop_reason, "target met");
  EXPECT_EQ(o.grid_status[0], "met");
  EXPECT_LE(o.reached_percent[0], DirectPartTarget);
  EXPECT_DOUBLE_EQ(o.reached_percent[0], reached_from_coefficients(r.coefficients[0], office));
}

// Shadow rays already at the rounds' limit: the grid is not raised, and when only its direct
// part keeps it above the target its gather stop (and the case's) is `direct rays limit`; the
// log names the count the sensors are at, the limit or a project's own count above it. The
// two sensors of the gathered grid whose direct part alone at the limit is above the target
// (sensors 0 and 5; 200 photons per source, since photons do not change that), so the stop
// comes at the grid's first estimate.
TEST(GatherDirectRounds, AtTheLimitTheStopIsDirectRaysLimit) {
  for (const int samples : {MaxDirectSamplesPerBin, 400}) {
    SCOPED_TRACE(std::to_string(samples) + " shadow rays per bin");
    Office office(true, false);
    office.photons_per_source = 200;
    office.direct_samples = std::size_t(samples);
    std::vector<SensorPoint>& points = office.description.grids.at(0).points;
    points = {points.at(0), points.at(5)};
    AccuracyGoal goal;
    goal.target_percent = DirectLimitTarget;
    std::vector<std::string> lines;
    const AccuracyResult r = run_accuracy_rounds(office.accuracy_case(6, DirectPartRays), goal, [&](const std::string& line) {
      std::printf("%s\n", line.c_str());
      lines.push_back(line);
    });
    const AccuracyOutcome& o = r.outcome;
    ASSERT_EQ(o.gather.size(), 1u);
    for (const std::string& l : lines) EXPECT_EQ(l.find(": shadow rays per bin "), std::string::npos) << l;
    EXPECT_EQ(o.direct_samples_per_bin, std::vector<int>({samples}));
    EXPECT_EQ(o.gather[0].stop_reason, "direct rays limit");
    EXPECT_EQ(o.grid_status[0], "above target");
    EXPECT_EQ(o.stop_reason, "direct rays limit");
    EXPECT_GT(o.reached_percent[0], DirectLimitTarget);
    const std::string words =
        samples > MaxDirectSamplesPerBin
            ? " by their direct component alone at 400 shadow rays per bin, the project's own count (above the "
              "rounds' limit of " + std::to_string(MaxDirectSamplesPerBin) + ")"
            : " by their direct component alone at " + std::to_string(MaxDirectSamplesPerBin) +
                  " shadow rays per bin, the rounds' limit";
    std::size_t named = 0;
    for (const std::string& l : lines) named += l.find(words) != std::string::npos;
    EXPECT_EQ(named, 1u) << words;
  }
}

// The gather's fixed part (engine/final_gather.h, "How the variance falls with the rays": the
// photon part's pairs of terms on two different rays) lies within the variance, and with one
// ray per sensor there is no pair of rays: it is 0.
TEST(GatherVarianceParts, FixedPartIsWithinTheVarianceAndZeroForOneRay) {
  const Office office;
  engine::TracingOptions tracing = office.accuracy_case(1, 1).tracing;
  tracing.photons_per_source = 500;
  const engine::PortEmitter emitter(*office.scene, office.sources);
  std::vector<engine::TracedPhotons> per_source(office.sources.size());
  for (std::size_t p = 0; p < office.sources.size(); ++p)
    per_source[p] = engine::trace_source_photons(*office.scene, office.materials, emitter, office.planes, tracing, p);
  const engine::GridPhotons photons = engine::GridPhotons::for_gather(
      engine::merge_traced_photons(std::move(per_source)).surface, office.sources.size());
  const std::vector<SensorPoint>& sensors = office.description.grids.at(1).points;
  for (const int rays : {1, 64}) {
    SCOPED_TRACE(std::to_string(rays) + " rays");
    engine::GatherOptions options;
    options.rays_per_sensor = rays;
    const engine::GatheredCoefficients g = engine::gather_photon_coefficients(
        *office.scene, office.materials, office.sources, photons.all(), sensors, options, &photons.groups());
    ASSERT_EQ(g.fixed_photon_variance.size(), g.variance.size());
    double fixed = 0, total = 0;
    for (std::size_t i = 0; i < g.variance.size(); ++i) {
      EXPECT_GE(g.fixed_photon_variance[i], 0.0);
      EXPECT_LE(g.fixed_photon_variance[i], g.variance[i]);
      fixed += g.fixed_photon_variance[i];
      total += g.variance[i];
    }
    EXPECT_GT(total, 0.0);
    if (rays == 1) {
      EXPECT_EQ(fixed, 0.0);
    }
    std::printf("%d rays: fixed part %.3g of the variance\n", rays, total > 0 ? fixed / total : 0.0);
  }
}

}  // namespace
}  // namespace dayphoton::study
