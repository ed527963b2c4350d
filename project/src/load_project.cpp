// load_project: stage 2 of project loading (STYLE.md A.3): located YAML tree -> typed Project.
// Every section is read through a ParamReader against its schema (project_schema.cpp), so
// unknown keys, missing keys, wrong types, ranges and enumerations are checked uniformly and
// located. Names are checked for uniqueness per kind, and names that become folders (grids,
// point sets, variants) against the one rule of path_name.h; outputs.folder must lie inside
// the project's folder unless allowed (LoadOptions, folder_outside_project). Material and
// room references (and the materials a variant replaces) are resolved after everything is
// read, with "did you mean" hints. Rules between keys (occupancy start < end, UDI band order) are checked here.
// Daylight systems are read against their type's schema section; a variant's changes to a
// system are merged into the base system's node and read again as a whole; the elements it
// adds are read like the base's, and what it removes and adds is checked against the base
// once everything is read (variant_checks.h).
// All errors are collected (Diagnostics, cap 50) and thrown together as one InputError. The
// file format is described in docs/project-format.md.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <tuple>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/project/honeybee_model.h"
#include "dayphoton/project/length_units.h"
#include "dayphoton/project/path_name.h"
#include "dayphoton/core/input_file.h"
#include "dayphoton/engine/material_registry.h"
#include "dayphoton/project/project.h"
#include "dayphoton/project/project_schema.h"
#include "dayphoton/project/site_geodesy.h"
#include "occupancy_reader.h"
#include "param_reader.h"
#include "sensor_areas.h"
#include "variant_checks.h"
#include "yaml_document.h"

namespace dayphoton::project {

namespace {

namespace fs = std::filesystem;

struct NameUse {
  std::string name;
  SourceLocation location;
};

/// Names of one kind (rooms, windows, ...): reports a second definition of the same name.
class NameSet {
 public:
  explicit NameSet(std::string kind) : m_kind(std::move(kind)) {}
  void add(const std::string& name, const SourceLocation& loc, Reporter& reporter) {
    auto [it, inserted] = m_first.emplace(name, loc);
    if (!inserted)
      reporter.error(loc, "duplicate " + m_kind + " name '" + name + "' (first defined at line " +
                              std::to_string(it->second.line) + ")");
  }
  bool contains(const std::string& name) const { return m_first.count(name) > 0; }
  /// The name where it was first defined (`name` must have been added).
  Located<std::string> first(const std::string& name) const { return {name, m_first.at(name)}; }
  std::vector<std::string> names() const {
    std::vector<std::string> n;
    for (const auto& kv : m_first) n.push_back(kv.first);
    return n;
  }

 private:
  std::string m_kind;
  std::map<std::string, SourceLocation> m_first;
};

/// Names that become folders (path_name.h): the rule, names reserved by the output layout,
/// and names that differ only in case (one folder on case-insensitive file systems).
class FolderNames {
 public:
  FolderNames(std::vector<std::string> reserved, std::string reserved_why)
      : m_reserved(std::move(reserved)), m_reserved_why(std::move(reserved_why)) {}
  /// `kind`: "grid", "variant", ... as the message names it.
  void add(const std::string& kind, const std::string& name, const SourceLocation& loc,
           Reporter& reporter) {
    const std::string shown =
        "'" + printable_name(name.substr(0, MaxPathNameLength)) +
        (name.size() > MaxPathNameLength ? "...'" : "'");
    if (const std::string problem = path_name_problem(name); !problem.empty()) {
      reporter.error(loc, kind + " name " + shown + " is not a portable folder name: " + problem +
                              " (" + PathNameRule + ")");
      return;
    }
    const std::string fold = path_name_fold(name);
    for (const std::string& reserved : m_reserved)
      if (fold == path_name_fold(reserved)) {
        reporter.error(loc, kind + " name " + shown + " is reserved: " + m_reserved_why);
        return;
      }
    const auto [it, inserted] = m_first.emplace(fold, NameUse{name, loc});
    if (!inserted && it->second.name != name)
      reporter.error(loc, kind + " name " + shown + " differs from '" + it->second.name +
                              "' (line " + std::to_string(it->second.location.line) +
                              ") only in case: on Windows and macOS both are one folder");
  }

 private:
  std::vector<std::string> m_reserved;
  std::string m_reserved_why;
  std::map<std::string, NameUse> m_first;  ///< by path_name_fold
};

class Loader {
 public:
  Loader(Project& project, Reporter& reporter, const LoadOptions& options)
      : m_project(project), m_reporter(reporter), m_options(options) {}

  void load(const YamlNode& root) {
    if (root.is_null()) {
      if (!m_reporter.has_errors())
        m_reporter.error(root.location, "the project file is empty");
      return;
    }
    if (!expect_map(root, "project", m_reporter)) return;
    ParamReader r(root, schema_section("project"), m_reporter);
    long long version = 1;
    if (r.read_integer("version", version)) m_project.format_version = static_cast<int>(version);
    if (const YamlNode* n = r.take("site")) read_site(*n);
    std::string study;
    const bool study_written = r.has("study");
    m_project.study_location = r.location_of("study");
    if (r.read_choice("study", study))
      m_project.study = study == "daylight_factor" ? StudyKind::DaylightFactor : StudyKind::Annual;
    const YamlNode* weather = r.take("weather");
    if (weather && weather->is_null())
      m_reporter.error(weather->location, "missing value for 'weather'");
    else if (weather)
      read_weather(*weather);
    const YamlNode* materials = r.take("materials");
    if (materials) read_materials(*materials);
    if (const YamlNode* n = r.take("geometry")) read_geometry(*n);
    // A RADIANCE scene or a Honeybee model brings its own materials; otherwise every project
    // needs some.
    if (!materials && m_project.geometry.radiance.empty() && !m_honeybee_given)
      m_reporter.error(root.location, "missing required key 'materials' in project");
    if (const YamlNode* n = r.take("sensors")) read_sensors(*n);
    if (const YamlNode* n = r.take("simulation")) {
      read_simulation(*n);
    } else {
      YamlNode empty_map;
      empty_map.kind = YamlNode::Kind::Map;
      empty_map.location = root.location;
      read_simulation(empty_map);
    }
    if (const YamlNode* n = r.take("outputs")) {
      read_outputs(*n);
    } else {
      YamlNode empty_map;
      empty_map.kind = YamlNode::Kind::Map;
      empty_map.location = root.location;
      read_outputs(empty_map);
    }
    if (const YamlNode* n = r.take("metrics")) {
      read_metrics(*n);
    } else {
      YamlNode empty_map;  // every key from its schema default
      empty_map.kind = YamlNode::Kind::Map;
      empty_map.location = root.location;
      read_metrics(empty_map);
    }
    for_each_item(r, "variants", [&](const YamlNode& n) { read_variant(n); });
    if (const YamlNode* n = r.take("operation")) read_operation(*n);
    for_each_item(r, "points_in_time", [&](const YamlNode& n) { read_point_in_time(n); });
    if (const YamlNode* n = r.take("sunlight_exposure")) read_sunlight_exposure(*n);
    if (const YamlNode* n = r.take("limits")) read_limits(*n);
    r.finish();
    check_photon_limit();

    check_study_kind(root, study_written, weather);
    check_references();
    for (std::size_t i = 0; i < m_project.variants.size(); ++i)
      check_variant(m_project, m_project.variants[i], m_variant_added[i], m_reporter);
  }

 private:
  // ---- paths ----------------------------------------------------------------------------
  std::string resolve(const std::string& written) const {
    const fs::path p(written);
    if (p.is_absolute() || m_project.directory.empty()) return p.lexically_normal().string();
    return (fs::path(m_project.directory) / p).lexically_normal().string();
  }

  /// Resolve a path value and check that a regular file exists there.
  bool existing_file(const std::string& what, const std::string& written,
                     const SourceLocation& loc, std::string& resolved) {
    resolved = resolve(written);
    const std::string problem = input_file_problem(resolved);
    if (problem == "not found") {
      m_reporter.error(loc, what + " '" + written + "' not found (looked for '" + resolved + "')");
      return false;
    }
    if (!problem.empty()) {
      m_reporter.error(loc, what + " '" + written + "' " + problem);
      return false;
    }
    return true;
  }

  // ---- site -----------------------------------------------------------------------------
  void read_site(const YamlNode& node) {
    if (!expect_map(node, "site", m_reporter)) return;
    Site& site = m_project.site;
    site.location = node.location;
    ParamReader r(node, schema_section("site"), m_reporter);
    r.read_string("name", site.name);
    r.read_bool("from_weather", site.from_weather);
    m_from_weather_location = r.location_of("from_weather");
    r.read_number("north", site.north_deg);
    if (r.has("north")) m_site_north_location = r.location_of("north");
    if (site.from_weather) {
      // One source of truth: the header's site is the sun's; a second one in the project
      // would be ignored, which is what from_weather must not do silently.
      for (const char* key : {"latitude", "longitude", "time_zone", "elevation", "utm_zone"})
        if (r.has(key)) {
          r.take(key);
          m_reporter.error(r.location_of(key),
                           std::string("'") + key + "' is not used with from_weather: true (the sun is computed for "
                               "the weather file header's site); remove it, or set from_weather: false to compute "
                               "the sun for this site" +
                               (std::string(key) == "utm_zone" ? " (a UTM zone needs the site's latitude and longitude)"
                                                               : ""));
        }
      r.finish();
      return;
    }
    for (const char* key : {"latitude", "longitude", "time_zone"})
      if (!r.has(key))
        m_reporter.error(node.location, std::string("missing required key '") + key +
                                            "' in site (or from_weather: true for the weather file's site)");
    const bool have_lat = r.read_angle("latitude", AngleKind::Latitude, site.latitude_deg);
    const bool have_lon = r.read_angle("longitude", AngleKind::Longitude, site.longitude_deg);
    r.read_number("time_zone", site.time_zone_h);
    site.time_zone_location = r.location_of("time_zone");
    r.read_number("elevation", site.elevation_m);
    if (const YamlNode* z = r.take("utm_zone"); z && !z->is_null()) {
      if (read_utm_zone(*z) && have_lat && have_lon) {
        try {
          // GeographicLib's gamma (grid north's bearing from true north); see project.h.
          site.meridian_convergence_deg =
              utm_meridian_convergence_deg(site.latitude_deg, site.longitude_deg, *site.utm_zone);
        } catch (const std::invalid_argument& e) {
          m_reporter.error(z->location, "cannot project the site into UTM zone " +
                                            std::to_string(*site.utm_zone) + ": " + e.what());
        }
      }
    }
    r.finish();
  }

  bool read_utm_zone(const YamlNode& node) {
    Site& site = m_project.site;
    if (node.is_scalar()) {
      int zone = 0;
      bool north = true;
      try {
        parse_utm_zone(node.scalar, zone, north);
      } catch (const std::invalid_argument& e) {
        m_reporter.error(node.location, "bad value " + node.describe() + " for 'utm_zone': " + e.what());
        return false;
      }
      site.utm_zone = zone;
      site.utm_north = north;
      return true;
    }
    if (!node.is_map()) {
      m_reporter.error(node.location, "expected '33N' or {zone: 33, hemisphere: north} for "
                                      "'utm_zone', got " + node.describe());
      return false;
    }
    ParamReader r(node, schema_section("utm_zone"), m_reporter);
    long long zone = 0;
    std::string hemisphere;
    const bool ok = r.read_integer("zone", zone) & r.read_choice("hemisphere", hemisphere);
    r.finish();
    if (!ok) return false;
    site.utm_zone = static_cast<int>(zone);
    site.utm_north = hemisphere == "north";
    return true;
  }

  // ---- points in time -------------------------------------------------------------------
  void read_point_in_time(const YamlNode& node) {
    if (!expect_map(node, "points_in_time item", m_reporter)) return;
    PointInTimeSpec c;
    c.location = node.location;
    ParamReader r(node, schema_section("point_in_time"), m_reporter);
    bool ok = true;
    if (r.read_string("name", c.name)) {
      m_point_folders.add("point-in-time case", c.name, r.location_of("name"), m_reporter);
      m_point_names.add(c.name, r.location_of("name"), m_reporter);
    } else {
      ok = false;
    }
    std::string date, time, sky;
    if (r.read_string("date", date)) ok = parse_month_day(date, r.location_of("date"), c.month, c.day) && ok;
    else ok = false;
    c.time_location = r.location_of("time");
    if (r.read_string("time", time)) ok = parse_time_of_day(time, c.time_location, c.hour_lst) && ok;
    else ok = false;
    if (r.read_choice("sky", sky))
      c.sky = sky == "weather" ? PointSky::Weather : sky == "cie" ? PointSky::CieGeneral : PointSky::CieOvercast;
    else
      ok = false;
    long long type = 0;
    const bool has_type = r.has("cie_type");
    if (r.read_integer("cie_type", type)) c.cie_type = static_cast<int>(type);
    const bool has_diffuse = r.has("diffuse_horizontal_illuminance");
    r.read_number("diffuse_horizontal_illuminance", c.diffuse_horizontal_illuminance_lux);
    const bool has_direct = r.has("direct_normal_illuminance");
    r.read_number("direct_normal_illuminance", c.direct_normal_illuminance_lux);
    // Each sky takes exactly its own keys: a key another sky needs is an error, not ignored.
    const std::string why = std::string("with sky: ") + point_sky_name(c.sky);
    if (c.sky == PointSky::CieGeneral) {
      if (!has_type) m_reporter.error(c.location, "missing required key 'cie_type' in points_in_time item (sky: cie)");
      if (!has_direct)
        m_reporter.error(c.location, "missing required key 'direct_normal_illuminance' in points_in_time item "
                                     "(sky: cie; the sun's direct normal illuminance in lux, 0 for no sun)");
    } else {
      if (has_type) m_reporter.error(r.location_of("cie_type"), "'cie_type' is not used " + why + " (only with sky: cie)");
      if (has_direct)
        m_reporter.error(r.location_of("direct_normal_illuminance"),
                         "'direct_normal_illuminance' is not used " + why +
                             (c.sky == PointSky::Weather ? " (the weather file gives the sun)" : " (it has no sun)"));
    }
    if (c.sky == PointSky::Weather && has_diffuse)
      m_reporter.error(r.location_of("diffuse_horizontal_illuminance"),
                       "'diffuse_horizontal_illuminance' is not used with sky: weather (the weather file gives the sky)");
    r.finish();
    if (ok) m_project.points_in_time.push_back(std::move(c));
  }

  // ---- EN 17037 exposure to sunlight ------------------------------------------------------
  void read_sunlight_exposure(const YamlNode& node) {
    if (!expect_map(node, "sunlight_exposure", m_reporter)) return;
    SunlightExposureSpec spec;
    spec.location = node.location;
    ParamReader r(node, schema_section("sunlight_exposure"), m_reporter);
    bool ok = true;
    std::string date;
    spec.date_location = r.location_of("date");
    if (r.read_string("date", date)) {
      if (parse_month_day(date, spec.date_location, spec.month, spec.day)) {
        const int at = spec.month * 100 + spec.day;
        if (at < SunlightFirstMonth * 100 + SunlightFirstDay || at > SunlightLastMonth * 100 + SunlightLastDay) {
          m_reporter.error(spec.date_location, "sunlight_exposure date '" + printable_name(date) +
                                                   "' is outside EN 17037's dates for the sunlight exposure: "
                                                   "give a date from 02-01 to 03-21");
          ok = false;
        }
      } else {
        ok = false;
      }
    } else {
      ok = false;
    }
    ok = r.read_number("min_altitude", spec.min_altitude_deg) && ok;
    ok = r.read_number("time_step", spec.time_step_min) && ok;
    spec.windows = read_names(r, "windows");
    r.finish();
    // The windows named must be windows of the room generator's rooms in an outside wall.
    std::vector<std::string> known;
    for (const RoomSpec& room : m_project.geometry.rooms)
      for (const WindowSpec& w : room.windows) known.push_back(w.name);
    std::set<std::string> interior;
    for (const InteriorWindow& iw : interior_windows(m_project.geometry)) interior.insert(iw.window);
    for (const Located<std::string>& name : spec.windows) {
      if (std::find(known.begin(), known.end(), name.value) == known.end()) {
        unknown_name("window", {name.value, name.location}, known, " in sunlight_exposure.windows");
        ok = false;
      } else if (interior.count(name.value)) {
        m_reporter.error(name.location, "window '" + name.value + "' in sunlight_exposure.windows is an interior "
                                        "window (between two rooms): the sun cannot be seen through it from outside");
        ok = false;
      }
    }
    if (known.size() == interior.size())
      m_reporter.error(node.location, "sunlight_exposure needs windows in the outside walls of `geometry.rooms`: "
                                      "this project has none (polygons, meshes and imported models are not assessed)");
    if (ok) m_project.sunlight_exposure = std::move(spec);
  }

  /// "MM-DD" (also "M-D"): a date of the calendar, 02-29 included (a weather case needs the
  /// weather file to hold that day, point_in_time.h; a CIE case's sun is a leap year's).
  bool parse_month_day(const std::string& text, const SourceLocation& at, int& month, int& day) {
    static const int days_in_month[12] = {31, 29, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
    const std::size_t dash = text.find('-');
    long long m = 0, d = 0;
    if (dash == std::string::npos || !parse_integer(text.substr(0, dash), m) || !parse_integer(text.substr(dash + 1), d) ||
        m < 1 || m > 12 || d < 1 || d > days_in_month[m - 1]) {
      m_reporter.error(at, "bad date '" + printable_name(text) +
                               "' for 'date': expected month-day, e.g. 03-21");
      return false;
    }
    month = static_cast<int>(m);
    day = static_cast<int>(d);
    return true;
  }

  /// "HH:MM" or decimal hours, in [0, 24].
  bool parse_time_of_day(const std::string& text, const SourceLocation& at, double& hours) {
    const std::size_t colon = text.find(':');
    double h = -1;
    if (colon == std::string::npos) {
      if (!parse_double(text, h)) h = -1;
    } else {
      long long hh = 0, mm = 0;
      if (colon + 3 == text.size() && parse_integer(text.substr(0, colon), hh) &&
          parse_integer(text.substr(colon + 1), mm) && mm >= 0 && mm < 60 && hh >= 0)
        h = double(hh) + double(mm) / 60.0;
    }
    if (!(h >= 0 && h <= 24)) {
      m_reporter.error(at, "bad time '" + printable_name(text) +
                               "' for 'time': expected local standard time as HH:MM or decimal hours in [0, 24]");
      return false;
    }
    hours = h;
    return true;
  }

  // ---- study kind -----------------------------------------------------------------------
  /// The study kind against what it needs and what it makes: an annual study needs the
  /// weather file; a daylight-factor study writes no annual output and has no operated
  /// shading; a weather file it names is not read (`check`, the run log and summary.json say
  /// so). A file without `study`,
  /// without a weather file and without annual outputs is a daylight-factor study.
  void check_study_kind(const YamlNode& root, bool study_written, const YamlNode* weather) {
    Outputs& o = m_project.outputs;
    if (o.radiance_sun_matrix && !o.coefficients)
      m_reporter.error(m_radiance_sun_matrix_location,
                       "outputs.radiance_sun_matrix: true needs outputs.coefficients: true (it is one of the "
                       "coefficient files)");
    else if (o.radiance_sun_matrix && m_project.simulation.sun != SunMode::Bins)
      m_reporter.error(m_radiance_sun_matrix_location,
                       "outputs.radiance_sun_matrix: true needs simulation.sun: bins (the sun is spread into the "
                       "sky coefficients otherwise)");
    if (m_project.site.from_weather && !weather)
      m_reporter.error(m_from_weather_location,
                       "site: from_weather: true needs a weather file ('weather'), whose header gives the site");
    if (!study_written && !weather && !o.annual_illuminance && !o.metrics)
      m_project.study = StudyKind::DaylightFactor;
    if (m_project.study == StudyKind::Annual) {
      if (weather) return;
      if (study_written)
        m_reporter.error(m_project.study_location,
                         "study: annual needs a weather file ('weather'); for daylight factors only, write "
                         "'study: daylight_factor'");
      else
        m_reporter.error(root.location,
                         "missing required key 'weather' in project (the annual study needs it; for daylight "
                         "factors only, write 'study: daylight_factor')");
      return;
    }
    // A daylight-factor study: points in time under the weather file's sky need the annual study.
    for (const PointInTimeSpec& c : m_project.points_in_time)
      if (c.sky == PointSky::Weather)
        m_reporter.error(c.location, "point-in-time case '" + c.name + "': sky: weather needs the annual study "
                                     "(study: annual with a weather file)");
      else if (m_project.site.from_weather)
        m_reporter.error(c.location, "point-in-time case '" + c.name + "': the sun needs the site, and a "
                                     "daylight-factor study does not read the weather file (site: from_weather); "
                                     "give latitude, longitude and time_zone in site");
    for (const auto& [key, written] : m_annual_outputs_written) {
      if (!written.second) continue;
      m_reporter.error(written.first, "outputs." + key + ": true needs the annual study; this project is a "
                                      "daylight-factor study (study: daylight_factor)");
    }
    o.annual_illuminance = false;
    o.metrics = false;
    if (m_project.operation)
      m_reporter.error(m_project.operation->location,
                       "operation needs the annual study (each hour's direct sun); this project is a "
                       "daylight-factor study (study: daylight_factor)");
  }

  // ---- weather --------------------------------------------------------------------------
  void read_weather(const YamlNode& node) {
    Weather& w = m_project.weather;
    w.location = node.location;
    if (node.is_scalar()) {
      w.path_as_written = node.scalar;
    } else if (node.is_map()) {
      ParamReader r(node, schema_section("weather"), m_reporter);
      const bool ok = r.read_string("file", w.path_as_written);
      w.location = r.location_of("file");
      r.finish();
      if (!ok) return;
    } else {
      m_reporter.error(node.location, "expected a weather file path (EPW or .wea) or {file: path} for 'weather', got " +
                                          node.describe());
      return;
    }
    existing_file("weather file", w.path_as_written, w.location, w.path);
  }

  // ---- materials ------------------------------------------------------------------------
  void read_materials(const YamlNode& node) {
    if (!expect_map(node, "materials", m_reporter)) return;
    for (const auto& entry : node.entries) {
      m_material_names.add(entry.key, entry.key_location, m_reporter);
      MaterialSpec m;
      if (read_material(entry, m)) m_project.materials.push_back(std::move(m));
    }
  }

  /// One material definition `name: {type: ..., ...}` (top level or in a variant).
  bool read_material(const YamlEntry& entry, MaterialSpec& m) {
    if (!expect_map(entry.value, entry.key, m_reporter)) return false;
    const YamlEntry* type_entry = entry.value.find("type");
    if (!type_entry) {
      m_reporter.error(entry.value.location,
                       "missing required key 'type' in material '" + entry.key + "'");
      return false;
    }
    // Validate the type itself (allowed values, hint) with any material section's entry.
    std::string type;
    {
      ParamReader type_reader(entry.value, schema_section("lambertian material"), m_reporter);
      if (!type_reader.read_choice("type", type)) return false;
    }
    m.name = entry.key;
    m.location = entry.key_location;
    ParamReader r(entry.value, schema_section(type + " material"), m_reporter);
    r.take("type");
    if (type == "lambertian") {
      m.type = MaterialType::Lambertian;
      r.read_rgb("reflectance", m.reflectance);
    } else if (type == "plastic" || type == "metal" || type == "translucent") {
      m.type = type == "plastic" ? MaterialType::Lambertian
               : type == "metal" ? MaterialType::Metal
                                 : MaterialType::Translucent;
      // A plastic is the Lambertian model with a specular lobe; keep the user's word for
      // messages and `check`.
      if (type == "plastic") m.type_as_written = type;
      r.read_rgb("reflectance", m.reflectance);
      r.read_number("specularity", m.specularity);
      r.read_number("roughness", m.roughness);
      if (type == "translucent") {
        r.read_number("transmissivity", m.transmissivity);
        r.read_number("transmitted_specular", m.transmitted_specular);
        read_shading_role(r, m);
      }
    } else if (type == "mirror") {
      m.type = MaterialType::Mirror;
      r.read_rgb("reflectance", m.reflectance);
    } else if (type == "glass") {
      m.type = MaterialType::Glass;
      r.read_rgb("transmittance", m.transmittance);
      r.read_number("refractive_index", m.refractive_index);
    } else if (type == "glazing") {
      m.type = MaterialType::Glazing;
      for_each_item(r, "panes", [&](const YamlNode& n) { m.panes.push_back(read_glazing_pane(n)); });
      if (r.has("panes") && m.panes.empty())
        m_reporter.error(r.location_of("panes"), "material '" + entry.key + "': a glazing needs at least one pane");
    } else if (type == "dielectric") {
      m.type = MaterialType::Dielectric;
      r.read_number("refractive_index", m.refractive_index);
      r.read_rgb("transmittance", m.transmittance);
    } else if (type == "opening") {
      m.type = MaterialType::Opening;
    } else if (const engine::MaterialModelEntry* model = engine::find_material_model(type); model && model->parse) {
      // A registered model reads its own keys (material_registry.h).
      m.type = MaterialType::Registered;
      m.model = type;
      MaterialKeys keys(r, *this);
      if (model->takes_transmittance_factor) read_shading_role(r, m);
      m.parameters = model->parse(keys, m);
      r.finish();
      return m.parameters != nullptr;
    }
    r.finish();
    return true;
  }

  /// The `shading` key of a material that can stand for a blind or a shade.
  static void read_shading_role(ParamReader& r, MaterialSpec& m) {
    std::string role;
    if (r.has("shading") && r.read_choice("shading", role))
      m.shading = role == "operable" ? ShadingRole::Operable : ShadingRole::Fixed;
  }

  /// A registered material model's view of its map (engine::MaterialKeyReader): the
  /// loader's own reader, so that its keys are checked and located like every other key.
  class MaterialKeys final : public engine::MaterialKeyReader {
   public:
    MaterialKeys(ParamReader& reader, Loader& loader) : m_reader(reader), m_loader(loader) {}
    bool has(const std::string& key) const override { return m_reader.has(key); }
    bool read_number(const std::string& key, double& out) override { return m_reader.read_number(key, out); }
    bool read_rgb(const std::string& key, Vec3& out) override { return m_reader.read_rgb(key, out); }
    bool read_string(const std::string& key, std::string& out) override { return m_reader.read_string(key, out); }
    bool read_path(const std::string& key, std::string& resolved_path) override {
      std::string written;
      if (!m_reader.has(key)) return m_reader.read_string(key, written);  // reports it if required
      if (!m_reader.read_string(key, written)) return false;
      return m_loader.existing_file(key, written, m_reader.location_of(key), resolved_path);
    }
    SourceLocation location_of(const std::string& key) const override { return m_reader.location_of(key); }
    void error(const SourceLocation& at, const std::string& message) override {
      m_reader.reporter().error(at, message);
    }
    void forward(const Diagnostic& diagnostic) override { m_reader.reporter().forward(diagnostic); }

   private:
    ParamReader& m_reader;
    Loader& m_loader;
  };

  /// One pane of a glazing: exactly one of transmittance, absorption (with thickness) and
  /// coating; a coated pane's optics are its coating's, so it takes no refractive index.
  GlazingPaneSpec read_glazing_pane(const YamlNode& node) {
    GlazingPaneSpec pane;
    ParamReader r(node, schema_section("glazing pane"), m_reporter);
    const char* forms[] = {"transmittance", "absorption", "coating"};
    std::vector<std::string> given;
    for (const char* key : forms)
      if (r.has(key)) given.push_back(key);
    if (given.size() != 1)
      m_reporter.error(node.location, given.empty()
                                          ? "a glazing pane needs one of 'transmittance', 'absorption' or 'coating'"
                                          : "a glazing pane takes only one of 'transmittance', 'absorption' and "
                                            "'coating', got '" + given[0] + "' and '" + given[1] + "'");
    for (std::size_t i = 1; i < given.size(); ++i) r.take(given[i]);  // reported above
    double thickness_mm = 0;
    if (r.has("thickness") && r.read_number("thickness", thickness_mm)) pane.thickness_m = thickness_mm * 1e-3;
    if (r.has("transmittance")) {
      pane.optics = GlazingPaneSpec::Optics::Transmittance;
      r.read_rgb("transmittance", pane.transmittance);
    } else if (r.has("absorption")) {
      pane.optics = GlazingPaneSpec::Optics::Absorption;
      r.read_rgb("absorption", pane.absorption_per_m);
      if (!r.has("thickness"))
        m_reporter.error(r.location_of("absorption"), "a glazing pane's 'absorption' needs its 'thickness'");
    } else if (const YamlNode* coating = r.take("coating"); coating && expect_map(*coating, "coating", m_reporter)) {
      pane.optics = GlazingPaneSpec::Optics::Coated;
      if (r.has("refractive_index")) {
        m_reporter.error(r.location_of("refractive_index"),
                         "a coated pane's optics are its coating's transmittance and reflectance; "
                         "'refractive_index' does not apply");
        r.take("refractive_index");
      }
      ParamReader c(*coating, schema_section("glazing coating"), m_reporter);
      std::string face;
      if (c.read_choice("face", face)) pane.coating_on_inner_face = face == "inner";
      c.read_rgb("transmittance", pane.transmittance);
      Vec3 coated{0, 0, 0};
      c.read_rgb("reflectance", coated);
      Vec3 glass_side = coated;
      if (c.has("glass_side_reflectance")) c.read_rgb("glass_side_reflectance", glass_side);
      pane.outer_reflectance = pane.coating_on_inner_face ? glass_side : coated;
      pane.inner_reflectance = pane.coating_on_inner_face ? coated : glass_side;
      c.finish();
    }
    if (pane.optics != GlazingPaneSpec::Optics::Coated) r.read_number("refractive_index", pane.refractive_index);
    r.finish();
    return pane;
  }

  void use_material(const ParamReader& r, const std::string& key, const std::string& name) {
    if (!name.empty()) m_material_uses.push_back({name, r.location_of(key)});
  }

  // ---- geometry -------------------------------------------------------------------------
  void read_geometry(const YamlNode& node) {
    if (!expect_map(node, "geometry", m_reporter)) return;
    ParamReader r(node, schema_section("geometry"), m_reporter);
    for_each_item(r, "rooms", [&](const YamlNode& n) { read_room(n); });
    Geometry& g = m_project.geometry;
    for_each_item(r, "polygons", [&](const YamlNode& n) { g.polygons.push_back(read_polygon(n, m_polygon_names)); });
    for_each_item(r, "boxes", [&](const YamlNode& n) { g.boxes.push_back(read_box(n, m_box_names)); });
    for_each_item(r, "meshes", [&](const YamlNode& n) { g.meshes.push_back(read_mesh(n, m_mesh_names)); });
    for_each_item(r, "systems", [&](const YamlNode& n) {
      if (auto sys = read_system(n, /*base=*/true)) m_project.geometry.systems.push_back(std::move(*sys));
    });
    for_each_item(r, "radiance", [&](const YamlNode& n) { g.radiance.push_back(read_radiance(n)); });
    if (r.has("honeybee")) read_honeybee(r);
    r.finish();
  }

  /// A RADIANCE scene entry: its files (each must exist; read when the scene is built),
  /// `ports` (auto or modifier names), `outdoor` (modifier names), `unsupported`.
  RadianceSceneSpec read_radiance(const YamlNode& node) {
    RadianceSceneSpec spec;
    spec.location = node.location;
    ParamReader r(node, schema_section("radiance scene"), m_reporter);
    for (const Located<std::string>& f : read_names(r, "files")) {
      std::string resolved;
      existing_file("RADIANCE scene file", f.value, f.location, resolved);
      spec.files.push_back({resolved, f.location});
      spec.files_as_written.push_back(f.value);
    }
    if (r.has("ports")) {
      const YamlNode& ports = r.node().find("ports")->value;
      if (ports.is_scalar() && ports.scalar == "auto") {
        r.take("ports");
      } else if (ports.is_sequence()) {
        spec.ports_auto = false;
        if (!ports.items.empty()) spec.port_modifiers = read_names(r, "ports");
        else r.take("ports");
      } else {
        m_reporter.error(ports.location, "expected 'auto' or a list of modifier names for 'ports', got " +
                                             ports.describe());
        r.take("ports");
      }
    }
    spec.outdoor_modifiers = read_names(r, "outdoor");
    std::string unsupported = "error";
    if (r.has("unsupported")) r.read_choice("unsupported", unsupported);
    spec.skip_unsupported = unsupported == "skip";
    spec.units_written = r.has("units");
    if (spec.units_written && r.read_choice("units", spec.units))
      spec.metres_per_unit = metres_per_length_unit(spec.units);
    r.finish();
    return spec;
  }

  /// `geometry.honeybee: model.hbjson`: the model is read now, so that its problems are
  /// reported with the project's and its grids can be named in `sensors`. Its modifiers
  /// become project materials under their identifiers (a project material of the same name
  /// is an error: one name, one material).
  /// An old Honeybee model's `north_angle` (honeybee_model.h): site.north's own convention,
  /// so it orients the model where the project writes no site.north; a site.north that
  /// differs, or a UTM zone (whose north is grid north), is a located error: which north is
  /// meant is the user's to say.
  void take_honeybee_north(HoneybeeModel& model) {
    const double angle = model.north_angle_deg;
    if (angle == 0) return;
    Site& site = m_project.site;
    const std::string words = "the Honeybee model's north_angle, " + format_number(angle) + " degrees (" +
                              model.north_angle_location.to_string() +
                              "; clockwise from +Y to north, as site.north counts)";
    if (m_site_north_location) {
      if (std::remainder(site.north_deg - angle, 360.0) != 0)
        m_reporter.error(*m_site_north_location,
                         "site.north is " + format_number(site.north_deg) + " degrees but " + words +
                             " differs: write site.north: " + format_number(angle) +
                             " to use the model's, or remove north_angle from the model");
      return;
    }
    if (site.utm_zone) {
      m_reporter.error(site.location, words + ", and the site has a utm_zone, whose site.north is measured to grid "
                                              "north: write site.north (the angle from +Y to grid north)");
      return;
    }
    site.north_deg = angle;
    model.notes.push_back("north_angle " + format_number(angle) + " (" + model.north_angle_location.to_string() +
                          ") orients the model: site.north " + format_number(angle));
  }

  void read_honeybee(ParamReader& r) {
    HoneybeeImport hb;
    m_honeybee_given = true;
    if (!r.read_string("honeybee", hb.path_as_written)) return;
    hb.location = r.location_of("honeybee");
    if (!existing_file("Honeybee model", hb.path_as_written, hb.location, hb.path)) return;
    try {
      hb.model = read_honeybee_model(hb.path, hb.path);
    } catch (const InputError& e) {
      for (const Diagnostic& d : e.diagnostics()) m_reporter.forward(d);
      return;
    }
    take_honeybee_north(hb.model);
    for (const MaterialSpec& m : hb.model.materials) {
      if (m_material_names.contains(m.name)) {
        m_reporter.error(m_material_names.first(m.name).location,
                         "material '" + m.name + "' is also a modifier of the Honeybee model (" + m.location.to_string() +
                             "); rename one of them");
        continue;
      }
      m_material_names.add(m.name, m.location, m_reporter);
      m_project.materials.push_back(m);
    }
    m_project.geometry.honeybee = std::move(hb);
  }

  template <typename F>
  void for_each_item(ParamReader& r, const std::string& key, F read_item) {
    const YamlNode* list = r.take(key);
    if (!list || !expect_list(*list, key, m_reporter)) return;
    const std::string section = r.schema().find(key)->section;
    for (const auto& item : list->items)
      if (expect_map(item, section, m_reporter)) read_item(item);
  }

  void read_room(const YamlNode& node) {
    RoomSpec room;
    room.location = node.location;
    ParamReader r(node, schema_section("room"), m_reporter);
    if (r.read_string("name", room.name)) m_room_names.add(room.name, r.location_of("name"), m_reporter);
    r.read_vec3("origin", room.origin);
    r.read_vec3("size", room.size_m);
    if (const YamlNode* mats = r.take("materials"); mats && expect_map(*mats, "materials", m_reporter)) {
      ParamReader m(*mats, schema_section("room materials"), m_reporter);
      if (m.read_string("floor", room.floor_material)) use_material(m, "floor", room.floor_material);
      if (m.read_string("ceiling", room.ceiling_material)) use_material(m, "ceiling", room.ceiling_material);
      std::string walls;
      const bool have_walls = m.has("walls") && m.read_string("walls", walls);
      if (have_walls) use_material(m, "walls", walls);
      else m.take("walls");
      static const char* const wall_keys[4] = {"south", "north", "east", "west"};
      bool all_overridden = true;
      for (int w = 0; w < 4; ++w) {
        std::string own;
        if (m.has(wall_keys[w]) && m.read_string(wall_keys[w], own)) {
          use_material(m, wall_keys[w], own);
          room.wall_material[w] = own;
        } else {
          m.take(wall_keys[w]);
          all_overridden = all_overridden && m.has(wall_keys[w]);
          room.wall_material[w] = walls;
        }
      }
      if (!m.has("walls") && !all_overridden)
        m_reporter.error(mats->location, "missing required key 'walls' in room materials");
      m.finish();
    }
    for_each_item(r, "windows", [&](const YamlNode& n) { room.windows.push_back(read_window(n, m_window_names)); });
    for_each_item(r, "roof_lights", [&](const YamlNode& n) { room.roof_lights.push_back(read_roof_light(n)); });
    r.finish();
    m_project.geometry.rooms.push_back(std::move(room));
  }

  /// A window of a room (its name into `names`), or with `room` one a variant adds: then
  /// the map also names the room.
  WindowSpec read_window(const YamlNode& node, NameSet& names, Located<std::string>* room = nullptr) {
    WindowSpec w;
    w.location = node.location;
    ParamReader r(node, schema_section(room ? "added window" : "window"), m_reporter);
    if (room && r.read_string("room", room->value)) {
      room->location = r.location_of("room");
      m_room_uses.push_back({room->value, room->location});
    }
    if (r.read_string("name", w.name)) {
      names.add(w.name, r.location_of("name"), m_reporter);
      if (m_roof_light_names.contains(w.name)) opening_name_clash(w.name, r.location_of("name"));
    }
    std::string wall;
    if (const YamlEntry* e = r.node().find("wall");
        e && e->value.is_scalar() && (e->value.scalar == "roof" || e->value.scalar == "ceiling")) {
      // The generator's openings in the ceiling are roof lights, not windows.
      m_reporter.error(e->value.location, "a window is in a wall (south, north, east or west), not in the " +
                                              e->value.scalar + ": an opening in the ceiling is a roof light "
                                              "(`roof_lights` of the room)");
      r.take("wall");
    } else if (r.read_choice("wall", wall))
      w.wall = wall == "south" ? Wall::South : wall == "north" ? Wall::North
               : wall == "east" ? Wall::East : Wall::West;
    r.read_number("width", w.width_m);
    r.read_number("height", w.height_m);
    r.read_number("sill", w.sill_m);
    double offset = 0;
    if (r.read_number("offset", offset)) w.offset_m = offset;
    if (r.read_string("material", w.material)) use_material(r, "material", w.material);
    r.read_number("frame_factor", w.frame_factor);
    r.read_number("maintenance_factor", w.maintenance_factor);
    r.finish();
    return w;
  }

  RoofLightSpec read_roof_light(const YamlNode& node) {
    RoofLightSpec l;
    l.location = node.location;
    for (const auto& e : node.entries) l.key_locations.push_back({e.key, e.value.location});
    ParamReader r(node, schema_section("roof light"), m_reporter);
    if (r.read_string("name", l.name)) {
      m_roof_light_names.add(l.name, r.location_of("name"), m_reporter);
      if (m_window_names.contains(l.name)) opening_name_clash(l.name, r.location_of("name"));
    }
    r.read_number("width", l.width_m);
    r.read_number("length", l.length_m);
    double offset = 0;
    if (r.read_number("offset_x", offset)) l.offset_x_m = offset;
    if (r.read_number("offset_y", offset)) l.offset_y_m = offset;
    r.read_number("well_depth", l.well_depth_m);
    if (r.has("well_material") && r.read_string("well_material", l.well_material))
      use_material(r, "well_material", l.well_material);
    if (r.read_string("material", l.material)) use_material(r, "material", l.material);
    r.finish();
    return l;
  }

  /// Windows and roof lights both name surfaces "<room>.<name>" and results: one name each.
  void opening_name_clash(const std::string& name, const SourceLocation& where) {
    m_reporter.error(where, "'" + name + "' names both a window and a roof light (each opening needs its own name)");
  }

  PolygonSpec read_polygon(const YamlNode& node, NameSet& names) {
    PolygonSpec p;
    p.location = node.location;
    ParamReader r(node, schema_section("polygon"), m_reporter);
    if (r.read_string("name", p.name)) names.add(p.name, r.location_of("name"), m_reporter);
    if (r.read_points("vertices", p.vertices) && p.vertices.size() < 3)
      m_reporter.error(r.location_of("vertices"), "'vertices' needs at least 3 points, got " +
                                                      std::to_string(p.vertices.size()));
    if (r.read_string("material", p.material)) use_material(r, "material", p.material);
    r.read_bool("port", p.port);
    read_facing(r, p.port, p.facing);
    read_outdoor(r, p.port, p.outdoor);
    r.finish();
    return p;
  }

  BoxSpec read_box(const YamlNode& node, NameSet& names) {
    BoxSpec b;
    b.location = node.location;
    ParamReader r(node, schema_section("box"), m_reporter);
    if (r.read_string("name", b.name)) names.add(b.name, r.location_of("name"), m_reporter);
    r.read_vec3("origin", b.origin);
    r.read_vec3("size", b.size_m);
    r.read_number("rotation", b.rotation_deg);
    if (r.read_string("material", b.material)) use_material(r, "material", b.material);
    read_outdoor(r, false, b.outdoor);
    r.finish();
    return b;
  }

  MeshSpec read_mesh(const YamlNode& node, NameSet& names) {
    MeshSpec m;
    m.location = node.location;
    ParamReader r(node, schema_section("mesh"), m_reporter);
    if (r.read_string("name", m.name)) names.add(m.name, r.location_of("name"), m_reporter);
    if (r.read_string("file", m.path_as_written))
      existing_file("OBJ file", m.path_as_written, r.location_of("file"), m.path);
    if (const YamlNode* map = r.take("material_map"); map && expect_map(*map, "material_map", m_reporter)) {
      for (const auto& e : map->entries) {
        if (!e.value.is_scalar() || e.value.scalar.empty()) {
          m_reporter.error(e.value.location, "expected a material name for '" + e.key + "', got " +
                                                 e.value.describe());
          continue;
        }
        m.material_map.emplace_back(e.key, e.value.scalar);
        m_material_uses.push_back({e.value.scalar, e.value.location});
      }
    }
    if (r.has("default_material") && r.read_string("default_material", m.default_material))
      use_material(r, "default_material", m.default_material);
    else
      r.take("default_material");
    r.read_vec3("translate", m.translate);
    r.read_number("scale", m.scale);
    r.read_number("rotation", m.rotation_deg);
    r.read_bool("port", m.port);
    read_facing(r, m.port, m.facing);
    read_outdoor(r, m.port, m.outdoor);
    r.finish();
    return m;
  }

  /// `outdoor` of a polygon, box or mesh: not for ports (light enters a port; an outdoor
  /// scatterer sends light toward one).
  void read_outdoor(ParamReader& r, bool port, bool& outdoor) {
    if (!r.read_bool("outdoor", outdoor) || !outdoor || !port) return;
    m_reporter.error(r.location_of("outdoor"), "a photon port cannot be 'outdoor' too (light enters the room "
                                               "through a port; an outdoor surface sends light toward the ports): "
                                               "remove 'port: true' or 'outdoor: true'");
  }

  /// `facing` of a polygon or mesh: only for ports.
  void read_facing(ParamReader& r, bool port, PortFacing& facing) {
    if (!r.has("facing")) return;
    std::string value;
    if (!r.read_choice("facing", value)) return;
    if (!port) {
      m_reporter.error(r.location_of("facing"), "'facing' applies to ports only (add 'port: true', or remove it)");
      return;
    }
    facing = value == "in" ? PortFacing::In : value == "out" ? PortFacing::Out : PortFacing::Auto;
  }

  // ---- daylight systems (docs/daylight-systems.md) --------------------------------------
  /// One system `{type: ..., name: ..., ...}`. `base`: a system of geometry.systems (its name
  /// is registered, its node kept for variants, its window checked against the project's);
  /// otherwise a variant's merged or added definition (variant_checks.h checks its window).
  std::optional<SystemSpec> read_system(const YamlNode& node, bool base) {
    if (!node.find("type")) {
      m_reporter.error(node.location, "missing required key 'type' in system");
      return std::nullopt;
    }
    std::string type;
    {
      ParamReader type_reader(node, schema_section("system"), m_reporter);
      if (!type_reader.read_choice("type", type)) return std::nullopt;
    }
    SystemSpec sys;
    sys.location = node.location;
    for (const auto& e : node.entries) sys.key_locations.push_back({e.key, e.value.location});
    ParamReader r(node, schema_section(type + " system"), m_reporter);
    r.take("type");
    if (r.read_string("name", sys.name) && base) {
      m_system_names.add(sys.name, r.location_of("name"), m_reporter);
      m_system_nodes.emplace(sys.name, node);
    }
    r.read_bool("enabled", sys.enabled);
    auto material = [&](const std::string& key, std::string& out) {
      if (r.has(key) && r.read_string(key, out)) use_material(r, key, out);
      else r.take(key);  // absent optional key (required ones report themselves)
    };
    auto required_material = [&](const std::string& key, std::string& out) {
      if (r.read_string(key, out)) use_material(r, key, out);
    };
    auto optional_number = [&](const std::string& key, std::optional<double>& out) {
      double v = 0;
      if (r.has(key) && r.read_number(key, v)) out = v;
      else r.take(key);
    };
    if (type == "light_pipe") {
      LightPipeSpec p;
      if (r.read_string("room", p.room)) m_room_uses.push_back({p.room, r.location_of("room")});
      r.read_number("x", p.x_m);
      r.read_number("y", p.y_m);
      r.read_number("diameter", p.diameter_m);
      r.read_number("length", p.length_m);
      long long n = 0;
      if (r.read_integer("sides", n)) p.sides = static_cast<int>(n);
      std::string collector;
      if (r.read_choice("collector", collector)) p.dome = collector == "dome";
      if (r.read_integer("dome_rings", n)) p.dome_rings = static_cast<int>(n);
      required_material("tube_material", p.tube_material);
      required_material("diffuser_material", p.diffuser_material);
      required_material("collector_material", p.collector_material);
      sys.params = p;
    } else {
      read_mount(r, type, sys.mount, base);
      if (type == "light_shelf") {
        LightShelfSpec p;
        r.read_number("height", p.height_m);
        r.read_number("depth", p.depth_m);
        r.read_number("tilt", p.tilt_deg);
        r.read_number("thickness", p.thickness_m);
        r.read_number("extension", p.extension_m);
        required_material("material", p.material);
        material("underside_material", p.underside_material);
        if (!p.underside_material.empty() && p.thickness_m == 0)
          m_reporter.error(r.location_of("underside_material"),
                           "'underside_material' needs a slab: give 'thickness' > 0 (a thin shelf "
                           "is one polygon whose two sides share 'material')");
        sys.params = p;
      } else if (type == "blinds") {
        BlindsSpec p;
        r.read_number("slat_width", p.slat_width_m);
        r.read_number("spacing", p.spacing_m);
        r.read_number("angle", p.angle_deg);
        r.read_number("crown", p.crown_m);
        long long n = 0;
        if (r.read_integer("facets", n)) p.facets = static_cast<int>(n);
        optional_number("offset", p.offset_m);
        optional_number("bottom", p.bottom_m);
        optional_number("top", p.top_m);
        r.read_number("extension", p.extension_m);
        required_material("material", p.material);
        sys.params = p;
      } else if (type == "prismatic_panel") {
        PrismaticPanelSpec p;
        r.read_number("apex_angle", p.apex_angle_deg);
        r.read_number("pitch", p.pitch_m);
        std::string apex;
        if (r.read_choice("apex", apex)) p.apex_outward = apex == "outward";
        r.read_number("backing", p.backing_m);
        r.read_number("offset", p.offset_m);
        optional_number("bottom", p.bottom_m);
        optional_number("top", p.top_m);
        required_material("material", p.material);
        sys.params = p;
      } else if (type == "lamella_panel") {
        LamellaPanelSpec p;
        r.read_number("thickness", p.thickness_m);
        r.read_number("spacing", p.spacing_m);
        r.read_number("lamella_angle", p.lamella_angle_deg);
        r.read_number("gap", p.gap_m);
        r.read_number("offset", p.offset_m);
        optional_number("bottom", p.bottom_m);
        optional_number("top", p.top_m);
        required_material("material", p.material);
        sys.params = p;
      } else if (type == "cpc") {
        CpcSpec p;
        r.read_number("acceptance_angle", p.acceptance_angle_deg);
        long long n = 0;
        if (r.read_integer("count", n)) p.count = static_cast<int>(n);
        std::string kind;
        if (r.read_choice("kind", kind)) p.dielectric = kind == "dielectric";
        if (r.read_integer("facets", n)) p.facets = static_cast<int>(n);
        r.read_number("tilt", p.tilt_deg);
        r.read_number("offset", p.offset_m);
        optional_number("bottom", p.bottom_m);
        optional_number("top", p.top_m);
        required_material("material", p.material);
        material("exit_material", p.exit_material);
        if (p.dielectric && p.exit_material.empty() && !r.has("exit_material"))
          m_reporter.error(node.location, "missing required key 'exit_material' in cpc system "
                                          "(a dielectric CPC's exit aperture is coated)");
        if (!p.dielectric && r.has("exit_material"))
          m_reporter.error(r.location_of("exit_material"),
                           "'exit_material' applies to kind: dielectric only (a reflective CPC's "
                           "exit aperture is open)");
        sys.params = p;
      } else if (type == "overhang") {
        OverhangSpec p;
        optional_number("height", p.height_m);
        r.read_number("depth", p.depth_m);
        r.read_number("tilt", p.tilt_deg);
        r.read_number("thickness", p.thickness_m);
        r.read_number("extension", p.extension_m);
        required_material("material", p.material);
        sys.params = p;
      } else if (type == "fins") {
        FinsSpec p;
        r.read_number("depth", p.depth_m);
        std::string jambs;
        if (r.read_choice("jambs", jambs)) {
          p.left = jambs != "right";
          p.right = jambs != "left";
        }
        r.read_number("offset", p.offset_m);
        r.read_number("extension", p.extension_m);
        r.read_number("angle", p.angle_deg);
        r.read_number("thickness", p.thickness_m);
        required_material("material", p.material);
        sys.params = p;
      }
    }
    r.finish();
    return sys;
  }

  /// `window`, `side` and `port` of a window-mounted system. Overhangs and fins are always
  /// outside (their schema has no `side`); `port` only means something outside.
  void read_mount(ParamReader& r, const std::string& type, WindowMount& mount, bool base) {
    if (r.read_string("window", mount.window) && base) m_window_uses.push_back({mount.window, r.location_of("window")});
    const bool has_side = r.schema().find("side") != nullptr;
    std::string side = "exterior";
    if (has_side) r.read_choice("side", side);
    mount.side = side == "interior" ? MountSide::Interior : MountSide::Exterior;
    std::string port;
    if (r.read_choice("port", port))
      mount.port = port == "enclosure" ? PortMode::Enclosure
                   : port == "window"  ? PortMode::Window
                                       : PortMode::System;
    if (mount.side == MountSide::Interior) {
      if (r.has("port"))
        m_reporter.error(r.location_of("port"), "'port' applies to exterior systems only (inside "
                                                "the room the window is the photon port)");
      mount.port = PortMode::Window;
    }
    (void)type;
  }

  // ---- sensors --------------------------------------------------------------------------
  void read_sensors(const YamlNode& node) {
    if (!expect_map(node, "sensors", m_reporter)) return;
    ParamReader r(node, schema_section("sensors"), m_reporter);
    for_each_item(r, "grids", [&](const YamlNode& n) { read_grid(n); });
    for_each_item(r, "points", [&](const YamlNode& n) { read_points(n); });
    if (const YamlNode* n = r.take("honeybee_grids")) read_honeybee_grids(*n);
    r.finish();
  }

  /// `sensors.honeybee_grids`: `all`, or a list of grid identifiers and maps
  /// {grid, name, drop_occluded}. Each grid becomes a point set (its sensors as the model
  /// gives them), named by its identifier unless `name` says otherwise.
  void read_honeybee_grids(const YamlNode& node) {
    const auto& hb = m_project.geometry.honeybee;
    if (!hb) {
      if (m_honeybee_given) return;  // the model's own errors are reported
      m_reporter.error(node.location, "'honeybee_grids' needs a Honeybee model (geometry: {honeybee: model.hbjson})");
      return;
    }
    std::vector<std::string> identifiers;
    for (const HoneybeeGrid& g : hb->model.grids) identifiers.push_back(g.identifier);
    std::set<std::string> mesh_told;  // a grid listed twice (under two names) gets its mesh's words once
    auto add = [&](const std::string& grid, const Located<std::string>& name, bool drop, const SourceLocation& at) {
      const auto it = std::find_if(hb->model.grids.begin(), hb->model.grids.end(),
                                   [&](const HoneybeeGrid& g) { return g.identifier == grid; });
      if (it == hb->model.grids.end()) {
        std::string message = "the Honeybee model has no sensor grid '" + grid + "'";
        const std::string hint = closest_match(grid, identifiers);
        if (!hint.empty()) message += " (did you mean '" + hint + "'?)";
        m_reporter.error(at, message);
        return;
      }
      // The mesh's faces weigh the sensors' shares as Honeybee does (docs/metrics.md,
      // "Sensor areas"); with the model's warnings, which the scene carries to check and run.
      std::vector<double> area_m2 = detail::unequal_areas_m2(it->mesh_face_areas_m2);
      auto model_diagnostic = [&](Severity severity, std::string message) {
        Diagnostic d;
        d.severity = severity;
        d.location = it->mesh_location;
        d.source_line = read_source_line(it->mesh_location.file, it->mesh_location.line);
        d.message = std::move(message);
        m_project.geometry.honeybee->model.warnings.push_back(std::move(d));
      };
      const bool first_mention = mesh_told.insert(grid).second;
      if (first_mention && !it->mesh_problem.empty()) {
        model_diagnostic(Severity::Warning,
                         "sensor grid '" + grid + "': its mesh " + it->mesh_problem +
                             ", so it is not used: every sensor counts as an equal share of the area, where Honeybee "
                             "weighs each by its mesh face's area (sDA, ASE, EN 17037's target areas and the grid "
                             "means can differ from Honeybee's); give the grid a mesh of one face per sensor");
      } else if (first_mention && !area_m2.empty()) {
        const auto [lo, hi] = std::minmax_element(area_m2.begin(), area_m2.end());
        double total_m2 = 0;
        for (double a : area_m2) total_m2 += a;
        model_diagnostic(Severity::Note,
                         "sensor grid '" + grid + "': the faces of its mesh differ in area (" +
                             format_number(std::round(*lo * 1e4) / 1e4) + " to " +
                             format_number(std::round(*hi * 1e4) / 1e4) + " m^2, " +
                             format_number(std::round(total_m2 * 1e2) / 1e2) +
                             " m^2 in all): each sensor's share of the area (sDA, ASE, EN 17037's target areas, "
                             "the grid means) is weighted by its face's area, as Honeybee does");
      }
      PointsSpec p;
      p.name = name.value;
      p.points = it->points;
      p.area_m2 = std::move(area_m2);
      p.drop_occluded = drop;
      p.location = at;
      m_sensor_folders.add("point set", p.name, name.location, m_reporter);
      m_sensor_names.add(p.name, name.location, m_reporter);
      m_project.sensors.points.push_back(std::move(p));
    };
    if (node.is_scalar() && node.scalar == "all") {
      if (hb->model.grids.empty())
        m_reporter.error(node.location, "'honeybee_grids: all', but the Honeybee model has no sensor grids "
                                        "(properties.radiance.sensor_grids)");
      for (const std::string& id : identifiers) add(id, {id, node.location}, false, node.location);
      return;
    }
    if (!node.is_sequence() || node.items.empty()) {
      m_reporter.error(node.location, "expected 'all' or a list of sensor grid identifiers for 'honeybee_grids', got " +
                                          node.describe());
      return;
    }
    for (const YamlNode& item : node.items) {
      if (item.is_scalar()) {
        add(item.scalar, {item.scalar, item.location}, false, item.location);
        continue;
      }
      if (!expect_map(item, "honeybee grid", m_reporter)) continue;
      ParamReader r(item, schema_section("honeybee grid"), m_reporter);
      std::string grid, name;
      bool drop = false;
      const bool have_grid = r.read_string("grid", grid);
      Located<std::string> shown{grid, r.location_of("grid")};
      if (r.has("name") && r.read_string("name", name)) shown = {name, r.location_of("name")};
      else r.take("name");
      r.read_bool("drop_occluded", drop);
      r.finish();
      if (have_grid) add(grid, shown, drop, item.location);
    }
  }

  void read_grid(const YamlNode& node) {
    GridSpec g;
    g.location = node.location;
    ParamReader r(node, schema_section("grid"), m_reporter);
    for (const auto& e : node.entries) g.key_locations.push_back({e.key, e.value.location});
    if (r.read_string("name", g.name)) {
      m_sensor_folders.add("grid", g.name, r.location_of("name"), m_reporter);
      m_sensor_names.add(g.name, r.location_of("name"), m_reporter);
    }
    // What the grid covers: exactly one of these keys.
    static const char* const outlines[] = {"room", "polygon", "wall", "rectangle"};
    std::vector<std::string> given;
    for (const char* key : outlines)
      if (r.has(key)) given.push_back(key);
    if (r.has("room") && r.read_string("room", g.room)) m_room_uses.push_back({g.room, r.location_of("room")});
    else r.take("room");
    if (r.has("polygon")) {
      if (r.read_points("polygon", g.polygon) && g.polygon.size() < 3)
        m_reporter.error(r.location_of("polygon"), "'polygon' needs at least 3 points, got " +
                                                       std::to_string(g.polygon.size()));
    } else {
      r.take("polygon");
    }
    if (const YamlNode* wall = r.take("wall"); wall && expect_map(*wall, "wall", m_reporter)) read_grid_wall(*wall, g);
    if (const YamlNode* rect = r.take("rectangle"); rect && expect_map(*rect, "rectangle", m_reporter))
      read_grid_rectangle(*rect, g);
    if (given.size() > 1)
      m_reporter.error(r.location_of(given[1]), "grid takes one of 'room', 'polygon', 'wall' and 'rectangle', got '" +
                                                    given[0] + "' and '" + given[1] + "'");
    else if (given.empty())
      m_reporter.error(node.location, "grid needs one of 'room', 'polygon', 'wall' and 'rectangle'");
    // Keys that only apply to one kind of grid: an error rather than silence (STYLE.md A.5).
    const bool surface_grid = r.has("wall") || r.has("rectangle");
    const std::string facing = r.has("wall") ? "a wall grid's sensors face into the room"
                                             : "a rectangle grid's sensors face u x v";
    for (const char* key : {"height", "normal"})
      if (surface_grid && r.has(key))
        m_reporter.error(r.location_of(key), "'" + std::string(key) + "' applies to room and polygon grids only (" +
                                                 facing + "; 'offset' moves them off the surface)");
    if (!surface_grid && r.has("offset"))
      m_reporter.error(r.location_of("offset"), "'offset' applies to wall and rectangle grids only (room and polygon "
                                                "grids are placed by 'height')");
    r.read_number("height", g.height_m);
    r.read_number("spacing", g.spacing_m);
    g.spacing_location = r.location_of("spacing");
    r.read_number("inset", g.inset_m);
    r.read_number("offset", g.offset_m);
    Vec3 normal;
    if (r.read_vec3("normal", normal)) {
      if (length(normal) > 0) g.normal = normalize(normal);
      else m_reporter.error(r.location_of("normal"), "'normal' must not be the zero vector");
    }
    r.read_bool("drop_occluded", g.drop_occluded);
    if (const YamlNode* occupancy = r.take("occupancy"); occupancy && expect_map(*occupancy, "occupancy", m_reporter))
      read_occupancy(*occupancy, m_project.directory, m_reporter, g.occupancy);
    r.finish();
    m_project.sensors.grids.push_back(std::move(g));
  }

  void read_grid_wall(const YamlNode& node, GridSpec& g) {
    ParamReader r(node, schema_section("grid wall"), m_reporter);
    for (const auto& e : node.entries) g.key_locations.push_back({"wall." + e.key, e.value.location});
    GridSpec::WallReference wall;
    const bool have_room = r.read_string("room", wall.room);
    if (have_room) m_room_uses.push_back({wall.room, r.location_of("room")});
    std::string surface;
    const bool have_surface = r.read_choice("wall", surface);
    r.finish();
    if (!have_room || !have_surface) return;
    for (RoomSurface s : {RoomSurface::South, RoomSurface::North, RoomSurface::East, RoomSurface::West,
                          RoomSurface::Floor, RoomSurface::Ceiling})
      if (surface == room_surface_name(s)) wall.surface = s;
    g.wall = wall;
  }

  void read_grid_rectangle(const YamlNode& node, GridSpec& g) {
    ParamReader r(node, schema_section("grid rectangle"), m_reporter);
    for (const auto& e : node.entries) g.key_locations.push_back({"rectangle." + e.key, e.value.location});
    GridSpec::Rectangle rect;
    const bool ok = r.read_vec3("origin", rect.origin) & r.read_vec3("u", rect.u) & r.read_vec3("v", rect.v);
    r.finish();
    if (ok) g.rectangle = rect;  // zero or parallel edges: generate_grid reports them at 'u'/'v'
  }

  void read_points(const YamlNode& node) {
    PointsSpec p;
    p.location = node.location;
    ParamReader r(node, schema_section("points"), m_reporter);
    if (r.read_string("name", p.name)) {
      m_sensor_folders.add("point set", p.name, r.location_of("name"), m_reporter);
      m_sensor_names.add(p.name, r.location_of("name"), m_reporter);
    }
    const bool has_points = r.has("points"), has_file = r.has("file");
    if (const YamlNode* list = r.take("points"); list && has_points) read_point_list(*list, p.points);
    if (has_file) {
      if (r.read_string("file", p.file_as_written))
        existing_file("points file", p.file_as_written, r.location_of("file"), p.file);
    } else {
      r.take("file");
    }
    if (r.has("units")) {
      if (!has_file)
        m_reporter.error(r.location_of("units"),
                         "'units' is the unit of a .pts 'file'; inline 'points' are in metres");
      if (r.read_choice("units", p.units)) p.metres_per_unit = metres_per_length_unit(p.units);
    }
    if (has_points && has_file)
      m_reporter.error(r.location_of("file"), "points takes 'points' or 'file', not both");
    else if (!has_points && !has_file)
      m_reporter.error(node.location, "points needs 'points' or 'file'");
    r.read_bool("drop_occluded", p.drop_occluded);
    if (const YamlNode* occupancy = r.take("occupancy"); occupancy && expect_map(*occupancy, "occupancy", m_reporter))
      read_occupancy(*occupancy, m_project.directory, m_reporter, p.occupancy);
    r.finish();
    m_project.sensors.points.push_back(std::move(p));
  }

  void read_point_list(const YamlNode& list, std::vector<SensorPoint>& out) {
    if (!list.is_sequence() || list.items.empty()) {
      m_reporter.error(list.location, "expected a list of [x, y, z, nx, ny, nz] for 'points', got " +
                                          list.describe());
      return;
    }
    for (const auto& item : list.items) {
      double v[6] = {};
      bool good = item.is_sequence() && item.items.size() == 6;
      for (int i = 0; good && i < 6; ++i) {
        const YamlNode& c = item.items[static_cast<std::size_t>(i)];
        good = c.is_scalar() && parse_double(c.scalar, v[i]);
      }
      if (!good) {
        m_reporter.error(item.location, "expected [x, y, z, nx, ny, nz] numbers in 'points', got " +
                                            item.describe());
        continue;
      }
      const Vec3 normal{v[3], v[4], v[5]};
      if (!(length(normal) > 0)) {
        m_reporter.error(item.location, "sensor normal must not be the zero vector");
        continue;
      }
      out.push_back({Vec3{v[0], v[1], v[2]}, normalize(normal)});
    }
  }

  // ---- simulation and outputs -----------------------------------------------------------
  void read_simulation(const YamlNode& node) {
    if (!expect_map(node, "simulation", m_reporter)) return;
    Simulation& s = m_project.simulation;
    s.location = node.location;
    ParamReader r(node, schema_section("simulation"), m_reporter);
    read_basis(r);
    long long v = 0;
    s.photons_per_bin_location = r.location_of("photons_per_bin");
    if (r.read_integer("photons_per_bin", v)) s.photons_per_bin = v;
    if (r.read_integer("bandwidth", v)) s.bandwidth = static_cast<int>(v);
    if (r.read_integer("seed", v)) s.seed = static_cast<unsigned long long>(v);
    r.read_number("ground_reflectance", s.ground_reflectance);
    std::string sun;
    if (r.read_choice("sun", sun)) s.sun = sun == "spread" ? SunMode::Spread : SunMode::Bins;
    if (r.read_integer("sun_mf", v)) s.sun_mf = static_cast<int>(v);
    if (r.read_integer("direct_samples_per_bin", v)) s.direct_samples_per_bin = static_cast<int>(v);
    if (r.read_integer("caustic_photons_per_bin", v)) s.caustic_photons_per_bin = v;
    if (r.read_integer("caustic_bandwidth", v)) s.caustic_bandwidth = static_cast<int>(v);
    if (const YamlNode* roi = r.take("region_of_interest"); roi && expect_map(*roi, "region_of_interest", m_reporter)) {
      Simulation::RegionOfInterest box;
      box.location = roi->location;
      ParamReader b(*roi, schema_section("region of interest"), m_reporter);
      b.read_vec3("origin", box.origin_m);
      b.read_vec3("size", box.size_m);
      b.finish();
      s.region_of_interest = box;
    }
    if (r.read_integer("max_attempts_per_photon", v)) s.max_attempts_per_photon = v;
    if (const YamlNode* acc = r.take("accuracy"); acc && expect_map(*acc, "accuracy", m_reporter))
      read_accuracy(*acc, r);
    std::string estimator;
    if (r.read_choice("estimator", estimator))
      s.estimator = estimator == "contribution" ? Estimator::Contribution : Estimator::PerSource;
    std::string point_estimate;
    if (r.read_choice("point_estimate", point_estimate))
      s.point_estimate = point_estimate == "surface" ? PointEstimate::Surface : PointEstimate::Gather;
    if (r.read_integer("gather_rays", v)) s.gather_rays = static_cast<int>(v);
    if (r.read_integer("gather_bandwidth", v)) s.gather_bandwidth = static_cast<int>(v);
    // No photon count and no accuracy: the run traces to the default accuracy target (the final
    // preset, docs/photon-tracing.md "Accuracy target"); explicit counts stay for experts.
    if (!s.accuracy && !r.has("photons_per_bin") && !r.has("caustic_photons_per_bin")) {
      Simulation::Accuracy a;
      a.preset = "final";
      a.target_df_relative_stderr_percent = 1.0;
      a.defaulted = true;
      a.location = node.location;
      a.max_photons_location = node.location;
      s.accuracy = a;
    }
    r.finish();
  }

  /// simulation.accuracy: a preset or a target, and the budgets. It replaces the photon
  /// counts, so writing photons_per_bin (or a caustic target) as well is an error.
  void read_accuracy(const YamlNode& node, ParamReader& simulation) {
    Simulation& s = m_project.simulation;
    Simulation::Accuracy a;
    a.location = node.location;
    ParamReader r(node, schema_section("accuracy"), m_reporter);
    const bool target_written = r.has("target_df_relative_stderr_percent");
    r.read_number("target_df_relative_stderr_percent", a.target_df_relative_stderr_percent);
    if (r.has("preset") && r.read_choice("preset", a.preset)) {
      if (target_written)
        m_reporter.error(r.location_of("preset"),
                         "give either 'preset' or 'target_df_relative_stderr_percent' in 'accuracy', not both");
      a.target_df_relative_stderr_percent = a.preset == "draft" ? 5.0 : a.preset == "standard" ? 2.0 : 1.0;
    }
    long long v = 0;
    if (r.read_integer("max_photons", v)) a.max_photons = v;
    r.read_number("max_seconds", a.max_seconds);
    r.finish();
    for (const char* key : {"photons_per_bin", "caustic_photons_per_bin"})
      if (simulation.has(key))
        m_reporter.error(simulation.location_of(key),
                         std::string("'") + key + "' and 'accuracy' exclude each other: the accuracy target chooses "
                         "the photons of every sky bin (remove one of them)");
    a.max_photons_location = r.location_of("max_photons");
    s.accuracy = a;
  }

  void read_basis(ParamReader& r) {
    Simulation& s = m_project.simulation;
    const YamlNode* node = r.take("basis");
    if (!node || node->is_null()) {
      s.basis = SkyBasis::Tregenza;  // schema default "tregenza"
      s.reinhart_mf = 1;
      return;
    }
    if (node->is_map()) {
      ParamReader b(*node, schema_section("basis"), m_reporter);
      long long mf = 1;
      if (b.read_integer("reinhart", mf)) {
        s.basis = SkyBasis::Reinhart;
        s.reinhart_mf = static_cast<int>(mf);
      }
      b.finish();
      return;
    }
    const std::string text = node->is_scalar() ? node->scalar : std::string();
    if (text == "tregenza") {
      s.basis = SkyBasis::Tregenza;
      s.reinhart_mf = 1;
      return;
    }
    const std::string prefix = "reinhart:";
    long long mf = 0;
    if (text.compare(0, prefix.size(), prefix) == 0) {
      std::string number = text.substr(prefix.size());
      while (!number.empty() && number.front() == ' ') number.erase(number.begin());
      if (parse_integer(number, mf) && mf >= 1 && mf <= 12) {
        s.basis = SkyBasis::Reinhart;
        s.reinhart_mf = static_cast<int>(mf);
      } else {
        m_reporter.error(node->location, "Reinhart subdivision in 'basis' must be an integer in "
                                         "[1, 12], got '" + number + "'");
      }
      return;
    }
    std::string message = "unknown value " + node->describe() +
                          " for 'basis': expected tregenza, reinhart:N or {reinhart: N}";
    const std::string hint = closest_match(text, {"tregenza", "reinhart"});
    if (!text.empty() && !hint.empty())
      message += " (did you mean '" + std::string(hint == "reinhart" ? "reinhart:N" : hint) + "'?)";
    m_reporter.error(node->location, message);
  }

  // ---- limits ---------------------------------------------------------------------------
  void read_limits(const YamlNode& node) {
    if (!expect_map(node, "limits", m_reporter)) return;
    ResourceLimits& l = m_project.limits;
    ParamReader r(node, schema_section("limits"), m_reporter);
    long long v = 0;
    if (r.read_integer("sensors_per_grid", v)) l.sensors_per_grid = static_cast<std::uint64_t>(v);
    if (r.read_integer("sensors", v)) l.sensors = static_cast<std::uint64_t>(v);
    if (r.read_integer("photons", v)) l.photons = static_cast<std::uint64_t>(v);
    r.finish();
  }

  /// The photons one tracing pass stores, (photons_per_bin + caustic_photons_per_bin) x sky
  /// bins, against limits.photons; reported at photons_per_bin before anything is traced.
  void check_photon_limit() {
    const Simulation& s = m_project.simulation;
    if (s.accuracy && s.accuracy->max_photons > 0 &&
        std::uint64_t(s.accuracy->max_photons) > m_project.limits.photons)
      m_reporter.error(s.accuracy->max_photons_location,
                       "accuracy.max_photons " + std::to_string(s.accuracy->max_photons) + " " +
                           over_limit_text(m_project.limits.photons, "limits.photons"));
    // Bins of the sky basis, ground included: Tregenza 145 patches + 1; Reinhart MF n
    // 144 n^2 + 1 patches + 1 (Reinhart, "Tregenza's and Reinhart's sky subdivisions";
    // RADIANCE's reinhartb.cal).
    const double bins = s.basis == SkyBasis::Tregenza ? 146.0 : 144.0 * s.reinhart_mf * s.reinhart_mf + 2.0;
    const double per_bin = double(s.photons_per_bin) + double(s.caustic_photons_per_bin);
    const double photons = per_bin * bins;
    const std::uint64_t limit = m_project.limits.photons;
    if (photons <= double(limit)) return;
    m_reporter.error(s.photons_per_bin_location,
                     "one tracing pass would store " + format_number(photons) + " photons (" +
                         format_number(per_bin) + " per bin x " + format_number(bins) + " sky bins), " +
                         over_limit_text(limit, "limits.photons") + "; 32 bytes each");
  }

  void read_outputs(const YamlNode& node) {
    if (!expect_map(node, "outputs", m_reporter)) return;
    Outputs& o = m_project.outputs;
    o.location = node.location;
    ParamReader r(node, schema_section("outputs"), m_reporter);
    if (r.read_string("folder", o.folder_as_written)) o.folder = resolve(o.folder_as_written);
    r.read_bool("daylight_factor", o.daylight_factor);
    r.read_bool("annual_illuminance", o.annual_illuminance);
    r.read_bool("metrics", o.metrics);
    for (const char* key : {"annual_illuminance", "metrics"})
      if (r.has(key))
        m_annual_outputs_written[key] = {r.location_of(key), key == std::string("metrics") ? o.metrics
                                                                                            : o.annual_illuminance};
    r.read_bool("illuminance_csv", o.illuminance_csv);
    r.read_bool("coefficients", o.coefficients);
    r.read_bool("radiance_sun_matrix", o.radiance_sun_matrix);
    // Outputs of the annual study only (check_study_kind).
    if (r.has("illuminance_csv")) m_annual_outputs_written["illuminance_csv"] = {r.location_of("illuminance_csv"), o.illuminance_csv};
    if (r.has("radiance_sun_matrix")) {
      m_annual_outputs_written["radiance_sun_matrix"] = {r.location_of("radiance_sun_matrix"), o.radiance_sun_matrix};
      m_radiance_sun_matrix_location = r.location_of("radiance_sun_matrix");
    }
    r.read_bool("images", o.images);
    r.read_bool("report", o.report);
    r.read_choice("matrix_format", o.matrix_format);
    r.read_bool("folder_outside_project", o.folder_outside_project);
    if (!m_options.output_folder_overridden && !o.folder_outside_project) {
      const std::string outside = outside_project(o.folder_as_written);
      if (!outside.empty())
        m_reporter.error(r.location_of("folder"),
                         "outputs.folder '" + printable_name(o.folder_as_written) + "' lies outside the project's folder (" +
                             outside + "): set 'folder_outside_project: true' in outputs to write there, "
                             "or give run --output");
    }
    r.finish();
  }

  /// Why a folder as written lies outside the project's folder ("an absolute path", "'..'
  /// leads out of it"), or "" if it lies inside. Lexical: a symbolic link inside is the user's own.
  static std::string outside_project(const std::string& written) {
    const fs::path p(written);
    if (p.has_root_directory() || p.has_root_name()) return "an absolute path";
    const fs::path normal = p.lexically_normal();
    if (!normal.empty() && *normal.begin() == "..") return "'..' leads out of it";
    return {};
  }

  // ---- metrics settings -----------------------------------------------------------------
  void read_metrics(const YamlNode& node) {
    if (!expect_map(node, "metrics", m_reporter)) return;
    MetricsSettings& m = m_project.metrics;
    m.location = node.location;
    ParamReader r(node, schema_section("metrics"), m_reporter);
    std::vector<double> thresholds;
    if (r.read_numbers("daylight_factor_thresholds", thresholds)) {
      bool unique = true;
      for (std::size_t i = 0; i < thresholds.size(); ++i)
        for (std::size_t j = 0; j < i; ++j)
          if (thresholds[i] == thresholds[j] && unique) {
            // Only a file value can repeat (the default has one element), so items exist.
            m_reporter.error(node.find("daylight_factor_thresholds")->value.items[i].location,
                             "duplicate value " + format_number(thresholds[i]) +
                                 " in 'daylight_factor_thresholds'");
            unique = false;
          }
      if (unique) m.daylight_factor_thresholds_percent = thresholds;
    }
    const bool da = r.read_number("da_threshold", m.da_threshold_lux);
    const bool start = r.read_number("occupancy_start", m.occupancy_start_h);
    const bool end = r.read_number("occupancy_end", m.occupancy_end_h);
    if (const YamlNode* occupancy = r.take("occupancy"); occupancy && expect_map(*occupancy, "occupancy", m_reporter)) {
      for (const char* old_key : {"occupancy_start", "occupancy_end"})
        if (r.has(old_key))
          m_reporter.error(node.find(old_key)->key_location,
                           std::string("'") + old_key + "' cannot be combined with 'occupancy': write the hours "
                           "there (every_day: [start, end])");
      read_occupancy(*occupancy, m_project.directory, m_reporter, m.occupancy);
    }
    const bool low = r.read_number("udi_lower", m.udi_lower_lux);
    const bool up1 = r.read_number("udi_upper_original", m.udi_upper_original_lux);
    const bool up2 = r.read_number("udi_upper_revised", m.udi_upper_revised_lux);
    r.read_number("sda_time_fraction", m.sda_time_fraction);
    r.read_number("ase_threshold", m.ase_threshold_lux);
    r.read_number("ase_hours", m.ase_hours);

    // Relations between keys. Reported at the first of the keys written in the file (a
    // default cannot be wrong on its own), so the caret points at what the user typed.
    auto at = [&](const char* first, const char* second) {
      return r.location_of(r.has(first) ? first : second);
    };
    auto value = [](double v) { return format_number(v); };
    if (start && end && !(m.occupancy_end_h > m.occupancy_start_h))
      m_reporter.error(at("occupancy_end", "occupancy_start"),
                       "'occupancy_end' (" + value(m.occupancy_end_h) +
                           ") must be after 'occupancy_start' (" + value(m.occupancy_start_h) + ")");
    if (low && up1 && !(m.udi_upper_original_lux > m.udi_lower_lux))
      m_reporter.error(at("udi_upper_original", "udi_lower"),
                       "'udi_upper_original' (" + value(m.udi_upper_original_lux) +
                           ") must be greater than 'udi_lower' (" + value(m.udi_lower_lux) + ")");
    if (low && up2 && !(m.udi_upper_revised_lux > m.udi_lower_lux))
      m_reporter.error(at("udi_upper_revised", "udi_lower"),
                       "'udi_upper_revised' (" + value(m.udi_upper_revised_lux) +
                           ") must be greater than 'udi_lower' (" + value(m.udi_lower_lux) + ")");
    else if (da && low && up2 &&
             (m.da_threshold_lux < m.udi_lower_lux || m.da_threshold_lux > m.udi_upper_revised_lux))
      // The revised UDI splits [udi_lower, udi_upper_revised] at the DA threshold into
      // supplementary and autonomous; outside that band the bins would not partition the hours.
      m_reporter.error(r.has("da_threshold") ? r.location_of("da_threshold")
                                             : at("udi_lower", "udi_upper_revised"),
                       "'da_threshold' (" + value(m.da_threshold_lux) +
                           ") must lie between 'udi_lower' (" + value(m.udi_lower_lux) +
                           ") and 'udi_upper_revised' (" + value(m.udi_upper_revised_lux) +
                           "): the revised UDI band is split there");
    r.finish();
  }

  // ---- variants -------------------------------------------------------------------------
  void read_variant(const YamlNode& node) {
    VariantSpec v;
    v.location = node.location;
    ParamReader r(node, schema_section("variant"), m_reporter);
    if (r.read_string("name", v.name)) {
      m_variant_folders.add("variant", v.name, r.location_of("name"), m_reporter);
      m_variant_names.add(v.name, r.location_of("name"), m_reporter);
    }
    std::size_t changes = 0;
    const YamlNode* empty_map = nullptr;
    auto count = [&](const YamlNode& map, std::size_t n) {
      changes += n;
      if (n == 0 && !empty_map) empty_map = &map;
    };
    bool any = false;
    for (const char* key : {"materials", "systems", "remove", "add"}) any = any || r.has(key);
    if (const YamlNode* mats = r.take("materials"); mats && expect_map(*mats, "materials", m_reporter)) {
      count(*mats, mats->entries.size());
      for (const auto& entry : mats->entries) {
        m_variant_material_uses.push_back({{entry.key, entry.key_location}, v.name});
        MaterialSpec m;
        if (read_material(entry, m)) v.materials.push_back(std::move(m));
      }
    }
    if (const YamlNode* systems = r.take("systems"); systems && expect_map(*systems, "systems", m_reporter)) {
      count(*systems, systems->entries.size());
      for (const auto& entry : systems->entries) read_variant_system(entry, v);
    }
    AddedNames added;
    // A `remove` or `add` with keys changes something, or has its own errors.
    if (const YamlNode* n = r.take("remove"); n && expect_map(*n, "remove", m_reporter))
      count(*n, read_variant_removals(*n, v.remove) + n->entries.size());
    if (const YamlNode* n = r.take("add"); n && expect_map(*n, "add", m_reporter))
      count(*n, read_variant_additions(*n, v.add, added) + n->entries.size());
    if (!any)
      m_reporter.error(node.location, "missing required key 'materials', 'systems', 'remove' or 'add' in variant");
    else if (changes == 0 && empty_map)
      m_reporter.error(empty_map->location, "variant '" + v.name + "' changes nothing (replace a material or "
                                            "system, or remove or add an element)");
    r.finish();
    m_project.variants.push_back(std::move(v));
    m_variant_added.push_back(std::move(added));
  }

  /// `remove: {polygons: [name, ...], ...}`; returns the number of names.
  std::size_t read_variant_removals(const YamlNode& node, VariantRemovals& out) {
    ParamReader r(node, schema_section("variant remove"), m_reporter);
    std::size_t n = 0;
    for (auto [key, list] : {std::pair{"polygons", &out.polygons}, {"boxes", &out.boxes}, {"meshes", &out.meshes},
                             {"systems", &out.systems}, {"windows", &out.windows}}) {
      *list = read_names(r, key);
      n += list->size();
    }
    r.finish();
    return n;
  }

  /// A non-empty list of names, each where it was written.
  std::vector<Located<std::string>> read_names(ParamReader& r, const std::string& key) {
    std::vector<Located<std::string>> names;
    const YamlNode* list = r.take(key);
    if (!list) return names;
    if (!list->is_sequence() || list->items.empty()) {
      m_reporter.error(list->location, "expected a list of one or more names for '" + key + "', got " +
                                           (list->is_sequence() ? std::string("an empty list") : list->describe()));
      return names;
    }
    for (const YamlNode& item : list->items) {
      if (item.is_scalar() && !item.scalar.empty()) names.push_back({item.scalar, item.location});
      else m_reporter.error(item.location, "expected a name in '" + key + "', got " + item.describe());
    }
    return names;
  }

  /// `add: {polygons: [...], ...}`: full definitions read as the base's, their names unique
  /// within the variant (against the base: check_variant). Returns the number of elements.
  std::size_t read_variant_additions(const YamlNode& node, VariantAdditions& out, AddedNames& added) {
    ParamReader r(node, schema_section("variant add"), m_reporter);
    NameSet polygons{"polygon"}, boxes{"box"}, meshes{"mesh"}, systems{"system"}, windows{"window"};
    auto located = [](const NameSet& names, const std::string& name, std::vector<Located<std::string>>& to) {
      const bool listed = std::any_of(to.begin(), to.end(), [&](const auto& l) { return l.value == name; });
      if (names.contains(name) && !listed) to.push_back(names.first(name));
    };
    for_each_item(r, "polygons", [&](const YamlNode& n) {
      out.polygons.push_back(read_polygon(n, polygons));
      located(polygons, out.polygons.back().name, added.polygons);
    });
    for_each_item(r, "boxes", [&](const YamlNode& n) {
      out.boxes.push_back(read_box(n, boxes));
      located(boxes, out.boxes.back().name, added.boxes);
    });
    for_each_item(r, "meshes", [&](const YamlNode& n) {
      out.meshes.push_back(read_mesh(n, meshes));
      located(meshes, out.meshes.back().name, added.meshes);
    });
    for_each_item(r, "systems", [&](const YamlNode& n) {
      auto sys = read_system(n, /*base=*/false);
      if (!sys) return;
      if (!sys->name.empty()) {
        systems.add(sys->name, sys->location_of("name"), m_reporter);
        located(systems, sys->name, added.systems);
      }
      out.systems.push_back(std::move(*sys));
    });
    for_each_item(r, "windows", [&](const YamlNode& n) {
      AddedWindow w;
      w.window = read_window(n, windows, &w.room);
      located(windows, w.window.name, added.windows);
      out.windows.push_back(std::move(w));
    });
    r.finish();
    return out.polygons.size() + out.boxes.size() + out.meshes.size() + out.systems.size() + out.windows.size();
  }

  /// `system_name: {key: value, ...}` of a variant: the base system's node with these keys
  /// put in place (or added), read again as a whole, so every rule of the system applies and
  /// errors point at the line that set the key (the variant's or the base's).
  void read_variant_system(const YamlEntry& entry, VariantSpec& v) {
    const auto base = m_system_nodes.find(entry.key);
    if (base == m_system_nodes.end()) {
      std::vector<std::string> known;
      for (const auto& kv : m_system_nodes) known.push_back(kv.first);
      unknown_name("system", {entry.key, entry.key_location}, known, " in variant '" + v.name + "'");
      return;
    }
    if (!expect_map(entry.value, entry.key, m_reporter)) return;
    if (entry.value.entries.empty()) {
      m_reporter.error(entry.value.location, "variant '" + v.name + "' changes no key of system '" +
                                                 entry.key + "'");
      return;
    }
    YamlNode merged = base->second;
    bool ok = true;
    for (const auto& change : entry.value.entries) {
      if (change.key == "type" || change.key == "name") {
        m_reporter.error(change.key_location, "a variant cannot change '" + change.key +
                                                  "' of system '" + entry.key +
                                                  "' (define another system and disable this one)");
        ok = false;
        continue;
      }
      bool replaced = false;
      for (auto& e : merged.entries)
        if (e.key == change.key) {
          e = change;
          replaced = true;
        }
      if (!replaced) merged.entries.push_back(change);
    }
    if (!ok) return;
    if (auto sys = read_system(merged, /*base=*/false)) v.systems.push_back(std::move(*sys));
  }

  // ---- operated shading -------------------------------------------------------------------
  void read_operation(const YamlNode& node) {
    if (!expect_map(node, "operation", m_reporter)) return;
    OperationSpec op;
    op.location = node.location;
    ParamReader r(node, schema_section("operation"), m_reporter);
    bool names = r.read_string("open", op.open.value);
    op.open.location = r.location_of("open");
    names = r.read_string("shaded", op.shaded.value) && names;
    op.shaded.location = r.location_of("shaded");
    r.read_number("direct_sun_threshold", op.direct_sun_threshold_lux);
    r.read_number("sunlit_limit", op.sunlit_limit_percent);
    r.finish();
    if (!names) return;
    // Case names: `base` or a variant (variants are read before this section).
    std::vector<std::string> cases = m_variant_names.names();
    cases.push_back(BaseCaseName);
    bool known = true;
    for (const auto* key : {"open", "shaded"}) {
      const Located<std::string>& name = std::string(key) == "open" ? op.open : op.shaded;
      if (name.value == BaseCaseName && m_variant_names.contains(BaseCaseName)) {
        m_reporter.error(name.location, "'" + std::string(key) + "': 'base' is ambiguous: a variant is named "
                                        "'base' too (rename the variant)");
        known = false;
      } else if (name.value != BaseCaseName && !m_variant_names.contains(name.value)) {
        unknown_name("case", {name.value, name.location}, cases,
                     " in operation." + std::string(key) + " (a variant name or 'base')");
        known = false;
      }
    }
    if (known && op.open.value == op.shaded.value)
      m_reporter.error(op.shaded.location, "operation 'shaded' names the same case as 'open' ('" +
                                               op.open.value + "'): nothing would be operated");
    // The rule needs each hour's direct sun, which only the sun-bins mode traces.
    if (m_project.simulation.sun == SunMode::Spread)
      m_reporter.error(node.location, "operation needs the direct sun of every hour: set simulation.sun "
                                      "to 'bins' (with 'spread' the sun is smeared into sky patches)");
    const Outputs& o = m_project.outputs;
    if (!o.annual_illuminance && !o.metrics)
      m_reporter.error(node.location, "operation needs annual results: outputs.annual_illuminance or "
                                      "outputs.metrics must be true");
    m_project.operation = std::move(op);
  }

  // ---- references -----------------------------------------------------------------------
  void check_references() {
    // A variant's system is read again from the base's lines: report each place once.
    std::set<std::tuple<std::string, std::string, int, int>> seen;
    for (const auto& use : m_material_uses)
      if (!m_material_names.contains(use.name) &&
          seen.insert({use.name, use.location.file, use.location.line, use.location.column}).second)
        unknown_name("material", use, m_material_names.names());
    // A variant replaces materials; it cannot add new ones (nothing would use them).
    for (const auto& use : m_variant_material_uses)
      if (!m_material_names.contains(use.material.name))
        unknown_name("material", use.material, m_material_names.names(),
                     " in variant '" + use.variant + "'");
    for (const auto& use : m_room_uses)
      if (!m_room_names.contains(use.name) &&
          seen.insert({"room " + use.name, use.location.file, use.location.line, use.location.column}).second)
        unknown_name("room", use, m_room_names.names());
    for (const auto& use : m_window_uses)
      if (!m_window_names.contains(use.name) &&
          seen.insert({"window " + use.name, use.location.file, use.location.line, use.location.column}).second)
        unknown_name("window", use, m_window_names.names());
  }

  void unknown_name(const std::string& kind, const NameUse& use, const std::vector<std::string>& known,
                    const std::string& where = "") {
    std::string message = "unknown " + kind + " '" + use.name + "'" + where;
    const std::string hint = closest_match(use.name, known);
    if (!hint.empty()) message += " (did you mean '" + hint + "'?)";
    m_reporter.error(use.location, message);
  }

  Project& m_project;
  Reporter& m_reporter;
  const LoadOptions& m_options;
  /// outputs.annual_illuminance and outputs.metrics where written, with their values
  /// (check_study_kind: a daylight-factor study cannot make them).
  std::map<std::string, std::pair<SourceLocation, bool>> m_annual_outputs_written;
  SourceLocation m_radiance_sun_matrix_location;  ///< of outputs.radiance_sun_matrix, if written
  NameSet m_point_names{"point-in-time case"};
  FolderNames m_point_folders{{}, ""};
  SourceLocation m_from_weather_location;  ///< of site.from_weather (its check needs the weather key)
  bool m_honeybee_given = false;  ///< geometry.honeybee written (read or not)
  std::optional<SourceLocation> m_site_north_location;  ///< site.north, where written
  NameSet m_material_names{"material"}, m_room_names{"room"}, m_window_names{"window"},
      m_roof_light_names{"roof light"},
      m_polygon_names{"polygon"}, m_box_names{"box"}, m_mesh_names{"mesh"},
      m_sensor_names{"sensor set"}, m_variant_names{"variant"}, m_system_names{"system"};
  // Sensor sets are folders beside `variants/` and `operated/` (docs/outputs.md); variants
  // are folders inside `variants/`.
  FolderNames m_sensor_folders{{"variants", "operated"},
                               "the output folder holds the folders 'variants' and 'operated'"};
  FolderNames m_variant_folders{{}, ""};
  std::vector<NameUse> m_material_uses, m_room_uses, m_window_uses;
  std::map<std::string, YamlNode> m_system_nodes;  ///< base systems as written, for variants
  struct VariantMaterialUse {
    NameUse material;
    std::string variant;
  };
  std::vector<VariantMaterialUse> m_variant_material_uses;
  std::vector<AddedNames> m_variant_added;  ///< per variant, in order
};

}  // namespace

const char* room_surface_name(RoomSurface surface) {
  switch (surface) {
    case RoomSurface::South: return "south";
    case RoomSurface::North: return "north";
    case RoomSurface::East: return "east";
    case RoomSurface::West: return "west";
    case RoomSurface::Floor: return "floor";
    case RoomSurface::Ceiling: return "ceiling";
  }
  return "north";
}

SourceLocation GridSpec::location_of(const std::string& key) const {
  for (const auto& kv : key_locations)
    if (kv.first == key) return kv.second;
  return location;
}

const char* study_kind_name(StudyKind kind) {
  return kind == StudyKind::DaylightFactor ? "daylight_factor" : "annual";
}

const char* point_sky_name(PointSky sky) {
  switch (sky) {
    case PointSky::CieOvercast: return "cie_overcast";
    case PointSky::CieGeneral: return "cie";
    case PointSky::Weather: return "weather";
  }
  return "cie_overcast";
}

const char* wall_name(Wall wall) {
  switch (wall) {
    case Wall::South: return "south";
    case Wall::North: return "north";
    case Wall::East: return "east";
    case Wall::West: return "west";
  }
  return "south";
}

Project load_project_from_string(const std::string& text, const std::string& path,
                                 const LoadOptions& options) {
  Project project;
  project.path = path;
  project.directory = fs::path(path).parent_path().string();
  Diagnostics diagnostics;  // cap 50
  const SourceText source(path, text);
  Reporter reporter(diagnostics, source);
  const YamlNode root = parse_yaml_document(text, reporter);
  Loader(project, reporter, options).load(root);  // a syntax error leaves a Null root: nothing more to say
  diagnostics.throw_if_errors();
  return project;
}

Project load_project(const std::string& path, const LoadOptions& options) {
  std::ifstream in = open_input_file(path, "project file");
  // One byte more than the limit is enough for the loader to say the file is too large.
  std::string text(MaxYamlBytes + 1, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  if (in.bad()) throw InputError(SourceLocation{path, 0, 0}, "cannot read project file");
  text.resize(static_cast<std::size_t>(in.gcount()));
  return load_project_from_string(text, path, options);
}

}  // namespace dayphoton::project
