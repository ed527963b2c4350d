// The methods section: what was computed and how, the validation figures and the uncertainty
// the run reached; see report_sections.h. The settings quoted are the model's labelled ones;
// the validation figures are validation_figures.h's, declared once.
#include <sstream>

#include "dayphoton/report/validation_figures.h"
#include "dayphoton/report/report_format.h"
#include "report_sections.h"

namespace dayphoton::report {

namespace {

/// The value of the run's labelled setting `name` ("" if the run has none).
std::string setting(const study::ResultsModel& m, const std::string& name) {
  for (const study::Setting& s : m.settings)
    if (s.name == name) return s.value;
  return "";
}

}  // namespace

std::string methods_section(const study::ResultsModel& m) {
  std::ostringstream s;
  const bool annual = m.study == "annual";
  s << "<section id=\"methods\"><h2>Methods</h2>";
  s << "<h3>What was computed</h3><ul>";
  s << "<li><strong>Daylight factor</strong> at every sensor: the illuminance under the CIE standard overcast sky "
       "(Moon and Spencer luminance distribution, CIE S 011 / ISO 15469 type 1 without sun) over the unobstructed "
       "horizontal illuminance, ground included (ground reflectance "
    << format_value(m.ground_reflectance, Precision::Fraction)
    << "). Both the light reaching a sensor straight from the sky and the light the room reflects are "
       "computed under the sky's own luminance in every direction, not a uniform luminance within each sky "
       "patch (sensors estimated by final gather, such as points and walls, take their reflected light through "
       "the patches).</li>";
  if (annual) {
    s << "<li><strong>Annual illuminance</strong> for every hour of the weather file, from daylight coefficients "
         "(the illuminance each sky patch of unit radiance gives at each sensor) times the hour's sky: the Perez "
         "all-weather sky model (Perez, Seals and Michalsky 1993) with the Perez 1990 luminous efficacies, "
         "following RADIANCE gendaymtx's conventions, on the "
      << (m.basis == "tregenza" ? std::string("Tregenza basis (145 sky patches and the ground)")
                                : "Reinhart basis with " + std::to_string(m.reinhart_mf) + " subdivisions (MF " +
                                      std::to_string(m.reinhart_mf) + ")")
      << ".</li>";
    const std::string sun = setting(m, "sun");
    if (sun == "bins")
      s << "<li><strong>Sun</strong>: the direct sun is traced exactly for every hour (shadow rays toward the "
           "sun's position), and the sun's reflected light is interpolated between sun positions traced in advance "
           "(sun bins, MF "
        << esc(setting(m, "sun mf")) << "). This gives ASE from the direct sun alone, as IES LM-83-12 asks.</li>";
    else if (sun == "spread")
      s << "<li><strong>Sun</strong>: spread into the nearest sky patches (RADIANCE gendaymtx's default); ASE, which "
           "needs the direct sun alone, is then not computed.</li>";
    s << "<li><strong>Metrics</strong> over the occupied hours: daylight autonomy, continuous daylight autonomy, "
         "useful daylight illuminance (Nabil and Mardaljevic 2005; revised bins of Mardaljevic), sDA and ASE (IES "
         "LM-83-12), EN 17037 daylight provision (climate-based method).</li>";
  } else {
    s << "<li>No annual illuminance: a daylight-factor study needs no weather file and traces no sun.</li>";
  }
  s << "</ul><h3>How</h3><p>Light is traced forward from each sky patch (and the ground) through the windows and "
       "other openings (photon ports) into the model; at every sensor a density estimate of the photons (a "
       "contribution photon map: each photon remembers which patch it came from) gives that patch's daylight "
       "coefficient. Light reaching a sensor straight through an opening is computed separately by shadow rays "
       "toward the opening; for the daylight factor (and a point-in-time CIE sky) each shadow ray takes the sky's "
       "luminance in its own direction, not its patch's mean. Photons per sky patch: "
    << esc(setting(m, "photons per bin").empty() ? "see the appendix" : setting(m, "photons per bin"))
    << "; photons per density estimate: " << esc(setting(m, "bandwidth").empty() ? "-" : setting(m, "bandwidth"))
    << ". Materials act on visible light in three colour channels (RGB); reported values are photometric.</p>";

  s << "<h3 id=\"validation\">Validation</h3><p>dayphoton was compared with " << ValidationReference << " on "
    << ValidationScene << ":</p><table class=\"validation-table\"><tr><th>comparison</th><th>measured</th></tr>";
  for (const ValidationFigure& f : ValidationFigures)
    s << "<tr><td>" << esc(f.what) << "</td><td class=\"n\">" << esc(f.doc_text) << "</td></tr>";
  s << "</table><p class=\"note\">Measured by the project's validation script; its full table and method are in "
       "the documentation (docs/validation.md).</p>";

  s << "<h3 id=\"uncertainty\">Uncertainty of this run</h3><p>Monte Carlo standard error of each sensor's daylight "
       "factor, relative to the daylight factor, over the sensors that receive daylight.</p>"
       "<table class=\"uncertainty-table\"><tr><th>case</th><th>grid</th><th>sensors with daylight</th>"
       "<th>RMS over the sensors (%)</th><th>largest (%)</th><th>accuracy target</th>"
       "<th>sensors whose DA verdict could change within 2 standard errors</th></tr>";
  for (const study::CaseResult& c : m.cases)
    for (const study::GridResult& g : c.grids) {
      if (!g.daylight_factor) continue;
      const study::DaylightFactorSummary& d = *g.daylight_factor;
      std::string target = "photon counts given by the project";
      if (d.accuracy)
        target = "95th percentile " + format_value(d.accuracy->reached_percent, Precision::DaylightFactor) +
                 " % (target " + format_value(d.accuracy->target_percent, Precision::DaylightFactor) + " %; " +
                 (d.accuracy->status == "not reachable by photons" ? "not reachable by photons; " : "") +
                 d.accuracy->stop_reason + " after " + std::to_string(d.accuracy->rounds) + " rounds)";
      s << "<tr><td>" << esc(case_label(c)) << "</td><td>" << esc(g.name) << "</td><td class=\"n\">"
        << d.sensors_with_daylight << "</td><td class=\"n\">"
        << format_value(d.rms_relative_stderr_percent, Precision::DaylightFactor) << "</td><td class=\"n\">"
        << format_value(d.max_relative_stderr_percent, Precision::DaylightFactor) << "</td><td>" << esc(target)
        << "</td><td class=\"n\">"
        << (g.annual && g.annual->da_verdicts_within_2_sigma ? std::to_string(*g.annual->da_verdicts_within_2_sigma)
                                                            : std::string("-"))
        << "</td></tr>";
    }
  s << "</table>" << accuracy_statements(m) << "</section>";
  return s.str();
}

}  // namespace dayphoton::report
