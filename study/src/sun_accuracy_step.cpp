// The sun rounds as one plan step: see sun_accuracy_step.h.
#include "sun_accuracy_step.h"

#include "dayphoton/study/accuracy_policy.h"

#include <cstdio>

#include <nlohmann/json.hpp>

#include "dayphoton/study/annual_sun.h"
#include "dayphoton/study/artifact_codec.h"
#include "dayphoton/study/cache_keys.h"
#include "dayphoton/study/content_hash.h"
#include "dayphoton/study/gather_accuracy_rounds.h"
#include "dayphoton/study/step_executor.h"
#include "gather_accuracy_json.h"

namespace dayphoton::study {
namespace {

std::string exact(double x) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}

}  // namespace

SunAccuracyOutcome accuracy_sun_coefficients(const project::Project& project, const std::string& prefix,
                                             const CaseScene& cs, const std::vector<sky::SunRecord>& suns,
                                             const engine::SunBins& bins,
                                             const engine::CoefficientOptions& estimating, RunContext& ctx,
                                             std::vector<GridSun>& result, const std::vector<SunRoundCase>* cases) {
  const project::Simulation& sim = project.simulation;
  const SimulationPlan& plan = ctx.plan;
  const std::vector<SensorGrid>& grids = cs.description.grids;
  SunAccuracyCase c;
  c.scene = &cs.scene;
  c.materials = &cs.materials;
  c.bins = &bins;
  c.suns = &suns;
  c.planes = &cs.layout.planes;
  c.plane_of_grid = &cs.layout.plane_of_grid;
  c.near_cut_sensors = &cs.layout.near_cut_sensors;
  c.grids = &grids;
  c.gather = plan.point_estimate == project::PointEstimate::Gather;
  c.tracing = plan.tracing_for(plan.sun_tracing, cs.layout);
  // As the rounds estimate (the gather's variance weights are the bins' yearly weights): so in
  // the keys too.
  c.estimating = estimating;
  c.cases = cases;
  AccuracyGoal goal;
  goal.target_percent = sim.accuracy->target_df_relative_stderr_percent;
  goal.max_photons = sim.accuracy->max_photons > 0 ? std::uint64_t(sim.accuracy->max_photons) : project.limits.photons;

  // Keys: the count-controlled bins' photon keys (scene, planes, bin patch, seed, reference
  // count), the goal and the rounds' policy, the year's suns (their weights are the measure),
  // and every grid (the rounds serve them all).
  std::vector<std::string> keys(bins.size());
  for (std::size_t i = 0; i < bins.size(); ++i)
    keys[i] = sun_photon_key(cs.scene_hash, cs.planes_hash, bins.multiplication_factor(), bins.patch(i),
                             sky::SunHalfAngle_rad, c.tracing);
  ContentHash year;
  for (const sky::SunRecord& s : suns) year.integer(std::int64_t(s.step)).vec3(s.direction).number(s.disc_radiance);
  // Point-in-time cases: the measure is each case's illuminance, so its other parts are inputs.
  if (cases && !cases->empty()) {
    year.text("point-in-time cases, budget floor " + exact(SunCaseBudgetFloor) + ", left-out sensors counted");
    for (const SunRoundCase& pc : *cases) {
      year.integer(std::int64_t(pc.sun));
      for (const std::vector<double>& v : pc.other_lux)
        for (double x : v) year.number(x);
      for (const std::vector<double>& v : pc.other_variance)
        for (double x : v) year.number(x);
    }
  }
  std::string rounds = "sun-accuracy:" + exact(goal.target_percent) + ":" + std::to_string(goal.max_photons) + ":" +
                       exact(AccuracyPercentile) + ":" + std::to_string(MaxAccuracyRounds) + ":" +
                       exact(AccuracyPilotFraction) + ":" + exact(AccuracyRoundAim) + ":" + exact(goal.max_growth) +
                       ":" +
                       (c.gather ? "gather-rays-photons:" + std::to_string(GatherMaxRounds) + ":" +
                                       exact(GatherMaxGrowth) + ":" + std::to_string(GatherMaxRays)
                                 : std::string("surface")) +
                       ":" + year.hex();
  for (std::string& k : keys) k += "|" + rounds;
  std::string all_grids;
  auto near_cuts = [&](std::size_t g) { return near_cut_count(*c.plane_of_grid, c.near_cut_sensors, g); };
  for (std::size_t g = 0; g < grids.size(); ++g)
    all_grids += sun_coefficients_key(keys, plan.sun_bin_minimum_bound_fraction, grids[g], c.estimating, near_cuts(g)) + ";";
  for (std::string& k : keys) k += "|" + all_grids;
  std::vector<std::string> grid_keys;
  for (std::size_t g = 0; g < grids.size(); ++g)
    grid_keys.push_back(sun_coefficients_key(keys, plan.sun_bin_minimum_bound_fraction, grids[g], c.estimating, near_cuts(g)));
  const std::string outcome_key = grid_keys.empty() ? std::string("none") : grid_keys.front();

  SunAccuracyOutcome outcome;
  Step step;
  step.kind = StepKind::SunCoefficients;
  for (const std::string& k : grid_keys) {
    step.outputs.push_back({"sun-coefficients", k});
    step.outputs.push_back({"sun-coefficients-variance", k});
  }
  step.outputs.push_back({"sun-accuracy", outcome_key});
  // Collective (plan_step.h): every process of the run takes part in the rounds (round_work.h).
  step.collective = true;
  auto to_json = [](const SunAccuracyOutcome& o) {
    return nlohmann::json{{"target_percent", o.target_percent}, {"reached_percent", o.reached_percent},
                          {"hourly_percent", o.hourly_percent}, {"grid_status", o.grid_status},
                          {"rounds", o.rounds},                 {"photons", o.photons},
                          {"attempts", o.attempts},             {"stop_reason", o.stop_reason},
                          {"gather", gather_accuracy_json(o.gather)},
                          {"near_cut", near_cut_reached_json(o.near_cut)},
                          {"case_reached_percent", o.case_reached_percent}}
        .dump();
  };
  step.compute = [&]() -> std::vector<std::string> {
    SunAccuracyResult r = run_sun_accuracy_rounds(
        c, goal, [&](const std::string& line) { ctx.log.line(prefix + line); }, ctx.executor.round_work());
    std::vector<std::string> bytes;
    for (std::size_t g = 0; g < grids.size(); ++g) {
      // The variances as the cache keeps them (single precision), as sun_bin_steps.cpp does.
      RadianceMatrix variance(grids[g].points.size(), bins.size(), 1);
      for (std::size_t i = 0; i < r.variance[g].size(); ++i) variance.data()[i] = static_cast<float>(r.variance[g][i]);
      result[g].bin_coefficients = std::move(r.coefficients[g]);
      result[g].bin_variance = variance.data();
      bytes.push_back(encode_matrix(result[g].bin_coefficients));
      bytes.push_back(encode_matrix(variance));
    }
    bytes.push_back(to_json(r.outcome));
    outcome = r.outcome;
    return bytes;
  };
  step.take = [&](const std::vector<std::string>& bytes) {
    for (std::size_t g = 0; g < grids.size(); ++g) {
      result[g].bin_coefficients = decode_matrix(bytes.at(2 * g));
      const RadianceMatrix v = decode_matrix(bytes.at(2 * g + 1));
      result[g].bin_variance.assign(v.data().begin(), v.data().end());
      if (result[g].bin_coefficients.rows() != grids[g].points.size() ||
          result[g].bin_coefficients.columns() != bins.size() ||
          result[g].bin_variance.size() != grids[g].points.size() * bins.size())
        return false;
    }
    const nlohmann::json j = nlohmann::json::parse(bytes.at(2 * grids.size()));
    SunAccuracyOutcome o;
    o.target_percent = j.at("target_percent").get<double>();
    o.reached_percent = j.at("reached_percent").get<std::vector<double>>();
    o.hourly_percent = j.at("hourly_percent").get<std::vector<double>>();
    o.grid_status = j.at("grid_status").get<std::vector<std::string>>();
    o.rounds = j.at("rounds").get<std::size_t>();
    o.photons = j.at("photons").get<std::uint64_t>();
    o.attempts = j.at("attempts").get<std::uint64_t>();
    o.stop_reason = j.at("stop_reason").get<std::string>();
    if (!j.contains("gather")) return false;  // made before the sun's gather rounds
    o.gather = gather_accuracy_from_json(j.at("gather"));
    if (!j.contains("near_cut")) return false;  // made before the near-cut rows' record
    o.near_cut = near_cut_reached_from_json(j.at("near_cut"));
    if (j.contains("case_reached_percent"))
      o.case_reached_percent = j.at("case_reached_percent").get<std::vector<std::vector<double>>>();
    if (o.reached_percent.size() != grids.size() || o.hourly_percent.size() != grids.size() ||
        o.grid_status.size() != grids.size() || o.gather.size() != grids.size() || o.near_cut.size() != grids.size())
      return false;
    outcome = std::move(o);
    return true;
  };
  ctx.progress.start(prefix + "sun photons (accuracy rounds)", 1, "runs");
  if (ctx.executor.lookup(step)) {
    ctx.log.line(prefix + "sun accuracy: cached (" + outcome.stop_reason + " after " + std::to_string(outcome.rounds) +
                 " round(s))");
  } else {
    ctx.executor.run(step);
    for (std::uint64_t a : outcome.pilot_attempts) ctx.report.sun_bins_traced += a > 0 ? 1 : 0;  // the lit bins
  }
  ctx.progress.advance(1);
  ctx.progress.end();
  for (std::size_t g = 0; g < grids.size(); ++g)
    ctx.log.line(prefix + "sun accuracy " + grids[g].name + ": " + sun_accuracy_sentence(outcome, g));
  return outcome;
}

}  // namespace dayphoton::study
