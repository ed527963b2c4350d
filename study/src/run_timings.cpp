// timings.json: see run_timings.h.
#include "dayphoton/study/run_timings.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "dayphoton/core/atomic_file.h"
#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/input_file.h"
#include "json_text.h"

namespace dayphoton::study {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

[[noreturn]] void fail(const std::string& path, const std::string& key, const std::string& what) {
  throw InputError(SourceLocation{path, 0, 0}, "timings.json: '" + key + "' " + what);
}

const json& at(const std::string& path, const json& j, const std::string& parent, const char* key) {
  if (!j.is_object()) fail(path, parent, "is not an object");
  const auto it = j.find(key);
  if (it == j.end()) fail(path, parent.empty() ? key : parent + "." + key, "is missing");
  return *it;
}

/// A time in seconds: a finite number >= 0.
double seconds(const std::string& path, const json& j, const std::string& parent, const char* key) {
  const json& v = at(path, j, parent, key);
  if (!v.is_number() || !std::isfinite(v.get<double>()) || v.get<double>() < 0)
    fail(path, parent.empty() ? key : parent + "." + key, "is not a number of seconds >= 0");
  return v.get<double>();
}

std::uint64_t count(const std::string& path, const json& j, const std::string& parent, const char* key) {
  const json& v = at(path, j, parent, key);
  if (!v.is_number_unsigned() && !(v.is_number_integer() && v.get<long long>() >= 0))
    fail(path, parent.empty() ? key : parent + "." + key, "is not a count");
  return v.get<std::uint64_t>();
}

std::string text(const std::string& path, const json& j, const std::string& parent, const char* key) {
  const json& v = at(path, j, parent, key);
  if (!v.is_string()) fail(path, parent.empty() ? key : parent + "." + key, "is not a string");
  return v.get<std::string>();
}

}  // namespace

bool StepTiming::operator==(const StepTiming& o) const {
  return name == o.name && unit == o.unit && work == o.work && wall_s == o.wall_s && cpu_s == o.cpu_s &&
         cached == o.cached;
}

bool RunTimings::operator==(const RunTimings& o) const {
  return steps == o.steps && total_wall_s == o.total_wall_s && total_cpu_s == o.total_cpu_s && threads == o.threads;
}

RunTimings run_timings_of(const std::vector<Progress::StepTime>& steps, double total_wall_s, double total_cpu_s,
                          unsigned threads) {
  RunTimings t;
  for (const Progress::StepTime& s : steps)
    t.steps.push_back({s.name, s.unit, s.cached ? 0 : s.work, s.cached ? 0 : s.seconds, s.cached ? 0 : s.cpu_seconds,
                       s.cached});
  t.total_wall_s = total_wall_s;
  t.total_cpu_s = total_cpu_s;
  t.threads = threads;
  return t;
}

std::string write_run_timings(const RunTimings& timings, const std::string& output_dir) {
  json steps = json::array();
  for (const StepTiming& s : timings.steps)
    steps.push_back({{"name", s.name},
                     {"cached", s.cached},
                     {"wall_s", s.wall_s},
                     {"cpu_s", s.cpu_s},
                     {"work", s.work},
                     {"unit", s.unit}});
  const json j = {{"schema_version", TimingsSchemaVersion},
                  {"threads", timings.threads},
                  {"total_wall_s", timings.total_wall_s},
                  {"total_cpu_s", timings.total_cpu_s},
                  {"steps", steps}};
  const std::string path = (fs::path(output_dir) / TimingsFileName).string();
  write_file_atomically(path, json_text(j) + "\n");
  return path;
}

RunTimings parse_run_timings(const std::string& text_in, const std::string& path) {
  const json j = json::parse(text_in, nullptr, false);
  if (j.is_discarded() || !j.is_object()) throw InputError(SourceLocation{path, 0, 0}, "timings.json is not a JSON object");
  const json& version = at(path, j, "", "schema_version");
  if (!version.is_number_integer()) fail(path, "schema_version", "is not an integer");
  if (version.get<long long>() != TimingsSchemaVersion)
    throw InputError(SourceLocation{path, 0, 0}, "timings.json has schema version " + version.dump() +
                                                     ", this dayphoton reads " + std::to_string(TimingsSchemaVersion));
  RunTimings t;
  const std::uint64_t threads = count(path, j, "", "threads");
  if (threads > 1u << 20) fail(path, "threads", "is not a thread count");
  t.threads = static_cast<unsigned>(threads);
  t.total_wall_s = seconds(path, j, "", "total_wall_s");
  t.total_cpu_s = seconds(path, j, "", "total_cpu_s");
  const json& steps = at(path, j, "", "steps");
  if (!steps.is_array()) fail(path, "steps", "is not an array");
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const json& s = steps[i];
    const std::string key = "steps[" + std::to_string(i) + "]";
    StepTiming st;
    st.name = text(path, s, key, "name");
    const json& cached = at(path, s, key, "cached");
    if (!cached.is_boolean()) fail(path, key + ".cached", "is not true or false");
    st.cached = cached.get<bool>();
    st.wall_s = seconds(path, s, key, "wall_s");
    st.cpu_s = seconds(path, s, key, "cpu_s");
    st.work = count(path, s, key, "work");
    st.unit = text(path, s, key, "unit");
    t.steps.push_back(std::move(st));
  }
  return t;
}

std::optional<RunTimings> read_run_timings(const std::string& results_dir) {
  const std::string path = (fs::path(results_dir) / TimingsFileName).string();
  if (input_file_problem(path) == "not found") return std::nullopt;
  std::ifstream in = open_input_file(path, "run timings");
  std::ostringstream s;
  s << in.rdbuf();
  return parse_run_timings(s.str(), path);
}

}  // namespace dayphoton::study
