#include "model_summary.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <ostream>
#include <sstream>

#include "dayphoton/core/polygon.h"
#include "dayphoton/core/units.h"
#include "dayphoton/core/diagnostics.h"
#include "dayphoton/engine/bsdf_material.h"
#include "dayphoton/engine/material_registry.h"
#include "dayphoton/engine/material.h"
#include "dayphoton/engine/scene.h"
#include "dayphoton/engine/sensor_support.h"
#include "dayphoton/study/placement_check.h"
#include "dayphoton/study/point_in_time.h"
#include "dayphoton/study/project_metric_settings.h"
#include "dayphoton/study/run_inputs.h"
#include "dayphoton/study/sun_site.h"
#include "dayphoton/weather/hourly_weather.h"

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

/// A port facing the zenith (as printed, to 0.1 degree).
bool horizontal(const PortInfo& p) { return p.tilt_deg < 0.05; }

/// The weather lines and the sun lines of the summary: which site the sun is computed for (the
/// sentence the run log, summary.json and the report print), the station's distance and the
/// hours with direct light while the sun is below the horizon (study/sun_site.h).
void describe_weather_and_sun(const project::Project& proj, std::vector<std::string>& lines,
                              std::vector<std::string>& sun_lines, sky::SolarSite& solar) {
  const project::Site& ps = proj.site;
  solar = sky::SolarSite{ps.latitude_deg, ps.longitude_deg, ps.time_zone_h, ps.elevation_m};
  // A daylight-factor study reads no weather file (load_project checks the annual study has one).
  if (proj.study == project::StudyKind::DaylightFactor) {
    lines = {proj.weather.path.empty() ? "none: a daylight-factor study (study: daylight_factor)"
                                       : "not used: a daylight-factor study (study: daylight_factor)"};
    sun_lines = {"none: a daylight-factor study traces no sun (CIE overcast sky only)"};
    return;
  }
  const weather::HourlyWeather weather = weather::read_hourly_weather(proj.weather.path);
  const weather::WeatherSite& loc = weather.site;
  lines.clear();
  if (weather.format == weather::WeatherFormat::Wea)  // a .wea header has only a place name
    lines.push_back(proj.weather.path_as_written + ": " + loc.city + (loc.country.empty() ? "" : ", " + loc.country) +
                    " (.wea, the site of its header)");
  else
    lines.push_back(proj.weather.path_as_written + ": " + loc.city + ", " + loc.state + ", " + loc.country +
                    " (WMO " + loc.wmo + ", " + loc.source + ")");
  lines.push_back(latitude_text(loc.latitude_deg) + ", " + longitude_text(loc.longitude_east_deg) + ", " +
                  utc_offset_text(loc.time_zone_h) + ", elevation " + fixed(loc.elevation_m, 1) + " m; " +
                  std::to_string(weather.records.size()) + " hourly records" +
                  (weather.leap_day_present ? " (with 29 February)" : ""));
  for (const Diagnostic& w : weather.warnings) lines.push_back("warning: " + w.location.to_string() + ": " + w.message);
  if (const std::optional<Diagnostic> w = study::partial_year_warning(proj, weather))
    lines.push_back("warning: " + w->location.to_string() + ": " + w->message);
  for (const std::string& line : study::occupancy_summary(proj, weather)) lines.push_back(line);
  // A time zone other than the file's is an error here as in `run` (located at time_zone).
  const study::SunSite site = study::resolve_sun_site(proj.site, weather);
  for (const Diagnostic& w : study::southern_daylight_saving_warnings(proj, site.solar.latitude_deg))
    lines.push_back("warning: " + w.location.to_string() + ": " + w.message);
  if (const std::optional<Diagnostic> w = study::radiation_clock_warning(proj, weather))
    lines.push_back("warning: " + w->location.to_string() + ": " + w->message);
  solar = site.solar;
  sun_lines = {study::sun_site_sentence(site)};
  if (const std::string w = study::station_distance_warning(site); !w.empty()) sun_lines.push_back(w);
  sun_lines.push_back(study::below_horizon_note(study::annual_below_horizon_direct(weather, site),
                                                proj.simulation.sun == project::SunMode::Bins));
}
double mean_rgb(const Vec3& v) { return (v.x + v.y + v.z) / 3.0; }

// One glazing pane as `check` lists it (RGB values as their mean).
std::string describe_pane(const GlazingPaneSpec& p) {
  std::string text = p.thickness_m > 0 ? format_number(p.thickness_m * 1e3) + " mm, " : std::string();
  switch (p.optics) {
    case GlazingPaneSpec::Optics::Transmittance:
      return text + "uncoated, normal transmittance " + fixed(mean_rgb(p.transmittance), 3) + ", n " +
             format_number(p.refractive_index);
    case GlazingPaneSpec::Optics::Absorption:
      return text + "uncoated, absorption " + format_number(mean_rgb(p.absorption_per_m)) + " /m, n " +
             format_number(p.refractive_index);
    case GlazingPaneSpec::Optics::Coated:
      return text + "coated " + (p.coating_on_inner_face ? "inner" : "outer") + " face, normal transmittance " +
             fixed(mean_rgb(p.transmittance), 3) + ", reflectance outer " + fixed(mean_rgb(p.outer_reflectance), 3) +
             " / inner " + fixed(mean_rgb(p.inner_reflectance), 3);
  }
  return text;
}

// Glass and glazing (and openings with a window's frame and maintenance factors): the
// transmittance for light from outside at the listed angles, with the window's factors.
void describe_glazing(const MaterialSpec& spec, MaterialArea& out) {
  const bool registered_glazing =
      spec.type == MaterialType::Registered && engine::material_model_of(spec).takes_transmittance_factor;
  const bool glazed = spec.type == MaterialType::Glass || spec.type == MaterialType::Glazing ||
                      (spec.type == MaterialType::Opening && spec.transmittance_factor != 1.0) ||
                      registered_glazing;
  if (!glazed) return;
  out.glazing = registered_glazing ? spec.model : material_type_name(spec.type);
  if (spec.type == MaterialType::Glazing)
    out.glazing += ", " + std::to_string(spec.panes.size()) + (spec.panes.size() == 1 ? " pane" : " panes");
  if (spec.transmittance_factor != 1.0) out.glazing += ", x " + format_number(spec.transmittance_factor);
  // A window's derived material has its base glazing's panes, listed there.
  for (std::size_t i = 0; spec.transmittance_factor == 1.0 && i < spec.panes.size(); ++i)
    out.panes.push_back("pane " + std::to_string(i + 1) + ": " + describe_pane(spec.panes[i]));
  if (const engine::BsdfMaterialParameters* bsdf = engine::bsdf_parameters(spec)) {
    // A measured BSDF has no straight part: list its hemispherical transmittance from the
    // front (outside) instead, for incidence in the plane of its local x axis (along the slats
    // of a blind whose up vector is vertical).
    out.glazing += " (hemispherical)";
    const KlemsBsdfData& d = *bsdf->data;
    for (double angle_deg : TransmittanceAnglesDeg) {
      const double a = deg_to_rad(angle_deg);
      const int patch = d.basis.patch({std::sin(a), 0, std::cos(a)});
      out.transmittance.push_back(spec.transmittance_factor * d.hemispherical(d.transmission_front, patch));
    }
    return;
  }
  const engine::Material model = engine::Material::from_spec(spec);
  // Pane 1 faces the side the normal points away from: light from outside travels along +n.
  const Vec3 normal{0, 0, 1};
  for (double angle_deg : TransmittanceAnglesDeg) {
    const double a = deg_to_rad(angle_deg);
    const Vec3 t = model.straight_transmittance({std::sin(a), 0, std::cos(a)}, normal);
    out.transmittance.push_back((t.x + t.y + t.z) / 3.0);
  }
}
}  // namespace

ModelSummary summarize_model(const project::Project& proj) {
  ModelSummary s;
  s.project_path = proj.path;
  s.site = proj.site;
  sky::SolarSite solar;
  describe_weather_and_sun(proj, s.weather_lines, s.sun_lines, solar);
  // The points in time whose sun needs no tracing are checked as `run` checks them.
  s.point_in_time_lines = study::check_points_in_time(proj.points_in_time, solar);
  s.scene = project::build_scene_description(proj);
  // Building the Embree scene runs the engine's own validation (degenerate triangles etc.).
  const engine::Scene scene = engine::Scene::build(s.scene);

  s.materials.resize(s.scene.materials.size());
  for (std::size_t i = 0; i < s.scene.materials.size(); ++i) {
    const MaterialSpec& spec = s.scene.materials[i];
    s.materials[i].name = spec.name;
    s.materials[i].type = material_type_as_written(spec);
    describe_glazing(spec, s.materials[i]);
    if (spec.type == MaterialType::Registered) {
      const engine::MaterialModelEntry& model = engine::material_model_of(spec);
      if (model.summary) s.materials[i].description = model.summary(spec);
    }
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
  // Outlines past the walls, exterior geometry that only shades: printed with the scene's warnings.
  s.scene.warnings.insert(s.scene.warnings.end(), placement.warnings.begin(), placement.warnings.end());
  // Sensors next to a cut, gathered: printed as notes.
  s.scene.warnings.insert(s.scene.warnings.end(), placement.notes.begin(), placement.notes.end());
  auto area_of = [&](const std::string& surface_name) {
    for (const Surface& surface : s.scene.surfaces)
      if (surface.name == surface_name) return polygon_area_m2(surface.vertices);
    return 0.0;
  };
  for (const project::RoomSpec& room : proj.geometry.rooms)
    for (const project::RoofLightSpec& l : room.roof_lights) {
      const std::string name = room.name + "." + l.name;
      s.roof_lights.push_back({name, area_of(name), l.well_depth_m});
    }
  for (const project::SystemSpec& system : proj.geometry.systems)
    s.system_lines.push_back(project::describe_system_light(system));
  if (const auto& hb = proj.geometry.honeybee) {
    const project::HoneybeeModel& m = hb->model;
    s.honeybee_lines.push_back(hb->path_as_written + " ('" + m.identifier + "'): " + std::to_string(m.rooms.size()) +
                               " rooms, " + std::to_string(m.surfaces.size()) + " surfaces, " +
                               std::to_string(m.materials.size()) + " modifiers, " + std::to_string(m.grids.size()) +
                               " sensor grids; units " + m.units + ", tolerance " + format_number(m.tolerance_m) + " m");
    s.honeybee_lines.insert(s.honeybee_lines.end(), m.notes.begin(), m.notes.end());
  }
  for (const project::RadianceSceneSpec& r : proj.geometry.radiance) {
    std::string files;
    for (const std::string& f : r.files_as_written) files += (files.empty() ? "" : " ") + f;
    s.radiance_lines.push_back(files + ": units " + r.units + " (" + format_number(r.metres_per_unit) + " m per unit" +
                               (r.units_written ? ")" : ", assumed: the entry has no `units`)") +
                               (r.ports_auto ? ", ports auto" : ""));
  }
  for (const project::InteriorWindow& w : project::interior_windows(proj.geometry)) {
    const std::string name = w.room + "." + w.window;
    s.interior_windows.push_back({name, w.adjoining_room, area_of(name)});
  }
  s.triangle_count = scene.triangle_count();
  const std::vector<engine::Material> models = engine::materials_of(s.scene.materials);
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
    // The plane's z in world coordinates: plane_height_m is its signed distance along the
    // sensors' normal, -z for a grid facing down (a ceiling grid at 2.9 m printed -2.90 m).
    const SensorGrid world = s.scene.world_grid(grid);
    info.plane_z_m = world.plane_normal.z * world.plane_height_m;
    info.facing_down = grid.planar && world.plane_normal.z < 0;
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
          const Vec3 world = s.scene.world_of(p.position);
          diag.error(grid.location,
                     "sensor set '" + grid.name + "': " + std::to_string(free + on_other) + " of " +
                         std::to_string(grid.points.size()) +
                         " sensors do not lie on a surface that stores photons (the first, sensor " +
                         std::to_string(first_bad + 1) + " at (" + format_coordinate(world.x) + ", " +
                         format_coordinate(world.y) + ", " + format_coordinate(world.z) + "), is " +
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
  out << "site     " << (s.site.name.empty() ? std::string("(unnamed)") : s.site.name) << ": ";
  if (s.site.from_weather)
    out << "the weather file's site (from_weather)";
  else
    out << latitude_text(s.site.latitude_deg) << ", " << longitude_text(s.site.longitude_deg) << ", "
        << utc_offset_text(s.site.time_zone_h) << ", elevation " << fixed(s.site.elevation_m, 1) << " m";
  out << ", north " << fixed(s.site.north_deg, 2) << " deg";
  if (s.site.utm_zone)
    out << " + meridian convergence " << fixed(s.site.meridian_convergence_deg, 4) << " deg (UTM "
        << *s.site.utm_zone << (s.site.utm_north ? "N" : "S") << ")";
  out << '\n';
  for (std::size_t i = 0; i < s.weather_lines.size(); ++i)
    out << (i == 0 ? "weather  " : "         ") << s.weather_lines[i] << '\n';
  for (std::size_t i = 0; i < s.sun_lines.size(); ++i)
    out << (i == 0 ? "sun      " : "         ") << s.sun_lines[i] << '\n';

  out << "surfaces " << s.surface_count << " polygons, " << s.triangle_count << " triangles\n";
  // Material names longer than the column (imported modifiers) widen it.
  int name_width = 20;
  for (const MaterialArea& m : s.materials) name_width = std::max(name_width, static_cast<int>(m.name.size()) + 1);
  out << "  " << std::left << std::setw(name_width) << "material" << std::setw(13) << "type"
      << std::right << std::setw(9) << "surfaces" << std::setw(12) << "area_m2" << '\n';
  for (const MaterialArea& m : s.materials)
    out << "  " << std::left << std::setw(name_width) << m.name << std::setw(13) << m.type << std::right
        << std::setw(9) << m.surfaces << std::setw(12) << fixed(m.area_m2, 2) << '\n'
        << (m.description.empty() ? "" : "    " + m.description + "\n");
  bool glazing_header = false;
  for (const MaterialArea& m : s.materials) {
    if (m.transmittance.empty()) continue;
    if (!glazing_header) {
      out << "glazing  transmittance from outside (mean of RGB) by angle of incidence\n";
      out << "  " << std::left << std::setw(name_width) << "material" << std::setw(24) << "kind" << std::right;
      for (double a : TransmittanceAnglesDeg) out << std::setw(8) << fixed(a, 0) + " deg";
      out << '\n';
      glazing_header = true;
    }
    out << "  " << std::left << std::setw(name_width) << m.name << std::setw(24) << m.glazing << std::right;
    for (double t : m.transmittance) out << std::setw(8) << fixed(t, 3);
    out << '\n';
    for (const std::string& pane : m.panes) out << "    " << pane << '\n';
  }

  out << "ports    " << s.ports.size() << '\n';
  if (!s.ports.empty())
    out << "  " << std::left << std::setw(20) << "name" << std::right << std::setw(10) << "area_m2"
        << std::setw(13) << "azimuth_deg" << std::setw(10) << "tilt_deg" << "  facing  room side\n";
  for (const PortInfo& p : s.ports)
    out << "  " << std::left << std::setw(20) << p.name << std::right << std::setw(10)
        << fixed(p.area_m2, 2) << std::setw(13)
        // A horizontal opening (a roof light) faces the zenith; it has no azimuth.
        << (horizontal(p) ? std::string("-") : fixed(p.azimuth_deg, 1)) << std::setw(10)
        << fixed(p.tilt_deg, 1) << "  " << std::left << std::setw(6)
        << (p.tilt_deg < 0.5 ? "up" : p.tilt_deg > 179.5 ? "down" : compass_point(p.azimuth_deg)) << "  "
        << p.room_side << std::right << '\n';

  if (!s.roof_lights.empty()) {
    out << "roof lights " << s.roof_lights.size() << " (glazing: the ports above)\n";
    out << "  " << std::left << std::setw(20) << "name" << std::right << std::setw(10) << "area_m2"
        << std::setw(15) << "well_depth_m" << '\n';
    for (const RoofLightInfo& l : s.roof_lights)
      out << "  " << std::left << std::setw(20) << l.name << std::right << std::setw(10) << fixed(l.area_m2, 2)
          << std::setw(15) << fixed(l.well_depth_m, 2) << (l.well_depth_m > 0 ? "" : "  flush") << '\n';
  }
  if (!s.interior_windows.empty()) {
    out << "interior windows " << s.interior_windows.size()
        << " (glazing between rooms, not ports: light reaches them through the exterior openings)\n";
    for (const InteriorWindowInfo& w : s.interior_windows)
      out << "  " << std::left << std::setw(20) << w.name << std::right << std::setw(10) << fixed(w.area_m2, 2)
          << "  into room '" << w.adjoining_room << "'\n";
  }

  if (!s.system_lines.empty()) {
    out << "systems  " << s.system_lines.size() << '\n';
    for (const std::string& line : s.system_lines) out << "  " << line << '\n';
  }

  for (std::size_t i = 0; i < s.honeybee_lines.size(); ++i)
    out << (i == 0 ? "honeybee " : "  ") << s.honeybee_lines[i] << '\n';
  if (!s.radiance_lines.empty()) {
    out << "radiance " << s.radiance_lines.size() << (s.radiance_lines.size() == 1 ? " scene" : " scenes") << '\n';
    for (const std::string& line : s.radiance_lines) out << "  " << line << '\n';
  }

  out << "sensors  " << s.grids.size() << (s.grids.size() == 1 ? " grid" : " grids") << '\n';
  for (const GridInfo& g : s.grids) {
    out << "  " << std::left << std::setw(20) << g.name << std::right << std::setw(6) << g.sensors
        << " sensors";
    if (g.columns > 0 && g.rows > 0)
      out << " (" << g.columns << " x " << g.rows << ", spacing " << fixed(g.spacing_m, 2) << " m)";
    if (g.planar) out << " on the plane at " << fixed(g.plane_z_m, 2) << " m" << (g.facing_down ? " facing down" : "");
    out << ", " << g.estimate << '\n';
  }
  for (const std::string& line : s.placement_lines) out << "  " << line << '\n';
  // What an imported RADIANCE scene left out or approximated (docs/radiance-import.md).
  for (const Diagnostic& w : s.scene.warnings)
    out << (w.severity == Severity::Note ? "note     " : "warning  ") << w.location.to_string() << ": " << w.message
        << '\n';
  if (!s.point_in_time_lines.empty()) {
    out << "points in time " << s.point_in_time_lines.size() << '\n';
    for (const std::string& line : s.point_in_time_lines) out << "  " << line << '\n';
  }
}

}  // namespace dayphoton::app
