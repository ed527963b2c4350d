// The EN 17037 exposure to sunlight section; see report_sections.h. The hours, spells and
// levels are the model's (study/sunlight_exposure.h computes them); nothing is assessed here.
#include <sstream>

#include "dayphoton/report/report_format.h"
#include "dayphoton/study/sunlight_exposure.h"
#include "report_sections.h"

namespace dayphoton::report {

std::string sunlight_section(const study::ResultsModel& m) {
  if (!m.sunlight_exposure) return "";
  const study::SunlightExposureSettings& e = *m.sunlight_exposure;
  static const char* const months[] = {"January", "February", "March"};
  std::ostringstream s;
  s << "<section id=\"sunlight\"><h2>Exposure to sunlight (EN 17037)</h2><p>Hours of possible sunlight on "
    << e.day << " " << (e.month >= 1 && e.month <= 3 ? months[e.month - 1] : "?")
    << " under a cloudless sky, the sun at or above " << format_value(e.min_altitude_deg, Precision::Length)
    << "&deg; altitude, seen from each window's reference point (centre of its width, on the glazing, at least "
    << format_value(study::SunlightPointAboveFloor_m, Precision::Length) << " m above the floor and "
    << format_value(study::SunlightPointAboveSill_m, Precision::Length)
    << " m above the sill); a room's hours are the union of its windows'. Times in local standard time "
       "(no daylight saving).</p>";
  s << "<table class=\"verdict-table\"><tr><th>case</th><th>room</th><th>hours</th><th>level</th><th>spells</th>"
       "<th>windows</th></tr>";
  for (const study::CaseResult& c : m.cases)
    for (const study::RoomSunlight& r : c.sunlight_exposure) {
      const std::string outcome = r.level == "not assessed" ? "not assessed" : r.level == "below minimum" ? "fail" : "pass";
      std::string windows;
      for (const study::WindowSunlight& w : r.windows)
        windows += (windows.empty() ? "" : "; ") + w.name + ": " +
                   (w.not_assessed.empty() ? format_value(w.hours, Precision::Ratio) + " h"
                                           : "not assessed, " + w.not_assessed);
      s << "<tr><td>" << esc(case_label(c)) << "</td><td>" << esc(r.room) << "</td><td class=\"n\">"
        << format_value(r.hours, Precision::Ratio) << "</td><td>" << verdict_badge(outcome, r.level) << "</td><td>"
        << esc(study::intervals_text(r.intervals)) << "</td><td>" << esc(windows) << "</td></tr>";
    }
  s << "</table><p class=\"note\">Levels: minimum " << format_value(study::SunlightMinimum_h, Precision::Length)
    << " h, medium " << format_value(study::SunlightMedium_h, Precision::Length) << " h, high "
    << format_value(study::SunlightHigh_h, Precision::Length)
    << " h (EN 17037:2018, exposure to sunlight). Everything drawn blocks the sun but clear glazing: blinds and "
       "operable shading count as drawn in each case. Sampled every "
    << format_value(e.time_step_min, Precision::Length)
    << " min, each change found to 1 s; the minimum altitude is the project's (EN 17037 makes it depend on the "
       "site).</p></section>";
  return s.str();
}

}  // namespace dayphoton::report
