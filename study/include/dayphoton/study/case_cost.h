// The estimated cost of one case of a run (the base project or a variant), in CPU seconds of
// one core, for dealing whole cases out to the ranks of an MPI run by cost (case_units.h;
// docs/cluster.md "Variants as units"). It decides where a case runs, never what it yields.
//
// The model: the work a case's steps scale with, times the unit costs measured on
// projects/office (docs/cluster.md "Cost model", the office column; one core of the 2-core
// reference machine):
//   sky photons     : stored photons of the sky sources (photons per bin x (sky bins + the
//                     ground's GroundPhotonFactor)) x SkyPhotonSeconds
//   sky estimates   : sensors x sky sources x SkyEstimateSeconds
//   sun bins        : (sun bins mode) stored photons of the bins x SunPhotonSeconds and
//                     sensors x bins x SunEstimateSeconds
//   direct sun      : (sun bins mode) sensors x sun hours x DirectSunSeconds
//   annual multiply : (annual illuminance or metrics) sensors x hours x AnnualMultiplySeconds
//   scene           : SceneSeconds (building the scene, the cached run's decoding)
// What it leaves out: the scene's cost per photon (its yield and the bounces before a photon
// is absorbed: a photon of the open plan costs twice the office's, and the office's variants
// differ by up to 25 % between themselves), the accuracy rounds' photon count (the reference
// photons_per_bin stands for it) and the points in time. So two cases of one size weigh the
// same, and cases whose sizes differ (photons, sensors, sun) weigh as their sizes.
#pragma once

#include <cstddef>

#include "dayphoton/project/project.h"
#include "dayphoton/study/sun_site.h"
#include "dayphoton/weather/hourly_weather.h"

namespace dayphoton::study {

/// Unit costs of the model (CPU seconds per unit; docs/cluster.md "Cost model", office).
namespace case_cost {
constexpr double SkyPhotonSeconds = 1.59e-6;     ///< per stored sky photon
constexpr double SunPhotonSeconds = 2.69e-6;     ///< per stored sun-bin photon
constexpr double SkyEstimateSeconds = 53e-6;     ///< per sensor and sky source
constexpr double SunEstimateSeconds = 7.8e-6;    ///< per sensor and sun bin
constexpr double DirectSunSeconds = 2.2e-3 / 3561.0;       ///< per sensor and sun hour (2.2 ms for 3,561 h)
constexpr double AnnualMultiplySeconds = 3.9e-3 / 8760.0;  ///< per sensor and hour (3.9 ms for 8,760 h)
constexpr double SceneSeconds = 0.16;            ///< per case
}  // namespace case_cost

/// What a project's weather gives every one of its cases: its hours, the hours with direct
/// sun (the sun above the horizon at the site and a direct normal irradiance > 0; the run's
/// suns are those whose direct illuminance by the Perez efficacy is > 0, a few fewer: 3,561
/// against 3,575 for the office) and, in the sun-bins mode, the sun bins of those suns
/// (engine::SunBins::for_suns). All 0 for a daylight-factor study.
struct SunYear {
  std::size_t hours = 0, sun_hours = 0, sun_bins = 0;
};

/// The SunYear of `project` with its weather and sun site (null for a daylight-factor study).
SunYear sun_year_of(const project::Project& project, const weather::HourlyWeather* weather, const SunSite* sun_site);

/// The estimated CPU seconds of case `case_project` (a project, or a variant applied to it)
/// whose weather gives `year`. Builds the case's scene description to count its sensors.
double case_cost_seconds(const project::Project& case_project, const SunYear& year);

/// The estimates of every case of `project` (the base, then each variant in order).
std::vector<double> case_costs_seconds(const project::Project& project, const SunYear& year);

}  // namespace dayphoton::study
