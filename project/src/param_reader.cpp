// Schema-driven reading of one YAML map (see param_reader.h). Modelled on the "mark each
// parameter as read, report the rest" idea of pbrt's ParameterDictionary::ReportUnused and
// Mitsuba's Properties::unqueried (STYLE.md A.5); code is our own.
#include "param_reader.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

#include "dayphoton/core/diagnostics.h"

namespace dayphoton::project {

namespace {

std::string join(const std::vector<std::string>& words) {
  std::string s;
  for (const auto& w : words) s += (s.empty() ? "" : ", ") + w;
  return s;
}

// A default written like a file value ("0.5", "[0, 0, 1]", "tregenza") as a tree node.
YamlNode default_node(const std::string& text, const SourceLocation& loc) {
  YamlNode n;
  n.location = loc;
  if (!text.empty() && text.front() == '[') {
    n.kind = YamlNode::Kind::Sequence;
    std::string item;
    for (char c : text.substr(1)) {
      if (c == ',' || c == ']') {
        YamlNode s;
        s.kind = YamlNode::Kind::Scalar;
        s.location = loc;
        const auto b = item.find_first_not_of(' '), e = item.find_last_not_of(' ');
        s.scalar = b == std::string::npos ? "" : item.substr(b, e - b + 1);
        n.items.push_back(s);
        item.clear();
      } else {
        item += c;
      }
    }
  } else {
    n.kind = YamlNode::Kind::Scalar;
    n.scalar = text;
  }
  return n;
}

}  // namespace

bool parse_double(const std::string& text, double& out) {
  if (text.empty() || std::isspace(static_cast<unsigned char>(text.front()))) return false;
  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || errno == ERANGE || !std::isfinite(v)) return false;
  out = v;
  return true;
}

bool parse_integer(const std::string& text, long long& out) {
  if (text.empty() || std::isspace(static_cast<unsigned char>(text.front()))) return false;
  errno = 0;
  char* end = nullptr;
  const long long v = std::strtoll(text.c_str(), &end, 10);
  if (end != text.c_str() + text.size() || errno == ERANGE) return false;
  out = v;
  return true;
}

bool parse_bool(const std::string& text, bool& out) {
  // YAML 1.1 booleans, as yaml-cpp's as<bool>() accepts them (lower case / capitalised).
  static const char* const yes[] = {"true", "True", "TRUE", "yes", "Yes", "YES", "on", "On", "ON"};
  static const char* const no[] = {"false", "False", "FALSE", "no", "No", "NO", "off", "Off", "OFF"};
  for (const char* y : yes)
    if (text == y) return out = true, true;
  for (const char* n : no)
    if (text == n) return out = false, true;
  return false;
}

bool expect_map(const YamlNode& node, const std::string& what, Reporter& reporter) {
  if (node.is_map()) return true;
  reporter.error(node.location, "expected a map for '" + what + "', got " + node.describe());
  return false;
}

bool expect_list(const YamlNode& node, const std::string& what, Reporter& reporter) {
  if (node.is_sequence()) return true;
  reporter.error(node.location, "expected a list for '" + what + "', got " + node.describe());
  return false;
}

ParamReader::ParamReader(const YamlNode& node, const SectionSchema& schema, Reporter& reporter)
    : m_node(node), m_schema(schema), m_reporter(reporter) {}

const ParamSchema& ParamReader::param(const std::string& key) const {
  const ParamSchema* p = m_schema.find(key);
  if (!p) throw std::logic_error("key '" + key + "' is not in schema section '" + m_schema.name + "'");
  return *p;
}

const YamlNode* ParamReader::take(const std::string& key) {
  const ParamSchema& p = param(key);
  m_read.insert(key);
  if (const YamlEntry* e = m_node.find(key)) {
    if (!e->value.is_null() || p.type == ParamType::Special) return &e->value;
    m_reporter.error(e->value.location, "missing value for '" + key + "'");
    return nullptr;
  }
  if (p.required)
    m_reporter.error(m_node.location, "missing required key '" + key + "' in " + m_schema.name);
  return nullptr;
}

SourceLocation ParamReader::location_of(const std::string& key) const {
  if (const YamlEntry* e = m_node.find(key)) return e->value.location;
  return m_node.location;
}

const YamlNode* ParamReader::value_or_default(const std::string& key, YamlNode& scratch) {
  const bool present = m_node.find(key) != nullptr;
  if (const YamlNode* v = take(key)) return v;
  const ParamSchema& p = param(key);
  if (present || p.default_value.empty()) return nullptr;
  scratch = default_node(p.default_value, m_node.location);
  return &scratch;
}

bool ParamReader::check_range(const ParamSchema& p, const YamlNode& at, double value) {
  if (p.in_range(value)) return true;
  m_reporter.error(at.location, "'" + p.name + "' must be " +
                                    (std::isfinite(p.min) && std::isfinite(p.max) ? "in " : "") +
                                    p.range_text() + ", got " + format_number(value));
  return false;
}

bool ParamReader::read_number(const std::string& key, double& out) {
  YamlNode scratch;
  const YamlNode* v = value_or_default(key, scratch);
  if (!v) return false;
  double x = 0;
  if (!v->is_scalar() || !parse_double(v->scalar, x)) {
    m_reporter.error(v->location, "expected a number for '" + key + "', got " + v->describe());
    return false;
  }
  if (!check_range(param(key), *v, x)) return false;
  out = x;
  return true;
}

bool ParamReader::read_integer(const std::string& key, long long& out) {
  YamlNode scratch;
  const YamlNode* v = value_or_default(key, scratch);
  if (!v) return false;
  long long x = 0;
  if (!v->is_scalar() || !parse_integer(v->scalar, x)) {
    m_reporter.error(v->location, "expected an integer for '" + key + "', got " + v->describe());
    return false;
  }
  if (!check_range(param(key), *v, static_cast<double>(x))) return false;
  out = x;
  return true;
}

bool ParamReader::read_bool(const std::string& key, bool& out) {
  YamlNode scratch;
  const YamlNode* v = value_or_default(key, scratch);
  if (!v) return false;
  if (!v->is_scalar() || !parse_bool(v->scalar, out)) {
    m_reporter.error(v->location, "expected true or false for '" + key + "', got " + v->describe());
    return false;
  }
  return true;
}

bool ParamReader::read_string(const std::string& key, std::string& out) {
  YamlNode scratch;
  const YamlNode* v = value_or_default(key, scratch);
  if (!v) return false;
  if (!v->is_scalar() || v->scalar.empty()) {
    m_reporter.error(v->location, "expected a string for '" + key + "', got " + v->describe());
    return false;
  }
  out = v->scalar;
  return true;
}

bool ParamReader::read_choice(const std::string& key, std::string& out) {
  YamlNode scratch;
  const YamlNode* v = value_or_default(key, scratch);
  if (!v) return false;
  const ParamSchema& p = param(key);
  if (v->is_scalar())
    for (const auto& c : p.choices)
      if (v->scalar == c) return out = c, true;
  std::string message = "unknown value " + v->describe() + " for '" + key + "': expected one of " +
                        join(p.choices);
  if (v->is_scalar()) {
    const std::string hint = closest_match(v->scalar, p.choices);
    if (!hint.empty()) message += " (did you mean '" + hint + "'?)";
  }
  m_reporter.error(v->location, message);
  return false;
}

bool ParamReader::read_angle(const std::string& key, AngleKind kind, double& out) {
  YamlNode scratch;
  const YamlNode* v = value_or_default(key, scratch);
  if (!v) return false;
  if (!v->is_scalar()) {
    m_reporter.error(v->location, "expected an angle for '" + key + "', got " + v->describe());
    return false;
  }
  double x = 0;
  try {
    x = parse_latlon_deg(v->scalar, kind);
  } catch (const std::invalid_argument& e) {
    m_reporter.error(v->location, "bad angle " + v->describe() + " for '" + key + "': " + e.what());
    return false;
  }
  if (!check_range(param(key), *v, x)) return false;
  out = x;
  return true;
}

bool ParamReader::read_vec3(const std::string& key, Vec3& out) {
  YamlNode scratch;
  const YamlNode* v = value_or_default(key, scratch);
  if (!v) return false;
  if (!v->is_sequence() || v->items.size() != 3) {
    m_reporter.error(v->location, "expected [x, y, z] for '" + key + "', got " +
                                      (v->is_sequence() ? std::to_string(v->items.size()) + " values"
                                                        : v->describe()));
    return false;
  }
  Vec3 r;
  bool ok = true;
  for (int i = 0; i < 3; ++i) {
    const YamlNode& item = v->items[static_cast<std::size_t>(i)];
    if (!item.is_scalar() || !parse_double(item.scalar, r[i])) {
      m_reporter.error(item.location, "expected a number in '" + key + "', got " + item.describe());
      ok = false;
    } else if (!check_range(param(key), item, r[i])) {
      ok = false;
    }
  }
  if (ok) out = r;
  return ok;
}

bool ParamReader::read_rgb(const std::string& key, Vec3& out) {
  YamlNode scratch;
  const YamlNode* v = value_or_default(key, scratch);
  if (!v) return false;
  if (v->is_scalar()) {
    double x = 0;
    if (!parse_double(v->scalar, x)) {
      m_reporter.error(v->location, "expected a number or [r, g, b] for '" + key + "', got " + v->describe());
      return false;
    }
    if (!check_range(param(key), *v, x)) return false;
    out = Vec3{x, x, x};
    return true;
  }
  if (!v->is_sequence() || v->items.size() != 3) {
    m_reporter.error(v->location, "expected a number or [r, g, b] for '" + key + "', got " +
                                      (v->is_sequence() ? std::to_string(v->items.size()) + " values"
                                                        : v->describe()));
    return false;
  }
  return read_vec3(key, out);  // same element checks (already marked read)
}

bool ParamReader::read_points(const std::string& key, std::vector<Vec3>& out) {
  const YamlNode* v = take(key);
  if (!v) return false;
  if (!v->is_sequence() || v->items.empty()) {
    m_reporter.error(v->location, "expected a list of [x, y, z] for '" + key + "', got " + v->describe());
    return false;
  }
  std::vector<Vec3> points;
  bool ok = true;
  for (const auto& item : v->items) {
    Vec3 p;
    bool good = item.is_sequence() && item.items.size() == 3;
    for (int i = 0; good && i < 3; ++i) {
      const YamlNode& c = item.items[static_cast<std::size_t>(i)];
      good = c.is_scalar() && parse_double(c.scalar, p[i]);
    }
    if (!good) {
      m_reporter.error(item.location, "expected [x, y, z] numbers in '" + key + "', got " + item.describe());
      ok = false;
    }
    points.push_back(p);
  }
  if (ok) out = std::move(points);
  return ok;
}

bool ParamReader::read_numbers(const std::string& key, std::vector<double>& out) {
  YamlNode scratch;
  const YamlNode* v = value_or_default(key, scratch);
  if (!v) return false;
  if (!v->is_sequence() || v->items.empty()) {
    m_reporter.error(v->location, "expected a list of one or more numbers for '" + key + "', got " +
                                      (v->is_sequence() ? std::string("an empty list") : v->describe()));
    return false;
  }
  std::vector<double> values;
  bool ok = true;
  for (const auto& item : v->items) {
    double x = 0;
    if (!item.is_scalar() || !parse_double(item.scalar, x)) {
      m_reporter.error(item.location, "expected a number in '" + key + "', got " + item.describe());
      ok = false;
    } else if (!check_range(param(key), item, x)) {
      ok = false;
    }
    values.push_back(x);
  }
  if (ok) out = std::move(values);
  return ok;
}

void ParamReader::finish() {
  for (const auto& e : m_node.entries) {
    if (m_read.count(e.key)) continue;
    std::string message = "unknown key '" + e.key + "' in " + m_schema.name;
    const std::string hint = closest_match(e.key, m_schema.keys());
    if (!hint.empty()) message += " (did you mean '" + hint + "'?)";
    m_reporter.error(e.key_location, message);
  }
}

}  // namespace dayphoton::project
