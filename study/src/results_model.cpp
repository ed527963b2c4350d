// results.json: writer and reader of the results model; see results_model.h and
// docs/outputs.md ("results.json") for every field.
#include "dayphoton/study/results_model.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "dayphoton/core/atomic_file.h"
#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/input_file.h"
#include "dayphoton/metrics/calendar.h"
#include "dayphoton/project/path_name.h"
#include "dayphoton/study/annual_illuminance.h"
#include "dayphoton/study/result_tables.h"
#include "json_text.h"

namespace dayphoton::study {

namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

json vec(const Vec3& v) { return json::array({v.x, v.y, v.z}); }
json polygon(const Polygon3& p) {
  json a = json::array();
  for (const Vec3& v : p) a.push_back(vec(v));
  return a;
}
json polygons(const std::vector<Polygon3>& ps) {
  json a = json::array();
  for (const Polygon3& p : ps) a.push_back(polygon(p));
  return a;
}
json optional_number(const std::optional<double>& v) { return v ? json(*v) : json(nullptr); }

json intervals_json(const std::vector<SunlightInterval>& intervals) {
  json a = json::array();
  for (const SunlightInterval& i : intervals) a.push_back(json::array({i.start_h, i.end_h}));
  return a;
}
json sunlight_json(const std::vector<RoomSunlight>& rooms) {
  json a = json::array();
  for (const RoomSunlight& r : rooms) {
    json windows = json::array();
    for (const WindowSunlight& w : r.windows)
      windows.push_back({{"name", w.name}, {"reference_point_m", vec(w.reference_point_m)},
                         {"intervals_h", intervals_json(w.intervals)}, {"hours", w.hours},
                         {"not_assessed", w.not_assessed}});
    a.push_back({{"room", r.room}, {"windows", windows}, {"intervals_h", intervals_json(r.intervals)},
                 {"hours", r.hours}, {"level", r.level}});
  }
  return a;
}

const char* scale_name(QuantityScale s) {
  switch (s) {
    case QuantityScale::DaylightFactor: return "daylight_factor";
    case QuantityScale::Percent: return "percent";
    case QuantityScale::Illuminance: return "illuminance";
  }
  return "percent";
}

json windows_json(const OccupancySummary::Windows& windows) {
  json a = json::array();
  for (const auto& [start, end] : windows) a.push_back({start, end});
  return a;
}

json occupancy_json(const OccupancySummary& o) {
  json week = json::array();
  for (const OccupancySummary::Windows& day : o.week) week.push_back(windows_json(day));
  json holidays = json::array();
  for (const OccupancySummary::Holiday& h : o.holidays)
    holidays.push_back({{"from", {h.from_month, h.from_day}}, {"to", {h.to_month, h.to_day}}});
  return {{"kind", o.kind},
          {"start_h", o.start_h},
          {"end_h", o.end_h},
          {"description", o.description},
          {"week", week},
          {"holiday_hours", windows_json(o.holiday_hours)},
          {"holidays", holidays},
          {"january_1", o.january_1.empty() ? json(nullptr) : json(o.january_1)},
          {"daylight_saving", o.daylight_saving},
          {"hourly", o.hourly},
          {"hourly_source", o.hourly_source}};
}

/// An accuracy block of a grid, the sky's (daylight_factor.accuracy) or the sun bins'
/// (sun_accuracy): the fields both kinds have, which the reader's accuracy_reached reads back;
/// the caller adds the fields of its kind (the sun's hourly value).
template <class Accuracy>
json accuracy_json(const Accuracy& a) {
  json j = {{"target_percent", a.target_percent}, {"reached_percent", a.reached_percent}, {"rounds", a.rounds},
            {"photons", a.photons}, {"stop_reason", a.stop_reason}, {"status", a.status}};
  // A grid estimated by final gather: its gather rays and rounds.
  if (a.gather_rays > 0) j["gather"] = {{"rays", a.gather_rays}, {"rounds", a.gather_rounds}, {"stop_reason", a.gather_stop_reason}};
  // A plane's sensors next to a cut, out of the measure: what they reached.
  if (a.near_cut_sensors > 0)
    j["near_cut"] = {{"sensors", a.near_cut_sensors},
                     {"gather_rays", a.near_cut_gather_rays},
                     {"rounds", a.near_cut_gather_rounds},
                     {"stop_reason", a.near_cut_stop_reason},
                     {"largest_relative_stderr_percent", a.near_cut_largest_percent}};
  return j;
}

json dropped_sensors_json(const GridResult& g) {
  json j = {{"outside_rooms", g.dropped_outside_rooms}, {"inside_solid", g.dropped_inside_solid}};
  if (g.dropped_on_cut_surface > 0) j["on_cut_surface"] = g.dropped_on_cut_surface;
  if (g.dropped_enclosed > 0) j["enclosed"] = g.dropped_enclosed;
  return j;
}

json grid_json(const GridResult& g) {
  json sensors = json::array();
  for (std::size_t i = 0; i < g.positions_m.size(); ++i) {
    json s = {{"position_m", vec(g.positions_m[i])}, {"normal", vec(g.normals[i])}};
    if (i < g.area_m2.size()) s["area_m2"] = g.area_m2[i];
    if (i < g.lattice.column_of.size()) {
      s["column"] = g.lattice.column_of[i];
      s["row"] = g.lattice.row_of[i];
    }
    sensors.push_back(s);
  }
  json lattice = {{"regular", g.lattice.regular}, {"columns", g.lattice.columns}, {"rows", g.lattice.rows}};
  if (g.lattice.regular) {
    lattice["spacing_m"] = g.lattice.spacing_m;
    lattice["origin_m"] = vec(g.lattice.origin_m);
    lattice["column_step_m"] = vec(g.lattice.column_step_m);
    lattice["row_step_m"] = vec(g.lattice.row_step_m);
  }
  json quantities = json::array();
  for (const SensorQuantity& q : g.quantities)
    quantities.push_back({{"stem", q.stem}, {"file", q.file}, {"column", q.column}, {"kind", q.kind},
                          {"quantity", q.quantity}, {"unit", q.unit}, {"scale", scale_name(q.scale)},
                          {"scale_label", q.scale_label}});
  json j = {{"name", g.name},
            {"folder", g.folder},
            {"orientation", orientation_name(g.orientation)},
            {"plan", g.plan},
            {"lattice", lattice},
            {"sensors", sensors},
            {"outline", polygon(g.outline)},
            {"openings_drawn", g.openings_drawn},
            {"dropped_sensors", dropped_sensors_json(g)},
            {"quantities", quantities},
            {"illuminance_table", g.has_illuminance_table},
            {"daylight_factor", nullptr},
            {"annual", nullptr}};
  if (const auto& d = g.daylight_factor) {
    json areas = json::array();
    for (const auto& [t, a] : d->area_at_or_above_percent) areas.push_back({{"threshold_percent", t}, {"area_percent", a}});
    j["daylight_factor"] = {{"mean_percent", d->mean_percent},
                            {"median_percent", d->median_percent},
                            {"min_percent", d->min_percent},
                            {"max_percent", d->max_percent},
                            {"uniformity", d->uniformity},
                            {"area_at_or_above", areas},
                            {"rms_relative_stderr_percent", d->rms_relative_stderr_percent},
                            {"max_relative_stderr_percent", d->max_relative_stderr_percent},
                            {"sensors_with_daylight", d->sensors_with_daylight},
                            {"accuracy", nullptr}};
    if (const auto& acc = d->accuracy) {
      j["daylight_factor"]["accuracy"] = accuracy_json(*acc);
      j["daylight_factor"]["accuracy"]["direct_samples_per_bin"] = acc->direct_samples_per_bin;
    }
  }
  if (const auto& a = g.annual) {
    json levels = json::array();
    for (const En17037Level& l : a->en17037)
      levels.push_back({{"level", l.level}, {"target_lux", l.target_lux}, {"minimum_target_lux", l.minimum_target_lux},
                        {"target_area_percent", l.target_area_percent},
                        {"minimum_target_area_percent", l.minimum_target_area_percent}, {"passes", l.passes}});
    j["annual"] = {
        {"sensors", a->sensors},
        {"time_steps", a->time_steps},
        {"occupied_hours", a->occupied_hours},
        {"settings",
         {{"da_threshold_lux", a->da_threshold_lux},
          {"udi_lower_lux", a->udi_lower_lux},
          {"udi_upper_original_lux", a->udi_upper_original_lux},
          {"udi_upper_revised_lux", a->udi_upper_revised_lux},
          {"sda_time_fraction", a->sda_time_fraction},
          {"ase_threshold_lux", a->ase_threshold_lux},
          {"ase_hours", a->ase_hours}}},
        {"occupancy", occupancy_json(a->occupancy)},
        {"mean",
         {{"da_percent", a->da_percent},
          {"cda_percent", a->cda_percent},
          {"da_max_percent", a->da_max_percent},
          {"udi_below_percent", a->udi_below_percent},
          {"udi_achieved_percent", a->udi_achieved_percent},
          {"udi_above_original_percent", a->udi_above_original_percent},
          {"udi_supplementary_percent", a->udi_supplementary_percent},
          {"udi_autonomous_percent", a->udi_autonomous_percent},
          {"udi_above_revised_percent", a->udi_above_revised_percent},
          {"mean_occupied_lux", a->mean_occupied_lux}}},
        {"sda_percent", a->sda_percent},
        {"sda_sensors", a->sda_sensors},
        {"ase_percent", optional_number(a->ase_percent)},
        {"en17037",
         {{"daylight_hours", a->en17037_daylight_hours},
          {"daylight_hours_source", a->en17037_daylight_hours_source},
          {"openings", a->en17037_openings},
          {"target_area_required_percent", a->en17037_target_area_required_percent},
          {"levels", levels}}},
        {"sky", a->sky},
        {"da_verdicts_within_2_sigma",
         a->da_verdicts_within_2_sigma ? json(*a->da_verdicts_within_2_sigma) : json(nullptr)}};
    if (a->da_verdicts_within_2_sigma_area_percent)
      j["annual"]["da_verdicts_within_2_sigma_area_percent"] = *a->da_verdicts_within_2_sigma_area_percent;
  }
  j["sun_accuracy"] = nullptr;
  if (const auto& sa = g.sun_accuracy) {
    j["sun_accuracy"] = accuracy_json(*sa);
    j["sun_accuracy"]["hourly_percent"] = sa->hourly_percent;
  }
  json points = json::array();
  for (const PointInTimeSummary& p : g.points_in_time) {
    points.push_back({{"name", p.name}, {"sky", p.sky}, {"mean_lux", p.mean_lux}, {"median_lux", p.median_lux},
                      {"min_lux", p.min_lux}, {"max_lux", p.max_lux}, {"uniformity", p.uniformity},
                      {"rms_relative_stderr_percent", optional_number(p.rms_relative_stderr_percent)},
                      {"max_relative_stderr_percent", optional_number(p.max_relative_stderr_percent)}});
    // Against the accuracy target: only runs with one have it.
    if (const auto& a = p.accuracy)
      points.back()["accuracy"] = {{"target_percent", a->target_percent}, {"reached_percent", a->reached_percent},
                                   {"status", a->status}, {"stop_reason", a->stop_reason},
                                   {"limiting_part", a->limiting_part.empty() ? json(nullptr) : json(a->limiting_part)}};
  }
  j["points_in_time"] = points;
  j["spacing_m"] = g.spacing_m;
  json verdicts = json::array();
  for (const Verdict& v : g.verdicts)
    verdicts.push_back({{"standard", v.standard}, {"criterion", v.criterion}, {"requirement", v.requirement},
                        {"value", optional_number(v.value)}, {"unit", v.unit}, {"outcome", v.outcome},
                        {"reason", v.reason}});
  j["verdicts"] = verdicts;
  return j;
}

json materials_json(const std::vector<MaterialSummary>& materials) {
  json a = json::array();
  for (const MaterialSummary& m : materials)
    a.push_back({{"name", m.name}, {"type", m.type}, {"reflectance", optional_number(m.reflectance)},
                 {"transmittance", optional_number(m.transmittance)}, {"specularity", m.specularity},
                 {"area_m2", m.area_m2}});
  return a;
}

json rooms_json(const std::vector<RoomSummary>& rooms) {
  json a = json::array();
  for (const RoomSummary& r : rooms) {
    json windows = json::array();
    for (const WindowSummary& w : r.windows)
      windows.push_back({{"name", w.name}, {"wall", w.wall}, {"width_m", w.width_m}, {"height_m", w.height_m},
                         {"sill_m", w.sill_m}, {"area_m2", w.area_m2}, {"material", w.material},
                         {"frame_factor", w.frame_factor}, {"maintenance_factor", w.maintenance_factor}});
    a.push_back({{"name", r.name}, {"width_m", r.width_m}, {"depth_m", r.depth_m}, {"height_m", r.height_m},
                 {"floor_area_m2", r.floor_area_m2}, {"window_area_m2", r.window_area_m2},
                 {"glazed_wall_area_m2", r.glazed_wall_area_m2}, {"roof_light_area_m2", r.roof_light_area_m2},
                 {"windows", windows}});
  }
  return a;
}

// ---- reading: every field required and typed, errors name the key -----------------------

struct Reader {
  std::string path;

  [[noreturn]] void fail(const std::string& key, const std::string& what) const {
    throw InputError(SourceLocation{path, 0, 0}, "results.json: '" + key + "' " + what);
  }
  const json& at(const json& j, const std::string& parent, const char* key) const {
    if (!j.is_object()) fail(parent, "is not an object");
    auto it = j.find(key);
    if (it == j.end()) fail(parent.empty() ? key : parent + "." + key, "is missing");
    return *it;
  }
  std::string name(const std::string& parent, const char* key) const { return parent.empty() ? key : parent + "." + key; }
  double number(const json& j, const std::string& parent, const char* key) const {
    const json& v = at(j, parent, key);
    if (!v.is_number()) fail(name(parent, key), "is not a number");
    return v.get<double>();
  }
  std::optional<double> optional_number(const json& j, const std::string& parent, const char* key) const {
    const json& v = at(j, parent, key);
    if (v.is_null()) return std::nullopt;
    if (!v.is_number()) fail(name(parent, key), "is not a number or null");
    return v.get<double>();
  }
  std::size_t count(const json& j, const std::string& parent, const char* key) const {
    const json& v = at(j, parent, key);
    if (!v.is_number_unsigned() && !(v.is_number_integer() && v.get<long long>() >= 0))
      fail(name(parent, key), "is not a count");
    return v.get<std::size_t>();
  }
  int integer(const json& j, const std::string& parent, const char* key) const {
    const json& v = at(j, parent, key);
    if (!v.is_number_integer()) fail(name(parent, key), "is not an integer");
    return v.get<int>();
  }
  bool boolean(const json& j, const std::string& parent, const char* key) const {
    const json& v = at(j, parent, key);
    if (!v.is_boolean()) fail(name(parent, key), "is not true or false");
    return v.get<bool>();
  }
  std::string text(const json& j, const std::string& parent, const char* key) const {
    const json& v = at(j, parent, key);
    if (!v.is_string()) fail(name(parent, key), "is not a string");
    return v.get<std::string>();
  }
  /// An accuracy block of a grid, the sky's (daylight_factor.accuracy) or the sun bins'
  /// (sun_accuracy): `key` of `j`, null when the run had no accuracy target. The fields both
  /// kinds have are read here (target, reached, rounds, photons, the rounds' stop, and the
  /// grid's status in accuracy_policy.h's words); `own(block, its key, result)` then reads the
  /// fields of its kind.
  template <class Accuracy, class Own>
  std::optional<Accuracy> accuracy_reached(const json& j, const std::string& parent, const char* key,
                                           const Own& own) const {
    const json& block = at(j, parent, key);
    if (block.is_null()) return std::nullopt;
    const std::string k = name(parent, key);
    Accuracy r;
    r.target_percent = number(block, k, "target_percent");
    r.reached_percent = number(block, k, "reached_percent");
    r.rounds = count(block, k, "rounds");
    r.photons = count(block, k, "photons");
    r.stop_reason = text(block, k, "stop_reason");
    r.status = text(block, k, "status");
    if (r.status != "met" && r.status != "above target" && r.status != "not reachable by photons")
      fail(name(k, "status"), "is not met, above target or not reachable by photons");
    own(block, k, r);
    return r;
  }
  /// An accuracy block's "gather" (the sky's or the sun bins'), present for a grid estimated by
  /// final gather only.
  template <class Accuracy>
  void gather_reached(const json& acc, const std::string& ck, Accuracy& r) const {
    if (!acc.contains("gather")) return;
    const std::string gk = ck + ".gather";
    const json& ga = at(acc, ck, "gather");
    r.gather_rays = static_cast<int>(count(ga, gk, "rays"));
    if (r.gather_rays < 1) fail(name(gk, "rays"), "is not at least 1");
    r.gather_rounds = count(ga, gk, "rounds");
    r.gather_stop_reason = text(ga, gk, "stop_reason");
  }
  /// An accuracy block's "near_cut", present for a plane with sensors next to a cut only.
  template <class Accuracy>
  void near_cut_reached(const json& acc, const std::string& ck, Accuracy& r) const {
    if (!acc.contains("near_cut")) return;
    const std::string nk = ck + ".near_cut";
    const json& nc = at(acc, ck, "near_cut");
    r.near_cut_sensors = count(nc, nk, "sensors");
    r.near_cut_gather_rays = integer(nc, nk, "gather_rays");
    r.near_cut_largest_percent = number(nc, nk, "largest_relative_stderr_percent");
    r.near_cut_gather_rounds = count(nc, nk, "rounds");
    r.near_cut_stop_reason = text(nc, nk, "stop_reason");
    if (r.near_cut_sensors < 1) fail(name(nk, "sensors"), "is not at least 1");
  }
  const json& array(const json& j, const std::string& parent, const char* key) const {
    const json& v = at(j, parent, key);
    if (!v.is_array()) fail(name(parent, key), "is not an array");
    return v;
  }
  Vec3 vector(const json& v, const std::string& key) const {
    if (!v.is_array() || v.size() != 3 || !v[0].is_number() || !v[1].is_number() || !v[2].is_number())
      fail(key, "is not a vector [x, y, z]");
    return {v[0].get<double>(), v[1].get<double>(), v[2].get<double>()};
  }
  Polygon3 polygon(const json& v, const std::string& key) const {
    if (!v.is_array()) fail(key, "is not a list of points");
    Polygon3 p;
    for (const json& e : v) p.push_back(vector(e, key));
    return p;
  }
  std::vector<Polygon3> polygons(const json& v, const std::string& key) const {
    if (!v.is_array()) fail(key, "is not a list of polygons");
    std::vector<Polygon3> ps;
    for (const json& e : v) ps.push_back(polygon(e, key));
    return ps;
  }
  std::vector<std::string> texts(const json& j, const std::string& parent, const char* key) const {
    std::vector<std::string> out;
    for (const json& e : array(j, parent, key)) {
      if (!e.is_string()) fail(name(parent, key), "holds a value that is not a string");
      out.push_back(e.get<std::string>());
    }
    return out;
  }

  OccupancySummary::Windows windows(const json& v, const std::string& key) const {
    if (!v.is_array()) fail(key, "is not a list of [start_h, end_h] windows");
    OccupancySummary::Windows w;
    for (const json& e : v) {
      if (!e.is_array() || e.size() != 2 || !e[0].is_number() || !e[1].is_number())
        fail(key, "holds a window that is not [start_h, end_h]");
      const double start = e[0].get<double>(), end = e[1].get<double>();
      if (!(start >= 0 && start < end && end <= 24)) fail(key, "holds a window outside 0 <= start < end <= 24");
      w.emplace_back(start, end);
    }
    return w;
  }
  std::vector<SunlightInterval> sunlight_intervals(const json& j, const std::string& parent) const {
    std::vector<SunlightInterval> out;
    for (const json& e : array(j, parent, "intervals_h")) {
      if (!e.is_array() || e.size() != 2 || !e[0].is_number() || !e[1].is_number())
        fail(name(parent, "intervals_h"), "holds an interval that is not [start_h, end_h]");
      const double start = e[0].get<double>(), end = e[1].get<double>();
      if (!(start >= 0 && start <= end && end <= 24)) fail(name(parent, "intervals_h"), "holds an interval outside 0..24 h");
      out.push_back({start, end});
    }
    return out;
  }
  std::vector<RoomSunlight> sunlight(const json& j, const std::string& parent) const {
    std::vector<RoomSunlight> rooms;
    const std::string k = name(parent, "sunlight_exposure");
    for (const json& rj : array(j, parent, "sunlight_exposure")) {
      RoomSunlight r;
      r.room = text(rj, k, "room");
      for (const json& wj : array(rj, k, "windows")) {
        WindowSunlight w;
        const std::string wk = k + ".windows";
        w.name = text(wj, wk, "name");
        w.reference_point_m = vector(at(wj, wk, "reference_point_m"), name(wk, "reference_point_m"));
        w.intervals = sunlight_intervals(wj, wk);
        w.hours = number(wj, wk, "hours");
        w.not_assessed = text(wj, wk, "not_assessed");
        r.windows.push_back(std::move(w));
      }
      r.intervals = sunlight_intervals(rj, k);
      r.hours = number(rj, k, "hours");
      r.level = text(rj, k, "level");
      if (r.level != "high" && r.level != "medium" && r.level != "minimum" && r.level != "below minimum" &&
          r.level != "not assessed")
        fail(name(k, "level"), "is not high, medium, minimum, below minimum or not assessed");
      rooms.push_back(std::move(r));
    }
    return rooms;
  }
  std::pair<int, int> month_day(const json& v, const std::string& key) const {
    if (!v.is_array() || v.size() != 2 || !v[0].is_number_integer() || !v[1].is_number_integer())
      fail(key, "is not [month, day]");
    const int month = v[0].get<int>(), day = v[1].get<int>();
    if (month < 1 || month > 12 || day < 1 || day > 31) fail(key, "is not a date [month, day]");
    return {month, day};
  }
  OccupancySummary occupancy(const json& oc, const std::string& ok) const {
    OccupancySummary o;
    o.kind = text(oc, ok, "kind");
    if (o.kind != "daily" && o.kind != "weekly" && o.kind != "hourly") fail(ok + ".kind", "is not daily, weekly or hourly");
    o.start_h = number(oc, ok, "start_h");
    o.end_h = number(oc, ok, "end_h");
    o.description = text(oc, ok, "description");
    const json& week = array(oc, ok, "week");
    if (!week.empty() && week.size() != 7) fail(ok + ".week", "has neither 0 nor 7 days");
    for (std::size_t d = 0; d < week.size(); ++d) o.week[d] = windows(week[d], ok + ".week");
    o.holiday_hours = windows(at(oc, ok, "holiday_hours"), ok + ".holiday_hours");
    for (const json& h : array(oc, ok, "holidays")) {
      const auto [from_month, from_day] = month_day(at(h, ok + ".holidays", "from"), ok + ".holidays.from");
      const auto [to_month, to_day] = month_day(at(h, ok + ".holidays", "to"), ok + ".holidays.to");
      o.holidays.push_back({from_month, from_day, to_month, to_day});
    }
    const json& j1 = at(oc, ok, "january_1");
    if (!j1.is_null()) {
      if (!j1.is_string() || !metrics::parse_weekday(j1.get<std::string>())) fail(ok + ".january_1", "is not a weekday or null");
      o.january_1 = j1.get<std::string>();
    }
    o.daylight_saving = text(oc, ok, "daylight_saving");
    if (!metrics::parse_daylight_saving(o.daylight_saving)) fail(ok + ".daylight_saving", "is not none, eu or us");
    o.hourly = text(oc, ok, "hourly");
    if (o.hourly.find_first_not_of("01") != std::string::npos) fail(ok + ".hourly", "holds a character other than 0 and 1");
    if (o.kind == "hourly" && o.hourly.empty()) fail(ok + ".hourly", "is empty for an hourly schedule");
    o.hourly_source = text(oc, ok, "hourly_source");
    return o;
  }

  GridResult grid(const json& j, const std::string& where) const {
    GridResult g;
    g.name = text(j, where, "name");
    const std::string at_grid = where + "[" + g.name + "]";
    g.folder = text(j, at_grid, "folder");
    const std::string o = text(j, at_grid, "orientation");
    if (o == "horizontal") g.orientation = GridOrientation::Horizontal;
    else if (o == "vertical") g.orientation = GridOrientation::Vertical;
    else if (o == "tilted") g.orientation = GridOrientation::Tilted;
    else fail(at_grid + ".orientation", "is not horizontal, vertical or tilted");
    g.plan = boolean(j, at_grid, "plan");
    const std::string lk = at_grid + ".lattice";
    const json& l = at(j, at_grid, "lattice");
    g.lattice.regular = boolean(l, lk, "regular");
    g.lattice.columns = integer(l, lk, "columns");
    g.lattice.rows = integer(l, lk, "rows");
    if (g.lattice.regular) {
      g.lattice.spacing_m = number(l, lk, "spacing_m");
      g.lattice.origin_m = vector(at(l, lk, "origin_m"), lk + ".origin_m");
      g.lattice.column_step_m = vector(at(l, lk, "column_step_m"), lk + ".column_step_m");
      g.lattice.row_step_m = vector(at(l, lk, "row_step_m"), lk + ".row_step_m");
    }
    const std::string sk = at_grid + ".sensors";
    for (const json& s : array(j, at_grid, "sensors")) {
      g.positions_m.push_back(vector(at(s, sk, "position_m"), sk + ".position_m"));
      g.normals.push_back(vector(at(s, sk, "normal"), sk + ".normal"));
      if (s.is_object() && s.contains("area_m2")) g.area_m2.push_back(number(s, sk, "area_m2"));
      const int c = integer(s, sk, "column"), r = integer(s, sk, "row");
      if (c < 0 || r < 0 || c >= g.lattice.columns || r >= g.lattice.rows) fail(sk, "has a cell outside the lattice");
      g.lattice.column_of.push_back(c);
      g.lattice.row_of.push_back(r);
    }
    if (!g.area_m2.empty() && g.area_m2.size() != g.positions_m.size()) fail(sk, "gives area_m2 for some sensors, not all");
    g.outline = polygon(at(j, at_grid, "outline"), at_grid + ".outline");
    for (const json& e : array(j, at_grid, "openings_drawn")) {
      if (!e.is_number_integer() || e.get<int>() < 0) fail(at_grid + ".openings_drawn", "holds a value that is not an index");
      g.openings_drawn.push_back(e.get<int>());
    }
    const json& dropped = at(j, at_grid, "dropped_sensors");
    g.dropped_outside_rooms = count(dropped, at_grid + ".dropped_sensors", "outside_rooms");
    g.dropped_inside_solid = count(dropped, at_grid + ".dropped_sensors", "inside_solid");
    if (dropped.is_object() && dropped.contains("on_cut_surface"))
      g.dropped_on_cut_surface = count(dropped, at_grid + ".dropped_sensors", "on_cut_surface");
    if (dropped.is_object() && dropped.contains("enclosed"))
      g.dropped_enclosed = count(dropped, at_grid + ".dropped_sensors", "enclosed");
    const std::string qk = at_grid + ".quantities";
    for (const json& q : array(j, at_grid, "quantities")) {
      SensorQuantity s;
      s.stem = text(q, qk, "stem");
      s.file = text(q, qk, "file");
      s.column = text(q, qk, "column");
      s.kind = text(q, qk, "kind");
      s.quantity = text(q, qk, "quantity");
      s.unit = text(q, qk, "unit");
      const std::string scale = text(q, qk, "scale");
      if (scale == "daylight_factor") s.scale = QuantityScale::DaylightFactor;
      else if (scale == "percent") s.scale = QuantityScale::Percent;
      else if (scale == "illuminance") s.scale = QuantityScale::Illuminance;
      else fail(qk + ".scale", "is not daylight_factor, percent or illuminance");
      s.scale_label = text(q, qk, "scale_label");
      // Names that become file names must stay inside the grid's folder.
      for (const std::string* n : {&s.stem, &s.file})
        if (!project::path_name_problem(*n).empty()) fail(qk, "names '" + project::printable_name(*n) + "', not a plain file name");
      g.quantities.push_back(s);
    }
    g.has_illuminance_table = boolean(j, at_grid, "illuminance_table");
    const json& df = at(j, at_grid, "daylight_factor");
    if (!df.is_null()) {
      const std::string dk = at_grid + ".daylight_factor";
      DaylightFactorSummary d;
      d.mean_percent = number(df, dk, "mean_percent");
      d.median_percent = number(df, dk, "median_percent");
      d.min_percent = number(df, dk, "min_percent");
      d.max_percent = number(df, dk, "max_percent");
      d.uniformity = number(df, dk, "uniformity");
      for (const json& a : array(df, dk, "area_at_or_above"))
        d.area_at_or_above_percent.emplace_back(number(a, dk + ".area_at_or_above", "threshold_percent"),
                                                number(a, dk + ".area_at_or_above", "area_percent"));
      d.rms_relative_stderr_percent = number(df, dk, "rms_relative_stderr_percent");
      d.max_relative_stderr_percent = number(df, dk, "max_relative_stderr_percent");
      d.sensors_with_daylight = count(df, dk, "sensors_with_daylight");
      d.accuracy = accuracy_reached<DaylightFactorSummary::AccuracyReached>(
          df, dk, "accuracy", [this](const json& acc, const std::string& ck, DaylightFactorSummary::AccuracyReached& r) {
            r.direct_samples_per_bin = integer(acc, ck, "direct_samples_per_bin");
            if (r.direct_samples_per_bin < 1) fail(name(ck, "direct_samples_per_bin"), "is not at least 1");
            gather_reached(acc, ck, r);
            near_cut_reached(acc, ck, r);
          });
      g.daylight_factor = d;
    }
    g.sun_accuracy = accuracy_reached<SunAccuracyReached>(
        j, at_grid, "sun_accuracy", [this](const json& sa, const std::string& sak, SunAccuracyReached& r) {
          r.hourly_percent = number(sa, sak, "hourly_percent");
          gather_reached(sa, sak, r);
          near_cut_reached(sa, sak, r);
        });
    const json& an = at(j, at_grid, "annual");
    if (!an.is_null()) {
      const std::string ak = at_grid + ".annual";
      AnnualSummary a;
      a.sensors = count(an, ak, "sensors");
      a.time_steps = count(an, ak, "time_steps");
      a.occupied_hours = count(an, ak, "occupied_hours");
      const json& st = at(an, ak, "settings");
      const std::string stk = ak + ".settings";
      a.da_threshold_lux = number(st, stk, "da_threshold_lux");
      a.udi_lower_lux = number(st, stk, "udi_lower_lux");
      a.udi_upper_original_lux = number(st, stk, "udi_upper_original_lux");
      a.udi_upper_revised_lux = number(st, stk, "udi_upper_revised_lux");
      a.sda_time_fraction = number(st, stk, "sda_time_fraction");
      a.ase_threshold_lux = number(st, stk, "ase_threshold_lux");
      a.ase_hours = number(st, stk, "ase_hours");
      a.occupancy = occupancy(at(an, ak, "occupancy"), ak + ".occupancy");
      const json& m = at(an, ak, "mean");
      const std::string mk = ak + ".mean";
      a.da_percent = number(m, mk, "da_percent");
      a.cda_percent = number(m, mk, "cda_percent");
      a.da_max_percent = number(m, mk, "da_max_percent");
      a.udi_below_percent = number(m, mk, "udi_below_percent");
      a.udi_achieved_percent = number(m, mk, "udi_achieved_percent");
      a.udi_above_original_percent = number(m, mk, "udi_above_original_percent");
      a.udi_supplementary_percent = number(m, mk, "udi_supplementary_percent");
      a.udi_autonomous_percent = number(m, mk, "udi_autonomous_percent");
      a.udi_above_revised_percent = number(m, mk, "udi_above_revised_percent");
      a.mean_occupied_lux = number(m, mk, "mean_occupied_lux");
      a.sda_percent = number(an, ak, "sda_percent");
      a.sda_sensors = count(an, ak, "sda_sensors");
      a.ase_percent = optional_number(an, ak, "ase_percent");
      const json& en = at(an, ak, "en17037");
      const std::string ek = ak + ".en17037";
      a.en17037_daylight_hours = count(en, ek, "daylight_hours");
      a.en17037_daylight_hours_source = text(en, ek, "daylight_hours_source");
      // Results written before the rule for horizontal openings have neither key: they were
      // assessed with the rule for vertical and inclined openings.
      if (en.contains("openings")) a.en17037_openings = text(en, ek, "openings");
      if (const auto v = optional_number(en, ek, "target_area_required_percent"))
        a.en17037_target_area_required_percent = *v;
      for (const json& lv : array(en, ek, "levels")) {
        const std::string lk2 = ek + ".levels";
        a.en17037.push_back({text(lv, lk2, "level"), number(lv, lk2, "target_lux"), number(lv, lk2, "minimum_target_lux"),
                             number(lv, lk2, "target_area_percent"), number(lv, lk2, "minimum_target_area_percent"),
                             boolean(lv, lk2, "passes")});
      }
      a.sky = text(an, ak, "sky");
      if (const auto v = optional_number(an, ak, "da_verdicts_within_2_sigma"))
        a.da_verdicts_within_2_sigma = static_cast<std::size_t>(*v);
      if (an.contains("da_verdicts_within_2_sigma_area_percent"))
        a.da_verdicts_within_2_sigma_area_percent = number(an, ak, "da_verdicts_within_2_sigma_area_percent");
      g.annual = a;
    }
    for (const json& p : array(j, at_grid, "points_in_time")) {
      const std::string pk = at_grid + ".points_in_time";
      g.points_in_time.push_back({text(p, pk, "name"), text(p, pk, "sky"), number(p, pk, "mean_lux"),
                                  number(p, pk, "median_lux"), number(p, pk, "min_lux"), number(p, pk, "max_lux"),
                                  number(p, pk, "uniformity"), optional_number(p, pk, "rms_relative_stderr_percent"),
                                  optional_number(p, pk, "max_relative_stderr_percent"), std::nullopt});
      if (p.contains("accuracy")) {
        const std::string ak = pk + ".accuracy";
        const json& a = at(p, pk, "accuracy");
        PointInTimeSummary::AccuracyReached r;
        r.target_percent = number(a, ak, "target_percent");
        r.reached_percent = number(a, ak, "reached_percent");
        r.status = text(a, ak, "status");
        if (r.status != "met" && r.status != "above target") fail(name(ak, "status"), "is not met or above target");
        r.stop_reason = text(a, ak, "stop_reason");
        if (!at(a, ak, "limiting_part").is_null()) r.limiting_part = text(a, ak, "limiting_part");
        g.points_in_time.back().accuracy = r;
      }
    }
    g.spacing_m = number(j, at_grid, "spacing_m");
    const std::string vk = at_grid + ".verdicts";
    for (const json& v : array(j, at_grid, "verdicts")) {
      Verdict d;
      d.standard = text(v, vk, "standard");
      d.criterion = text(v, vk, "criterion");
      d.requirement = text(v, vk, "requirement");
      d.value = optional_number(v, vk, "value");
      d.unit = text(v, vk, "unit");
      d.outcome = text(v, vk, "outcome");
      if (d.outcome != "pass" && d.outcome != "fail" && d.outcome != "not assessed")
        fail(vk + ".outcome", "is not pass, fail or not assessed");
      if ((d.outcome == "not assessed") == d.value.has_value())
        fail(vk + ".value", d.value ? "is given for a criterion not assessed" : "is missing for an assessed criterion");
      d.reason = text(v, vk, "reason");
      g.verdicts.push_back(d);
    }
    return g;
  }

  std::vector<MaterialSummary> materials(const json& j, const std::string& parent) const {
    std::vector<MaterialSummary> out;
    const std::string k = parent + ".materials";
    for (const json& m : array(j, parent, "materials")) {
      MaterialSummary s;
      s.name = text(m, k, "name");
      s.type = text(m, k, "type");
      s.reflectance = optional_number(m, k, "reflectance");
      s.transmittance = optional_number(m, k, "transmittance");
      s.specularity = number(m, k, "specularity");
      s.area_m2 = number(m, k, "area_m2");
      for (const std::optional<double>* f : {&s.reflectance, &s.transmittance})
        if (*f && !(**f >= 0 && **f <= 1)) fail(k + "[" + s.name + "]", "has a reflectance or transmittance outside [0, 1]");
      out.push_back(s);
    }
    return out;
  }

  std::vector<RoomSummary> rooms(const json& j, const std::string& parent) const {
    std::vector<RoomSummary> out;
    const std::string k = parent + ".rooms";
    for (const json& r : array(j, parent, "rooms")) {
      RoomSummary s;
      s.name = text(r, k, "name");
      const std::string rk = k + "[" + s.name + "]";
      s.width_m = number(r, rk, "width_m");
      s.depth_m = number(r, rk, "depth_m");
      s.height_m = number(r, rk, "height_m");
      s.floor_area_m2 = number(r, rk, "floor_area_m2");
      s.window_area_m2 = number(r, rk, "window_area_m2");
      s.glazed_wall_area_m2 = number(r, rk, "glazed_wall_area_m2");
      s.roof_light_area_m2 = number(r, rk, "roof_light_area_m2");
      const std::string wk = rk + ".windows";
      for (const json& w : array(r, rk, "windows"))
        s.windows.push_back({text(w, wk, "name"), text(w, wk, "wall"), number(w, wk, "width_m"), number(w, wk, "height_m"),
                             number(w, wk, "sill_m"), number(w, wk, "area_m2"), text(w, wk, "material"),
                             number(w, wk, "frame_factor"), number(w, wk, "maintenance_factor")});
      out.push_back(s);
    }
    return out;
  }
};

}  // namespace

std::string orientation_name(GridOrientation o) {
  switch (o) {
    case GridOrientation::Horizontal: return "horizontal";
    case GridOrientation::Vertical: return "vertical";
    case GridOrientation::Tilted: return "tilted";
  }
  return "tilted";
}

bool SensorLattice::operator==(const SensorLattice& o) const {
  return regular == o.regular && columns == o.columns && rows == o.rows && spacing_m == o.spacing_m &&
         origin_m == o.origin_m && column_step_m == o.column_step_m && row_step_m == o.row_step_m &&
         column_of == o.column_of && row_of == o.row_of;
}
bool SensorQuantity::operator==(const SensorQuantity& o) const {
  return stem == o.stem && file == o.file && column == o.column && kind == o.kind && quantity == o.quantity &&
         unit == o.unit && scale == o.scale && scale_label == o.scale_label;
}
bool DaylightFactorSummary::operator==(const DaylightFactorSummary& o) const {
  return mean_percent == o.mean_percent && median_percent == o.median_percent && min_percent == o.min_percent &&
         max_percent == o.max_percent && uniformity == o.uniformity &&
         area_at_or_above_percent == o.area_at_or_above_percent &&
         rms_relative_stderr_percent == o.rms_relative_stderr_percent &&
         max_relative_stderr_percent == o.max_relative_stderr_percent && sensors_with_daylight == o.sensors_with_daylight &&
         accuracy == o.accuracy;
}
bool DaylightFactorSummary::AccuracyReached::operator==(const AccuracyReached& o) const {
  return target_percent == o.target_percent && reached_percent == o.reached_percent && rounds == o.rounds &&
         photons == o.photons && stop_reason == o.stop_reason && status == o.status &&
         gather_rays == o.gather_rays && gather_rounds == o.gather_rounds &&
         gather_stop_reason == o.gather_stop_reason && direct_samples_per_bin == o.direct_samples_per_bin &&
         near_cut_sensors == o.near_cut_sensors && near_cut_gather_rays == o.near_cut_gather_rays &&
         near_cut_largest_percent == o.near_cut_largest_percent && near_cut_gather_rounds == o.near_cut_gather_rounds &&
         near_cut_stop_reason == o.near_cut_stop_reason;
}
bool SunAccuracyReached::operator==(const SunAccuracyReached& o) const {
  return target_percent == o.target_percent && reached_percent == o.reached_percent &&
         hourly_percent == o.hourly_percent && rounds == o.rounds && photons == o.photons &&
         stop_reason == o.stop_reason && status == o.status && gather_rays == o.gather_rays &&
         gather_rounds == o.gather_rounds && gather_stop_reason == o.gather_stop_reason &&
         near_cut_sensors == o.near_cut_sensors && near_cut_gather_rays == o.near_cut_gather_rays &&
         near_cut_largest_percent == o.near_cut_largest_percent && near_cut_gather_rounds == o.near_cut_gather_rounds &&
         near_cut_stop_reason == o.near_cut_stop_reason;
}
bool OccupancySummary::operator==(const OccupancySummary& o) const {
  return kind == o.kind && start_h == o.start_h && end_h == o.end_h && description == o.description &&
         week == o.week && holiday_hours == o.holiday_hours && holidays == o.holidays && january_1 == o.january_1 &&
         daylight_saving == o.daylight_saving && hourly == o.hourly && hourly_source == o.hourly_source;
}
bool En17037Level::operator==(const En17037Level& o) const {
  return level == o.level && target_lux == o.target_lux && minimum_target_lux == o.minimum_target_lux &&
         target_area_percent == o.target_area_percent && minimum_target_area_percent == o.minimum_target_area_percent &&
         passes == o.passes;
}
bool AnnualSummary::operator==(const AnnualSummary& o) const {
  return sensors == o.sensors && time_steps == o.time_steps && occupied_hours == o.occupied_hours &&
         da_threshold_lux == o.da_threshold_lux && udi_lower_lux == o.udi_lower_lux &&
         udi_upper_original_lux == o.udi_upper_original_lux && udi_upper_revised_lux == o.udi_upper_revised_lux &&
         sda_time_fraction == o.sda_time_fraction && ase_threshold_lux == o.ase_threshold_lux &&
         ase_hours == o.ase_hours && occupancy == o.occupancy && da_percent == o.da_percent &&
         cda_percent == o.cda_percent && da_max_percent == o.da_max_percent &&
         udi_below_percent == o.udi_below_percent && udi_achieved_percent == o.udi_achieved_percent &&
         udi_above_original_percent == o.udi_above_original_percent &&
         udi_supplementary_percent == o.udi_supplementary_percent &&
         udi_autonomous_percent == o.udi_autonomous_percent && udi_above_revised_percent == o.udi_above_revised_percent &&
         mean_occupied_lux == o.mean_occupied_lux && sda_percent == o.sda_percent && sda_sensors == o.sda_sensors &&
         ase_percent == o.ase_percent && en17037_daylight_hours == o.en17037_daylight_hours &&
         en17037_daylight_hours_source == o.en17037_daylight_hours_source && en17037_openings == o.en17037_openings &&
         en17037_target_area_required_percent == o.en17037_target_area_required_percent && en17037 == o.en17037 &&
         sky == o.sky &&
         da_verdicts_within_2_sigma == o.da_verdicts_within_2_sigma &&
         da_verdicts_within_2_sigma_area_percent == o.da_verdicts_within_2_sigma_area_percent;
}
std::string AnnualSummary::en17037_level() const {
  if (en17037.empty()) return "";
  std::string level = "none";
  for (const En17037Level& l : en17037)
    if (l.passes) level = l.level;
  return level;
}
bool PointInTimeSummary::operator==(const PointInTimeSummary& o) const {
  return name == o.name && sky == o.sky && mean_lux == o.mean_lux && median_lux == o.median_lux &&
         min_lux == o.min_lux && max_lux == o.max_lux && uniformity == o.uniformity &&
         rms_relative_stderr_percent == o.rms_relative_stderr_percent &&
         max_relative_stderr_percent == o.max_relative_stderr_percent && accuracy == o.accuracy;
}
bool PointInTimeSummary::AccuracyReached::operator==(const AccuracyReached& o) const {
  return target_percent == o.target_percent && reached_percent == o.reached_percent && status == o.status &&
         stop_reason == o.stop_reason && limiting_part == o.limiting_part;
}
bool Verdict::operator==(const Verdict& o) const {
  return standard == o.standard && criterion == o.criterion && requirement == o.requirement && value == o.value &&
         unit == o.unit && outcome == o.outcome && reason == o.reason;
}
bool MaterialSummary::operator==(const MaterialSummary& o) const {
  return name == o.name && type == o.type && reflectance == o.reflectance && transmittance == o.transmittance &&
         specularity == o.specularity && area_m2 == o.area_m2;
}
bool WindowSummary::operator==(const WindowSummary& o) const {
  return name == o.name && wall == o.wall && width_m == o.width_m && height_m == o.height_m && sill_m == o.sill_m &&
         area_m2 == o.area_m2 && material == o.material && frame_factor == o.frame_factor &&
         maintenance_factor == o.maintenance_factor;
}
bool RoomSummary::operator==(const RoomSummary& o) const {
  return name == o.name && width_m == o.width_m && depth_m == o.depth_m && height_m == o.height_m &&
         floor_area_m2 == o.floor_area_m2 && window_area_m2 == o.window_area_m2 &&
         glazed_wall_area_m2 == o.glazed_wall_area_m2 && roof_light_area_m2 == o.roof_light_area_m2 &&
         windows == o.windows;
}
const SensorQuantity* GridResult::find_quantity(const std::string& kind) const {
  for (const SensorQuantity& q : quantities)
    if (q.kind == kind) return &q;
  return nullptr;
}
bool GridResult::operator==(const GridResult& o) const {
  return name == o.name && folder == o.folder && positions_m == o.positions_m && normals == o.normals && area_m2 == o.area_m2 &&
         orientation == o.orientation && plan == o.plan && lattice == o.lattice && outline == o.outline &&
         openings_drawn == o.openings_drawn && dropped_outside_rooms == o.dropped_outside_rooms &&
         dropped_inside_solid == o.dropped_inside_solid && dropped_on_cut_surface == o.dropped_on_cut_surface &&
         dropped_enclosed == o.dropped_enclosed && quantities == o.quantities &&
         daylight_factor == o.daylight_factor && annual == o.annual && sun_accuracy == o.sun_accuracy && points_in_time == o.points_in_time &&
         has_illuminance_table == o.has_illuminance_table && spacing_m == o.spacing_m && verdicts == o.verdicts;
}
bool CaseResult::operator==(const CaseResult& o) const {
  return kind == o.kind && name == o.name && folder == o.folder && changes == o.changes && openings == o.openings &&
         systems == o.systems && materials == o.materials && rooms == o.rooms &&
         opening_area_m2 == o.opening_area_m2 && blinds_in_place == o.blinds_in_place &&
         shading_materials_in_place == o.shading_materials_in_place && grids == o.grids &&
         sunlight_exposure == o.sunlight_exposure;
}
bool WindowSunlight::operator==(const WindowSunlight& o) const {
  return name == o.name && reference_point_m == o.reference_point_m && intervals == o.intervals && hours == o.hours &&
         not_assessed == o.not_assessed;
}
bool RoomSunlight::operator==(const RoomSunlight& o) const {
  return room == o.room && windows == o.windows && intervals == o.intervals && hours == o.hours && level == o.level;
}
bool SunlightExposureSettings::operator==(const SunlightExposureSettings& o) const {
  return month == o.month && day == o.day && year == o.year && min_altitude_deg == o.min_altitude_deg &&
         time_step_min == o.time_step_min;
}
bool ResultsModel::operator==(const ResultsModel& o) const {
  return schema_version == o.schema_version && project_name == o.project_name && project_file == o.project_file &&
         dayphoton_version == o.dayphoton_version && compiler == o.compiler && study == o.study &&
         site_name == o.site_name && latitude_deg == o.latitude_deg && longitude_deg == o.longitude_deg &&
         time_zone_h == o.time_zone_h && elevation_m == o.elevation_m && sun_from_weather == o.sun_from_weather &&
         sun_site == o.sun_site && sun_sentence == o.sun_sentence && station_distance_km == o.station_distance_km &&
         below_horizon_hours == o.below_horizon_hours && below_horizon_their_sun == o.below_horizon_their_sun &&
         weather_file == o.weather_file && basis == o.basis && reinhart_mf == o.reinhart_mf &&
         ground_reflectance == o.ground_reflectance && settings == o.settings && notes == o.notes && cases == o.cases &&
         title == o.title && not_assessed == o.not_assessed && sunlight_exposure == o.sunlight_exposure;
}

std::string results_json(const ResultsModel& m) {
  json settings = json::array();
  for (const Setting& s : m.settings) settings.push_back({{"name", s.name}, {"value", s.value}});
  json cases = json::array();
  for (const CaseResult& c : m.cases) {
    json grids = json::array();
    for (const GridResult& g : c.grids) grids.push_back(grid_json(g));
    cases.push_back({{"kind", c.kind}, {"name", c.name}, {"folder", c.folder}, {"changes", c.changes},
                     {"openings", polygons(c.openings)}, {"systems", polygons(c.systems)},
                     {"materials", materials_json(c.materials)}, {"rooms", rooms_json(c.rooms)},
                     {"opening_area_m2", c.opening_area_m2}, {"grids", grids}});
    if (!c.blinds_in_place.empty()) cases.back()["blinds_in_place"] = c.blinds_in_place;
    if (!c.sunlight_exposure.empty()) cases.back()["sunlight_exposure"] = sunlight_json(c.sunlight_exposure);
    if (!c.shading_materials_in_place.empty()) {
      json materials = json::array();
      for (const ShadingMaterialInPlace& s : c.shading_materials_in_place)
        materials.push_back({{"material", s.material}, {"why", s.why}});
      cases.back()["shading_materials_in_place"] = materials;
    }
  }
  json site = {{"name", m.site_name}, {"latitude_deg", m.latitude_deg}, {"longitude_deg", m.longitude_deg},
               {"time_zone_h", m.time_zone_h}, {"elevation_m", m.elevation_m}, {"sun_from_weather", m.sun_from_weather},
               {"sun_site", nullptr}, {"sun_sentence", m.sun_sentence},
               {"station_distance_km", optional_number(m.station_distance_km)},
               {"below_horizon_hours", m.below_horizon_hours ? json(*m.below_horizon_hours) : json(nullptr)},
               {"below_horizon_their_sun", m.below_horizon_their_sun}};
  if (m.sun_site)
    site["sun_site"] = {{"latitude_deg", (*m.sun_site)[0]}, {"longitude_deg", (*m.sun_site)[1]},
                        {"time_zone_h", (*m.sun_site)[2]}, {"elevation_m", (*m.sun_site)[3]}};
  const json j = {{"schema_version", m.schema_version},
                  {"project", {{"name", m.project_name}, {"title", m.title}, {"file", m.project_file}}},
                  {"versions", {{"dayphoton", m.dayphoton_version}, {"compiler", m.compiler}}},
                  {"study", m.study},
                  {"site", site},
                  {"weather_file", m.weather_file},
                  {"sky", {{"basis", m.basis}, {"reinhart_mf", m.reinhart_mf}, {"ground_reflectance", m.ground_reflectance}}},
                  {"settings", settings},
                  {"notes", m.notes},
                  {"not_assessed", m.not_assessed},
                  {"cases", cases}};
  json out = j;
  if (m.sunlight_exposure) {
    const SunlightExposureSettings& e = *m.sunlight_exposure;
    out["sunlight_exposure"] = {{"date", json::array({e.month, e.day})}, {"year", e.year},
                                {"min_altitude_deg", e.min_altitude_deg}, {"time_step_min", e.time_step_min}};
  }
  return json_text(out) + "\n";
}

ResultsModel parse_results_json(const std::string& text, const std::string& path) {
  const Reader r{path};
  const json j = json::parse(text, nullptr, false);
  if (j.is_discarded() || !j.is_object()) throw InputError(SourceLocation{path, 0, 0}, "results.json is not a JSON object");
  ResultsModel m;
  m.schema_version = r.integer(j, "", "schema_version");
  if (m.schema_version != ResultsSchemaVersion)
    throw InputError(SourceLocation{path, 0, 0},
                     "results.json has schema version " + std::to_string(m.schema_version) + ", this dayphoton reads " +
                         std::to_string(ResultsSchemaVersion) + ": run the study again with this dayphoton");
  const json& project = r.at(j, "", "project");
  m.project_name = r.text(project, "project", "name");
  m.title = r.text(project, "project", "title");
  m.project_file = r.text(project, "project", "file");
  const json& versions = r.at(j, "", "versions");
  m.dayphoton_version = r.text(versions, "versions", "dayphoton");
  m.compiler = r.text(versions, "versions", "compiler");
  m.study = r.text(j, "", "study");
  const json& site = r.at(j, "", "site");
  m.site_name = r.text(site, "site", "name");
  m.latitude_deg = r.number(site, "site", "latitude_deg");
  m.longitude_deg = r.number(site, "site", "longitude_deg");
  m.time_zone_h = r.number(site, "site", "time_zone_h");
  m.elevation_m = r.number(site, "site", "elevation_m");
  m.sun_from_weather = r.boolean(site, "site", "sun_from_weather");
  const json& sun = r.at(site, "site", "sun_site");
  if (!sun.is_null())
    m.sun_site = std::array<double, 4>{r.number(sun, "site.sun_site", "latitude_deg"),
                                       r.number(sun, "site.sun_site", "longitude_deg"),
                                       r.number(sun, "site.sun_site", "time_zone_h"),
                                       r.number(sun, "site.sun_site", "elevation_m")};
  m.sun_sentence = r.text(site, "site", "sun_sentence");
  m.station_distance_km = r.optional_number(site, "site", "station_distance_km");
  if (const auto h = r.optional_number(site, "site", "below_horizon_hours")) m.below_horizon_hours = static_cast<std::size_t>(*h);
  m.below_horizon_their_sun = r.text(site, "site", "below_horizon_their_sun");
  m.weather_file = r.text(j, "", "weather_file");
  const json& sky = r.at(j, "", "sky");
  m.basis = r.text(sky, "sky", "basis");
  if (m.basis != "tregenza" && m.basis != "reinhart") r.fail("sky.basis", "is not tregenza or reinhart");
  m.reinhart_mf = r.integer(sky, "sky", "reinhart_mf");
  if (m.reinhart_mf < 1) r.fail("sky.reinhart_mf", "is not a positive integer");
  m.ground_reflectance = r.number(sky, "sky", "ground_reflectance");
  for (const json& s : r.array(j, "", "settings")) m.settings.push_back({r.text(s, "settings", "name"), r.text(s, "settings", "value")});
  m.notes = r.texts(j, "", "notes");
  m.not_assessed = r.texts(j, "", "not_assessed");
  if (j.contains("sunlight_exposure")) {
    const json& e = r.at(j, "", "sunlight_exposure");
    SunlightExposureSettings st;
    const auto [month, day] = r.month_day(r.at(e, "sunlight_exposure", "date"), "sunlight_exposure.date");
    st.month = month;
    st.day = day;
    st.year = r.integer(e, "sunlight_exposure", "year");
    st.min_altitude_deg = r.number(e, "sunlight_exposure", "min_altitude_deg");
    st.time_step_min = r.number(e, "sunlight_exposure", "time_step_min");
    m.sunlight_exposure = st;
  }
  for (const json& c : r.array(j, "", "cases")) {
    CaseResult cr;
    cr.kind = r.text(c, "cases", "kind");
    if (cr.kind != "base" && cr.kind != "variant" && cr.kind != "operated") r.fail("cases.kind", "is not base, variant or operated");
    cr.name = r.text(c, "cases", "name");
    cr.folder = r.text(c, "cases", "folder");
    cr.changes = r.texts(c, "cases", "changes");
    cr.openings = r.polygons(r.at(c, "cases", "openings"), "cases.openings");
    cr.systems = r.polygons(r.at(c, "cases", "systems"), "cases.systems");
    cr.materials = r.materials(c, "cases[" + cr.name + "]");
    cr.rooms = r.rooms(c, "cases[" + cr.name + "]");
    cr.opening_area_m2 = r.number(c, "cases", "opening_area_m2");
    if (c.contains("blinds_in_place")) cr.blinds_in_place = r.texts(c, "cases", "blinds_in_place");
    if (c.contains("sunlight_exposure")) cr.sunlight_exposure = r.sunlight(c, "cases");
    if (c.contains("shading_materials_in_place"))
      for (const json& s : r.array(c, "cases", "shading_materials_in_place"))
        cr.shading_materials_in_place.push_back({r.text(s, "cases.shading_materials_in_place", "material"),
                                                 r.text(s, "cases.shading_materials_in_place", "why")});
    for (const json& g : r.array(c, "cases", "grids")) {
      cr.grids.push_back(r.grid(g, "cases[" + cr.name + "].grids"));
      for (int k : cr.grids.back().openings_drawn)
        if (static_cast<std::size_t>(k) >= cr.openings.size()) r.fail("cases.grids.openings_drawn", "names an opening that is not listed");
    }
    m.cases.push_back(std::move(cr));
  }
  return m;
}

std::string write_results_model(const ResultsModel& model, const std::string& output_dir) {
  const std::string path = (fs::path(output_dir) / ResultsFileName).string();
  write_file_atomically(path, results_json(model));
  return path;
}

ResultsModel read_results_model(const std::string& results_dir) {
  const std::string path = (fs::path(results_dir) / ResultsFileName).string();
  if (input_file_problem(path) == "not found") {
    const bool old_run = fs::exists(fs::path(results_dir) / "summary.json");
    throw InputError(SourceLocation{path, 0, 0},
                     old_run ? "this results folder has no results.json: it was written by an older dayphoton; run the "
                               "study again (`dayphoton run PROJECT --output " + results_dir + "`) to report on it"
                             : "cannot open the results model (is this a results folder of `dayphoton run`?)");
  }
  std::ifstream in = open_input_file(path, "results model");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_results_json(text.str(), path);
}

std::string grid_folder(const std::string& results_dir, const GridResult& grid) {
  // Each '/'-separated part must be a portable folder name ("variants/<name>/<grid>").
  std::string rest = grid.folder;
  fs::path out(results_dir);
  while (!rest.empty()) {
    const std::size_t slash = rest.find('/');
    const std::string part = rest.substr(0, slash);
    const std::string problem = project::path_name_problem(part);
    if (!problem.empty())
      throw InputError(SourceLocation{(fs::path(results_dir) / ResultsFileName).string(), 0, 0},
                       "results.json: grid folder '" + project::printable_name(grid.folder) +
                           "' is not a path of portable folder names: " + problem);
    out /= part;
    rest = slash == std::string::npos ? std::string() : rest.substr(slash + 1);
  }
  return out.string();
}

std::vector<double> read_quantity_values(const std::string& results_dir, const GridResult& grid,
                                         const SensorQuantity& quantity) {
  const std::string path = (fs::path(grid_folder(results_dir, grid)) / quantity.file).string();
  const SensorTable table = read_sensor_table(path);
  if (table.column(quantity.column) < 0)
    throw InputError(SourceLocation{path, 1, 0}, "no column '" + quantity.column + "' (results.json names it)");
  if (table.rows.size() != grid.positions_m.size())
    throw InputError(SourceLocation{path, 0, 0}, std::to_string(table.rows.size()) + " rows for the " +
                                                     std::to_string(grid.positions_m.size()) + " sensors of results.json");
  return table.values(quantity.column);
}

metrics::IlluminanceTable read_illuminance_table(const std::string& results_dir, const GridResult& grid) {
  const std::string path = (fs::path(grid_folder(results_dir, grid)) / "illuminance.bin").string();
  if (!grid.has_illuminance_table)
    throw InputError(SourceLocation{path, 0, 0}, "results.json says grid '" + grid.name +
                                                     "' has no annual illuminance (illuminance_table: false)");
  metrics::IlluminanceTable table;
  try {
    table = read_illuminance_binary(path);
  } catch (const std::runtime_error& e) {
    throw InputError(SourceLocation{path, 0, 0}, e.what());
  }
  if (table.sensor_count() != grid.positions_m.size())
    throw InputError(SourceLocation{path, 0, 0}, std::to_string(table.sensor_count()) + " sensors, results.json has " +
                                                     std::to_string(grid.positions_m.size()));
  return table;
}

}  // namespace dayphoton::study
