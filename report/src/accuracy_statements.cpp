// The accuracy statements of report.html (report_sections.h): per case and grid, in plain words,
// what the accuracy target's rounds reached for the sky patches (the daylight factor) and for
// the sun bins (the annual sun-bin illuminance): the target and the measure it applies to, the
// value reached, the rounds and photons, why the rounds stopped and, when the grid is above
// the target, why and what to change (docs/photon-tracing.md, "Accuracy target"). From the
// results model's typed values alone.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "dayphoton/report/report_format.h"
#include "dayphoton/study/accuracy_rounds.h"
#include "dayphoton/study/gather_accuracy_rounds.h"
#include "dayphoton/study/plan_policy.h"
#include "report_sections.h"

namespace dayphoton::report {

namespace {

/// "4.4 million", "950 000" (whole photons below a million).
std::string photon_count(std::uint64_t n) {
  char buf[64];
  if (n >= 1000000) {
    std::snprintf(buf, sizeof buf, "%.1f million", double(n) / 1e6);
    return buf;
  }
  std::string digits = std::to_string(n), out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ' ';
    out += digits[i];
  }
  return out;
}

/// "95th percentile of the sensors (19 sensors in 20 at or below it)".
std::string measure_words() {
  const double p = study::AccuracyPercentile;
  const long in = std::lround(100.0 / (100.0 - p));
  return std::to_string(std::lround(p)) + "th percentile of the sensors (" + std::to_string(in - 1) +
         " sensors in " + std::to_string(in) + " are at or below it)";
}

/// What a grid's accuracy rounds reached, the parts the sky and the sun share.
struct Reached {
  double target_percent = 0, reached_percent = 0;
  std::size_t rounds = 0;
  std::uint64_t photons = 0;
  std::string stop_reason, status;
  int gather_rays = 0;  ///< > 0: a grid estimated by final gather (its own rounds and stop below)
  std::size_t gather_rounds = 0;
  std::string gather_stop_reason{};
  int direct_samples_per_bin = 0;  ///< the sky's shadow rays per patch at the end; 0 for the sun (none)
  /// A plane's sensors next to a cut, out of the measure (study::NearCutReached); 0: none.
  std::size_t near_cut_sensors = 0;
  int near_cut_gather_rays = 0;
  double near_cut_largest_percent = 0;
  std::size_t near_cut_gather_rounds = 0;
  std::string near_cut_stop_reason{};
};

/// What the sensors next to a column or partition reached, which the measure leaves out
/// (docs/photon-tracing.md "Accuracy target"): "" without any.
std::string near_cut_sentence(const Reached& r) {
  if (r.near_cut_sensors == 0) return "";
  std::ostringstream s;
  const bool above = r.near_cut_largest_percent > r.target_percent;
  s << " The " << r.near_cut_sensors << (r.near_cut_sensors == 1 ? " sensor" : " sensors")
    << " next to a column or partition, estimated by final gather at " << r.near_cut_gather_rays
    << " rays per sensor";
  if (r.near_cut_gather_rounds > 0)
    s << " after " << r.near_cut_gather_rounds << (r.near_cut_gather_rounds == 1 ? " gather round" : " gather rounds");
  s << " and left out of this measure, reach up to "
    << format_value(r.near_cut_largest_percent, Precision::DaylightFactor) << " %";
  if (above)
    s << ": <strong>above the target</strong> (their gather rounds stopped with \"" << esc(r.near_cut_stop_reason)
      << "\"; more <code>simulation.gather_rays</code> or photons lower it).";
  else
    s << ", within the target.";
  return s.str();
}

/// The shadow rays at their limit, with the count the grid ended at (`samples_per_bin`, from
/// results.json): `who` raises them up to MaxDirectSamplesPerBin per sky patch and keeps a
/// project's own larger direct_samples_per_bin unchanged, so the advice is a count above both.
std::string direct_rays_at_limit(const std::string& who, int samples_per_bin) {
  const std::string limit = std::to_string(study::MaxDirectSamplesPerBin);
  const std::string above = std::to_string(std::max(samples_per_bin, study::MaxDirectSamplesPerBin));
  return "those rays were at their limit, " + std::to_string(samples_per_bin) +
         " per sky patch for this grid: " + who + " raise them up to " + limit +
         " per sky patch, and keep the project's own <code>simulation.direct_samples_per_bin</code> where it is "
         "higher. What to do: set <code>simulation.direct_samples_per_bin</code> above " + above +
         ", or ask for a looser target.";
}

/// Why a grid estimated by final gather is above the target and what to change, from its own
/// gather rounds' stop (study/gather_accuracy.h).
std::string gather_why_and_what_to_do(const Reached& r) {
  const std::string gathered = "Why: this grid's sensors are estimated by final gather (rays traced from each sensor)";
  if (r.gather_stop_reason == "gather ray limit")
    return gathered + ", and the gather rounds reached their limit of " + std::to_string(study::GatherMaxRays) +
           " rays per sensor. What to do: ask for a looser target, or place these sensors where the photons "
           "reach them (a work plane rather than points in the air or on a wall).";
  if (r.gather_stop_reason == "gather photon part")
    return gathered + ", and what remains of their error comes from the photons the gather rays read, which "
           "more gather rays do not reduce. What to do: give fixed photon counts "
           "(<code>simulation.photons_per_bin</code>, instead of the accuracy target) above the photons the "
           "rounds traced, or ask for a looser target.";
  if (r.gather_stop_reason == "photon budget")
    return gathered + ", and what remains of their error comes from the photons the gather rays read, which "
           "more gather rays do not reduce; more photons would, but the photon budget left no room for them. "
           "What to do: raise "
           "<code>simulation.accuracy.max_photons</code> (by default <code>limits.photons</code>), or ask for a "
           "looser target.";
  if (r.gather_stop_reason == "photon round limit")
    return gathered + ", and what remains of their error comes from the photons the gather rays read, which "
           "more gather rays do not reduce; more photons would, but the photon rounds had reached their limit "
           "of " +
           std::to_string(study::MaxAccuracyRounds) +
           " rounds. What to do: give fixed photon counts (<code>simulation.photons_per_bin</code>, instead of "
           "the accuracy target) above the photons the rounds traced, or ask for a looser target.";
  if (r.gather_stop_reason == "round limit")
    return gathered + ", and the gather rounds' limit (" + std::to_string(study::GatherMaxRounds) +
           " rounds) came first. What to do: start from more rays (<code>simulation.gather_rays</code>), or ask "
           "for a looser target.";
  if (r.gather_stop_reason == "time budget")
    return gathered + ", and the time budget (<code>simulation.accuracy.max_seconds</code>) ran out. What to "
           "do: raise it or remove it; this stop depends on the machine's speed.";
  if (r.gather_stop_reason == "direct component")
    return gathered + "; the sensors still above the target are so by the noise of their direct light (the "
           "shadow rays toward the sky through the openings), which more gather rays do not reduce. What to do: "
           "raise <code>simulation.direct_samples_per_bin</code>.";
  if (r.gather_stop_reason == "direct rays limit")
    return gathered + "; the sensors still above the target are so by the noise of their direct light (the "
           "shadow rays toward the sky through the openings), and " +
           direct_rays_at_limit("the gather rounds", r.direct_samples_per_bin);
  return gathered + "; the gather rounds stopped with \"" + esc(r.gather_stop_reason) + "\".";
}

/// Why the grid is above the target and what to change, from the grid's status and the
/// case's stop reason ("" when the grid met the target).
std::string why_and_what_to_do(const Reached& r) {
  if (r.status == "not reachable by photons")
    return "Why: this grid's sensors are estimated by final gather (rays traced from each sensor), and part "
           "of their error comes from those rays, which more photons do not reduce; the rounds do not chase "
           "it. What to do: raise <code>simulation.gather_rays</code>.";
  if (r.stop_reason == "photon budget")
    return "Why: the photon budget was reached first. What to do: raise "
           "<code>simulation.accuracy.max_photons</code> (by default <code>limits.photons</code>), or accept "
           "the value reached.";
  if (r.stop_reason == "time budget")
    return "Why: the time budget (<code>simulation.accuracy.max_seconds</code>) ran out. What to do: raise it "
           "or remove it; this stop depends on the machine's speed.";
  if (r.stop_reason == "round limit")
    return "Why: the round limit (" + std::to_string(study::MaxAccuracyRounds) +
           " rounds) came first: the error fell more slowly than the photons grew. What to do: ask for a looser "
           "target, or use the per-source estimator (<code>simulation.estimator</code>) if the contribution "
           "estimator is set.";
  if (r.stop_reason == "direct component")
    return "Why: the sensors still above the target are so by the noise of their direct light (the shadow rays "
           "toward the sky through the openings), which more photons do not reduce. What to do: raise "
           "<code>simulation.direct_samples_per_bin</code>.";
  if (r.stop_reason == "direct rays limit")
    return "Why: the sensors still above the target are so by the noise of their direct light (the shadow rays "
           "toward the sky through the openings), and " +
           direct_rays_at_limit("the rounds", r.direct_samples_per_bin);
  if (r.stop_reason == "no light") return "Why: no light reaches the grid's sensors, so there is nothing to measure.";
  return "Why: the rounds stopped with \"" + esc(r.stop_reason) + "\".";
}

/// One statement: "<what>: target ...; reached ... after N rounds (M photons). <verdict>".
std::string statement(const std::string& what, const Reached& r) {
  const bool met = r.status.empty() ? r.reached_percent <= r.target_percent : r.status == "met";
  std::ostringstream s;
  s << what << ": the target is a relative standard error of at most "
    << format_value(r.target_percent, Precision::DaylightFactor) << " % at the " << measure_words() << ". Reached "
    << format_value(r.reached_percent, Precision::DaylightFactor) << " % ";
  if (r.gather_rays > 0)
    s << "by final gather at " << r.gather_rays << " rays per sensor, after " << r.gather_rounds
      << (r.gather_rounds == 1 ? " gather round" : " gather rounds") << " following " << r.rounds
      << (r.rounds == 1 ? " round" : " rounds") << " of photon tracing (" << photon_count(r.photons) << " photons). ";
  else
    s << "after " << r.rounds << (r.rounds == 1 ? " round" : " rounds") << " of photon tracing ("
      << photon_count(r.photons) << " photons). ";
  if (met) {
    s << (r.near_cut_sensors > 0 && r.near_cut_largest_percent > r.target_percent
              ? "Target met by the sensors it measures."
              : "Target met.");
    if (r.gather_rays == 0 && r.stop_reason != "target met")
      s << " (The rounds serve every grid of the case; they stopped with \"" << esc(r.stop_reason)
        << "\" for another grid.)";
  } else {
    s << "<strong>Above the target"
      << (r.status == "not reachable by photons" ? " and not reachable by photons" : "") << ".</strong> "
      << (r.gather_rays > 0 ? gather_why_and_what_to_do(r) : why_and_what_to_do(r));
  }
  s << near_cut_sentence(r);
  return s.str();
}

}  // namespace

std::string sky_accuracy_statement(const study::DaylightFactorSummary::AccuracyReached& a) {
  return statement("Daylight factor (sky patches)",
                   Reached{a.target_percent, a.reached_percent, a.rounds, a.photons, a.stop_reason, a.status,
                           a.gather_rays, a.gather_rounds, a.gather_stop_reason, a.direct_samples_per_bin,
                           a.near_cut_sensors, a.near_cut_gather_rays, a.near_cut_largest_percent,
                           a.near_cut_gather_rounds, a.near_cut_stop_reason});
}

std::string sun_accuracy_statement(const study::SunAccuracyReached& a) {
  return statement("Annual sun-bin illuminance (the indirect sunlight of every sun hour, summed over the year)",
                   Reached{a.target_percent, a.reached_percent, a.rounds, a.photons, a.stop_reason, a.status,
                           a.gather_rays, a.gather_rounds, a.gather_stop_reason, 0, a.near_cut_sensors,
                           a.near_cut_gather_rays, a.near_cut_largest_percent, a.near_cut_gather_rounds,
                           a.near_cut_stop_reason}) +
         " One hour's sun-bin value carries more: " + format_value(a.hourly_percent, Precision::DaylightFactor) +
         " % at the same percentile (reported, not targeted; the annual metrics count hours over thresholds).";
}

std::string accuracy_statements(const study::ResultsModel& m) {
  std::ostringstream s;
  for (const study::CaseResult& c : m.cases)
    for (const study::GridResult& g : c.grids) {
      const std::string attrs = " data-case=\"" + esc(case_label(c)) + "\" data-grid=\"" + esc(g.name) + "\"";
      const std::string who = m.cases.size() > 1 ? esc(case_label(c)) + ", " + esc(g.name) : esc(g.name);
      if (g.daylight_factor && g.daylight_factor->accuracy)
        s << "<li class=\"accuracy\" data-part=\"sky\"" << attrs << "><strong>" << who << "</strong>. "
          << sky_accuracy_statement(*g.daylight_factor->accuracy) << "</li>";
      if (g.sun_accuracy)
        s << "<li class=\"accuracy\" data-part=\"sun\"" << attrs << "><strong>" << who << "</strong>. "
          << sun_accuracy_statement(*g.sun_accuracy) << "</li>";
    }
  const std::string items = s.str();
  if (items.empty()) return "";
  return "<h3 id=\"accuracy\">Accuracy the run reached</h3><p>The project asked for an accuracy instead of photon "
         "counts: photons were traced in rounds until each grid's error reached the target, or until a limit "
         "stopped them.</p><ul class=\"accuracy-statements\">" +
         items + "</ul>";
}

}  // namespace dayphoton::report
