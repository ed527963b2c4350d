// The report's one formatting helper: every number report.html prints as text goes through
// format_value with the precision of its kind, so a quantity has the same precision in every
// table (docs/report.md, "Precision"), and the HTML escaping and pass/fail badges the
// sections share. Used by every section of report.html (report/src/*_section.cpp, report_html.cpp).
#pragma once

#include <optional>
#include <string>

namespace dayphoton::report {

/// What a number is, which decides how it is printed.
enum class Precision {
  DaylightFactor,  ///< %: 0.1 % steps from 1 % up, 2 significant digits below (2.7, 0.34)
  Illuminance,     ///< lx: 3 significant digits (548, 1230, 12.3)
  Percent,         ///< shares of time or area, %: whole points (98)
  Ratio,           ///< uniformity, window-to-wall ratio: 2 decimals (0.41)
  Fraction,        ///< reflectance, transmittance: 2 decimals (0.60)
  Length,          ///< m: up to 2 decimals, no trailing zeros (6, 0.9, 1.25)
  Area,            ///< m2: up to 1 decimal, no trailing zeros (48, 6.5)
  Points,          ///< differences of percentages, signed whole points (+3, -12, 0)
  Seconds,         ///< durations, s: 2 significant digits below 10 s (0.42, 4.2), whole seconds
                   ///< above (42, 1234), "< 0.01" below 0.01 s (never "0.00")
};

/// `value` as text at the precision of `kind`; "-" for a value that is not finite.
std::string format_value(double value, Precision kind);
/// The same, "-" for none.
std::string format_value(const std::optional<double>& value, Precision kind);
/// A signed difference (+0.4, -12) at the precision of `kind` (Percent -> whole points).
std::string format_delta(double delta, Precision kind);

/// Text made safe for HTML element content and attribute values.
std::string esc(const std::string& text);

/// A verdict badge: outcome "pass", "fail" or "not assessed", with `text` shown.
std::string verdict_badge(const std::string& outcome, const std::string& text);

}  // namespace dayphoton::report
