// Filling the results model from the run's data in memory; see results_model_builder.h.
#include "dayphoton/study/results_model_builder.h"

#include <cmath>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <variant>

#include <nlohmann/json.hpp>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/polygon.h"
#include "dayphoton/core/units.h"
#include "dayphoton/engine/material.h"
#include "dayphoton/study/point_in_time.h"
#include "dayphoton/study/result_files.h"
#include "dayphoton/study/sensor_lattice.h"
#include "dayphoton/study/shading_materials.h"

namespace dayphoton::study {

namespace {

/// A setting's value as the report shows it: text as is, booleans yes/no, numbers shortest.
std::string setting_text(const nlohmann::json& v) {
  if (v.is_string()) return v.get<std::string>();
  if (v.is_boolean()) return v.get<bool>() ? "yes" : "no";
  if (v.is_number_integer() || v.is_number_unsigned()) return v.dump();
  if (v.is_number()) return format_number(v.get<double>());
  return v.dump();
}

GridOrientation orientation_of(const std::vector<SensorPoint>& points) {
  bool up = true, side = true;
  for (const SensorPoint& p : points) {
    const double z = std::fabs(p.normal.z) / std::max(1e-300, length(p.normal));
    up = up && z > 1 - 1e-6;
    side = side && z < 1e-6;
  }
  return up ? GridOrientation::Horizontal : side ? GridOrientation::Vertical : GridOrientation::Tilted;
}

}  // namespace

std::string relative_folder(const std::string& output_dir, const std::string& folder) {
  const std::string r = std::filesystem::path(folder).lexically_normal().lexically_relative(
                                                          std::filesystem::path(output_dir).lexically_normal())
                            .generic_string();
  return r == "." ? std::string() : r;
}

ResultsModel results_model_header(const project::Project& project, const std::string& version, const SunSite* sun_site,
                                  const sky::BelowHorizonDirect* below, const nlohmann::json& simulation,
                                  const std::vector<std::string>& notes) {
  ResultsModel m;
  m.project_file = project.path;
  m.project_name = std::filesystem::path(project.path).filename().string();
  m.title = project_title(project.path);
  m.dayphoton_version = version;
  m.compiler = __VERSION__;
  m.study = project::study_kind_name(project.study);
  const project::Site& ps = project.site;
  m.site_name = ps.name;
  const sky::SolarSite solar =
      sun_site ? sun_site->solar : sky::SolarSite{ps.latitude_deg, ps.longitude_deg, ps.time_zone_h, ps.elevation_m};
  m.latitude_deg = solar.latitude_deg;
  m.longitude_deg = solar.longitude_deg;
  m.time_zone_h = solar.time_zone_h;
  m.elevation_m = solar.elevation_m;
  m.sun_from_weather = ps.from_weather;
  if (sun_site) {
    m.sun_site = std::array<double, 4>{solar.latitude_deg, solar.longitude_deg, solar.time_zone_h, solar.elevation_m};
    m.sun_sentence = sun_site_sentence(*sun_site);
    m.station_distance_km = sun_site->station_distance_km;
  }
  if (below) {
    m.below_horizon_hours = below->records;
    m.below_horizon_their_sun = project.simulation.sun == project::SunMode::Bins ? "left out"
                                                                                : "spread into the nearest sky patches";
  }
  m.weather_file = project.study == project::StudyKind::Annual ? project.weather.path : std::string();
  m.basis = project.simulation.basis == project::SkyBasis::Tregenza ? "tregenza" : "reinhart";
  m.reinhart_mf = project.simulation.basis == project::SkyBasis::Tregenza ? 1 : project.simulation.reinhart_mf;
  m.ground_reflectance = project.simulation.ground_reflectance;
  for (auto it = simulation.begin(); it != simulation.end(); ++it) {
    std::string name = it.key();
    for (char& c : name)
      if (c == '_') c = ' ';
    m.settings.push_back({name, setting_text(*it)});
  }
  m.notes = notes;
  if (project.sunlight_exposure) {
    const project::SunlightExposureSpec& e = *project.sunlight_exposure;
    m.sunlight_exposure = SunlightExposureSettings{e.month, e.day, PointInTimeSolarYear, e.min_altitude_deg, e.time_step_min};
  }
  return m;
}

std::string project_title(const std::string& project_path) {
  const std::filesystem::path p = std::filesystem::absolute(project_path).lexically_normal();
  const std::string stem = p.stem().string();
  if (p.filename() == "project.yaml" && p.has_parent_path() && !p.parent_path().filename().empty())
    return p.parent_path().filename().string();
  return stem;
}

void set_building(CaseResult& c, const project::Project& project, const SceneDescription& scene) {
  c.materials.clear();
  c.rooms.clear();
  c.opening_area_m2 = 0;
  c.blinds_in_place.clear();
  for (const project::SystemSpec& system : project.geometry.systems)
    if (system.enabled && std::holds_alternative<project::BlindsSpec>(system.params))
      c.blinds_in_place.push_back(system.name);
  c.shading_materials_in_place.clear();
  std::vector<double> area(scene.materials.size(), 0.0);
  for (const Surface& s : scene.surfaces) {
    if (s.material >= 0 && static_cast<std::size_t>(s.material) < area.size())
      area[static_cast<std::size_t>(s.material)] += polygon_area_m2(s.vertices);
    if (s.port || s.port_if_outdoors) c.opening_area_m2 += polygon_area_m2(s.vertices);
  }
  for (std::size_t i = 0; i < scene.materials.size(); ++i) {
    if (area[i] <= 0) continue;  // defined but on no surface of this case
    const MaterialSpec& spec = scene.materials[i];
    if (const std::optional<std::string> why = operable_shading_reason(spec))
      c.shading_materials_in_place.push_back({spec.name, *why});
    MaterialSummary m;
    m.name = spec.name;
    m.type = material_type_as_written(spec);
    m.area_m2 = area[i];
    const engine::Material model = engine::Material::from_spec(spec);
    switch (spec.type) {
      case MaterialType::Lambertian:
      case MaterialType::Metal:
      case MaterialType::Mirror:
      case MaterialType::Translucent:
        m.reflectance = dot(RgbLuminanceWeights, spec.reflectance);
        m.specularity = spec.type == MaterialType::Mirror ? 1.0 : spec.specularity;
        break;
      case MaterialType::Registered: m.reflectance = dot(RgbLuminanceWeights, model.diffuse_reflectance()); break;
      default: break;
    }
    // Light from outside at normal incidence travels along +n (pane 1 faces away from n).
    const Vec3 n{0, 0, 1};
    const double t = dot(RgbLuminanceWeights, model.straight_transmittance(n, n) + model.diffuse_transmittance());
    if (t > 0) m.transmittance = t;
    c.materials.push_back(m);
  }
  // Windows between two rooms are listed but are not openings to the outside: they count in
  // neither the window area nor the window-to-wall ratio.
  const std::vector<project::InteriorWindow> interior = project::interior_windows(project.geometry);
  auto is_interior = [&](const std::string& room, const std::string& window) {
    for (const project::InteriorWindow& w : interior)
      if (w.room == room && w.window == window) return true;
    return false;
  };
  for (const project::RoomSpec& r : project.geometry.rooms) {
    RoomSummary room;
    room.name = r.name;
    room.width_m = r.size_m.x;
    room.depth_m = r.size_m.y;
    room.height_m = r.size_m.z;
    room.floor_area_m2 = r.size_m.x * r.size_m.y;
    bool glazed[4] = {false, false, false, false};
    for (const project::WindowSpec& w : r.windows) {
      const double a = w.width_m * w.height_m;
      const bool inner = is_interior(r.name, w.name);
      room.windows.push_back({w.name, std::string(project::wall_name(w.wall)) + (inner ? " (interior)" : ""), w.width_m,
                              w.height_m, w.sill_m, a, w.material, w.frame_factor, w.maintenance_factor});
      if (inner) continue;
      room.window_area_m2 += a;
      glazed[static_cast<int>(w.wall)] = true;
    }
    for (int k = 0; k < 4; ++k) {
      if (!glazed[k]) continue;
      const project::Wall wall = static_cast<project::Wall>(k);
      const double length = wall == project::Wall::South || wall == project::Wall::North ? r.size_m.x : r.size_m.y;
      room.glazed_wall_area_m2 += length * r.size_m.z;
    }
    for (const project::RoofLightSpec& l : r.roof_lights) {
      const double a = l.width_m * l.length_m;
      room.windows.push_back({l.name, "roof", l.width_m, l.length_m, l.well_depth_m, a, l.material, 1, 1});
      room.roof_light_area_m2 += a;
    }
    c.rooms.push_back(room);
  }
}

CaseResult results_case(const std::string& kind, const std::string& name, const std::string& folder,
                        const std::vector<std::string>& changes) {
  CaseResult c;
  c.kind = kind;
  c.name = name;
  c.folder = folder;
  c.changes = changes;
  return c;
}

namespace {
/// A polygon of `scene` in world coordinates (SceneDescription::world_origin_m).
Polygon3 world_polygon(const SceneDescription& scene, const std::vector<Vec3>& vertices) {
  Polygon3 world;
  for (const Vec3& v : vertices) world.push_back(scene.world_of(v));
  return world;
}
}  // namespace

void set_plan_geometry(CaseResult& c, const SceneDescription& scene) {
  c.openings.clear();
  c.systems.clear();
  for (const Surface& s : scene.surfaces) {
    // Port candidates of an imported scene (glazing under `ports: auto`) count as openings:
    // which of them face outdoors is decided by the engine's ray scene.
    if (s.port || s.port_if_outdoors) c.openings.push_back(world_polygon(scene, s.vertices));
    if (s.outdoor_scatterer) c.systems.push_back(world_polygon(scene, s.vertices));
  }
}

CaseResult operated_case(const CaseResult& base, const std::string& name, const std::string& folder) {
  CaseResult c = base;
  c.kind = "operated";
  c.name = name;
  c.folder = folder;
  c.changes.clear();
  c.sunlight_exposure.clear();  // the sun's hours are the open and shaded cases' own geometry
  for (GridResult& g : c.grids) {
    g.quantities.clear();
    g.daylight_factor.reset();
    g.annual.reset();
    g.points_in_time.clear();
    g.has_illuminance_table = false;
  }
  return c;
}

void add_operated_grid(CaseResult& c, const std::string& grid, const std::string& folder, const AnnualStudy& study,
                       const AnnualStudySettings& settings, const AnnualOutputs& which) {
  for (GridResult& g : c.grids)
    if (g.name == grid) {
      g.folder = folder;
      add_annual(g, study, settings, which);
      return;
    }
  throw std::logic_error("operated grid '" + grid + "' is not a grid of the base case");
}

GridResult results_grid(const SensorGrid& grid, const std::string& folder, const CaseResult& c,
                        std::size_t dropped_outside_rooms, std::size_t dropped_inside_solid,
                        std::size_t dropped_on_cut_surface, std::size_t dropped_enclosed) {
  GridResult g;
  g.name = grid.name;
  g.folder = folder;
  for (const SensorPoint& p : grid.points) {
    g.positions_m.push_back(p.position);
    g.normals.push_back(p.normal);
  }
  g.area_m2 = grid.area_m2;
  g.orientation = orientation_of(grid.points);
  g.lattice = sensor_lattice(grid.points);
  g.outline = grid.outline;
  g.spacing_m = grid.spacing_m;
  g.dropped_outside_rooms = dropped_outside_rooms;
  g.dropped_inside_solid = dropped_inside_solid;
  g.dropped_on_cut_surface = dropped_on_cut_surface;
  g.dropped_enclosed = dropped_enclosed;
  // A plan (a horizontal grid, or a point set without an outline) shows every opening; an
  // elevation (a wall or rectangle grid) only those in its wall, since any other port would
  // be projected onto it as if it were in that wall.
  const Vec3 n = grid.plane_normal;
  g.plan = grid.planar || grid.outline.size() < 3 || std::fabs(n.z) > 1 - 1e-9;
  for (std::size_t k = 0; k < c.openings.size(); ++k) {
    const Polygon3& w = c.openings[k];
    bool drawn = g.plan;
    if (!drawn && w.size() >= 3 && std::fabs(dot(polygon_normal(w), n)) >= 1 - 1e-6) {
      drawn = true;
      for (const Vec3& p : w) drawn = drawn && std::fabs(dot(p - grid.outline[0], n)) <= ElevationWindowDistance_m;
    }
    if (drawn) g.openings_drawn.push_back(static_cast<int>(k));
  }
  return g;
}

void add_daylight_factor(GridResult& grid, const GridStatistics& st, const DaylightFactorUncertainty& u) {
  DaylightFactorSummary d;
  d.mean_percent = st.mean;
  d.median_percent = st.median;
  d.min_percent = st.min;
  d.max_percent = st.max;
  d.uniformity = st.uniformity;
  d.area_at_or_above_percent = st.area_at_or_above_percent;
  d.rms_relative_stderr_percent = u.rms_relative_stderr_percent;
  d.max_relative_stderr_percent = u.max_relative_stderr_percent;
  d.sensors_with_daylight = u.sensors_with_light;
  grid.daylight_factor = d;
  grid.quantities.insert(grid.quantities.begin(),
                         SensorQuantity{"daylight_factor", "daylight_factor.csv", "df_percent", "daylight_factor",
                                        "daylight factor", "%", QuantityScale::DaylightFactor, "daylight factor"});
}

void add_annual(GridResult& grid, const AnnualStudy& study, const AnnualStudySettings& settings,
                const AnnualOutputs& which) {
  const metrics::MetricSettings& m = settings.metrics;
  AnnualSummary a;
  a.sensors = study.sensors.size();
  a.time_steps = study.illuminance.step_count();
  a.occupied_hours = study.occupied_hours;
  a.da_threshold_lux = m.da_threshold_lux;
  a.udi_lower_lux = m.udi_lower_lux;
  a.udi_upper_original_lux = m.udi_upper_original_lux;
  a.udi_upper_revised_lux = m.udi_upper_revised_lux;
  a.sda_time_fraction = m.sda_time_fraction;
  a.ase_threshold_lux = m.ase_threshold_lux;
  a.ase_hours = m.ase_hours;
  const metrics::OccupancyPlan& plan = settings.occupancy;
  switch (plan.kind) {
    case metrics::OccupancyPlan::Kind::Daily:
      a.occupancy.kind = "daily";
      a.occupancy.start_h = plan.daily.start_h;
      a.occupancy.end_h = plan.daily.end_h;
      break;
    case metrics::OccupancyPlan::Kind::Weekly: a.occupancy.kind = "weekly"; break;
    case metrics::OccupancyPlan::Kind::Hourly: a.occupancy.kind = "hourly"; break;
  }
  if (plan.kind != metrics::OccupancyPlan::Kind::Daily) a.occupancy.start_h = a.occupancy.end_h = 0;
  a.occupancy.description = plan.description();
  // The definition (what recorded_annual_settings rebuilds the plan from).
  auto windows = [](const metrics::DayHours& hours) {
    OccupancySummary::Windows w;
    for (const metrics::HourWindow& h : hours) w.emplace_back(h.start_h, h.end_h);
    return w;
  };
  if (plan.kind == metrics::OccupancyPlan::Kind::Weekly) {
    for (std::size_t d = 0; d < 7; ++d) a.occupancy.week[d] = windows(plan.week[d]);
    a.occupancy.holiday_hours = windows(plan.holiday_hours);
    for (const metrics::DateRange& h : plan.holidays)
      a.occupancy.holidays.push_back({h.from_month, h.from_day, h.to_month, h.to_day});
  }
  if (plan.january_1) a.occupancy.january_1 = metrics::weekday_name(*plan.january_1);
  a.occupancy.daylight_saving = plan.daylight_saving == metrics::DaylightSaving::Eu   ? "eu"
                                : plan.daylight_saving == metrics::DaylightSaving::Us ? "us"
                                                                                        : "none";
  if (plan.kind == metrics::OccupancyPlan::Kind::Hourly) {
    a.occupancy.hourly.reserve(plan.hourly.size());
    for (bool occupied : plan.hourly) a.occupancy.hourly += occupied ? '1' : '0';
    a.occupancy.hourly_source = plan.hourly_source;
  }
  const metrics::SensorMetrics& mean = study.grid.mean;
  a.da_percent = mean.da_percent;
  a.cda_percent = mean.cda_percent;
  a.da_max_percent = mean.da_max_percent;
  a.udi_below_percent = mean.udi_below_percent;
  a.udi_achieved_percent = mean.udi_original_percent;
  a.udi_above_original_percent = mean.udi_above_original_percent;
  a.udi_supplementary_percent = mean.udi_supplementary_percent;
  a.udi_autonomous_percent = mean.udi_autonomous_percent;
  a.udi_above_revised_percent = mean.udi_above_revised_percent;
  a.mean_occupied_lux = mean.mean_occupied_lux;
  a.sda_percent = study.grid.sda_percent;
  for (const metrics::SensorMetrics& s : study.sensors) a.sda_sensors += s.da_percent >= 100.0 * m.sda_time_fraction;
  if (study.grid.ase_percent >= 0) a.ase_percent = study.grid.ase_percent;
  if (!study.grid.en17037.empty()) {
    a.en17037_daylight_hours = study.illuminance.step_count() / 2;
    a.en17037_daylight_hours_source = study.daylight_hours_source;
    a.en17037_openings = metrics::en17037_openings_name(m.en17037_openings);
    a.en17037_target_area_required_percent = metrics::en17037_target_area_required_percent(m);
    for (std::size_t i = 0; i < study.grid.en17037.size(); ++i) {
      const metrics::En17037Result& r = study.grid.en17037[i];
      a.en17037.push_back({r.level, metrics::En17037Levels[i].target_lux, metrics::En17037Levels[i].minimum_target_lux,
                           r.target_area_percent, r.minimum_target_area_percent, r.passes});
    }
  }
  a.sky = study.sky_description;
  grid.annual = a;
  grid.has_illuminance_table = which.illuminance;
  if (!which.metrics) return;
  // The columns of metrics.csv, named once by result_files.h (index,x,y,z first).
  const std::vector<std::string> c = metrics_csv_columns(m, false);
  const std::string x = format_number(m.da_threshold_lux), low = format_number(m.udi_lower_lux),
                    up1 = format_number(m.udi_upper_original_lux), up2 = format_number(m.udi_upper_revised_lux);
  auto stem = [](const std::string& column) { return column.substr(0, column.size() - std::string("_percent").size()); };
  grid.quantities.push_back({stem(c[4]), "metrics.csv", c[4], "da", "daylight autonomy (" + x + " lx)", "%",
                             QuantityScale::Percent, "daylight autonomy"});
  grid.quantities.push_back({stem(c[8]), "metrics.csv", c[8], "udi_achieved",
                             "useful daylight illuminance, achieved (" + low + "-" + up1 + " lx)", "%",
                             QuantityScale::Percent, "UDI achieved"});
  grid.quantities.push_back({stem(c[11]), "metrics.csv", c[11], "udi_autonomous",
                             "useful daylight illuminance, autonomous (" + x + "-" + up2 + " lx)", "%",
                             QuantityScale::Percent, "UDI autonomous"});
  grid.quantities.push_back({"mean_occupied_illuminance", "metrics.csv", c[13], "mean_occupied_illuminance",
                             "mean illuminance over the occupied hours", "lx", QuantityScale::Illuminance,
                             "mean illuminance over the occupied hours"});
}

void add_verdict_uncertainty(GridResult& grid, const VerdictUncertainty& u) {
  if (!grid.annual) return;
  grid.annual->da_verdicts_within_2_sigma = u.da_verdicts_uncertain;
  grid.annual->da_verdicts_within_2_sigma_area_percent = u.da_verdicts_uncertain_area_percent;
}

void add_point_in_time(GridResult& grid, const std::string& name, const std::string& sky, const GridStatistics& st,
                       const DaylightFactorUncertainty& u, const PointInTimeAccuracy* accuracy) {
  grid.points_in_time.push_back({name, sky, st.mean, st.median, st.min, st.max, st.uniformity,
                                 u.rms_relative_stderr_percent, u.max_relative_stderr_percent, std::nullopt});
  if (accuracy)
    grid.points_in_time.back().accuracy = PointInTimeSummary::AccuracyReached{
        accuracy->target_percent, accuracy->reached_percent, accuracy->status, accuracy->stop_reason,
        accuracy->status == "met" ? std::string() : accuracy->limiting_part};
  grid.quantities.push_back({"point_in_time_" + name, "point_in_time.csv", name + "_lux", "point_in_time",
                             "illuminance at point in time '" + name + "'", "lx", QuantityScale::Illuminance,
                             "illuminance"});
}

}  // namespace dayphoton::study
