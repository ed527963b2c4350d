// The report's formatting helper; see report_format.h.
#include "dayphoton/report/report_format.h"

#include <cmath>
#include <cstdio>

namespace dayphoton::report {

namespace {

std::string fixed(double v, int decimals) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, v);
  std::string s = buffer;
  if (s.find_first_not_of("-0.") == std::string::npos && s[0] == '-') s.erase(0, 1);  // no "-0"
  return s;
}

std::string trimmed(double v, int decimals) {
  std::string s = fixed(v, decimals);
  if (s.find('.') != std::string::npos) {
    s.erase(s.find_last_not_of('0') + 1);
    if (s.back() == '.') s.pop_back();
  }
  return s;
}

/// `v` rounded to `digits` significant digits, printed without exponent.
std::string significant(double v, int digits) {
  if (v == 0) return "0";
  const int magnitude = static_cast<int>(std::floor(std::log10(std::fabs(v))));
  const int decimals = std::max(0, digits - 1 - magnitude);
  const double step = std::pow(10.0, magnitude - digits + 1);
  const double rounded = std::round(v / step) * step;
  // Rounding up may add a digit (9.99 -> 10.0): print the rounded value with the digits it needs.
  const int m2 = static_cast<int>(std::floor(std::log10(std::fabs(rounded))));
  return fixed(rounded, std::max(0, std::min(decimals, digits - 1 - m2)));
}

}  // namespace

std::string format_value(double v, Precision kind) {
  if (!std::isfinite(v)) return "-";
  switch (kind) {
    case Precision::DaylightFactor: return std::fabs(v) >= 0.995 ? fixed(v, 1) : significant(v, 2);
    case Precision::Illuminance: return significant(v, 3);
    case Precision::Percent: return fixed(v, 0);
    case Precision::Ratio:
    case Precision::Fraction: return fixed(v, 2);
    case Precision::Length: return trimmed(v, 2);
    case Precision::Area: return trimmed(v, 1);
    case Precision::Points: return format_delta(v, Precision::Percent);
    case Precision::Seconds:
      if (v < 0.01) return "< 0.01";
      return v < 9.95 ? significant(v, 2) : fixed(v, 0);
  }
  return fixed(v, 2);
}

std::string format_value(const std::optional<double>& v, Precision kind) { return v ? format_value(*v, kind) : "-"; }

std::string format_delta(double delta, Precision kind) {
  if (!std::isfinite(delta)) return "-";
  const std::string s = format_value(delta, kind == Precision::Points ? Precision::Percent : kind);
  if (s.find_first_not_of("0.") == std::string::npos) return s;  // zero at this precision: no sign
  return delta > 0 ? "+" + s : s;
}

std::string esc(const std::string& s) {
  std::string out;
  out.reserve(s.size());
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string verdict_badge(const std::string& outcome, const std::string& text) {
  const char* cls = outcome == "pass" ? "pass" : outcome == "fail" ? "fail" : "na-badge";
  return std::string("<span class=\"badge ") + cls + "\">" + esc(text) + "</span>";
}

}  // namespace dayphoton::report
