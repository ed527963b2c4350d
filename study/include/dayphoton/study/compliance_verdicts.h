// Compliance verdicts of a run's grids against published daylighting criteria, decided once
// from the results model's typed summaries (results_model.h) and stored in it
// (GridResult::verdicts, ResultsModel::not_assessed), so that the report only shows them.
//
// Criteria (each threshold a constant below, declared once):
//  - IES LM-83-12, "Approved Method: IES Spatial Daylight Autonomy (sDA) and Annual Sunlight
//    Exposure (ASE)", sections 2.1.1 and 2.2.1: sDA300/50% >= 55 % of the area "nominally
//    accepted", >= 75 % "preferred"; ASE1000,250 <= 10 % (above 10 %: unsatisfactory visual
//    comfort). Assessed only when the run's settings are LM-83's (300 lx, 50 %, 1000 lx, 250 h)
//    and its analysis period (section 2.1.2: 8 am to 6 pm local clock time, every day of a
//    year: a daily 08:00-18:00 window, or a weekly one with that window every day and no
//    holidays, with or without daylight saving time, over a whole year of records). A school
//    week or a part of a year gives an sDA and an ASE of their own hours, not LM-83's, nor
//    LEED's, which takes LM-83's.
//  - USGBC LEED v4.1 BD+C, EQ credit Daylight, option 1 (table 1): sDA300/50% >= 40 % (1 point),
//    >= 55 % (2), >= 75 % (3); ASE1000,250 above 10 % needs the glare design described.
//  - EN 17037:2018 (CEN, "Daylight in buildings"), clause 5.1 and annex A table A.1, daylight
//    provision by the climate-based method: per level the target illuminance on >= 50 % and
//    the minimum target on >= 95 % of the reference plane for >= 50 % of the daylight hours
//    (metrics/en17037.h computes them; this only carries the outcome).
//  - BRE Global, BREEAM UK New Construction 2014, Hea 01 Visual comfort, tables 10 and 11
//    (office, industrial and "all other building types", occupied spaces): average daylight
//    factor >= 2 % and criterion (a): uniformity (minimum / average) >= 0.4 or a minimum point
//    daylight factor >= 0.8 %. Criteria (b) view of sky and (c) room depth are not assessed.
// All of them are defined on horizontal work planes: a vertical or tilted grid gets "not
// assessed" with that reason. LM-83's ASE is "with all operable shading devices retracted" and
// its sDA is computed "with hourly blind operation" (section 2.2.6, the 2 % rule, whose direct
// sun "excludes the effect of any blinds"): a case with venetian blinds in place every hour, or
// an operated result whose open case has them, gets "not assessed" for both (and for LEED's
// sDA), since its ASE is the sun through the slats (projects/blinds: 0 % with the slats at
// 45 degrees, 30 % with them raised) and its sDA is not the operated one.
#pragma once

#include "dayphoton/study/results_model.h"

namespace dayphoton::study {

/// IES LM-83-12 thresholds.
constexpr double Lm83SdaAcceptedPercent = 55, Lm83SdaPreferredPercent = 75, Lm83AseMaxPercent = 10;
constexpr double Lm83DaThresholdLux = 300, Lm83SdaTimeFraction = 0.5, Lm83AseThresholdLux = 1000, Lm83AseHours = 250;
/// LEED v4.1 EQ Daylight option 1: sDA300/50% for 1, 2 and 3 points.
constexpr double LeedSdaPointsPercent[3] = {40, 55, 75};
/// BREEAM UK NC 2014 Hea 01 (offices and other building types).
constexpr double BreeamAverageDfPercent = 2.0, BreeamUniformity = 0.4, BreeamMinimumPointDfPercent = 0.8;

/// LM-83-12's analysis period (section 2.1.2): every day 08:00-18:00 local clock time over a year.
constexpr double Lm83AnalysisStart_h = 8, Lm83AnalysisEnd_h = 18;

/// Whether the grid's annual metrics are over LM-83's analysis period; if not, `why` says what
/// they are over instead.
bool lm83_analysis_period(const AnnualSummary& annual, std::string& why);

/// LEED v4.1 option 1 points (0..3) for a grid's sDA300/50%.
int leed_v41_points(double sda_percent);

/// The verdicts of one grid (the grid's own summaries; its orientation decides whether any
/// applies). `blinds_in_place` and `shading_materials`: the case's (CaseResult::
/// blinds_in_place, shading_materials_in_place); `operated`: the case is the operated result
/// (its shading is that of its open case).
std::vector<Verdict> grid_verdicts(const GridResult& grid, const std::vector<std::string>& blinds_in_place = {},
                                   bool operated = false,
                                   const std::vector<ShadingMaterialInPlace>& shading_materials = {});

/// Fill every grid's verdicts and the model's not-assessed statements.
void assess_compliance(ResultsModel& model);

}  // namespace dayphoton::study
