#include "model_summary.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <ostream>
#include <sstream>

#include "dayphoton/core/polygon.h"
#include "dayphoton/core/units.h"
#include "dayphoton/core/diagnostics.h"
#include "dayphoton/engine/material.h"
#include "dayphoton/engine/scene.h"
#include "dayphoton/engine/sensor_support.h"
#include "dayphoton/study/placement_check.h"
#include "dayphoton/weather/epw_reader.h"

namespace dayphoton::app {

std::string compass_point(double azimuth_deg) {
  static const char* points[16] = {"N", "NNE", "NE", "ENE", "E", "ESE", "SE", "SSE",
                                   "S", "SSW", "SW", "WSW", "W", "WNW", "NW", "NNW"};
  double a = std::fmod(azimuth_deg, 360.0);
  if (a < 0) a += 360.0;
  return points[static_cast<int>(std::floor(a / 22.5 + 0.5)) % 16];
}

namespace {
std::string fixed(double v, int digits) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(digits) << v;
  return s.str();
}
std::string latitude_text(double deg) {
  return fixed(std::abs(deg), 4) + (deg >= 0 ? " N" : " S");
}
std::string longitude_text(double deg) {
  return fixed(std::abs(deg), 4) + (deg >= 0 ? " E" : " W");
}
std::string utc_offset_text(double hours) {
  std::ostringstream s;
  s << "UTC" << (hours >= 0 ? "+" : "") << hours;
  return s.str();
}

std::vector<std::string> describe_weather(const project::Project& proj) {
  // A daylight-factor study needs no weather file (load_project checks when one is needed).
  if (proj.weather.path.empty()) return {"none (daylight factors only)"};
  const weather::EpwFile epw = weather::read_epw(proj.weather.path);
  const weather::EpwLocation& loc = epw.header.location;
  std::vector<std::string> lines;
  lines.push_back(proj.weather.path_as_written + ": " + loc.city + ", " + loc.state + ", " + loc.country +
                  " (WMO " + loc.wmo + ", " + loc.source + ")");
  lines.push_back(latitude_text(loc.latitude_deg) + ", " + longitude_text(loc.longitude_east_deg) + ", " +
                  utc_offset_text(loc.time_zone_h) + ", elevation " + fixed(loc.elevation_m, 1) + " m; " +
                  std::to_string(epw.records.size()) + " hourly records" +
                  (epw.leap_day_present ? " (with 29 February)" : ""));
  for (const Diagnostic& w : epw.warnings) lines.push_back("warning: " + w.location.to_string() + ": " + w.message);
  // A weather station far from the site is legal (the nearest station) but worth a look.
  const double distance_deg = std::hypot(loc.latitude_deg - proj.site.latitude_deg,
                                         loc.longitude_east_deg - proj.site.longitude_deg);
  if (distance_deg > 1.0)
    lines.push_back("note: the weather station is " + fixed(distance_deg, 1) +
                    " degrees from the site; the sun is computed for the site");
  if (std::abs(loc.time_zone_h - proj.site.time_zone_h) > 1e-9)
    lines.push_back("note: the weather file's time zone (" + utc_offset_text(loc.time_zone_h) +
                    ") differs from the site's (" + utc_offset_text(proj.site.time_zone_h) +
                    "); records are read in the file's time zone");
  return lines;
}
}  // namespace

ModelSummary summarize_model(const project::Project& proj) {
  ModelSummary s;
  s.project_path = proj.path;
  s.site = proj.site;
  s.weather_lines = describe_weather(proj);
  s.scene = project::build_scene_description(proj);
  // Building the Embree scene runs the engine's own validation (degenerate triangles etc.).
  const engine::Scene scene = engine::Scene::build(s.scene);

  s.materials.resize(s.scene.materials.size());
  for (std::size_t i = 0; i < s.scene.materials.size(); ++i) {
    s.materials[i].name = s.scene.materials[i].name;
    s.materials[i].type = material_type_name(s.scene.materials[i].type);
  }
  s.surface_count = s.scene.surfaces.size();
  for (const Surface& surface : s.scene.surfaces) {
    const double area = polygon_area_m2(surface.vertices);
    if (surface.material >= 0) {
      s.materials[surface.material].surfaces += 1;
      s.materials[surface.material].area_m2 += area;
    }
  }
  // Ports as the engine sees them: Port::normal points into the room whichever way the
  // polygon was drawn (engine/port_facing.h); the window faces the opposite way.
  for (std::size_t k = 0; k < scene.ports().size(); ++k) {
    const engine::Port& p = scene.ports()[k];
    const Vec3 outward = p.normal * -1.0;
    PortInfo port;
    port.name = p.name;
    port.area_m2 = p.area_m2;
    port.azimuth_deg = rad_to_deg(std::atan2(outward.x, outward.y));
    if (port.azimuth_deg < 0) port.azimuth_deg += 360.0;
    port.tilt_deg = rad_to_deg(std::acos(std::clamp(outward.z, -1.0, 1.0)));
    port.room_side = study::describe_port_facing(scene, k);
    s.ports.push_back(port);
  }
  // Ports that face no decidable way, sensors outside every room or in a solid, no port or
  // no sensor: located errors (study/placement_check.h); dropped sensors are listed.
  const study::PlacementCheck placement =
      study::check_placement(scene, s.scene.grids, proj);
  for (const study::SensorSetPlacement& set : placement.sets)
    if (set.dropped) s.placement_lines.push_back(set.description);
  s.triangle_count = scene.triangle_count();
  std::vector<engine::Material> models;
  for (const MaterialSpec& m : s.scene.materials) models.push_back(engine::Material::from_spec(m));
  Diagnostics diag;
  const project::Simulation& sim = proj.simulation;
  for (const SensorGrid& grid : s.scene.grids) {
    GridInfo info;
    info.name = grid.name;
    info.sensors = grid.points.size();  // after dropping (drop_occluded)
    info.columns = grid.columns;
    info.rows = grid.rows;
    info.spacing_m = grid.spacing_m;
    info.planar = grid.planar;
    info.plane_height_m = grid.plane_height_m;
    if (grid.planar) {
      info.estimate = "receiver plane";
    } else {
      std::size_t free = 0, on_storing = 0, on_other = 0;
      std::size_t first_bad = grid.points.size();
      for (std::size_t i = 0; i < grid.points.size(); ++i) {
        const engine::SensorSupport support = engine::sensor_support(scene, models, grid.points[i]);
        (support == engine::SensorSupport::Free ? free
         : support == engine::SensorSupport::OnStoringSurface ? on_storing : on_other)++;
        if (support != engine::SensorSupport::OnStoringSurface && first_bad == grid.points.size()) first_bad = i;
      }
      if (sim.point_estimate == project::PointEstimate::Gather) {
        info.estimate = "final gather (" + std::to_string(sim.gather_rays) + " rays; " + std::to_string(free) +
                        " in mid air, " + std::to_string(on_storing + on_other) + " on surfaces)";
      } else {
        info.estimate = "surface photons";
        if (first_bad < grid.points.size()) {
          const SensorPoint& p = grid.points[first_bad];
          diag.error(grid.location,
                     "sensor set '" + grid.name + "': " + std::to_string(free + on_other) + " of " +
                         std::to_string(grid.points.size()) +
                         " sensors do not lie on a surface that stores photons (the first, sensor " +
                         std::to_string(first_bad + 1) + " at (" + format_number(p.position.x) + ", " +
                         format_number(p.position.y) + ", " + format_number(p.position.z) + "), is " +
                         (free > 0 && engine::sensor_support(scene, models, p) == engine::SensorSupport::Free
                              ? "in mid air"
                              : "on a black, specular or transparent surface") +
                         "); simulation.point_estimate: surface would give them no photon light: use "
                         "point_estimate: gather");
        }
      }
    }
    s.grids.push_back(info);
  }
  diag.throw_if_errors();
  return s;
}


void print_model_summary(const ModelSummary& s, std::ostream& out) {
  out << "project  " << s.project_path << '\n';
  out << "site     " << (s.site.name.empty() ? std::string("(unnamed)") : s.site.name) << ": "
      << latitude_text(s.site.latitude_deg) << ", " << longitude_text(s.site.longitude_deg)
      << ", " << utc_offset_text(s.site.time_zone_h) << ", elevation "
      << fixed(s.site.elevation_m, 1) << " m, north " << fixed(s.site.north_deg, 2) << " deg";
  if (s.site.utm_zone)
    out << " + meridian convergence " << fixed(s.site.meridian_convergence_deg, 4) << " deg (UTM "
        << *s.site.utm_zone << (s.site.utm_north ? "N" : "S") << ")";
  out << '\n';
  for (std::size_t i = 0; i < s.weather_lines.size(); ++i)
    out << (i == 0 ? "weather  " : "         ") << s.weather_lines[i] << '\n';

  out << "surfaces " << s.surface_count << " polygons, " << s.triangle_count << " triangles\n";
  out << "  " << std::left << std::setw(20) << "material" << std::setw(13) << "type"
      << std::right << std::setw(9) << "surfaces" << std::setw(12) << "area_m2" << '\n';
  for (const MaterialArea& m : s.materials)
    out << "  " << std::left << std::setw(20) << m.name << std::setw(13) << m.type << std::right
        << std::setw(9) << m.surfaces << std::setw(12) << fixed(m.area_m2, 2) << '\n';

  out << "ports    " << s.ports.size() << '\n';
  if (!s.ports.empty())
    out << "  " << std::left << std::setw(20) << "name" << std::right << std::setw(10) << "area_m2"
        << std::setw(13) << "azimuth_deg" << std::setw(10) << "tilt_deg" << "  facing  room side\n";
  for (const PortInfo& p : s.ports)
    out << "  " << std::left << std::setw(20) << p.name << std::right << std::setw(10)
        << fixed(p.area_m2, 2) << std::setw(13) << fixed(p.azimuth_deg, 1) << std::setw(10)
        << fixed(p.tilt_deg, 1) << "  " << std::left << std::setw(6)
        << (p.tilt_deg < 0.5 ? "up" : p.tilt_deg > 179.5 ? "down" : compass_point(p.azimuth_deg)) << "  "
        << p.room_side << std::right << '\n';

  out << "sensors  " << s.grids.size() << (s.grids.size() == 1 ? " grid" : " grids") << '\n';
  for (const GridInfo& g : s.grids) {
    out << "  " << std::left << std::setw(20) << g.name << std::right << std::setw(6) << g.sensors
        << " sensors";
    if (g.columns > 0 && g.rows > 0)
      out << " (" << g.columns << " x " << g.rows << ", spacing " << fixed(g.spacing_m, 2) << " m)";
    if (g.planar) out << " on the plane at " << fixed(g.plane_height_m, 2) << " m";
    out << ", " << g.estimate << '\n';
  }
  for (const std::string& line : s.placement_lines) out << "  " << line << '\n';
}

}  // namespace dayphoton::app
