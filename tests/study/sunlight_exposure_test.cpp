// EN 17037 exposure to sunlight (study/sunlight_exposure.h) against closed forms of the sun's
// path: a window with nothing in front (the minimum altitude alone ends the day), reveals that
// limit the sun's azimuth (tan relation), a long obstruction in front (the profile angle), in
// both hemispheres; and the project keys' located errors.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/engine/scene.h"
#include "dayphoton/project/project.h"
#include "dayphoton/sky/solar_position.h"
#include "dayphoton/study/point_in_time.h"
#include "dayphoton/study/sunlight_exposure.h"

namespace dayphoton::study {
namespace {

constexpr double Pi = 3.14159265358979323846;
constexpr double Deg = Pi / 180.0;
/// Each spell's ends against the closed form. The closed form gives the hour angle at an end
/// from the declination; both are taken from SPA's direction to the sun at the end itself
/// (topocentric, as the run sees it): held at the transit's value the declination, which
/// changes by 0.4 degree a day near the equinox, moves the ends by up to 50 s; 15 degrees of
/// hour angle an hour from the transit by 5 s; the geocentric values instead of the
/// topocentric ones (parallax, 0.0024 degree) by up to 6 s where the profile angle changes
/// slowly. What remains is the run's bisection, which returns the middle of a bracket of at
/// most 1 s around each change: within 0.5 s, so 1 s (measured: 0.40 s at most).
constexpr double EndTolerance_h = 1.0 / 3600.0;

/// A 4 x 5 x 3 m room at the origin with one 2 m wide window (sill 0.9 m, 1.5 m high) in
/// `wall`, at `latitude`, longitude 0, UTC; `extra` more geometry (polygons).
std::string room_yaml(double latitude, const std::string& wall, const std::string& sunlight,
                      const std::string& polygons = "") {
  return "site: {latitude: " + std::to_string(latitude) + ", longitude: 0, time_zone: 0}\n"
         "study: daylight_factor\n"
         "materials:\n"
         "  grey: {type: lambertian, reflectance: 0.5}\n"
         "  glass: {type: glass, transmittance: 0.6}\n"
         "geometry:\n"
         "  rooms:\n"
         "    - name: office\n"
         "      size: [4, 5, 3]\n"
         "      materials: {floor: grey, ceiling: grey, walls: grey}\n"
         "      windows: [{name: w, wall: " + wall + ", width: 2, height: 1.5, sill: 0.9, material: glass}]\n" +
         (polygons.empty() ? std::string() : "  polygons:\n" + polygons) +
         "sensors:\n  grids:\n    - {name: workplane, room: office, height: 0.8, spacing: 1}\n"
         "sunlight_exposure: " + sunlight + "\n";
}

struct Assessed {
  project::Project project;
  std::vector<RoomSunlight> rooms;
};

Assessed assess(const std::string& yaml) {
  Assessed a{project::load_project_from_string(yaml, "room.yaml"), {}};
  const SceneDescription description = project::build_scene_description(a.project);
  const engine::Scene scene = engine::Scene::build(description);
  const project::SunlightExposureSpec& se = *a.project.sunlight_exposure;
  const SunlightDay day{point_in_time_site(a.project, nullptr), PointInTimeSolarYear, se.month, se.day,
                        se.min_altitude_deg, se.time_step_min};
  a.rooms = assess_sunlight_exposure(a.project, description, scene, day);
  return a;
}

/// The sun's declination at transit, the transit (local standard hours) of the day, and the
/// declination at any hour, from SPA.
struct SunDay {
  double latitude = 0;
  int month = 3, day = 21;
  double declination_rad = 0, transit_h = 12;
  /// The hour `side` (-1 morning, +1 afternoon) of the day at which the sun's hour angle
  /// equals side x hour_angle(declination) (rad, >= 0), both at that hour and both from SPA's
  /// direction (E, N, U): sin d = sin phi U + cos phi N, tan H = -E / (cos phi U - sin phi N)
  /// (fixed point, 6 passes).
  template <class HourAngle>
  double at(int side, const HourAngle& hour_angle) const {
    const double phi = latitude * Deg;
    double t = transit_h + side * hour_angle(declination_rad) / Deg / 15.0;
    for (int i = 0; i < 6; ++i) {
      const Vec3 v = sky::solar_position({latitude, 0, 0, 0}, {PointInTimeSolarYear, month, day, t}).direction;
      const double d = std::asin(std::sin(phi) * v.z + std::cos(phi) * v.y);
      const double h = std::atan2(-v.x, std::cos(phi) * v.z - std::sin(phi) * v.y);
      t += (side * hour_angle(d) - h) / Deg / 15.0;
    }
    return t;
  }
};
SunDay sun_day(double latitude, int month, int day) {
  const sky::SolarSite site{latitude, 0, 0, 0};
  const sky::SunEvents e = sky::sun_events(site, PointInTimeSolarYear, month, day);
  return {latitude, month, day, sky::solar_position(site, {PointInTimeSolarYear, month, day, e.transit_h}).declination_rad,
          e.transit_h};
}

/// The hour angle (rad, >= 0) at which the sun's altitude is `altitude_rad` (the textbook
/// relation sin a = sin phi sin d + cos phi cos d cos H).
double hour_angle_at_altitude(double latitude_rad, double declination_rad, double altitude_rad) {
  return std::acos((std::sin(altitude_rad) - std::sin(latitude_rad) * std::sin(declination_rad)) /
                   (std::cos(latitude_rad) * std::cos(declination_rad)));
}

void expect_one_spell(const RoomSunlight& room, double start_h, double end_h) {
  ASSERT_EQ(room.intervals.size(), 1u) << intervals_text(room.intervals);
  EXPECT_NEAR(room.intervals[0].start_h, start_h, EndTolerance_h);
  EXPECT_NEAR(room.intervals[0].end_h, end_h, EndTolerance_h);
  EXPECT_NEAR(room.hours, end_h - start_h, 2 * EndTolerance_h);
  EXPECT_EQ(room.level, sunlight_level(room.hours));
}

TEST(SunlightExposure, WithNothingInFrontTheMinimumAltitudeBoundsTheEquinoxDay) {
  // An equator-facing window at 21 March sees the sun whenever it is up (the equinox sun rises
  // and sets within a fraction of a degree of due east and west): the spell is where the
  // altitude is at or above the minimum, +-H0 about transit with
  // cos H0 = (sin a_min - sin phi sin d) / (cos phi cos d).
  struct Case {
    double latitude;
    const char* wall;
    double min_altitude_deg;
  };
  for (const Case c : {Case{40, "south", 10}, Case{52, "south", 5}, Case{60, "south", 12},
                       Case{-35, "north", 10}, Case{-50, "north", 15}}) {
    SCOPED_TRACE(std::to_string(c.latitude) + " " + c.wall);
    const Assessed a =
        assess(room_yaml(c.latitude, c.wall, "{date: 03-21, min_altitude: " + std::to_string(c.min_altitude_deg) + "}"));
    ASSERT_EQ(a.rooms.size(), 1u);
    const SunDay s = sun_day(c.latitude, 3, 21);
    const auto h0 = [&](double d) { return hour_angle_at_altitude(c.latitude * Deg, d, c.min_altitude_deg * Deg); };
    expect_one_spell(a.rooms[0], s.at(-1, h0), s.at(+1, h0));
    ASSERT_EQ(a.rooms[0].windows.size(), 1u);
    // The reference point: centre of the width, 1.2 m above the floor (the sill + 0.3 m is lower).
    const Vec3 p = a.rooms[0].windows[0].reference_point_m;
    EXPECT_NEAR(p.x, 2.0, 1e-9);
    EXPECT_NEAR(p.z, 1.2, 1e-9);
    EXPECT_NEAR(p.y, std::string(c.wall) == "south" ? 0.0 : 5.0, 1e-9);
  }
}

TEST(SunlightExposure, TheSitesNorthTurnsTheWindow) {
  // north: 90 puts true north along model +X, so the model's south wall faces east: at the
  // equinox its window sees the morning sun from the minimum altitude until the sun crosses
  // the meridian (hour angle 0); north: 180 turns it to face north, where the equinox sun
  // above 5 degrees never is.
  const double latitude = 52;
  std::string east = room_yaml(latitude, "south", "{date: 03-21, min_altitude: 5}");
  east.replace(east.find("time_zone: 0}"), 13, "time_zone: 0, north: 90}");
  const Assessed a = assess(east);
  const SunDay s = sun_day(latitude, 3, 21);
  const auto h0 = [&](double d) { return hour_angle_at_altitude(latitude * Deg, d, 5 * Deg); };
  expect_one_spell(a.rooms[0], s.at(-1, h0), s.at(+1, [](double) { return 0.0; }));
  // The reference point in world coordinates: model (2, 0) turned counter-clockwise by 90 degrees.
  EXPECT_NEAR(a.rooms[0].windows[0].reference_point_m.x, 0.0, 1e-9);
  EXPECT_NEAR(a.rooms[0].windows[0].reference_point_m.y, 2.0, 1e-9);
  std::string north = room_yaml(latitude, "south", "{date: 03-21, min_altitude: 5}");
  north.replace(north.find("time_zone: 0}"), 13, "time_zone: 0, north: 180}");
  const Assessed n = assess(north);
  EXPECT_EQ(n.rooms[0].hours, 0.0);
  EXPECT_EQ(n.rooms[0].level, "below minimum");
}

TEST(SunlightExposure, RevealsLimitTheSunsAzimuthByTheirDepth) {
  // Fins of depth D at both jambs of a window of width W: from the reference point at the
  // centre the sun is seen while its azimuth from the window's normal is below
  // atan(W / (2 D)). On a south facade the sun's azimuth from south obeys
  // tan A = sin H / (sin phi cos H - cos phi tan d), solved here for H by bisection.
  const double latitude = 52, depth = 0.6, width = 2;
  auto fin = [&](const std::string& name, double x) {
    return "    - {name: " + name + ", material: grey, vertices: [[" + std::to_string(x) + ", 0, -10], [" +
           std::to_string(x) + ", " + std::to_string(-depth) + ", -10], [" + std::to_string(x) + ", " +
           std::to_string(-depth) + ", 20], [" + std::to_string(x) + ", 0, 20]]}\n";
  };
  const Assessed a = assess(room_yaml(latitude, "south", "{date: 03-21, min_altitude: 5}", fin("left", 1) + fin("right", 3)));
  ASSERT_EQ(a.rooms.size(), 1u);
  const SunDay s = sun_day(latitude, 3, 21);
  const double phi = latitude * Deg, limit = std::atan(width / (2 * depth));
  const auto h1 = [&](double d) {
    auto azimuth = [&](double h) { return std::atan2(std::sin(h), std::sin(phi) * std::cos(h) - std::cos(phi) * std::tan(d)); };
    double lo = 0, hi = Pi / 2;
    for (int i = 0; i < 60; ++i) (azimuth(0.5 * (lo + hi)) < limit ? lo : hi) = 0.5 * (lo + hi);
    return 0.5 * (lo + hi);
  };
  // The altitude at the limit lies far above the 5 degree minimum.
  ASSERT_LT(h1(s.declination_rad), hour_angle_at_altitude(phi, s.declination_rad, 5 * Deg) - 15 * Deg);
  expect_one_spell(a.rooms[0], s.at(-1, h1), s.at(+1, h1));
  // Without the fins the same window sees the sun much longer: the fins are what limits it.
  const Assessed open = assess(room_yaml(latitude, "south", "{date: 03-21, min_altitude: 5}"));
  EXPECT_GT(open.rooms[0].hours, a.rooms[0].hours + 2);
}

/// A wall parallel to the room's `wall` side, `distance` in front of it, its top `k` x
/// distance above the reference point (1.2 m), 1 km long.
std::string obstruction(const std::string& wall, double distance, double k) {
  const double y = wall == "south" ? -distance : 5 + distance, top = 1.2 + k * distance;
  const std::string ys = std::to_string(y), z = std::to_string(top);
  return "    - {name: across, material: grey, vertices: [[-500, " + ys + ", -5], [500, " + ys + ", -5], [500, " + ys +
         ", " + z + "], [-500, " + ys + ", " + z + "]]}\n";
}

/// The hour angle (rad) at which the sun's profile angle on an equator-facing facade equals
/// atan(k): the profile angle p obeys
///   tan p = (sin phi sin d + cos phi cos d cos H) / (sin phi cos d cos H - cos phi sin d)
/// (latitude and declination taken positive toward the pole behind the facade), which equals
/// k at cos H = -sin d (k cos phi + sin phi) / (cos d (cos phi - k sin phi)).
double hour_angle_at_profile(double phi, double d, double k) {
  return std::acos(-std::sin(d) * (k * std::cos(phi) + std::sin(phi)) / (std::cos(d) * (std::cos(phi) - k * std::sin(phi))));
}

TEST(SunlightExposure, ALongObstructionHidesTheSunBelowItsProfileAngle) {
  // A long wall D in front of the facade hides the sun while its profile angle on the facade
  // is below atan(h / D), h its top above the reference point: tan p = tan(altitude) /
  // cos(azimuth from the normal). (At an equinox the profile angle on an equator-facing
  // facade is 90 - phi all day, so a February date is taken.)
  // 45 N, 15 February, a south window, h / D = tan 20 deg: the winter sun's profile angle is
  // largest at noon, so one spell about transit.
  {
    const double latitude = 45, k = std::tan(20 * Deg);
    const Assessed a = assess(room_yaml(latitude, "south", "{date: 02-15, min_altitude: 5}", obstruction("south", 10, k)));
    ASSERT_EQ(a.rooms.size(), 1u);
    const SunDay s = sun_day(latitude, 2, 15);
    const double phi = latitude * Deg, d = s.declination_rad;
    const auto h1 = [&](double dd) { return hour_angle_at_profile(phi, dd, k); };
    ASSERT_LT(h1(d), hour_angle_at_altitude(phi, d, 5 * Deg) - 7.5 * Deg);  // the wall binds, not the altitude
    expect_one_spell(a.rooms[0], s.at(-1, h1), s.at(+1, h1));
  }
  // 40 S, 15 February (late summer), a north window, h / D = tan 70 deg: the summer sun's
  // profile angle is smallest at noon (it rises and sets behind the facade), so the wall hides
  // the middle of the day and two spells remain, each ending where the sun passes into the
  // facade's plane, cos H = tan d / tan phi.
  {
    const double latitude = -40, k = std::tan(70 * Deg);
    const Assessed a = assess(room_yaml(latitude, "north", "{date: 02-15, min_altitude: 5}", obstruction("north", 10, k)));
    ASSERT_EQ(a.rooms.size(), 1u);
    const SunDay s = sun_day(latitude, 2, 15);
    const double phi = -latitude * Deg;  // mirrored: the south pole behind the facade, declination sign flipped
    ASSERT_LT(s.declination_rad, 0);
    const auto h1 = [&](double d) { return hour_angle_at_profile(phi, -d, k); };
    const auto h2 = [&](double d) { return std::acos(std::tan(-d) / std::tan(phi)); };
    // The facade binds, not the altitude.
    ASSERT_LT(h2(s.declination_rad), hour_angle_at_altitude(phi, -s.declination_rad, 5 * Deg) - 7.5 * Deg);
    const RoomSunlight& room = a.rooms[0];
    ASSERT_EQ(room.intervals.size(), 2u) << intervals_text(room.intervals);
    EXPECT_NEAR(room.intervals[0].start_h, s.at(-1, h2), EndTolerance_h);
    EXPECT_NEAR(room.intervals[0].end_h, s.at(-1, h1), EndTolerance_h);
    EXPECT_NEAR(room.intervals[1].start_h, s.at(+1, h1), EndTolerance_h);
    EXPECT_NEAR(room.intervals[1].end_h, s.at(+1, h2), EndTolerance_h);
    EXPECT_NEAR(room.hours, s.at(+1, h2) - s.at(+1, h1) + s.at(-1, h1) - s.at(-1, h2), 4 * EndTolerance_h);
  }
}

TEST(SunlightExposure, LevelsAreTheStandardsHours) {
  EXPECT_EQ(sunlight_level(1.49), "below minimum");
  EXPECT_EQ(sunlight_level(1.5), "minimum");
  EXPECT_EQ(sunlight_level(2.99), "minimum");
  EXPECT_EQ(sunlight_level(3.0), "medium");
  EXPECT_EQ(sunlight_level(4.0), "high");
}

TEST(SunlightExposure, ARoomsWindowsJoinAsAUnion) {
  const std::vector<SunlightInterval> u = interval_union({{{8, 10}, {13, 14}}, {{9.5, 11}}, {{14, 15}}});
  ASSERT_EQ(u.size(), 2u);
  EXPECT_EQ(u[0], (SunlightInterval{8, 11}));
  EXPECT_EQ(u[1], (SunlightInterval{13, 15}));
  EXPECT_DOUBLE_EQ(total_hours(u), 5.0);
  EXPECT_EQ(intervals_text(u), "08:00-11:00, 13:00-15:00");
}

TEST(SunlightExposure, AWindowBelowTheReferencePointIsNotAssessed) {
  // A window from 0.1 to 0.6 m above the floor cannot hold a point 1.2 m above it.
  std::string yaml = room_yaml(52, "south", "{min_altitude: 5}");
  yaml.replace(yaml.find("height: 1.5, sill: 0.9"), 22, "height: 0.5, sill: 0.1");
  const Assessed a = assess(yaml);
  ASSERT_EQ(a.rooms.size(), 1u);
  EXPECT_EQ(a.rooms[0].level, "not assessed");
  EXPECT_NE(a.rooms[0].windows[0].not_assessed.find("below EN 17037's reference point"), std::string::npos);
  EXPECT_EQ(a.rooms[0].hours, 0.0);
}

/// The message of the InputError that loading `yaml` throws ("" if none).
std::string load_error(const std::string& yaml) {
  try {
    project::load_project_from_string(yaml, "room.yaml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(SunlightExposure, BadKeysAreLocatedErrors) {
  // The section is the last line of room_yaml's text: line 15.
  const std::string late = load_error(room_yaml(52, "south", "{date: 03-22, min_altitude: 5}"));
  EXPECT_NE(late.find("room.yaml:15:"), std::string::npos) << late;
  EXPECT_NE(late.find("outside EN 17037's dates"), std::string::npos) << late;
  EXPECT_NE(load_error(room_yaml(52, "south", "{date: 01-31, min_altitude: 5}")).find("from 02-01 to 03-21"),
            std::string::npos);
  const std::string missing = load_error(room_yaml(52, "south", "{date: 03-01}"));
  EXPECT_NE(missing.find("min_altitude"), std::string::npos) << missing;
  EXPECT_NE(missing.find("room.yaml:15:"), std::string::npos) << missing;
  const std::string steep = load_error(room_yaml(52, "south", "{min_altitude: 50}"));
  EXPECT_NE(steep.find("min_altitude"), std::string::npos) << steep;
  const std::string step = load_error(room_yaml(52, "south", "{min_altitude: 5, time_step: 0}"));
  EXPECT_NE(step.find("time_step"), std::string::npos) << step;
  const std::string unknown = load_error(room_yaml(52, "south", "{min_altitude: 5, windows: [v]}"));
  EXPECT_NE(unknown.find("unknown window 'v'"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("room.yaml:15:"), std::string::npos) << unknown;
  // Valid: the default date is 21 March, the last of the standard's.
  const project::Project ok = project::load_project_from_string(room_yaml(52, "south", "{min_altitude: 5}"), "room.yaml");
  ASSERT_TRUE(ok.sunlight_exposure);
  EXPECT_EQ(ok.sunlight_exposure->month, 3);
  EXPECT_EQ(ok.sunlight_exposure->day, 21);
  EXPECT_EQ(ok.sunlight_exposure->time_step_min, 1.0);
}

}  // namespace
}  // namespace dayphoton::study
