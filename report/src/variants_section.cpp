// The variants section: every case side by side per grid, with its difference from the base
// case; see report_sections.h.
#include <algorithm>
#include <functional>
#include <optional>
#include <sstream>

#include "dayphoton/report/report_format.h"
#include "report_sections.h"

namespace dayphoton::report {

namespace {

using study::GridResult;

struct Row {
  std::string label;
  Precision precision;
  std::string unit;
  std::function<std::optional<double>(const GridResult&)> value;
};

std::vector<Row> rows() {
  auto df = [](double study::DaylightFactorSummary::*f) {
    return [f](const GridResult& g) -> std::optional<double> {
      if (!g.daylight_factor) return std::nullopt;
      return (*g.daylight_factor).*f;
    };
  };
  auto annual = [](double study::AnnualSummary::*f) {
    return [f](const GridResult& g) -> std::optional<double> {
      if (!g.annual) return std::nullopt;
      return (*g.annual).*f;
    };
  };
  return {{"mean daylight factor", Precision::DaylightFactor, "%", df(&study::DaylightFactorSummary::mean_percent)},
          {"median daylight factor", Precision::DaylightFactor, "%", df(&study::DaylightFactorSummary::median_percent)},
          {"minimum daylight factor", Precision::DaylightFactor, "%", df(&study::DaylightFactorSummary::min_percent)},
          {"uniformity (min / mean DF)", Precision::Ratio, "", df(&study::DaylightFactorSummary::uniformity)},
          {"sDA (share of the area)", Precision::Percent, "%", annual(&study::AnnualSummary::sda_percent)},
          {"ASE (share of the area)", Precision::Percent, "%",
           [](const GridResult& g) -> std::optional<double> { return g.annual ? g.annual->ase_percent : std::nullopt; }},
          {"daylight autonomy, grid mean", Precision::Percent, "%", annual(&study::AnnualSummary::da_percent)},
          {"UDI achieved, grid mean", Precision::Percent, "%", annual(&study::AnnualSummary::udi_achieved_percent)},
          {"UDI exceeded, grid mean", Precision::Percent, "%", annual(&study::AnnualSummary::udi_above_original_percent)},
          {"mean illuminance, occupied hours", Precision::Illuminance, "lx",
           annual(&study::AnnualSummary::mean_occupied_lux)}};
}

const GridResult* find_grid(const study::CaseResult& c, const std::string& name) {
  for (const GridResult& g : c.grids)
    if (g.name == name) return &g;
  return nullptr;
}

}  // namespace

std::string variants_section(const study::ResultsModel& m) {
  if (m.cases.size() < 2) return {};
  const study::CaseResult& base = m.cases.front();
  std::ostringstream s;
  s << "<section id=\"variants\"><h2>Variants side by side</h2><p>Each case is the project with the changes listed "
       "below; sensors and settings are the same in every case. In brackets: the difference from the base case "
       "(daylight factor in points of %, shares in percentage points, illuminance in lx).</p>";
  s << "<ul class=\"changes\">";
  for (std::size_t k = 1; k < m.cases.size(); ++k) {
    const study::CaseResult& c = m.cases[k];
    std::string changes;
    for (const std::string& ch : c.changes) changes += (changes.empty() ? "" : "; ") + ch;
    s << "<li><strong>" << esc(case_label(c)) << "</strong>: "
      << esc(c.kind == "operated" ? "per hour the open or the shaded case, by the LM-83 blinds rule"
                                  : changes.empty() ? "no change" : changes)
      << "</li>";
  }
  s << "</ul>";
  const std::vector<Row> table = rows();
  for (const GridResult& bg : base.grids) {
    s << "<h3>Grid " << esc(bg.name) << "</h3><table class=\"variants-table\"><tr><th>metric</th><th>base</th>";
    for (std::size_t k = 1; k < m.cases.size(); ++k) s << "<th>" << esc(case_label(m.cases[k])) << "</th>";
    s << "</tr>";
    for (const Row& row : table) {
      const std::optional<double> b = row.value(bg);
      bool any = b.has_value();
      for (std::size_t k = 1; k < m.cases.size(); ++k)
        if (const GridResult* g = find_grid(m.cases[k], bg.name)) any = any || row.value(*g).has_value();
      if (!any) continue;
      s << "<tr><td>" << esc(row.label) << (row.unit.empty() ? "" : " (" + esc(row.unit) + ")") << "</td><td class=\"n\">"
        << format_value(b, row.precision) << "</td>";
      for (std::size_t k = 1; k < m.cases.size(); ++k) {
        const GridResult* g = find_grid(m.cases[k], bg.name);
        const std::optional<double> v = g ? row.value(*g) : std::nullopt;
        s << "<td class=\"n\">" << format_value(v, row.precision);
        if (v && b) s << " <span class=\"delta\">(" << format_delta(*v - *b, row.precision) << ")</span>";
        s << "</td>";
      }
      s << "</tr>";
    }
    // The EN 17037 level, as words, where any case computed it.
    auto level = [](const GridResult* g) {
      const std::string l = g && g->annual ? g->annual->en17037_level() : std::string();
      return l.empty() ? std::string("-") : l;
    };
    std::vector<std::string> levels{level(&bg)};
    for (std::size_t k = 1; k < m.cases.size(); ++k) levels.push_back(level(find_grid(m.cases[k], bg.name)));
    if (std::any_of(levels.begin(), levels.end(), [](const std::string& l) { return l != "-"; })) {
      s << "<tr><td>EN 17037 level</td>";
      for (const std::string& l : levels) s << "<td>" << esc(l) << "</td>";
      s << "</tr>";
    }
    s << "</table>";
  }
  // Materials a variant defines differently from the base.
  std::ostringstream diff;
  for (std::size_t k = 1; k < m.cases.size(); ++k)
    for (const study::MaterialSummary& vm : m.cases[k].materials) {
      const study::MaterialSummary* bm = nullptr;
      for (const study::MaterialSummary& x : base.materials)
        if (x.name == vm.name) bm = &x;
      if (bm && bm->type == vm.type && bm->reflectance == vm.reflectance && bm->transmittance == vm.transmittance &&
          bm->specularity == vm.specularity)
        continue;
      diff << "<tr><td>" << esc(case_label(m.cases[k])) << "</td><td>" << esc(vm.name) << "</td><td>"
           << (bm ? esc(bm->type) + " &#8594; " : std::string()) << esc(vm.type) << "</td><td class=\"n\">"
           << (bm ? format_value(bm->reflectance, Precision::Fraction) + " &#8594; " : "")
           << format_value(vm.reflectance, Precision::Fraction) << "</td><td class=\"n\">"
           << (bm ? format_value(bm->transmittance, Precision::Fraction) + " &#8594; " : "")
           << format_value(vm.transmittance, Precision::Fraction) << "</td></tr>";
    }
  if (!diff.str().empty())
    s << "<h3>Materials that differ from the base case</h3><table class=\"variant-materials\"><tr><th>case</th>"
         "<th>material</th><th>type</th><th>reflectance</th><th>visible transmittance</th></tr>"
      << diff.str() << "</table>";
  s << "</section>";
  return s.str();
}

}  // namespace dayphoton::report
