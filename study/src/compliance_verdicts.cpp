// Compliance verdicts; see compliance_verdicts.h for the criteria and their sources.
#include "dayphoton/study/compliance_verdicts.h"

#include <cmath>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/metrics/annual_metrics.h"

namespace dayphoton::study {

namespace {

const char* const Lm83 = "IES LM-83-12";
const char* const Leed = "LEED v4.1 EQ Daylight, option 1";
const char* const En17037 = "EN 17037 daylight provision";
const char* const Breeam = "BREEAM UK NC 2014 Hea 01";

Verdict assessed(const char* standard, const std::string& criterion, const std::string& requirement, double value,
                 const std::string& unit, bool passes, const std::string& note = {}) {
  return {standard, criterion, requirement, value, unit, passes ? "pass" : "fail", note};
}
Verdict not_assessed(const char* standard, const std::string& criterion, const std::string& requirement,
                     const std::string& why) {
  return {standard, criterion, requirement, std::nullopt, "", "not assessed", why};
}

std::string n(double v) { return format_number(v); }

}  // namespace

bool lm83_analysis_period(const AnnualSummary& a, std::string& why) {
  const OccupancySummary& o = a.occupancy;
  const std::pair<double, double> window{Lm83AnalysisStart_h, Lm83AnalysisEnd_h};
  bool every_day = false;
  if (o.kind == "daily") {
    every_day = o.start_h == Lm83AnalysisStart_h && o.end_h == Lm83AnalysisEnd_h;
  } else if (o.kind == "weekly") {
    every_day = o.holidays.empty();
    for (const OccupancySummary::Windows& day : o.week) every_day = every_day && day == OccupancySummary::Windows{window};
  }
  if (!every_day) {
    why = "the run's occupancy (" + o.description + ") is not LM-83's analysis period, 08:00-18:00 every day";
    return false;
  }
  if (a.time_steps < 8760) {
    why = "the weather file holds " + std::to_string(a.time_steps) + " hourly records, not LM-83's year";
    return false;
  }
  return true;
}

int leed_v41_points(double sda_percent) {
  int points = 0;
  for (double threshold : LeedSdaPointsPercent) points += sda_percent >= threshold;
  return points;
}

namespace {
/// Why LM-83's sDA and ASE are not assessed on a case with operable shading in place (`blinds`
/// systems, shading materials: shading_materials.h); "" when none is.
std::string shading_in_place_why(const std::vector<std::string>& blinds,
                                 const std::vector<ShadingMaterialInPlace>& materials, bool operated) {
  std::vector<std::string> parts;
  if (!blinds.empty()) {
    std::string names;
    for (std::size_t i = 0; i < blinds.size(); ++i)
      names += (i == 0 ? "" : i + 1 == blinds.size() ? " and " : ", ") + ("'" + blinds[i] + "'");
    parts.push_back("the blinds " + names);
  }
  for (const ShadingMaterialInPlace& m : materials)
    parts.push_back("the operable shading material '" + m.material + "' (" + m.why + ")");
  if (parts.empty()) return {};
  std::string list;
  for (std::size_t i = 0; i < parts.size(); ++i)
    list += (i == 0 ? "" : i + 1 == parts.size() ? " and " : ", ") + parts[i];
  if (operated)
    return "the open case has " + list + " in place: LM-83 takes ASE and the 2 % rule's direct sun with every "
           "operable shading device retracted (section 2.2.6); make the open case one without them";
  const bool one = blinds.empty() && materials.size() == 1;  // "the blinds ... are"
  return list + (one ? " is" : " are") + " in place every hour: LM-83 takes ASE with every operable shading device "
         "retracted and sDA with the blinds operated hour by hour (section 2.2.6); give the project an `operation` "
         "whose open case has none of them and read the operated result";
}
}  // namespace

std::vector<Verdict> grid_verdicts(const GridResult& g, const std::vector<std::string>& blinds_in_place, bool operated,
                                   const std::vector<ShadingMaterialInPlace>& shading_materials) {
  const std::string sda = "sDA" + n(Lm83DaThresholdLux) + "/" + n(100 * Lm83SdaTimeFraction) + "%";
  const std::string ase = "ASE" + n(Lm83AseThresholdLux) + "," + n(Lm83AseHours);
  const std::string sda_req = ">= " + n(Lm83SdaAcceptedPercent) + " % of the area (nominally accepted), >= " +
                              n(Lm83SdaPreferredPercent) + " % preferred";
  const std::string ase_req = "<= " + n(Lm83AseMaxPercent) + " % of the area";
  const std::string leed_req = ">= " + n(LeedSdaPointsPercent[0]) + " % (1 point), >= " + n(LeedSdaPointsPercent[1]) +
                               " % (2), >= " + n(LeedSdaPointsPercent[2]) + " % (3)";
  const std::string breeam_crit = "average DF, uniformity or minimum point DF";
  const std::string breeam_req = "average DF >= " + n(BreeamAverageDfPercent) + " % and (uniformity >= " +
                                 n(BreeamUniformity) + " or minimum DF >= " + n(BreeamMinimumPointDfPercent) + " %)";
  std::vector<Verdict> out;
  if (g.orientation != GridOrientation::Horizontal) {
    const std::string why = "the grid is " + orientation_name(g.orientation) +
                            ": these criteria are defined on horizontal work planes";
    out.push_back(not_assessed(Lm83, sda, sda_req, why));
    out.push_back(not_assessed(Lm83, ase, ase_req, why));
    out.push_back(not_assessed(Leed, sda, leed_req, why));
    out.push_back(not_assessed(En17037, "level", "minimum, medium or high", why));
    out.push_back(not_assessed(Breeam, breeam_crit, breeam_req, why));
    return out;
  }
  if (const auto& a = g.annual) {
    const bool lm83_sda = a->da_threshold_lux == Lm83DaThresholdLux && a->sda_time_fraction == Lm83SdaTimeFraction;
    const std::string run_sda = "sDA" + n(a->da_threshold_lux) + "/" + n(100 * a->sda_time_fraction) + "%";
    std::string period_why;
    const bool lm83_period = lm83_analysis_period(*a, period_why);
    const std::string shading_why = shading_in_place_why(blinds_in_place, shading_materials, operated);
    if (!lm83_period) {
      out.push_back(not_assessed(Lm83, sda, sda_req, period_why));
      out.push_back(not_assessed(Leed, sda, leed_req, period_why));
    } else if (!shading_why.empty()) {
      out.push_back(not_assessed(Lm83, sda, sda_req, shading_why));
      out.push_back(not_assessed(Leed, sda, leed_req, shading_why));
    } else if (lm83_sda) {
      out.push_back(assessed(Lm83, sda, sda_req, a->sda_percent, "%", a->sda_percent >= Lm83SdaAcceptedPercent,
                             a->sda_percent >= Lm83SdaPreferredPercent ? "preferred level reached" : ""));
      const int points = leed_v41_points(a->sda_percent);
      out.push_back(assessed(Leed, sda, leed_req, a->sda_percent, "%", points > 0,
                             std::to_string(points) + (points == 1 ? " point" : " points")));
    } else {
      const std::string why = "the run computed " + run_sda + ", not " + sda;
      out.push_back(not_assessed(Lm83, sda, sda_req, why));
      out.push_back(not_assessed(Leed, sda, leed_req, why));
    }
    const bool lm83_ase = a->ase_threshold_lux == Lm83AseThresholdLux && a->ase_hours == Lm83AseHours;
    if (!a->ase_percent)
      out.push_back(not_assessed(Lm83, ase, ase_req,
                                 "ASE not computed: the run spread the sun into sky patches (simulation.sun: spread)"));
    else if (!lm83_period)
      out.push_back(not_assessed(Lm83, ase, ase_req, period_why));
    else if (!shading_why.empty())
      out.push_back(not_assessed(Lm83, ase, ase_req, shading_why));
    else if (!lm83_ase)
      out.push_back(not_assessed(Lm83, ase, ase_req,
                                 "the run computed ASE" + n(a->ase_threshold_lux) + "," + n(a->ase_hours) + ", not " + ase));
    else
      out.push_back(assessed(Lm83, ase, ase_req, *a->ase_percent, "%", *a->ase_percent <= Lm83AseMaxPercent,
                             *a->ase_percent > Lm83AseMaxPercent ? "LEED v4.1: describe how the design addresses glare"
                                                                 : ""));
    if (a->en17037.empty()) {
      out.push_back(not_assessed(En17037, "level", "minimum, medium or high",
                                 "the weather file has no diffuse horizontal illuminance to rank the daylight hours"));
    } else {
      const std::string level = a->en17037_level();
      int passed = 0;
      for (const En17037Level& l : a->en17037) passed += l.passes;
      // The rule: the target over 50 % of the area, or over 95 % under horizontal openings.
      const bool horizontal =
          a->en17037_openings == metrics::en17037_openings_name(metrics::MetricSettings::Openings::Horizontal);
      const std::string rule = horizontal ? " (horizontal openings: the target over 95 % of the area)" : "";
      out.push_back(assessed(En17037, "level", "minimum, medium or high", passed, "level", passed > 0,
                             (level == "none" ? "no level reached" : level + " level reached") + rule));
    }
  } else {
    const char* why = "no annual results for this grid";
    out.push_back(not_assessed(Lm83, sda, sda_req, why));
    out.push_back(not_assessed(Lm83, ase, ase_req, why));
    out.push_back(not_assessed(Leed, sda, leed_req, why));
    out.push_back(not_assessed(En17037, "level", "minimum, medium or high", why));
  }
  if (const auto& df = g.daylight_factor) {
    const bool average = df->mean_percent >= BreeamAverageDfPercent;
    const bool uniform = df->uniformity >= BreeamUniformity || df->min_percent >= BreeamMinimumPointDfPercent;
    out.push_back(assessed(Breeam, breeam_crit, breeam_req, df->mean_percent, "%", average && uniform,
                           "uniformity " + format_number(std::round(100 * df->uniformity) / 100) + ", minimum DF " +
                               format_number(std::round(100 * df->min_percent) / 100) + " %"));
  } else {
    out.push_back(not_assessed(Breeam, breeam_crit, breeam_req, "no daylight factors for this grid"));
  }
  return out;
}

void assess_compliance(ResultsModel& model) {
  bool annual = false, ase_missing = false, en_missing = false;
  for (CaseResult& c : model.cases)
    for (GridResult& g : c.grids) {
      g.verdicts = grid_verdicts(g, c.blinds_in_place, c.kind == "operated", c.shading_materials_in_place);
      if (g.annual) {
        annual = true;
        ase_missing = ase_missing || !g.annual->ase_percent;
        en_missing = en_missing || g.annual->en17037.empty();
      }
    }
  std::vector<std::string>& s = model.not_assessed;
  s.clear();
  bool sunlight = false;
  for (const CaseResult& c : model.cases) sunlight = sunlight || !c.sunlight_exposure.empty();
  s.push_back(sunlight ? "EN 17037 view out and protection from glare: not computed by dayphoton."
                       : "EN 17037 view out, exposure to sunlight and protection from glare: not computed by dayphoton.");
  s.push_back("Glare (daylight glare probability or any other glare index): not computed.");
  s.push_back("BREEAM Hea 01 criteria (b) view of sky and (c) room depth, glare control and view out: not assessed; "
              "its daylighting credits also depend on the share of all relevant building areas that comply, which "
              "one study's grids do not establish.");
  s.push_back("LM-83 and LEED: whether the grids cover the regularly occupied floor area, and the operable "
              "shading LM-83 requires in the sDA calculation (section 2.2.6), are for the design team to confirm.");
  if (!annual)
    s.push_back("Annual metrics (sDA, ASE, UDI, EN 17037 daylight provision): not computed, this is a "
                "daylight-factor study.");
  if (ase_missing) s.push_back("ASE: not computed for every grid (the run spread the sun into sky patches).");
  if (en_missing)
    s.push_back("EN 17037 daylight provision: not computed for every grid (the weather file has no diffuse "
                "horizontal illuminance).");
}

}  // namespace dayphoton::study
