#include "occupancy_reader.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "dayphoton/core/input_file.h"
#include "occupancy_csv.h"
#include "param_reader.h"

namespace dayphoton::project {

namespace {

constexpr const char* DayKeys[7] = {"monday", "tuesday", "wednesday", "thursday", "friday", "saturday", "sunday"};
constexpr int DaysInMonth[12] = {31, 29, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
constexpr const char* HoursForms = "expected hours as [start, end], a list of such windows ([[8, 12], [13, 17]]) or 'closed'";

/// One window [start, end] from a two-item list.
bool read_window(const YamlNode& n, const std::string& key, Reporter& reporter, std::pair<double, double>& out) {
  if (!n.is_sequence() || n.items.size() != 2) {
    reporter.error(n.location, "'" + key + "': " + HoursForms + ", got " + n.describe());
    return false;
  }
  double v[2] = {0, 0};
  for (int i = 0; i < 2; ++i) {
    const YamlNode& item = n.items[static_cast<std::size_t>(i)];
    if (!item.is_scalar() || !parse_double(item.scalar, v[i])) {
      reporter.error(item.location, "'" + key + "': expected an hour (a number of hours, 0 to 24), got " + item.describe());
      return false;
    }
    if (!(v[i] >= 0 && v[i] <= 24)) {
      reporter.error(item.location, "'" + key + "': hours must be in [0, 24], got " + format_number(v[i]));
      return false;
    }
  }
  if (!(v[1] > v[0])) {
    reporter.error(n.items[1].location, "'" + key + "': the end (" + format_number(v[1]) +
                                            ") must be after the start (" + format_number(v[0]) + ")");
    return false;
  }
  out = {v[0], v[1]};
  return true;
}

bool read_hours(const YamlNode& n, const std::string& key, Reporter& reporter, OccupancySpec::Windows& out) {
  out.clear();
  if (n.is_scalar() && n.scalar == "closed") return true;
  if (!n.is_sequence() || n.items.empty()) {
    reporter.error(n.location, "'" + key + "': " + HoursForms + ", got " + n.describe());
    return false;
  }
  // [8, 17] or [[8, 12], [13, 17]]
  if (!n.items[0].is_sequence()) {
    std::pair<double, double> w;
    if (!read_window(n, key, reporter, w)) return false;
    out.push_back(w);
    return true;
  }
  bool ok = true;
  for (const YamlNode& item : n.items) {
    std::pair<double, double> w;
    if (!read_window(item, key, reporter, w)) {
      ok = false;
      continue;
    }
    if (!out.empty() && w.first < out.back().second) {
      reporter.error(item.location, "'" + key + "': windows must be in time order and must not overlap: [" +
                                        format_number(w.first) + ", " + format_number(w.second) +
                                        "] starts before the previous one ends (" +
                                        format_number(out.back().second) + ")");
      ok = false;
      continue;
    }
    out.push_back(w);
  }
  return ok;
}

/// "MM-DD" -> month, day; false if not a date of a (leap) year.
bool parse_month_day(const std::string& text, int& month, int& day) {
  if (text.size() != 5 || text[2] != '-') return false;
  for (int i : {0, 1, 3, 4})
    if (text[static_cast<std::size_t>(i)] < '0' || text[static_cast<std::size_t>(i)] > '9') return false;
  month = std::stoi(text.substr(0, 2));
  day = std::stoi(text.substr(3, 2));
  return month >= 1 && month <= 12 && day >= 1 && day <= DaysInMonth[month - 1];
}

bool read_holiday(const YamlNode& n, Reporter& reporter, OccupancySpec::Holiday& out) {
  if (!n.is_scalar()) {
    reporter.error(n.location, "'holidays': expected a date MM-DD or a period MM-DD..MM-DD, got " + n.describe());
    return false;
  }
  const std::string& t = n.scalar;
  const std::size_t dots = t.find("..");
  const std::string from = dots == std::string::npos ? t : t.substr(0, dots);
  const std::string to = dots == std::string::npos ? t : t.substr(dots + 2);
  if (parse_month_day(from, out.from_month, out.from_day) && parse_month_day(to, out.to_month, out.to_day)) return true;
  std::string hint;
  if (t.size() == 10 && t[4] == '-' && t[7] == '-')
    hint = " (the weather file stands for a typical year: write the date without the year, '" + t.substr(5) + "')";
  reporter.error(n.location, "'holidays': '" + t + "' is not a date MM-DD (12-25) or a period MM-DD..MM-DD (07-06..08-31)" +
                                 hint);
  return false;
}

std::string read_text_file(const std::string& path, const SourceLocation& from) {
  std::ifstream in = open_input_file(path, "occupancy schedule", from);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

bool read_occupancy(const YamlNode& node, const std::string& project_directory, Reporter& reporter,
                    OccupancySpec& out) {
  const std::size_t errors_before = reporter.diagnostics().error_count();
  out = OccupancySpec{};
  out.given = true;
  out.location = node.location;
  ParamReader r(node, schema_section("occupancy"), reporter);

  if (const YamlNode* file = r.take("file")) {
    for (const YamlEntry& e : node.entries)
      if (e.key != "file" && r.schema().find(e.key)) {
        reporter.error(e.key_location, "'" + e.key + "' cannot be combined with 'file': the CSV gives every hour");
        r.take(e.key);
      }
    std::string written;
    if (!file->is_scalar() || file->scalar.empty()) {
      reporter.error(file->location, "'file': expected a path, got " + file->describe());
    } else {
      written = file->scalar;
      const std::filesystem::path p(written);
      out.file = (p.is_absolute() || project_directory.empty() ? p : std::filesystem::path(project_directory) / p)
                     .lexically_normal()
                     .string();
      const std::string problem = input_file_problem(out.file);
      if (problem == "not found")
        reporter.error(file->location, "occupancy schedule '" + written + "' not found (looked for '" + out.file + "')");
      else if (!problem.empty())
        reporter.error(file->location, "occupancy schedule '" + written + "' " + problem);
      else {
        try {
          out.hourly = read_occupancy_csv_text(read_text_file(out.file, file->location), out.file, reporter.diagnostics());
        } catch (const InputError& e) {
          for (const Diagnostic& d : e.diagnostics()) reporter.diagnostics().error(d.location, d.message, d.source_line);
        }
      }
    }
    r.finish();
    return reporter.diagnostics().error_count() == errors_before;
  }

  // Hours: a day's own key, else weekdays / weekends, else every_day, else closed.
  OccupancySpec::Windows every_day, weekdays, weekends;
  bool any_hours = false;
  auto hours = [&](const char* key, OccupancySpec::Windows& into) {
    const YamlNode* n = r.take(key);
    if (!n) return false;
    any_hours = true;
    return read_hours(*n, key, reporter, into);
  };
  const bool has_every = hours("every_day", every_day);
  const bool has_weekdays = hours("weekdays", weekdays);
  const bool has_weekends = hours("weekends", weekends);
  for (int d = 0; d < 7; ++d) {
    OccupancySpec::Windows& day = out.week[static_cast<std::size_t>(d)];
    if (hours(DayKeys[d], day)) continue;
    if (r.has(DayKeys[d])) continue;  // its error is reported
    if (d < 5 && has_weekdays) day = weekdays;
    else if (d >= 5 && has_weekends) day = weekends;
    else if (has_every) day = every_day;
  }
  if (const YamlNode* n = r.take("holidays")) {
    if (!n->is_sequence()) {
      reporter.error(n->location, "'holidays': expected a list of dates MM-DD and periods MM-DD..MM-DD, got " + n->describe());
    } else {
      for (const YamlNode& item : n->items) {
        OccupancySpec::Holiday h;
        if (read_holiday(item, reporter, h)) out.holidays.push_back(h);
      }
    }
  }
  if (const YamlNode* n = r.take("holiday_hours")) {
    if (!r.has("holidays"))
      reporter.error(n->location, "'holiday_hours' without 'holidays': list the holiday dates");
    read_hours(*n, "holiday_hours", reporter, out.holiday_hours);
  }
  std::string january_1;
  if (r.has("january_1") && r.read_choice("january_1", january_1))
    for (int d = 0; d < 7; ++d)
      if (january_1 == DayKeys[d]) out.january_1 = d;
  r.read_choice("daylight_saving", out.daylight_saving);
  r.finish();
  if (!any_hours && reporter.diagnostics().error_count() == errors_before)
    reporter.error(node.location, "the occupancy gives no hours: write every_day, weekdays, weekends or a day's "
                                  "hours (e.g. weekdays: [8, 17]), or a file");
  return reporter.diagnostics().error_count() == errors_before;
}

}  // namespace dayphoton::project
