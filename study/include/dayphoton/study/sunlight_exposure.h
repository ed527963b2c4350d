// EN 17037 exposure to sunlight: how long, on one cloudless date, the sun is seen from a
// reference point of each window, and the level the room reaches (docs/metrics.md, "EN 17037
// exposure to sunlight").
//
// The rules, from EN 17037:2018 "Daylight in buildings" (CEN), its recommendation for the
// exposure to sunlight and its calculation method (docs/metrics.md names what was checked
// against which text):
//  - the duration is the possible sunlight on a date between 1 February and 21 March under a
//    cloudless sky (project.h SunlightFirstMonth..SunlightLastDay), counted only while the
//    sun is at or above a minimum altitude that the standard makes depend on the site: the
//    project states it (`sunlight_exposure.min_altitude`, no default);
//  - the reference point P lies on the inner surface of the window, at the centre of its
//    width, at least 1.2 m above the floor and at least 0.3 m above the sill: dayphoton takes
//    the lowest such point (SunlightPointAboveFloor_m, SunlightPointAboveSill_m); a window
//    whose head lies below it is not assessed (said in the results, never counted as 0 h);
//  - levels: minimum 1.5 h, medium 3 h, high 4 h (SunlightMinimum_h ...).
// dayphoton's choices where the text leaves one: the sun's position by NREL's SPA without
// refraction (the geometric altitude of the disc's centre, sky/solar_position.h); the sun
// sampled every `time_step` minutes (default 1) and every change of visibility found by
// bisection to SunlightChangeResolution_s; the spells of a room's windows joined as a union
// (an hour seen through two windows counts once); the times in local standard time of the
// site's time zone (no daylight saving; the duration does not depend on the clock).
//
// What blocks the sun: every surface of the case's scene as drawn (walls, reveals, overhangs,
// fins, other buildings, the ground, blinds and louvres, outdoor geometry) except clear
// glazing: `glass`, `glazing` and `opening` materials pass the ray; `translucent`, `bsdf`,
// `dielectric` and every opaque material stop it. Operable shading is taken as drawn: a case
// with blinds or operable shading materials in place gives the hours with them (the report
// says so); a variant without them gives the possible sunlight.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "dayphoton/core/scene_description.h"
#include "dayphoton/core/vec3.h"
#include "dayphoton/engine/scene.h"
#include "dayphoton/project/project.h"
#include "dayphoton/project/window_rectangle.h"
#include "dayphoton/sky/solar_position.h"
#include "dayphoton/study/results_model.h"

namespace dayphoton::study {

/// EN 17037's levels of the daily sunlight exposure, hours.
constexpr double SunlightMinimum_h = 1.5;
constexpr double SunlightMedium_h = 3.0;
constexpr double SunlightHigh_h = 4.0;
/// EN 17037's reference point: at least this high above the floor and above the sill.
constexpr double SunlightPointAboveFloor_m = 1.2;
constexpr double SunlightPointAboveSill_m = 0.3;
/// A change of visibility between two samples is found by bisection to this (dayphoton's).
constexpr double SunlightChangeResolution_s = 1.0;

/// "high" (>= 4 h), "medium" (>= 3 h), "minimum" (>= 1.5 h) or "below minimum".
std::string sunlight_level(double hours);

/// The reference point of a window in model coordinates (its rectangle's plane), or nothing
/// when the window's head lies below the point's height.
std::optional<Vec3> sunlight_reference_point(const project::WindowRectangle& window);

/// The day and the sampling of the sun.
struct SunlightDay {
  sky::SolarSite site;  ///< the site the sun is for (its time zone is the clock of the spells)
  int year = 2001, month = 3, day = 21;
  double min_altitude_deg = 0;
  double time_step_min = 1;
};

/// The spells of the day (local standard hours, [0, 24]) during which the sun is at or above
/// the minimum altitude and `visible(direction)` holds (direction: unit, world coordinates,
/// toward the sun).
std::vector<SunlightInterval> sunlit_intervals(const SunlightDay& day,
                                               const std::function<bool(const Vec3&)>& visible);

/// The union of several windows' spells, sorted.
std::vector<SunlightInterval> interval_union(const std::vector<std::vector<SunlightInterval>>& windows);
/// Their total length, hours.
double total_hours(const std::vector<SunlightInterval>& intervals);

/// True when a ray from `point_m` (scene coordinates) toward `direction` reaches the sky
/// through clear glazing only (see the header comment for what blocks it).
bool sun_seen(const engine::Scene& scene, const Vec3& point_m, const Vec3& direction);

/// The assessment of one case: per room of `project.geometry.rooms` with windows assessed
/// (project.sunlight_exposure's), in file order. `description` and `scene` are the case's.
std::vector<RoomSunlight> assess_sunlight_exposure(const project::Project& project,
                                                   const SceneDescription& description,
                                                   const engine::Scene& scene, const SunlightDay& day);

/// The spells as clock times, "09:12-15:40, 16:02-16:30" (minutes rounded), or "none".
std::string intervals_text(const std::vector<SunlightInterval>& intervals);

/// The run log's lines of one case: per room its hours, level and spells, per window its own
/// (or why it was not assessed).
std::vector<std::string> sunlight_log_lines(const std::vector<RoomSunlight>& rooms);

}  // namespace dayphoton::study
