// The accuracy rounds' shared loop: see accuracy_round_loop.h.
#include "accuracy_round_loop.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "dayphoton/study/accuracy_policy.h"
#include "dayphoton/study/plan_policy.h"

namespace dayphoton::study {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

/// Rays per attempt of a source so far, plus one (its emission), for sharing the tracing out:
/// 1 before its first attempt.
double cost_per_attempt(const engine::SourcePhotonRecord& r) {
  return r.attempts > 0 ? 1.0 + double(r.raw.tallies.at(0).rays) / double(r.attempts) : 1.0;
}

}  // namespace

std::string direct_rays_limit_words(int samples_per_bin) {
  return std::to_string(samples_per_bin) + " shadow rays per bin, " +
         (samples_per_bin > MaxDirectSamplesPerBin
              ? "the project's own count (above the rounds' limit of " + std::to_string(MaxDirectSamplesPerBin) + ")"
              : std::string("the rounds' limit"));
}

std::string round_number(double x, const char* format) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, x);
  return buffer;
}

std::string round_outcome_sentence(const std::string& measure, double reached_percent, double target_percent,
                                   const std::string& detail, const std::string& stop_reason, std::size_t rounds,
                                   std::uint64_t photons) {
  return measure + " (" + round_number(AccuracyPercentile, "%.0f") + "th percentile of the sensors) " +
         round_number(reached_percent) + " % " + (reached_percent <= target_percent ? "<=" : ">") + " target " +
         round_number(target_percent) + " %" + detail + ": " + stop_reason + " after " + std::to_string(rounds) +
         " round(s), " + round_number(double(photons), "%.0f") + " photons";
}

engine::TracedPhotons round_photons(const std::vector<engine::SourcePhotonRecord>& records, bool relabel) {
  return engine::scaled_merged_photons(records, relabel);
}

RoundLoopOutcome run_round_loop(const RoundSources& sources, const AccuracyGoal& goal, const RoundMeasure& measure,
                                const RoundLoopText& text, const std::function<void(const std::string&)>& log,
                                RoundWork& work, Clock::time_point start, const RoundLoopFinish& finish,
                                const RoundDirect& direct) {
  const std::size_t n = sources.reference.size();
  double trace_seconds = 0;
  std::uint64_t traced_attempts = 0;
  // Extends every source p with next[p] > its attempts to next[p] (one call of the work: the
  // sources' attempt ranges over the processes); false if none grows.
  auto extend_to = [&](std::vector<engine::SourcePhotonRecord>& records, const std::vector<std::uint64_t>& next) {
    std::vector<RoundWork::AttemptRequest> requests;
    for (std::size_t p = 0; p < n; ++p)
      if (next[p] > records[p].attempts)
        requests.push_back({p, records[p].attempts, next[p], cost_per_attempt(records[p])});
    if (requests.empty()) return false;
    std::vector<engine::AttemptRange> ranges = work.trace(requests, sources.trace);
    for (std::size_t i = 0; i < requests.size(); ++i)
      engine::append_round_range(records[requests[i].source], requests[i].last, std::move(ranges[i]));
    return true;
  };

  // Round 1, the pilot.
  std::vector<engine::SourcePhotonRecord> records(n);
  {
    const Clock::time_point t = Clock::now();
    std::vector<std::size_t> target(n);
    for (std::size_t p = 0; p < n; ++p) {
      target[p] = static_cast<std::size_t>(std::max(1.0, std::round(sources.reference[p] * AccuracyPilotFraction)));
      records[p] = sources.empty_record(p);
    }
    // engine::pilot_source_photons of every source, one doubling of each at a time: each
    // decided from the record's counts, summed over however many ranges traced it.
    std::vector<std::uint64_t> next(n);
    do {
      for (std::size_t p = 0; p < n; ++p)
        next[p] = engine::next_pilot_attempts(records[p], target[p], sources.max_prepass_attempts_per_target)
                      .value_or(records[p].attempts);
    } while (extend_to(records, next));
    trace_seconds += seconds_since(t);
    for (const auto& r : records) traced_attempts += r.attempts;
  }
  RoundLoopOutcome outcome;
  for (const auto& r : records) outcome.pilot_attempts.push_back(r.attempts);
  // Photons at the reference per attempt, from the pilot (fixed from now on, so a source's
  // scale is proportional to its attempts).
  std::vector<double> per_attempt(n, 0.0);
  for (std::size_t p = 0; p < n; ++p) {
    const engine::SourceTally& t = records[p].raw.tallies.at(0);
    const double stored = double(t.stored_global + t.stored_caustic);
    if (records[p].attempts > 0 && stored > 0)
      per_attempt[p] = stored / double(records[p].attempts) / sources.reference[p];
  }

  std::string pending;    // a budget that cut the last round short
  bool finished = false;  // `finish` ran on the records as they are
  for (std::size_t round = 1;; ++round) {
    const Clock::time_point estimate_start = Clock::now();
    std::vector<double> scale(n, 1.0);
    for (std::size_t p = 0; p < n; ++p)
      if (per_attempt[p] > 0) scale[p] = double(records[p].attempts) * per_attempt[p];
    const RoundMeasurement m = measure(round, records, scale);
    const double estimate_seconds = seconds_since(estimate_start);
    std::uint64_t stored = 0, attempts = 0;
    std::vector<double> cost(n, 0.0);
    for (std::size_t p = 0; p < n; ++p) {
      stored += records[p].stored();
      attempts += records[p].attempts;
      cost[p] = double(records[p].raw.tallies.at(0).rays);
    }
    outcome.rounds = round;
    outcome.photons = stored;
    outcome.attempts = attempts;
    log(text.name + " round " + std::to_string(round) + (round == 1 ? " (pilot)" : "") + ": " +
        round_number(double(stored), "%.0f") + " photons, " + round_number(double(attempts), "%.0f") + " attempts; " +
        text.measure + " (" + round_number(AccuracyPercentile, "%.0f") + "th percentile)" + m.grids + " (target " +
        round_number(goal.target_percent) + " %)");
    // The chased grids' stop, if they stop; else the plan of their next round, with the direct
    // part's own decision (RoundDirect): a raise of shadow rays and its photon plan, if it fits
    // the time budget.
    std::string stop;
    std::vector<std::uint64_t> next(n);
    double more_photons = 0, more_attempts = 0;
    // next[p] from the factors of each source's photons (`scale`), and what they add.
    auto plan_next = [&](const std::vector<double>& factor) {
      more_photons = more_attempts = 0;
      for (std::size_t p = 0; p < n; ++p) {
        const double s = p < factor.size() ? factor[p] : 1.0;
        next[p] = s > 1.0 ? static_cast<std::uint64_t>(std::ceil(double(records[p].attempts) * s)) : records[p].attempts;
        more_attempts += double(next[p] - records[p].attempts);
        more_photons += double(records[p].stored()) * (std::max(s, 1.0) - 1.0);
      }
    };
    DirectRoundPlan direct_plan;
    double direct_seconds = 0;
    bool direct_timed_out = false;  // a raise the time budget left no room for
    if (m.met) {
      stop = met_stop_reason(m.grid_status);
    } else if (!pending.empty() && (pending != "photon budget" || !direct.plan || round >= MaxAccuracyRounds)) {
      // A photon budget spent leaves the shadow rays their rounds (below); any other cut ends them.
      stop = pending;
    } else if (round >= MaxAccuracyRounds) {
      stop = "round limit";
    } else {
      RoundPlan plan =
          next_round_scale(m.chased, cost, AccuracyRoundAim * goal.target_percent, AccuracyPercentile, goal.max_growth);
      if (direct.plan) {
        direct_plan = direct.plan(cost, plan, AccuracyRoundAim * goal.target_percent);
        if (direct_plan.raised() && goal.max_seconds > 0) {
          direct_seconds = direct.seconds(direct_plan);
          const double room = goal.max_seconds - work.agreed(seconds_since(start) + estimate_seconds);
          if (room < direct_seconds) {
            log(text.name + ": no raise of shadow rays in round " + std::to_string(round + 1) +
                ": the time budget leaves no room for it");
            direct_plan.rays = 0;
            direct_seconds = 0;
            direct_timed_out = true;
          }
        }
        if (direct_plan.raised()) plan = direct_plan.photons;
      }
      plan_next(plan.scale);
      if (!pending.empty() && !direct_plan.raised()) {
        stop = pending;  // the photon budget is spent and no raise of shadow rays is planned
      } else if (!(more_attempts > 0) && !direct_plan.raised()) {
        if (direct_timed_out) {
          stop = "time budget";
        } else if (direct_plan.sensors_at_limit > 0) {
          stop = "direct rays limit";
          log(text.name + ": " + std::to_string(direct_plan.sensors_at_limit) +
              " sensor(s) miss the target by their direct component alone at " +
              direct_rays_limit_words(direct_plan.samples_at_limit));
        } else {
          stop = plan.sensors_direct_limited > 0 ? "direct component"
                 : plan.sensors_left_out > 0     ? "other parts"
                                                 : "no light";
          if (plan.sensors_direct_limited > 0)
            log(text.name + ": " + std::to_string(plan.sensors_direct_limited) +
                " sensor(s) miss the target by their direct component alone, which photons do not reduce "
                "(more simulation.direct_samples_per_bin would)");
          else if (plan.sensors_left_out > 0)
            log(text.name + ": " + std::to_string(plan.sensors_left_out) +
                " sensor(s) miss the target by the parts of their error these photons do not reduce");
        }
      }
    }
    bool for_finish = false;  // this round's plan is what `finish` asked for (no raise of shadow rays)
    if (!stop.empty()) {
      outcome.stop_reason = stop;
      if (!finish) break;
      const std::vector<double> asked = finish.finish(outcome, records);
      finished = true;
      plan_next(asked);
      if (!(more_attempts > 0)) break;
      // The chased grids stopped on a budget (a raise of their shadow rays the time budget had no
      // room for), not on their own: the gathered grids' round is refused for the same reason.
      const std::string refuse = !pending.empty()            ? pending
                                 : direct_timed_out          ? "time budget"
                                 : round >= MaxAccuracyRounds ? "round limit"
                                                              : "";
      if (!refuse.empty()) {
        log(text.name + ": no round " + std::to_string(round + 1) + " for the gathered grids' photon part: the " +
            refuse);
        finish.refused(outcome, refuse);
        break;
      }
      for_finish = true;
      finished = false;
    }
    // Budgets: the share of the planned increments that fits.
    double share = 1.0;
    std::string cut;
    if (goal.max_photons > 0) {
      const double room = double(goal.max_photons) - double(stored);
      if (room < more_photons) {
        share = std::max(0.0, room / more_photons);
        cut = "photon budget";
      }
    }
    if (goal.max_seconds > 0 && more_attempts > 0) {
      // The first process's clock, so that every process cuts the round alike (round_work.h).
      const double per_attempt_s = traced_attempts > 0 ? work.agreed(trace_seconds) / double(traced_attempts) : 0.0;
      const double room = goal.max_seconds - work.agreed(seconds_since(start) + estimate_seconds) - direct_seconds;
      const double need = per_attempt_s * more_attempts;
      if (room < need && (need > 0 ? std::max(0.0, room / need) : 0.0) < share) {
        share = need > 0 ? std::max(0.0, room / need) : 0.0;
        cut = "time budget";
      }
    }
    if (share < 1.0) {
      for (std::size_t p = 0; p < n; ++p)
        next[p] = records[p].attempts +
                  static_cast<std::uint64_t>(std::floor(share * double(next[p] - records[p].attempts)));
      if (share < 0.05 && direct_plan.raised()) {
        // The raise fits (its time was taken off the room above): the round raises the shadow
        // rays alone, and is the last.
        for (std::size_t p = 0; p < n; ++p) next[p] = records[p].attempts;
        pending = cut;
        log(text.name + ": round " + std::to_string(round + 1) + " raises the shadow rays only: the " + cut +
            " leaves no room for photons" + (cut == "photon budget" ? "" : "; the last round"));
      } else if (share < 0.05) {
        log(text.name + ": no round " + std::to_string(round + 1) + ": the " + cut + " leaves room for " +
            round_number(100.0 * share) + " % of it");
        if (for_finish) {
          finish.refused(outcome, cut);
          finished = true;
        } else {
          outcome.stop_reason = cut;
        }
        break;
      } else {
        pending = cut;
        log(text.name + ": round " + std::to_string(round + 1) + " cut to " + round_number(100.0 * share) +
            " % of its plan by the " + cut + "; the last round");
      }
    }
    if (for_finish)
      log(text.name + ": round " + std::to_string(round + 1) +
          " traces more photons for the gathered grids' photon part (which more gather rays do not reduce)");
    for (std::size_t p = 0; p < n; ++p) traced_attempts += next[p] - records[p].attempts;
    const Clock::time_point t = Clock::now();
    extend_to(records, next);
    trace_seconds += seconds_since(t);
    if (direct_plan.raised()) direct.apply(round + 1, direct_plan);
  }
  for (const auto& r : records) outcome.final_attempts.push_back(r.attempts);
  if (finish && !finished) {
    // The chased grids stopped on a budget: the others take their turn, and what they ask for
    // is refused for the same reason.
    const std::string reason = outcome.stop_reason;
    const std::vector<double> asked = finish.finish(outcome, records);
    bool more = false;
    for (std::size_t p = 0; p < n && p < asked.size(); ++p) more = more || asked[p] > 1.0;
    if (more) finish.refused(outcome, reason);
  }
  log(text.name + ": " + outcome.stop_reason + " after " + std::to_string(outcome.rounds) + " round(s)");
  return outcome;
}

}  // namespace dayphoton::study
