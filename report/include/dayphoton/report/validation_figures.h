// The validation figures the report's methods section quotes: dayphoton against RADIANCE on
// the reference office (6 m x 8 m x 3 m, one south window, 165 work-plane sensors, Oakland
// TMY3), as measured by scripts/validate_office.py and tabled in docs/validation.md ("The
// reference office against RADIANCE (measured)"). Declared once here; a test checks that
// docs/validation.md states the same numbers, so a re-measurement updates both or fails.
#pragma once

namespace dayphoton::report {

struct ValidationFigure {
  const char* what;       ///< the comparison, in words
  double value;           ///< the measured figure
  const char* unit;       ///< "%" (relative), "points" (percentage points)
  const char* doc_text;   ///< the figure as docs/validation.md prints it
};

/// RADIANCE version of the reference results.
constexpr const char* ValidationReference = "RADIANCE 5.4a (rtrace, rfluxmtx, gendaymtx)";
constexpr const char* ValidationScene =
    "the reference office (6 m x 8 m x 3 m, one 4 m x 1.5 m south window, 165 work-plane sensors at 0.8 m, "
    "Oakland TMY3 weather)";

constexpr ValidationFigure ValidationFigures[] = {
    {"daylight factor, per-sensor relative RMS difference (daylight coefficients x RADIANCE's sky vector)", 1.32, "%",
     "1.32 %"},
    {"daylight factor, largest per-sensor relative difference", 4.08, "%", "+4.08 %"},
    {"daylight factor, per-sensor relative RMS difference from an independent brute-force backward Monte Carlo "
     "reference on the same patch basis and sky vector (10^6 paths per sensor; its own noise, 0.62 % RMS, included)",
     0.98, "%", "0.98 %"},
    {"daylight factor, per-sensor relative RMS difference (exact CIE overcast sky)", 2.18, "%", "2.18 %"},
    {"sDA300/50%, dayphoton and RADIANCE", 0.6, "points", "84.2 % vs 83.6 %"},
    {"DA300, largest per-sensor difference", 7.34, "points", "+7.34 points"},
    {"DA300, largest per-sensor difference of an independent backward Monte Carlo reference from RADIANCE", 4.87,
     "points", "+4.87 points"},
    {"UDI 100-2000 lx, largest per-sensor difference", 1.57, "points", "1.57 points"},
};

}  // namespace dayphoton::report
