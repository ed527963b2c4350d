// Point-in-time cases (project key `points_in_time`): the illuminance at every sensor at one
// date and local standard time under one sky, with its sun and every reflection of both.
//
// Each case becomes one step of the sun-bins mode's layout (annual_sun.h), so the cases are
// computed exactly as an hour of the annual study:
//   E[case][s] = sky coefficients x the case's sky column (sky and ground, no sun)
//              + direct sun  : traced exactly for the case's sun (direct_sun_coefficients)
//              + indirect sun: the sun-bin coefficients interpolated to the case's sun
// The skies:
//   - cie_overcast: the CIE standard overcast sky (Moon & Spencer 1942; CIE S 011 type 16)
//     scaled to the given horizontal illuminance, built as the daylight factor's sky is, so
//     E = DF x E_h / 100 at every sensor;
//   - cie: the CIE standard general sky of type 1..15 (ISO 15469:2004 / CIE S 011/E:2003) for
//     the sun at the case's time, scaled to the given diffuse horizontal illuminance, plus a
//     sun of the given direct normal illuminance;
//   - weather: the weather file's record that contains the time, taken from the annual
//     study's sky without the sun and its sun record (the same numbers as that hour of
//     the annual study).
// The ground (bin 0) is the Lambertian ground lit by the sky and the sun, as in the annual sky
// matrix (sky::ground_radiance_rgb).
#pragma once

#include <string>
#include <vector>

#include "dayphoton/core/scene_description.h"
#include "dayphoton/engine/direct_component.h"
#include "dayphoton/metrics/illuminance_table.h"
#include "dayphoton/project/project.h"
#include "dayphoton/sky/patch_basis.h"
#include "dayphoton/sky/solar_position.h"
#include "dayphoton/study/annual_sun.h"
#include "dayphoton/study/sun_site.h"

namespace dayphoton::study {

/// The solar position algorithm of the CIE cases: NREL SPA (Reda & Andreas 2004), without
/// refraction, for this year (a date of the study has no year; the sun's position at a given
/// date and time moves by less than 0.02 degree from one year to the next within a leap cycle).
constexpr int PointInTimeSolarYear = 2001;
/// The year of a CIE case dated 02-29, which only a leap year has: the day between 02-28 and
/// 03-01 of the year above (its sun within the same 0.02 degree).
constexpr int PointInTimeLeapSolarYear = 2004;

/// The site the CIE cases' sun is computed for: the annual study's sun site (`sun_site`, the
/// weather header's under `site.from_weather`), else the project's own.
sky::SolarSite point_in_time_site(const project::Project& project, const SunSite* sun_site);

/// The project's checks of the cases that need no tracing, for `check` and before `run`
/// writes anything: a CIE general sky needs its sun above the horizon at the site (an
/// InputError with every such case located at its `time`). Returns one line per case for
/// `check`: "winter: 12-21 10:30 local standard time, CIE standard general sky type 12, sun at
/// 22.3 deg altitude, 152.5 deg azimuth".
std::vector<std::string> check_points_in_time(const std::vector<project::PointInTimeSpec>& cases,
                                              const sky::SolarSite& site);

/// The cases' skies and suns: one step per case in file order (time stamp = the case's date and
/// time), sky columns without the sun, a SunRecord for every case whose sun is above the
/// horizon and has direct light. `annual` (the annual study's sky without the sun and its
/// suns) is needed only by `sky: weather` cases. Throws InputError located at a case's `time`
/// for a CIE general sky whose sun is below the horizon, or at the case for a weather case
/// whose time the weather file does not hold (02-29 of a file without that day: said so).
SkyAndSuns point_in_time_skies(const std::vector<project::PointInTimeSpec>& cases, const sky::SolarSite& site,
                               const sky::PatchBasis& basis, double ground_reflectance,
                               const SkyAndSuns* annual);

/// The CIE cases' skies as continuous radiance (engine/direct_component.h, "Continuous
/// skies"), the ground of the same sky below the horizon: the sky of point_in_time_skies'
/// column, so the direct part of a case's illuminance can be taken from the continuous sky
/// instead of the patch means (points_in_time_case.h). `sky_of_case[k]` receives the index
/// into the result of case k's sky, or -1 (a weather case: its sky is the annual study's
/// patch column). A CIE general sky whose sun is below the horizon gets none (-1; run's
/// checks refuse it first).
std::vector<engine::ContinuousSky> point_in_time_continuous_skies(const std::vector<project::PointInTimeSpec>& cases,
                                                                  const sky::SolarSite& site, double ground_reflectance,
                                                                  std::vector<int>& sky_of_case);

/// The photon part's sub-patch correction of the CIE general cases (docs/photon-map.md, "The
/// point-in-time photon part"): (4 x bins) x cases x 1 in sky::SkyMatrix::quadrant_deltas'
/// layout, case k's column sky::sky_vector_quadrant_deltas of its sky against its column of
/// point_in_time_skies; zero for the other cases (a cie_overcast case's photon part takes the
/// daylight factor's continuous-sky correction, a weather case's deltas are its hour's in
/// point_in_time_skies) and for a general sky whose sun is below the horizon.
RadianceMatrix point_in_time_cie_quadrant_deltas(const std::vector<project::PointInTimeSpec>& cases,
                                                 const sky::SolarSite& site, const sky::PatchBasis& basis,
                                                 double ground_reflectance);

/// Case k's column of point_in_time_skies' sky matrix: its sky over the basis (bins x 1).
RadianceMatrix point_in_time_sky_column(const SkyAndSuns& skies, std::size_t k);

/// One sentence per case for the run log and summary.json: "winter_noon: 12-21 12:00 LST,
/// CIE general sky type 12, sun at 28.8 deg altitude, 180.1 deg azimuth, 80000 lx direct
/// normal, 10000 lx diffuse horizontal".
std::vector<std::string> describe_points_in_time(const std::vector<project::PointInTimeSpec>& cases,
                                                 const SkyAndSuns& skies);

}  // namespace dayphoton::study
