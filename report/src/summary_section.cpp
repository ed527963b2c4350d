// The summary and the verdicts sections; see report_sections.h. Values and verdicts are the
// model's (study/compliance_verdicts.h decides them); nothing is assessed here.
#include <sstream>

#include "dayphoton/report/report_format.h"
#include "report_sections.h"

namespace dayphoton::report {

namespace {

using study::GridResult;
using study::Verdict;

const Verdict* find_verdict(const GridResult& g, const std::string& standard_prefix, const std::string& criterion_prefix) {
  for (const Verdict& v : g.verdicts)
    if (v.standard.rfind(standard_prefix, 0) == 0 && v.criterion.rfind(criterion_prefix, 0) == 0) return &v;
  return nullptr;
}

/// A compact cell: the badge of a verdict ("pass", "fail", "n/a"), its note for LEED points.
std::string verdict_cell(const Verdict* v, bool show_note) {
  if (!v) return "<td>-</td>";
  const std::string text = v->outcome == "not assessed" ? "n/a" : show_note && !v->reason.empty() ? v->reason : v->outcome;
  return "<td title=\"" + esc(v->standard + " " + v->criterion + ": " + v->requirement +
                              (v->outcome == "not assessed" ? " (not assessed: " + v->reason + ")" : "")) +
         "\">" + verdict_badge(v->outcome, text) + "</td>";
}

/// The metric settings' labels of the first annual grid ("sDA300/50%", "ASE1000,250", "UDI 100-2000 lx").
struct Labels {
  std::string sda = "sDA", ase = "ASE", udi = "UDI achieved";
};
Labels labels(const study::ResultsModel& m) {
  Labels l;
  for (const study::CaseResult& c : m.cases)
    for (const GridResult& g : c.grids)
      if (g.annual) {
        const study::AnnualSummary& a = *g.annual;
        l.sda = "sDA" + format_value(a.da_threshold_lux, Precision::Illuminance) + "/" +
                format_value(100 * a.sda_time_fraction, Precision::Percent) + "%";
        l.ase = "ASE" + format_value(a.ase_threshold_lux, Precision::Illuminance) + "," +
                format_value(a.ase_hours, Precision::Illuminance);
        l.udi = "UDI " + format_value(a.udi_lower_lux, Precision::Illuminance) + "&#8211;" +
                format_value(a.udi_upper_original_lux, Precision::Illuminance) + " lx";
        return l;
      }
  return l;
}

}  // namespace

std::string summary_section(const study::ResultsModel& m) {
  const Labels l = labels(m);
  std::ostringstream s;
  s << "<section id=\"summary\"><h2>Summary</h2>";
  s << "<p class=\"lead\">"
    << (m.study == "annual" ? "Climate-based annual daylight study with daylight factors"
                            : "Daylight-factor study (CIE standard overcast sky)")
    << " of <strong>" << esc(m.title) << "</strong>";
  if (!m.site_name.empty()) s << ", site " << esc(m.site_name);
  std::size_t grids = 0;
  for (const study::CaseResult& c : m.cases) grids += c.grids.size();
  s << ": " << grids << (grids == 1 ? " sensor grid" : " sensor grids") << " in " << m.cases.size()
    << (m.cases.size() == 1 ? " case" : " cases") << ".</p>";
  s << "<table class=\"summary-table\"><tr><th>case</th><th>grid</th><th>sensors</th><th>mean DF (%)</th>"
       "<th>median DF (%)</th><th>"
    << l.sda << " (% of area)</th><th>" << l.ase << " (% of area)</th><th>" << l.udi
    << " (% of occupied hours)</th><th>EN 17037 level</th><th>LM-83 sDA</th><th>LM-83 ASE</th><th>LEED v4.1</th>"
       "<th>BREEAM Hea 01</th></tr>";
  for (const study::CaseResult& c : m.cases)
    for (const GridResult& g : c.grids) {
      const auto& df = g.daylight_factor;
      const auto& a = g.annual;
      s << "<tr><td>" << esc(case_label(c)) << "</td><td><a href=\"#" << grid_section_id(c, g) << "\">" << esc(g.name)
        << "</a>" << (g.orientation != study::GridOrientation::Horizontal ? " <span class=\"note\">(" +
                                                                               study::orientation_name(g.orientation) + ")</span>"
                                                                         : std::string())
        << "</td><td class=\"n\">" << g.positions_m.size() << "</td>";
      s << "<td class=\"n\">" << (df ? format_value(df->mean_percent, Precision::DaylightFactor) : "-")
        << "</td><td class=\"n\">" << (df ? format_value(df->median_percent, Precision::DaylightFactor) : "-") << "</td>";
      if (a) {
        const std::string level = a->en17037_level();
        s << "<td class=\"n\">" << format_value(a->sda_percent, Precision::Percent) << "</td><td class=\"n\">"
          << format_value(a->ase_percent, Precision::Percent) << "</td><td class=\"n\">"
          << format_value(a->udi_achieved_percent, Precision::Percent) << "</td><td>"
          << esc(g.orientation != study::GridOrientation::Horizontal ? "n/a" : level.empty() ? "-" : level) << "</td>";
      } else {
        s << "<td class=\"n\">-</td><td class=\"n\">-</td><td class=\"n\">-</td><td>-</td>";
      }
      s << verdict_cell(find_verdict(g, "IES LM-83", "sDA"), false) << verdict_cell(find_verdict(g, "IES LM-83", "ASE"), false)
        << verdict_cell(find_verdict(g, "LEED", "sDA"), true) << verdict_cell(find_verdict(g, "BREEAM", ""), false)
        << "</tr>";
    }
  s << "</table><p class=\"note\">DF: daylight factor under the CIE standard overcast sky. sDA and ASE: share of the "
       "grid's sensors (its area) meeting the criterion. UDI: grid mean share of occupied hours within the range. "
       "EN 17037: the highest daylight-provision level reached. Verdicts in detail, with their requirements: "
       "<a href=\"#verdicts\">Compliance</a>; n/a: not assessed.</p>";
  s << "<h3 id=\"not-assessed\">Not assessed</h3><ul class=\"not-assessed\">";
  for (const std::string& line : m.not_assessed) s << "<li>" << esc(line) << "</li>";
  for (const study::CaseResult& c : m.cases)
    for (const GridResult& g : c.grids)
      if (g.orientation != study::GridOrientation::Horizontal)
        s << "<li>" << esc(case_label(c)) << " / " << esc(g.name) << ": LM-83, LEED, EN 17037 and BREEAM verdicts, "
          << "since the grid is " << study::orientation_name(g.orientation)
          << " and these criteria are defined on horizontal work planes.</li>";
  s << "</ul></section>";
  return s.str();
}

std::string verdicts_section(const study::ResultsModel& m) {
  std::ostringstream s;
  s << "<section id=\"verdicts\"><h2>Compliance</h2><table class=\"verdict-table\"><tr><th>case</th><th>grid</th>"
       "<th>standard</th><th>criterion</th><th>requirement</th><th>value</th><th>result</th><th>remark</th></tr>";
  for (const study::CaseResult& c : m.cases)
    for (const GridResult& g : c.grids)
      for (const Verdict& v : g.verdicts) {
        std::string value = "-";
        if (v.value) {
          if (v.unit == "level") value = format_value(*v.value, Precision::Length) + " of 3";
          else if (v.standard.rfind("BREEAM", 0) == 0) value = format_value(*v.value, Precision::DaylightFactor) + " %";
          else value = format_value(*v.value, Precision::Percent) + " " + esc(v.unit);
        }
        s << "<tr><td>" << esc(case_label(c)) << "</td><td>" << esc(g.name) << "</td><td>" << esc(v.standard)
          << "</td><td>" << esc(v.criterion) << "</td><td>" << esc(v.requirement) << "</td><td class=\"n\">" << value
          << "</td><td>" << verdict_badge(v.outcome, v.outcome) << "</td><td>" << esc(v.reason) << "</td></tr>";
      }
  s << "</table><p class=\"note\">Sources: IES LM-83-12 sections 2.1.1 and 2.2.1; USGBC LEED v4.1 BD+C EQ credit "
       "Daylight, option 1, table 1; EN 17037:2018 clause 5.1 and annex A, table A.1 (climate-based method); BRE "
       "Global BREEAM UK New Construction 2014 Hea 01, tables 10 and 11 (offices and other building types, "
       "criterion (a)). Each verdict is for one grid: a rating scheme's credit depends on all of its relevant "
       "areas.</p></section>";
  return s.str();
}

}  // namespace dayphoton::report
