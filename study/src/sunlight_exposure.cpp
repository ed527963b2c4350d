// EN 17037 exposure to sunlight (see sunlight_exposure.h for the rules and the choices).
#include "dayphoton/study/sunlight_exposure.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

#include "dayphoton/project/north_rotation.h"

namespace dayphoton::study {

namespace {

constexpr double Pi = 3.14159265358979323846;
/// A ray passes at most this many glazing surfaces (panes drawn as polygons) before it counts
/// as blocked: a guard against a ray caught between coplanar panes, far above any real facade.
constexpr int MaxGlazingCrossings = 64;

bool passes_sun(MaterialType type) {
  return type == MaterialType::Glass || type == MaterialType::Glazing || type == MaterialType::Opening;
}

std::string metres(double v) {
  std::ostringstream s;
  s.precision(2);
  s << std::fixed << v << " m";
  return s.str();
}

}  // namespace

std::string sunlight_level(double hours) {
  if (hours >= SunlightHigh_h) return "high";
  if (hours >= SunlightMedium_h) return "medium";
  if (hours >= SunlightMinimum_h) return "minimum";
  return "below minimum";
}

std::optional<Vec3> sunlight_reference_point(const project::WindowRectangle& w) {
  const double height = std::max(SunlightPointAboveFloor_m, w.sill_m + SunlightPointAboveSill_m);
  if (height > w.sill_m + w.height_m) return std::nullopt;
  return w.left_bottom_m + w.along * (0.5 * w.width_m) + Vec3{0, 0, height - w.sill_m};
}

std::vector<SunlightInterval> sunlit_intervals(const SunlightDay& day,
                                               const std::function<bool(const Vec3&)>& visible) {
  const sky::SolarPositionOptions spa;  // SPA, no refraction: the geometric altitude
  auto lit = [&](double hour) {
    const sky::SolarPosition p = sky::solar_position(day.site, {day.year, day.month, day.day, hour}, spa);
    if (p.altitude_rad * 180.0 / Pi < day.min_altitude_deg) return false;
    return visible(p.direction);
  };
  const double step_h = day.time_step_min / 60.0;
  const double resolution_h = SunlightChangeResolution_s / 3600.0;
  const int samples = static_cast<int>(std::ceil(24.0 / step_h - 1e-9));
  // The instant between `a` (state `at_a`) and `b` where the state changes, to the resolution.
  auto change = [&](double a, double b, bool at_a) {
    while (b - a > resolution_h) {
      const double m = 0.5 * (a + b);
      (lit(m) == at_a ? a : b) = m;
    }
    return 0.5 * (a + b);
  };
  std::vector<SunlightInterval> out;
  double previous_t = 0;
  bool previous = lit(0);
  double start = 0;
  for (int k = 1; k <= samples; ++k) {
    const double t = std::min(24.0, k * step_h);
    const bool now = lit(t);
    if (now != previous) {
      const double at = change(previous_t, t, previous);
      if (now) start = at;
      else out.push_back({start, at});
    }
    previous = now;
    previous_t = t;
  }
  if (previous) out.push_back({start, 24.0});
  return out;
}

std::vector<SunlightInterval> interval_union(const std::vector<std::vector<SunlightInterval>>& windows) {
  std::vector<SunlightInterval> all;
  for (const auto& w : windows) all.insert(all.end(), w.begin(), w.end());
  std::sort(all.begin(), all.end(), [](const SunlightInterval& a, const SunlightInterval& b) {
    return a.start_h < b.start_h || (a.start_h == b.start_h && a.end_h < b.end_h);
  });
  std::vector<SunlightInterval> out;
  for (const SunlightInterval& i : all) {
    if (!out.empty() && i.start_h <= out.back().end_h) out.back().end_h = std::max(out.back().end_h, i.end_h);
    else out.push_back(i);
  }
  return out;
}

double total_hours(const std::vector<SunlightInterval>& intervals) {
  double h = 0;
  for (const SunlightInterval& i : intervals) h += i.end_h - i.start_h;
  return h;
}

bool sun_seen(const engine::Scene& scene, const Vec3& point_m, const Vec3& direction) {
  // Past a pane the ray goes on from the same origin with tmin just beyond the hit, not from
  // an origin offset along the pane's normal: that offset (ray_epsilon_m, 1e-5 of the scene's
  // largest coordinate: 5 mm in a scene 500 m across) would move the reference point toward
  // the obstructions and shift every spell's ends by seconds.
  engine::Ray ray{point_m, direction};
  const auto& materials = scene.description().materials;
  for (int crossing = 0; crossing <= MaxGlazingCrossings; ++crossing) {
    const std::optional<engine::Hit> hit = scene.intersect(ray);
    if (!hit) return true;
    if (hit->material < 0 || !passes_sun(materials[static_cast<std::size_t>(hit->material)].type)) return false;
    ray.tmin = hit->t + scene.ray_epsilon_m();
  }
  return false;
}

std::vector<RoomSunlight> assess_sunlight_exposure(const project::Project& project,
                                                   const SceneDescription& description,
                                                   const engine::Scene& scene, const SunlightDay& day) {
  std::vector<RoomSunlight> out;
  if (!project.sunlight_exposure) return out;
  const project::SunlightExposureSpec& spec = *project.sunlight_exposure;
  std::set<std::string> named, interior;
  for (const auto& n : spec.windows) named.insert(n.value);
  for (const project::InteriorWindow& iw : project::interior_windows(project.geometry)) interior.insert(iw.window);
  const double north = project.site.rotation_to_true_north_deg();
  for (const project::RoomSpec& room : project.geometry.rooms) {
    RoomSunlight r;
    r.room = room.name;
    std::vector<std::vector<SunlightInterval>> spells;
    for (const project::WindowSpec& w : room.windows) {
      if (interior.count(w.name) || (!named.empty() && !named.count(w.name))) continue;
      const project::WindowRectangle rect = project::window_rectangle(room, w);
      WindowSunlight ws;
      ws.name = w.name;
      const std::optional<Vec3> p = sunlight_reference_point(rect);
      if (!p) {
        const double height = std::max(SunlightPointAboveFloor_m, rect.sill_m + SunlightPointAboveSill_m);
        ws.reference_point_m = project::model_to_world(rect.left_bottom_m + rect.along * (0.5 * rect.width_m), north);
        ws.not_assessed = "its head (" + metres(rect.sill_m + rect.height_m) +
                          " above the floor) is below EN 17037's reference point (" + metres(height) +
                          ": at least 1.2 m above the floor and 0.3 m above the sill)";
        r.windows.push_back(std::move(ws));
        continue;
      }
      ws.reference_point_m = project::model_to_world(*p, north);
      const Vec3 outward = project::model_to_world(rect.outward, north);
      const Vec3 start = ws.reference_point_m - description.world_origin_m;
      ws.intervals = sunlit_intervals(day, [&](const Vec3& d) {
        return dot(d, outward) > 0 && sun_seen(scene, start, d);
      });
      ws.hours = total_hours(ws.intervals);
      spells.push_back(ws.intervals);
      r.windows.push_back(std::move(ws));
    }
    if (r.windows.empty()) continue;
    r.intervals = interval_union(spells);
    r.hours = total_hours(r.intervals);
    r.level = spells.empty() ? "not assessed" : sunlight_level(r.hours);
    out.push_back(std::move(r));
  }
  return out;
}

std::string intervals_text(const std::vector<SunlightInterval>& intervals) {
  if (intervals.empty()) return "none";
  auto clock = [](double hours) {
    const int minutes = static_cast<int>(std::lround(std::clamp(hours, 0.0, 24.0) * 60.0));
    const int h = minutes / 60, m = minutes % 60;
    return std::string{char('0' + h / 10), char('0' + h % 10), ':', char('0' + m / 10), char('0' + m % 10)};
  };
  std::string out;
  for (const SunlightInterval& i : intervals)
    out += (out.empty() ? "" : ", ") + clock(i.start_h) + "-" + clock(i.end_h);
  return out;
}

std::vector<std::string> sunlight_log_lines(const std::vector<RoomSunlight>& rooms) {
  std::vector<std::string> lines;
  auto hours = [](double h) {
    std::ostringstream s;
    s.precision(2);
    s << std::fixed << h << " h";
    return s.str();
  };
  for (const RoomSunlight& r : rooms) {
    lines.push_back("EN 17037 sunlight exposure, room " + r.room + ": " + hours(r.hours) + ", " + r.level + " (" +
                    intervals_text(r.intervals) + ")");
    for (const WindowSunlight& w : r.windows)
      lines.push_back("  window " + w.name + ": " +
                      (w.not_assessed.empty() ? hours(w.hours) + " (" + intervals_text(w.intervals) + ")"
                                              : "not assessed: " + w.not_assessed));
  }
  return lines;
}

}  // namespace dayphoton::study
