// report.html from a results model; see report_html.h for the sections and docs/report.md for
// what each plot shows. Everything is drawn here as inline SVG (plots, legends, axes) or as a
// PNG data: URI inside an SVG (the temporal map and the sky, one pixel per value).
#include "dayphoton/report/report_html.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <sstream>

#include "dayphoton/core/atomic_file.h"
#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/units.h"
#include "dayphoton/metrics/annual_metrics.h"
#include "dayphoton/report/colour_scale.h"
#include "dayphoton/report/plan_picture.h"
#include "dayphoton/study/image_files.h"
#include "dayphoton/report/report_format.h"
#include "dayphoton/report/temporal_map.h"
#include "report_sections.h"

#ifndef DAYPHOTON_VERSION
#define DAYPHOTON_VERSION "unknown"
#endif

namespace dayphoton::report {

namespace {

/// A point-in-time case against the accuracy target, in words (docs/report.md): "0.8 % &#8804; 1 %:
/// met", "3.1 % &gt; 1 %: direct rays limit (direct sun)", or "no target" for a run with photon
/// counts, "not stated" for files made before it was stated.
std::string point_in_time_accuracy_words(const study::PointInTimeSummary& p) {
  if (!p.accuracy) return p.rms_relative_stderr_percent ? "no target" : "not stated";
  const study::PointInTimeSummary::AccuracyReached& a = *p.accuracy;
  const std::string reached = format_value(a.reached_percent, Precision::DaylightFactor) + " %";
  const std::string target = format_value(a.target_percent, Precision::DaylightFactor) + " %";
  if (a.status == "met") return reached + " &#8804; " + target + ": met";
  return reached + " &gt; " + target + ": " + esc(a.stop_reason) +
         (a.limiting_part.empty() ? std::string() : " (" + esc(a.limiting_part) + ")");
}


namespace fs = std::filesystem;
using study::AnnualSummary;
using study::GridResult;
using study::ResultsModel;
using study::base64;
using study::encode_png;
using study::read_exr;

std::string join(const std::string& dir, const std::string& name) { return (fs::path(dir) / name).string(); }

std::string num(double v, int decimals) {
  if (!std::isfinite(v)) return "-";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, v);
  std::string s = buffer;
  if (s.find_first_not_of("-0.") == std::string::npos && s[0] == '-') s.erase(0, 1);  // no "-0.0"
  return s;
}

/// A tick label: integers plainly, otherwise up to 2 decimals without trailing zeros.
std::string tick(double v) {
  if (std::abs(v - std::round(v)) < 1e-9 * std::max(1.0, std::abs(v))) {
    if (std::abs(v) >= 1000) {
      char buffer[32];
      std::snprintf(buffer, sizeof buffer, "%.0f", v);
      std::string s = buffer, out;
      const int n = static_cast<int>(s.size());
      for (int i = 0; i < n; ++i) {
        out += s[static_cast<std::size_t>(i)];
        if ((n - 1 - i) % 3 == 0 && i != n - 1 && s[static_cast<std::size_t>(i)] != '-') out += "&#8201;";
      }
      return out;
    }
    return num(v, 0);
  }
  std::string s = num(v, 2);
  s.erase(s.find_last_not_of('0') + 1);
  if (s.back() == '.') s.pop_back();
  return s;
}

/// A threshold as it appears in metric names (metrics.csv columns): shortest form, "2000", "250.5".
std::string key_number(double v) {
  std::string s = num(v, 6);
  s.erase(s.find_last_not_of('0') + 1);
  if (s.back() == '.') s.pop_back();
  return s;
}

/// Element ids: letters, digits, '-' and '_' only.
std::string id_part(const std::string& s) {
  std::string out;
  for (char c : s) out += (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_') ? c : '_';
  return out;
}

// ---- inputs -----------------------------------------------------------------------------

struct GridData {
  std::string case_kind;  ///< "base", "variant", "operated"
  std::string case_name;  ///< "" for the base case, else the variant or "operated (open/shaded)"
  std::vector<std::string> changes;  ///< a variant's: what it changes
  const GridResult* grid = nullptr;
  std::string name;
  std::string folder;  ///< relative to the results folder
  std::string folder_path;  ///< inside the results folder, for the reader
  std::string id;
  std::vector<Vec3> positions;
  std::optional<std::vector<double>> df, da, udi, autonomous;
  std::optional<metrics::IlluminanceTable> illuminance;
  std::vector<std::string> problems;
  PlanGeometry plan;  ///< outline, openings and daylight systems near the grid (plan_picture.h)

  std::string title() const { return case_name.empty() ? name : case_name + " / " + name; }
  const AnnualSummary* annual() const { return grid->annual ? &*grid->annual : nullptr; }
};

/// A grid of the model with the values the report draws, read through the model's typed
/// reader (study::read_quantity_values); what cannot be read is listed as a problem.
GridData load_grid(const std::string& results_dir, const study::CaseResult& c, const GridResult& grid) {
  GridData g;
  g.case_kind = c.kind;
  g.case_name = c.name;
  g.changes = c.changes;
  g.grid = &grid;
  g.name = grid.name;
  g.folder = grid.folder;
  g.folder_path = (fs::path(results_dir) / grid.folder).string();
  g.id = grid_section_id(c, grid);
  g.positions = grid.positions_m;
  // The geometry the grid PNGs draw, chosen by the same rule (what is near the grid).
  g.plan = plan_geometry(c, grid);
  auto values = [&](const char* kind, std::optional<std::vector<double>>& out) {
    const study::SensorQuantity* q = grid.find_quantity(kind);
    if (!q) return;
    try {
      out = study::read_quantity_values(results_dir, grid, *q);
    } catch (const std::exception& e) {
      g.problems.push_back(e.what());
    }
  };
  values("daylight_factor", g.df);
  values("da", g.da);
  values("udi_achieved", g.udi);
  values("udi_autonomous", g.autonomous);
  if (grid.has_illuminance_table) {
    try {
      g.illuminance = study::read_illuminance_table(results_dir, grid);  // checks the sensor count
    } catch (const std::exception& e) {
      g.problems.push_back(e.what());
    }
  }
  return g;
}

// ---- SVG pieces -------------------------------------------------------------------------

/// Per-report state: the counter that keeps gradient ids unique within one page.
struct PageIds {
  int gradients = 0;
};

/// A vertical legend: gradient bar with ticks, the quantity and unit on top.
std::string legend_svg(const ColourScale& scale, PageIds& page) {
  const int id = ++page.gradients;
  const double top = 28, height = 220, left = 8, bar = 18;
  std::ostringstream s;
  s << "<svg class=\"plot legend\" width=\"110\" height=\"" << (top + height + 20) << "\" role=\"img\" aria-label=\""
    << esc(scale.quantity) << " legend\">";
  s << "<defs><linearGradient id=\"lg" << id << "\" x1=\"0\" y1=\"1\" x2=\"0\" y2=\"0\">";
  for (int i = 0; i <= 8; ++i)
    s << "<stop offset=\"" << num(i / 8.0, 3) << "\" stop-color=\"" << hex_colour(viridis(i / 8.0)) << "\"/>";
  s << "</linearGradient></defs>";
  s << "<text x=\"" << left << "\" y=\"12\" class=\"lt\">" << esc(scale.unit) << "</text>";
  s << "<rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << bar << "\" height=\"" << height
    << "\" fill=\"url(#lg" << id << ")\" stroke=\"#444\" stroke-width=\"0.5\"/>";
  const std::vector<double> ticks = scale.ticks();
  for (std::size_t i = 0; i < ticks.size(); ++i) {
    const double y = top + height * (1 - scale.position(ticks[i]));
    std::string label = tick(ticks[i]);
    if (i == 0 && scale.min > 0 && !scale.logarithmic) label = "&#8804;" + label;
    if (i + 1 == ticks.size()) label = "&#8805;" + label;
    if (i == 0 && scale.logarithmic) label = "&#8804;" + label;
    s << "<line x1=\"" << left + bar << "\" x2=\"" << left + bar + 5 << "\" y1=\"" << num(y, 1) << "\" y2=\""
      << num(y, 1) << "\" stroke=\"#444\"/>";
    s << "<text x=\"" << left + bar + 8 << "\" y=\"" << num(y + 4, 1) << "\" class=\"lt\">" << label << "</text>";
  }
  s << "</svg>";
  return s.str();
}

/// Plan frame: image axes of the lattice (columns along the axis closest to east, rows toward
/// the south), or world x / -y for sensors not on a lattice.
struct Frame {
  Vec3 origin, u{1, 0, 0}, v{0, -1, 0};
  double px_per_m = 40, margin = 34, min_u = 0, min_v = 0;
  double x(const Vec3& p) const { return margin + (dot(p - origin, u) - min_u) * px_per_m; }
  double y(const Vec3& p) const { return margin + (dot(p - origin, v) - min_v) * px_per_m; }
};

/// The grid PNGs' system colours (plan_picture.h) as CSS.
const std::string SystemFillCss = hex_colour({SystemFill[0], SystemFill[1], SystemFill[2]});
const std::string SystemEdgeCss = hex_colour({SystemEdge[0], SystemEdge[1], SystemEdge[2]});

std::string polygon_points(const Frame& f, const std::vector<Vec3>& poly) {
  std::ostringstream s;
  for (const Vec3& p : poly) s << num(f.x(p), 1) << ',' << num(f.y(p), 1) << ' ';
  return s.str();
}

/// A false-colour plan of per-sensor values with the room outline, windows, north arrow and a
/// 1 m scale bar; value labels in the cells when they are large enough.
std::string plan_svg(const GridData& g, const study::SensorLattice& lattice, const std::vector<double>& values,
                     const ColourScale& scale, Precision precision, const std::string& what) {
  Frame f;
  if (lattice.regular) {
    f.origin = lattice.origin_m;
    f.u = lattice.column_step_m / lattice.spacing_m;
    f.v = lattice.row_step_m / lattice.spacing_m;
  } else if (!g.positions.empty()) {
    f.origin = g.positions[0];
  }
  // Extent over cells, outline and windows.
  const double half = lattice.regular ? 0.5 * lattice.spacing_m : 0.1;
  double lo_u = std::numeric_limits<double>::infinity(), hi_u = -lo_u, lo_v = lo_u, hi_v = -lo_u;
  auto extend = [&](const Vec3& p, double pad) {
    const double a = dot(p - f.origin, f.u), b = dot(p - f.origin, f.v);
    lo_u = std::min(lo_u, a - pad);
    hi_u = std::max(hi_u, a + pad);
    lo_v = std::min(lo_v, b - pad);
    hi_v = std::max(hi_v, b + pad);
  };
  for (const Vec3& p : g.positions) extend(p, half);
  for (const Vec3& p : g.plan.outline) extend(p, 0);
  for (const auto& w : g.plan.openings)
    for (const Vec3& p : w) extend(p, 0);
  for (const auto& w : g.plan.systems)
    for (const Vec3& p : w) extend(p, 0);
  if (!std::isfinite(lo_u)) lo_u = hi_u = lo_v = hi_v = 0;
  const double span_u = std::max(hi_u - lo_u, 0.5), span_v = std::max(hi_v - lo_v, 0.5);
  f.px_per_m = std::min({460.0 / span_u, 460.0 / span_v, 90.0});
  f.min_u = lo_u;
  f.min_v = lo_v;
  const double width = 2 * f.margin + span_u * f.px_per_m, height = 2 * f.margin + span_v * f.px_per_m + 10;

  std::ostringstream s;
  s << "<svg class=\"plot plan\" width=\"" << num(width, 0) << "\" height=\"" << num(height, 0) << "\" viewBox=\"0 0 "
    << num(width, 0) << ' ' << num(height, 0) << "\" role=\"img\" aria-label=\"" << esc(what) << " plan of "
    << esc(g.title()) << "\">";
  if (g.plan.outline.size() >= 3)
    s << "<polygon points=\"" << polygon_points(f, g.plan.outline)
      << "\" fill=\"#f2f2f2\" stroke=\"#222\" stroke-width=\"2\"/>";
  const double cell = lattice.regular ? lattice.spacing_m * f.px_per_m : 0;
  const bool labels = lattice.regular && cell >= 26 && values.size() <= 800;
  for (std::size_t i = 0; i < values.size() && i < g.positions.size(); ++i) {
    const auto c = scale.colour(values[i]);
    const double cx = f.x(g.positions[i]), cy = f.y(g.positions[i]);
    if (lattice.regular) {
      s << "<rect x=\"" << num(cx - cell / 2, 1) << "\" y=\"" << num(cy - cell / 2, 1) << "\" width=\"" << num(cell, 1)
        << "\" height=\"" << num(cell, 1) << "\" fill=\"" << hex_colour(c) << "\"><title>sensor " << i << ": "
        << format_value(values[i], precision) << ' ' << esc(scale.unit) << "</title></rect>";
      if (labels)
        s << "<text x=\"" << num(cx, 1) << "\" y=\"" << num(cy + 3.5, 1) << "\" class=\"cv\" fill=\""
          << (scale.position(values[i]) > 0.62 ? "#000" : "#fff") << "\">" << format_value(values[i], precision)
          << "</text>";
    } else {
      s << "<circle cx=\"" << num(cx, 1) << "\" cy=\"" << num(cy, 1) << "\" r=\"5\" fill=\"" << hex_colour(c)
        << "\" stroke=\"#333\" stroke-width=\"0.5\"><title>sensor " << i << ": " << format_value(values[i], precision) << ' '
        << esc(scale.unit) << "</title></circle>";
    }
  }
  if (g.plan.outline.size() >= 3)
    s << "<polygon points=\"" << polygon_points(f, g.plan.outline) << "\" fill=\"none\" stroke=\"#222\" stroke-width=\"2\"/>";
  // Outdoor daylight systems (shelves, louvres, panels) projected onto the plan: half-transparent
  // grey with a dark edge, as on the grid PNGs (plan_picture.h SystemFill, SystemEdge).
  for (const auto& sys : g.plan.systems)
    s << "<polygon class=\"system\" points=\"" << polygon_points(f, sys) << "\" fill=\"" << SystemFillCss
      << "\" fill-opacity=\"" << num(SystemFill[3] / 255.0, 2) << "\" stroke=\"" << SystemEdgeCss
      << "\" stroke-width=\"1.5\"><title>daylight system</title></polygon>";
  for (const auto& w : g.plan.openings)
    s << "<polygon class=\"window\" points=\"" << polygon_points(f, w)
      << "\" fill=\"#7fc8ff\" stroke=\"#1565c0\" stroke-width=\"5\" stroke-linejoin=\"round\"><title>window</title></polygon>";
  // North arrow (the world +Y direction in the plan frame), if north lies in the plane.
  const double nu = f.u.y, nv = f.v.y, nl = std::sqrt(nu * nu + nv * nv);
  if (nl > 0.3) {
    const double ax = width - 20, ay = 34, dx = nu / nl * 12, dy = nv / nl * 12;
    s << "<line x1=\"" << num(ax - dx, 1) << "\" y1=\"" << num(ay - dy, 1) << "\" x2=\"" << num(ax + dx, 1)
      << "\" y2=\"" << num(ay + dy, 1) << "\" stroke=\"#000\" stroke-width=\"2\" marker-end=\"url(#arrowhead)\"/>";
    s << "<text x=\"" << num(ax + dx * 2.1, 1) << "\" y=\"" << num(ay + dy * 2.1 + 4, 1)
      << "\" class=\"lt\" text-anchor=\"middle\">N</text>";
  }
  // 1 m scale bar.
  const double sy = height - 12;
  s << "<line x1=\"" << f.margin << "\" y1=\"" << num(sy, 1) << "\" x2=\"" << num(f.margin + f.px_per_m, 1) << "\" y2=\""
    << num(sy, 1) << "\" stroke=\"#000\" stroke-width=\"2\"/><text x=\"" << num(f.margin + f.px_per_m + 6, 1)
    << "\" y=\"" << num(sy + 4, 1) << "\" class=\"lt\">1 m</text>";
  s << "</svg>";
  return s.str();
}

/// A histogram of `values` over `edges` (the last bin open above), bars coloured by the scale;
/// each value counts its sensor's area when `area_m2` is given (GridResult::area_m2).
std::string histogram_svg(const std::vector<double>& values, const std::vector<double>& edges,
                          const ColourScale& scale, const std::string& x_label, const std::string& what,
                          const std::vector<double>& area_m2) {
  const std::size_t bins = edges.size();  // bin i = [edges[i], edges[i+1]); last = [edges.back(), inf)
  const bool weighted = area_m2.size() == values.size() && !area_m2.empty();
  std::vector<double> counts(bins, 0);
  double total = 0;
  for (std::size_t i = 0; i < values.size(); ++i) {
    std::size_t b = 0;
    while (b + 1 < bins && values[i] >= edges[b + 1]) ++b;
    const double w = weighted ? area_m2[i] : 1.0;
    counts[b] += w;
    total += w;
  }
  const double n = weighted ? (total > 0 ? total : 1.0) : std::max<double>(1, static_cast<double>(values.size()));
  double peak = 0;
  for (double& c : counts) {
    c = 100 * c / n;
    peak = std::max(peak, c);
  }
  const double ymax = std::max(10.0, std::ceil(peak / 10) * 10);
  const double left = 46, top = 14, w = 380, h = 170, bw = w / static_cast<double>(bins);
  std::ostringstream s;
  s << "<svg class=\"plot histogram\" width=\"" << left + w + 16 << "\" height=\"" << top + h + 46
    << "\" role=\"img\" aria-label=\"" << esc(what) << "\">";
  for (int k = 0; k <= 5; ++k) {
    const double v = ymax * k / 5, y = top + h - h * v / ymax;
    s << "<line x1=\"" << left << "\" x2=\"" << left + w << "\" y1=\"" << num(y, 1) << "\" y2=\"" << num(y, 1)
      << "\" stroke=\"#ddd\"/><text x=\"" << left - 5 << "\" y=\"" << num(y + 4, 1)
      << "\" class=\"lt\" text-anchor=\"end\">" << tick(v) << "</text>";
  }
  for (std::size_t b = 0; b < bins; ++b) {
    const double centre = b + 1 < bins ? 0.5 * (edges[b] + edges[b + 1]) : edges[b];
    const double bh = h * counts[b] / ymax;
    s << "<rect x=\"" << num(left + b * bw + 1, 1) << "\" y=\"" << num(top + h - bh, 1) << "\" width=\""
      << num(bw - 2, 1) << "\" height=\"" << num(std::max(bh, 0.0), 1) << "\" fill=\""
      << hex_colour(scale.colour(centre)) << "\"><title>" << tick(edges[b])
      << (b + 1 < bins ? "&#8211;" + tick(edges[b + 1]) : std::string(" and above")) << ' ' << esc(scale.unit) << ": "
      << format_value(counts[b], Precision::Percent) << (weighted ? " % of the area" : " % of sensors")
      << "</title></rect>";
  }
  const std::size_t label_every = bins > 12 ? 2 : 1;
  for (std::size_t b = 0; b < bins; b += label_every)
    s << "<text x=\"" << num(left + b * bw, 1) << "\" y=\"" << top + h + 14 << "\" class=\"lt\" text-anchor=\"middle\">"
      << tick(edges[b]) << "</text>";
  s << "<line x1=\"" << left << "\" x2=\"" << left + w << "\" y1=\"" << top + h << "\" y2=\"" << top + h
    << "\" stroke=\"#000\"/>";
  s << "<text x=\"" << left + w / 2 << "\" y=\"" << top + h + 34 << "\" class=\"lt\" text-anchor=\"middle\">"
    << esc(x_label) << "</text>";
  s << "<text x=\"12\" y=\"" << top + h / 2 << "\" class=\"lt\" text-anchor=\"middle\" transform=\"rotate(-90 12 "
    << top + h / 2 << ")\">sensors (%)</text>";
  s << "</svg>";
  return s.str();
}

/// Stacked bars of the grid's mean time shares in both UDI conventions.
std::string udi_bars_svg(const AnnualSummary& a) {
  const double lo = a.udi_lower_lux, up1 = a.udi_upper_original_lux, x = a.da_threshold_lux, up2 = a.udi_upper_revised_lux;
  struct Part {
    std::string label;
    double share;
    const char* colour;
  };
  const std::vector<Part> original{{"fell short (&lt; " + tick(lo) + " lx)", a.udi_below_percent, "#9e9ac8"},
                                   {"achieved (" + tick(lo) + "&#8211;" + tick(up1) + " lx)", a.udi_achieved_percent, "#41ab5d"},
                                   {"exceeded (&gt; " + tick(up1) + " lx)", a.udi_above_original_percent, "#fd8d3c"}};
  const std::vector<Part> revised{{"fell short (&lt; " + tick(lo) + " lx)", a.udi_below_percent, "#9e9ac8"},
                                  {"supplementary (" + tick(lo) + "&#8211;" + tick(x) + " lx)", a.udi_supplementary_percent, "#c7e9c0"},
                                  {"autonomous (" + tick(x) + "&#8211;" + tick(up2) + " lx)", a.udi_autonomous_percent, "#41ab5d"},
                                  {"exceeded (&gt; " + tick(up2) + " lx)", a.udi_above_revised_percent, "#fd8d3c"}};
  const double left = 215, w = 420, bar = 26;
  std::ostringstream s;
  s << "<svg class=\"plot udi\" width=\"" << left + w + 20 << "\" height=\"250\" role=\"img\" "
       "aria-label=\"UDI time shares, both conventions\">";
  auto draw = [&](const std::vector<Part>& parts, double y, const std::string& title) {
    s << "<text x=\"0\" y=\"" << y + 17 << "\" class=\"lt\">" << title << "</text>";
    double at = left;
    for (const Part& p : parts) {
      const double pw = w * std::clamp(p.share, 0.0, 100.0) / 100;
      s << "<rect x=\"" << num(at, 1) << "\" y=\"" << y << "\" width=\"" << num(pw, 1) << "\" height=\"" << bar
        << "\" fill=\"" << p.colour << "\"><title>" << p.label << ": " << format_value(p.share, Precision::Percent) << " %</title></rect>";
      if (pw > 34)
        s << "<text x=\"" << num(at + pw / 2, 1) << "\" y=\"" << y + 17 << "\" class=\"cv\" fill=\"#000\">"
          << format_value(p.share, Precision::Percent) << "</text>";
      at += pw;
    }
  };
  draw(original, 10, "original (Nabil &amp; Mardaljevic)");
  draw(revised, 50, "revised (Mardaljevic)");
  for (int k = 0; k <= 4; ++k)
    s << "<text x=\"" << left + w * k / 4 << "\" y=\"96\" class=\"lt\" text-anchor=\"middle\">" << k * 25
      << "</text>";
  s << "<text x=\"" << left + w / 2 << "\" y=\"112\" class=\"lt\" text-anchor=\"middle\">share of occupied hours, grid mean (%)</text>";
  // Key: one colour per kind of bin.
  const std::vector<Part> key{{"fell short", 0, "#9e9ac8"},
                              {"supplementary (revised)", 0, "#c7e9c0"},
                              {"achieved (original) / autonomous (revised)", 0, "#41ab5d"},
                              {"exceeded", 0, "#fd8d3c"}};
  double ky = 130;
  for (const Part& p : key) {
    s << "<rect x=\"" << left << "\" y=\"" << ky << "\" width=\"14\" height=\"14\" fill=\"" << p.colour
      << "\"/><text x=\"" << left + 20 << "\" y=\"" << ky + 11 << "\" class=\"lt\">" << p.label << "</text>";
    ky += 22;
  }
  s << "</svg>";
  return s.str();
}

/// The occupancy schedule as " (schedule)" for weekly and hourly schedules; "" for the
/// daily window (shown on the temporal map).
std::string occupancy_note(const study::OccupancySummary& occupancy) {
  if (occupancy.kind == "daily") return "";
  return " (" + esc(occupancy.description) + ")";
}

/// Day of year x hour map of the grid's mean illuminance (over the sensors' areas when
/// `area_m2` is given); occupancy window dashed.
std::string temporal_svg(const metrics::IlluminanceTable& table, double occupancy_start_h, double occupancy_end_h,
                         const ColourScale& scale, const std::vector<double>& area_m2) {
  // Days in file order; one slot per clock hour (sub-hourly records are averaged): the map of
  // temporal_map.png (report/temporal_map.h).
  const TemporalMap map = temporal_map(table, area_m2);
  const std::vector<std::pair<int, int>>& days = map.days;
  const int nd = std::max<int>(1, static_cast<int>(days.size()));
  // Pixel (day, hour) with hour 0 at the bottom; below 1 lx (night) grey.
  RgbaImage image(nd, 24, {255, 255, 255, 0});
  for (int d = 0; d < static_cast<int>(days.size()); ++d)
    for (int h = 0; h < 24; ++h) {
      const double v = map.at(d, h);
      if (std::isnan(v)) continue;
      const auto c = v < 1 ? std::array<std::uint8_t, 3>{60, 60, 60} : scale.colour(v);
      image.at(d, 23 - h) = {c[0], c[1], c[2], 255};
    }
  const double left = 44, top = 10, w = 2 * nd, h = 24 * 9;
  std::ostringstream s;
  s << "<svg class=\"plot temporal\" width=\"" << left + w + 12 << "\" height=\"" << top + h + 40 << "\" viewBox=\"0 0 "
    << left + w + 12 << ' ' << top + h + 40 << "\" role=\"img\" aria-label=\"temporal map of the mean illuminance\">";
  s << "<image x=\"" << left << "\" y=\"" << top << "\" width=\"" << w << "\" height=\"" << h
    << "\" preserveAspectRatio=\"none\" style=\"image-rendering:pixelated\" href=\"data:image/png;base64,"
    << base64(encode_png(image)) << "\"/>";
  s << "<rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << w << "\" height=\"" << h
    << "\" fill=\"none\" stroke=\"#000\"/>";
  for (double oh : {occupancy_start_h, occupancy_end_h}) {
    if (!std::isfinite(oh)) continue;  // a weekly or hourly schedule: no one daily window to draw
    const double y = top + h - h * oh / 24;
    s << "<line x1=\"" << left << "\" x2=\"" << left + w << "\" y1=\"" << num(y, 1) << "\" y2=\"" << num(y, 1)
      << "\" stroke=\"#fff\" stroke-dasharray=\"4 3\" stroke-width=\"1\"/>";
  }
  for (int hh = 0; hh <= 24; hh += 6) {
    const double y = top + h - h * hh / 24.0;
    s << "<text x=\"" << left - 6 << "\" y=\"" << num(y + 4, 1) << "\" class=\"lt\" text-anchor=\"end\">"
      << (hh < 10 ? "0" : "") << hh << ":00</text>";
  }
  static const char* const months[] = {"Jan", "Feb", "Mar", "Apr", "May", "Jun", "Jul", "Aug", "Sep", "Oct", "Nov", "Dec"};
  for (int d = 0; d < static_cast<int>(days.size()); ++d)
    if (days[static_cast<std::size_t>(d)].second == 1) {
      const double x = left + 2 * d;
      s << "<line x1=\"" << x << "\" x2=\"" << x << "\" y1=\"" << top + h << "\" y2=\"" << top + h + 5
        << "\" stroke=\"#000\"/><text x=\"" << x + 3 << "\" y=\"" << top + h + 17 << "\" class=\"lt\">"
        << months[(days[static_cast<std::size_t>(d)].first - 1) % 12] << "</text>";
    }
  s << "<text x=\"" << left + w / 2 << "\" y=\"" << top + h + 34 << "\" class=\"lt\" text-anchor=\"middle\">day of year; "
       "hour of local standard time on the left; dashed: occupied hours</text>";
  s << "</svg>";
  return s.str();
}

/// The sky fisheye (sky_mean.exr or sky_hour.exr) as a false-colour luminance picture with the
/// compass points (east left: the sky seen from below).
std::string sky_svg(const FloatImage& sky, const ColourScale& scale, const std::string& what) {
  const double size = 260, pad = 22;
  std::ostringstream s;
  s << "<svg class=\"plot sky\" width=\"" << size + 2 * pad << "\" height=\"" << size + 2 * pad
    << "\" role=\"img\" aria-label=\"" << esc(what) << "\">";
  s << "<image x=\"" << pad << "\" y=\"" << pad << "\" width=\"" << size << "\" height=\"" << size
    << "\" href=\"data:image/png;base64," << base64(encode_png(luminance_false_colour(sky, scale))) << "\"/>";
  s << "<circle cx=\"" << pad + size / 2 << "\" cy=\"" << pad + size / 2 << "\" r=\"" << size / 2
    << "\" fill=\"none\" stroke=\"#000\"/>";
  s << "<text x=\"" << pad + size / 2 << "\" y=\"15\" class=\"lt\" text-anchor=\"middle\">N</text>";
  s << "<text x=\"" << pad + size / 2 << "\" y=\"" << size + 2 * pad - 5 << "\" class=\"lt\" text-anchor=\"middle\">S</text>";
  s << "<text x=\"6\" y=\"" << pad + size / 2 + 4 << "\" class=\"lt\">E</text>";
  s << "<text x=\"" << size + 2 * pad - 14 << "\" y=\"" << pad + size / 2 + 4 << "\" class=\"lt\">W</text>";
  s << "</svg>";
  return s.str();
}

// ---- sections ---------------------------------------------------------------------------

/// Rows of (label, value), both already HTML (escape data with esc() before).
std::string key_value_table(const std::vector<std::pair<std::string, std::string>>& rows) {
  std::ostringstream s;
  s << "<table class=\"kv\">";
  for (const auto& [k, v] : rows) s << "<tr><th>" << k << "</th><td>" << v << "</td></tr>";
  s << "</table>";
  return s.str();
}

/// The grid means of the annual metrics, labelled, in the order of metrics.csv's columns:
/// (label, value, unit, precision).
struct MetricRow {
  std::string label;
  double value;
  std::string unit;
  Precision precision;
};
std::vector<MetricRow> metric_rows(const AnnualSummary& a) {
  const std::string x = key_number(a.da_threshold_lux), low = key_number(a.udi_lower_lux),
                    up1 = key_number(a.udi_upper_original_lux), up2 = key_number(a.udi_upper_revised_lux);
  return {{"daylight autonomy DA" + x + ": E &#8805; " + x + " lx", a.da_percent, "%", Precision::Percent},
          {"continuous daylight autonomy cDA" + x + " (mean of min(1, E/" + x + " lx))", a.cda_percent, "%", Precision::Percent},
          {"DAmax: share of occupied hours above 10 times the DA threshold", a.da_max_percent, "%", Precision::Percent},
          {"UDI fell short: E &lt; " + low + " lx", a.udi_below_percent, "%", Precision::Percent},
          {"UDI achieved (original): " + low + "&#8211;" + up1 + " lx", a.udi_achieved_percent, "%", Precision::Percent},
          {"UDI exceeded: E &gt; " + up1 + " lx", a.udi_above_original_percent, "%", Precision::Percent},
          {"revised UDI supplementary: " + low + "&#8211;" + x + " lx", a.udi_supplementary_percent, "%", Precision::Percent},
          {"revised UDI autonomous: " + x + "&#8211;" + up2 + " lx", a.udi_autonomous_percent, "%", Precision::Percent},
          {"UDI exceeded: E &gt; " + up2 + " lx", a.udi_above_revised_percent, "%", Precision::Percent},
          {"mean illuminance, occupied hours", a.mean_occupied_lux, "lx", Precision::Illuminance}};
}

/// The key of a plan's drawn geometry: one entry per kind of thing the plan shows (the grid's
/// outline, windows, daylight systems); empty when it shows none.
std::string plan_key_svg(const GridData& g) {
  std::vector<std::pair<std::string, std::string>> entries;  // (symbol, label)
  if (g.plan.outline.size() >= 3)
    entries.emplace_back("<rect x=\"4\" y=\"-9\" width=\"22\" height=\"12\" fill=\"#f2f2f2\" stroke=\"#222\" "
                         "stroke-width=\"2\"/>",
                         g.plan.plan ? "room / grid outline" : "wall / grid outline");
  if (!g.plan.openings.empty())
    entries.emplace_back("<line x1=\"4\" y1=\"-3\" x2=\"26\" y2=\"-3\" stroke=\"#1565c0\" stroke-width=\"5\"/>",
                         "window or opening");
  if (!g.plan.systems.empty())
    entries.emplace_back(std::string("<rect x=\"4\" y=\"-9\" width=\"22\" height=\"12\" fill=\"") + SystemFillCss +
                             "\" fill-opacity=\"" + num(SystemFill[3] / 255.0, 2) + "\" stroke=\"" + SystemEdgeCss +
                             "\" stroke-width=\"1.5\"/>",
                         "daylight system (outdoors, seen from above)");
  if (entries.empty()) return "";
  std::ostringstream s;
  const int row = 20;
  s << "<svg class=\"plot key\" width=\"300\" height=\"" << row * static_cast<int>(entries.size()) + 8
    << "\" role=\"img\" aria-label=\"key of the plan\">";
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const int y = row * static_cast<int>(i) + 18;
    s << "<g class=\"key-entry\" transform=\"translate(0," << y << ")\">" << entries[i].first << "<text x=\"34\" y=\"1\" "
      << "class=\"lt\">" << esc(entries[i].second) << "</text></g>";
  }
  s << "</svg>";
  return s.str();
}

std::string plan_block(const GridData& g, const study::SensorLattice& lattice, const std::vector<double>& values,
                       const ColourScale& scale, Precision precision, const std::string& caption, PageIds& page) {
  std::ostringstream s;
  s << "<figure class=\"planfig\"><div class=\"row\">" << plan_svg(g, lattice, values, scale, precision, caption)
    << "<div class=\"keys\">" << legend_svg(scale, page) << plan_key_svg(g) << "</div></div><figcaption>" << caption
    << "</figcaption></figure>";
  return s.str();
}

std::string grid_section(const GridData& g, PageIds& page) {
  std::ostringstream s;
  // Variant names are portable folder names, so only the operated case starts with "operated (".
  const bool operated = g.case_kind == "operated";
  s << "<section class=\"grid\" id=\"" << g.id << "\"><h2>"
    << (g.case_name.empty() ? "Grid " : operated ? "Operated shading " : "Variant ")
    << esc(g.title()) << "</h2>";
  const double spacing = g.grid->spacing_m > 0 ? g.grid->spacing_m : g.grid->lattice.regular ? g.grid->lattice.spacing_m : 0;
  s << "<p class=\"meta\">" << g.positions.size() << " sensors"
    << (spacing > 0 ? ", spacing " + format_value(spacing, Precision::Length) + " m" : std::string()) << ", "
    << study::orientation_name(g.grid->orientation);
  if (!g.grid->area_m2.empty()) {
    double total_m2 = 0;
    for (double a : g.grid->area_m2) total_m2 += a;
    s << "; each sensor weighted by the area it stands for (" << format_value(total_m2, Precision::Length)
      << " m&#178; in all): every share and mean below is of the area";
  }
  if (!g.changes.empty()) {
    std::string changes;
    for (const std::string& c : g.changes) changes += (changes.empty() ? "" : ", ") + c;
    s << "; changes: " << esc(changes);
  }
  s << "</p>";
  for (const std::string& p : g.problems) s << "<p class=\"problem\">could not read: " << esc(p) << "</p>";
  const study::SensorLattice& lattice = g.grid->lattice;
  const AnnualSummary* annual = g.annual();
  // Sensors standing for unequal areas: every share and mean is of the area.
  const bool by_area = !g.grid->area_m2.empty();
  const char* const shares_of = by_area ? "the area" : "sensors";

  // Daylight factor.
  s << "<div class=\"part\" id=\"" << g.id << "-df\"><h3>Daylight factor (CIE overcast sky)</h3>";
  if (g.df && g.grid->daylight_factor) {
    const std::vector<double>& df = *g.df;
    s << plan_block(g, lattice, df, daylight_factor_scale(), Precision::DaylightFactor,
                    std::string("Daylight factor per sensor (%), CIE standard overcast sky, ground included. Windows in blue") +
                        (g.plan.systems.empty() ? "." : ", outdoor daylight systems in grey (see the key)."),
                    page);
    const study::DaylightFactorSummary& st = *g.grid->daylight_factor;
    auto df_text = [](double v) { return format_value(v, Precision::DaylightFactor) + " %"; };
    std::vector<std::pair<std::string, std::string>> rows{
        {"mean", df_text(st.mean_percent)},
        {"median", df_text(st.median_percent)},
        {"minimum", df_text(st.min_percent)},
        {"maximum", df_text(st.max_percent)},
        {"uniformity (min / mean)", format_value(st.uniformity, Precision::Ratio)}};
    for (const auto& [threshold, area] : st.area_at_or_above_percent)
      rows.emplace_back("area with DF &#8805; " + format_value(threshold, Precision::DaylightFactor) + " %",
                        format_value(area, Precision::Percent) + " %");
    // The Monte Carlo uncertainty (docs/outputs.md, daylight_factor.csv): relative standard
    // error of DF over the sensors with daylight; the methods section tables it for every grid.
    rows.emplace_back("standard error of DF, RMS over sensors (relative)", df_text(st.rms_relative_stderr_percent));
    rows.emplace_back("standard error of DF, largest (relative)", df_text(st.max_relative_stderr_percent));
    if (annual && annual->da_verdicts_within_2_sigma)
      rows.emplace_back("sensors whose DA verdict could change within 2 standard errors",
                        std::to_string(*annual->da_verdicts_within_2_sigma) +
                            (annual->da_verdicts_within_2_sigma_area_percent
                                 ? " (" + format_value(*annual->da_verdicts_within_2_sigma_area_percent, Precision::Percent) +
                                       " % of the area)"
                                 : std::string()));
    s << key_value_table(rows);
  } else {
    s << "<p class=\"na\">daylight_factor.csv not found: the daylight factor was not computed.</p>";
  }
  s << "</div>";

  // Point-in-time cases: each case's statistics beside its Monte Carlo uncertainty (docs/
  // outputs.md, point_in_time.csv: the relative standard error over the sensors with light).
  if (!g.grid->points_in_time.empty()) {
    s << "<div class=\"part\" id=\"" << g.id << "-pit\"><h3>Point in time</h3>"
      << "<table class=\"grid-table\"><tr><th>case</th><th>sky</th><th>mean</th><th>median</th><th>minimum</th>"
         "<th>maximum</th><th>uniformity (min / mean)</th><th>standard error, RMS over sensors (relative)</th>"
         "<th>standard error, largest (relative)</th><th>accuracy target (95th percentile)</th></tr>";
    auto lux = [](double v) { return format_value(v, Precision::Illuminance) + " lx"; };
    auto relative = [](const std::optional<double>& v) {
      return v ? format_value(*v, Precision::DaylightFactor) + " %" : std::string("not stated");
    };
    for (const study::PointInTimeSummary& p : g.grid->points_in_time)
      s << "<tr><td>" << esc(p.name) << "</td><td>" << esc(p.sky) << "</td><td class=\"n\">" << lux(p.mean_lux)
        << "</td><td class=\"n\">" << lux(p.median_lux) << "</td><td class=\"n\">" << lux(p.min_lux)
        << "</td><td class=\"n\">" << lux(p.max_lux) << "</td><td class=\"n\">"
        << format_value(p.uniformity, Precision::Ratio) << "</td><td class=\"n\">"
        << relative(p.rms_relative_stderr_percent) << "</td><td class=\"n\">"
        << relative(p.max_relative_stderr_percent) << "</td><td>" << point_in_time_accuracy_words(p)
        << "</td></tr>";
    s << "</table><p class=\"note\">Illuminance at every sensor at each case's date and time (project key "
         "<code>points_in_time</code>; per sensor in <code>point_in_time.csv</code>, each value with its standard "
         "error). The standard error is the Monte Carlo one, relative to the value, over the sensors with light. "
         "With an accuracy target each case is held to it as the daylight factor is (95 % of the sensors with light "
         "at or below it); a case above it names the part of its error that keeps it there (the sky, the sun's "
         "reflections through the sun bins, or the direct sun's shadow rays at a shadow edge) and what stopped "
         "the run: raise <code>accuracy.max_photons</code> for a photon budget, <code>max_seconds</code> for a time "
         "budget; at the direct rays limit the case's penumbra needs more than 256 shadow rays over the sun's "
         "disc.</p>"
         "</div>";
  }

  // DA.
  s << "<div class=\"part\" id=\"" << g.id << "-da\"><h3>Daylight autonomy</h3>";
  const std::vector<double> da = g.da && annual ? *g.da : std::vector<double>{};
  if (!da.empty()) {
    const std::string threshold = key_number(annual->da_threshold_lux);
    s << plan_block(g, lattice, da, percent_scale("DA" + threshold), Precision::Percent,
                    "DA" + threshold + ": share of occupied hours with illuminance &#8805; " + threshold + " lx (%).", page);
  } else {
    s << "<p class=\"na\">metrics.csv not found: no annual results.</p>";
  }
  s << "</div>";

  // UDI.
  s << "<div class=\"part\" id=\"" << g.id << "-udi\"><h3>Useful daylight illuminance</h3>";
  const std::vector<double> udi = g.udi ? *g.udi : std::vector<double>{};
  const std::vector<double> autonomous = g.autonomous ? *g.autonomous : std::vector<double>{};
  if (!udi.empty() && annual) {
    s << "<div class=\"row\">"
      << plan_block(g, lattice, udi, percent_scale("UDI achieved"), Precision::Percent,
                    "UDI achieved, original convention (" + key_number(annual->udi_lower_lux) + "&#8211;" +
                        key_number(annual->udi_upper_original_lux) +
                        " lx): share of occupied hours (%).", page);
    if (!autonomous.empty())
      s << plan_block(g, lattice, autonomous, percent_scale("UDI autonomous"), Precision::Percent,
                      "UDI autonomous, revised convention (" + key_number(annual->da_threshold_lux) + "&#8211;" +
                          key_number(annual->udi_upper_revised_lux) +
                          " lx): share of occupied hours (%).", page);
    s << "</div><figure>" << udi_bars_svg(*annual)
      << "<figcaption>Grid means of the UDI bins in both conventions (each bar sums to 100 %).</figcaption></figure>";
  } else {
    s << "<p class=\"na\">no annual results.</p>";
  }
  s << "</div>";

  // Compliance: the model's verdicts (study/compliance_verdicts.h), with the values they test.
  s << "<div class=\"part\" id=\"" << g.id << "-compliance\"><h3>Compliance</h3>";
  if (!g.grid->verdicts.empty()) {
    s << "<table class=\"grid-table\"><tr><th>standard</th><th>criterion</th><th>requirement</th><th>value</th>"
         "<th>result</th><th>remark</th></tr>";
    for (const study::Verdict& v : g.grid->verdicts) {
      std::string value = "-";
      if (v.value)
        value = v.unit == "level" ? format_value(*v.value, Precision::Length) + " of 3"
                : v.standard.rfind("BREEAM", 0) == 0 ? format_value(*v.value, Precision::DaylightFactor) + " %"
                                                     : format_value(*v.value, Precision::Percent) + " " + esc(v.unit);
      s << "<tr><td>" << esc(v.standard) << "</td><td>" << esc(v.criterion) << "</td><td>" << esc(v.requirement)
        << "</td><td class=\"n\">" << value << "</td><td>" << verdict_badge(v.outcome, v.outcome) << "</td><td>"
        << esc(v.reason) << "</td></tr>";
    }
    s << "</table>";
  } else {
    s << "<p class=\"na\">no verdicts recorded.</p>";
  }
  if (annual && !annual->en17037.empty() && g.grid->orientation == study::GridOrientation::Horizontal) {
    const std::string target_area = format_value(annual->en17037_target_area_required_percent, Precision::Percent);
    s << "<table class=\"grid-table\"><tr><th>EN 17037 level</th><th>target (" << target_area
      << " % of the area)</th><th>area reaching it</th>"
         "<th>minimum target (95 % of the area)</th><th>area reaching it</th><th>result</th></tr>";
    for (const study::En17037Level& level : annual->en17037)
      s << "<tr><td>" << esc(level.level) << "</td><td>" << format_value(level.target_lux, Precision::Illuminance)
        << " lx</td><td>" << format_value(level.target_area_percent, Precision::Percent) << " %</td><td>"
        << format_value(level.minimum_target_lux, Precision::Illuminance) << " lx</td><td>"
        << format_value(level.minimum_target_area_percent, Precision::Percent) << " %</td><td>"
        << verdict_badge(level.passes ? "pass" : "fail", level.passes ? "pass" : "fail") << "</td></tr>";
    s << "</table><p class=\"note\">EN 17037 daylight provision over " << annual->en17037_daylight_hours
      << " daylight hours (half the year, ranked by " << esc(annual->en17037_daylight_hours_source)
      << "); a level passes when its target is met on &#8805; " << target_area
      << " % and its minimum target on &#8805; 95 % of the area, each for &#8805; 50 % of the daylight hours"
      << (annual->en17037_openings == metrics::en17037_openings_name(metrics::MetricSettings::Openings::Horizontal)
              ? " (the model's daylight openings are horizontal: EN 17037 asks the target over 95 % of the area)"
              : "")
      << ".</p>";
  }
  s << "</div>";

  // Temporal map.
  s << "<div class=\"part\" id=\"" << g.id << "-temporal\"><h3>Temporal map of the mean illuminance</h3>";
  if (g.illuminance && g.illuminance->step_count() > 0) {
    const bool daily = !annual || annual->occupancy.kind == "daily";
    const ColourScale scale = illuminance_scale();
    s << "<figure><div class=\"row\">"
      << temporal_svg(*g.illuminance, daily ? (annual ? annual->occupancy.start_h : 8.0) : NAN,
                      daily ? (annual ? annual->occupancy.end_h : 18.0) : NAN, scale, g.grid->area_m2)
      << legend_svg(scale, page)
      << "</div><figcaption>Mean illuminance over the grid's " << g.illuminance->sensor_count()
      << (by_area ? " sensors, each weighted by its area," : " sensors") << " for every hour of the weather year (lx, logarithmic; below 1 lx grey).</figcaption></figure>";
    if (fs::exists(join(g.folder_path, "temporal_map.png")))  // report/temporal_map.h
      s << "<p class=\"note\">As a picture: <a href=\"" << esc(g.folder) << "/temporal_map.png\">" << esc(g.folder)
        << "/temporal_map.png</a>.</p>";
  } else {
    s << "<p class=\"na\">illuminance.bin not found: no annual illuminance.</p>";
  }
  s << "</div>";

  // Histograms.
  s << "<div class=\"part\" id=\"" << g.id << "-histograms\"><h3>Distributions over the sensors</h3><div class=\"row\">";
  bool any = false;
  if (g.df) {
    std::vector<double> edges;
    for (int i = 0; i <= 20; ++i) edges.push_back(0.5 * i);
    s << "<figure>"
      << histogram_svg(*g.df, edges, daylight_factor_scale(), "daylight factor (%)", "daylight factor histogram",
                       g.grid->area_m2)
      << "<figcaption>Daylight factor: share of " << shares_of << " per 0.5 % bin (last bin: 10 % and above).</figcaption></figure>";
    any = true;
  }
  if (!da.empty()) {
    std::vector<double> edges;
    for (int i = 0; i < 10; ++i) edges.push_back(10.0 * i);
    s << "<figure>"
      << histogram_svg(da, edges, percent_scale("DA"), "daylight autonomy (% of occupied hours)",
                       "daylight autonomy histogram", g.grid->area_m2)
      << "<figcaption>Daylight autonomy: share of " << shares_of << " per 10 % bin.</figcaption></figure>";
    any = true;
  }
  if (!any) s << "<p class=\"na\">no per-sensor results.</p>";
  s << "</div></div>";

  // Metrics table.
  s << "<div class=\"part\" id=\"" << g.id << "-metrics\"><h3>Grid metrics</h3>";
  if (annual) {
    s << "<table class=\"grid-table\"><tr><th>metric (grid mean over " << (by_area ? "the area" : "sensors")
      << ")</th><th>value</th><th>unit</th></tr>";
    for (const MetricRow& row : metric_rows(*annual))
      s << "<tr><td>" << row.label << "</td><td class=\"n\">" << format_value(row.value, row.precision) << "</td><td>" << row.unit
        << "</td></tr>";
    s << "<tr><td>sDA (share of " << shares_of << ")</td><td class=\"n\">"
      << format_value(annual->sda_percent, Precision::Percent) << "</td><td>%</td></tr>";
    s << "<tr><td>ASE (share of " << shares_of << ")</td><td class=\"n\">"
      << format_value(annual->ase_percent, Precision::Percent) << "</td><td>%</td></tr>";
    s << "<tr><td>occupied hours" << occupancy_note(annual->occupancy) << "</td><td class=\"n\">"
      << annual->occupied_hours << "</td><td>h</td></tr>";
    s << "<tr><td>time steps</td><td class=\"n\">" << annual->time_steps << "</td><td></td></tr>";
    s << "</table><p class=\"note\">Sky: " << esc(annual->sky) << ".</p>";
  } else {
    s << "<p class=\"na\">no annual results.</p>";
  }
  s << "</div></section>";
  return s.str();
}

const char* const Style = R"CSS(
body{font-family:"DejaVu Sans",Helvetica,Arial,sans-serif;margin:24px auto;max-width:1180px;color:#111;line-height:1.35;padding:0 16px}
h1{font-size:1.6em;margin-bottom:0.2em}h2{border-bottom:2px solid #333;margin-top:1.6em}h3{margin-bottom:0.3em}
table{border-collapse:collapse;margin:0.5em 0}th,td{border:1px solid #bbb;padding:3px 8px;text-align:left;vertical-align:top}
th{background:#eee}td.n{text-align:right;font-variant-numeric:tabular-nums}table.kv th{width:18em}td.cached{color:#555;font-style:italic}table.timings td.n{white-space:nowrap}.keys{display:flex;flex-direction:column;gap:8px}tr.total th{text-align:left}
.row{display:flex;flex-wrap:wrap;gap:18px;align-items:flex-start}figure{margin:0.4em 0}figcaption{font-size:0.85em;color:#333;max-width:560px}
.lt{font-size:11px;fill:#111}.cv{font-size:9px;text-anchor:middle}.badge{padding:1px 8px;border-radius:3px;font-weight:bold;white-space:nowrap}
.pass{background:#c7e9c0;color:#00441b}.fail{background:#fcbba1;color:#67000d}.na-badge{background:#e5e5e5;color:#333;font-weight:normal}
.na,.note{color:#444;font-size:0.9em}.lead{font-size:1.1em}.delta{color:#555;font-size:0.9em}
table.summary-table th,table.summary-table td{padding:3px 6px}
.problem{color:#a00}nav ul{columns:2}code{font-size:0.9em}.meta{color:#333}
#report-check{display:none}
@media print{body{max-width:none;margin:0;font-size:9.5pt}nav,#report-check,.screen-only{display:none}
a{color:inherit;text-decoration:none}
.part,figure,table,tr{break-inside:avoid;page-break-inside:avoid}h2,h3{break-after:avoid;page-break-after:avoid}
section{break-before:page;page-break-before:always}section#summary{break-before:auto;page-break-before:auto}
*{-webkit-print-color-adjust:exact;print-color-adjust:exact}}
)CSS";

// The self-check: every listed section exists, every plot SVG has drawn content with a
// non-empty bounding box, every embedded PNG decodes; the outcome goes into #report-check
// (data-status "ok" or "failed") for the headless-browser test, and failures to the console.
const char* const Script = R"JS(
(function () {
  var marker = document.getElementById('report-check');
  var problems = [];
  var ids = (document.body.getAttribute('data-sections') || '').split(' ').filter(function (s) { return s; });
  ids.forEach(function (id) { if (!document.getElementById(id)) problems.push('missing section ' + id); });
  var plots = document.querySelectorAll('svg.plot');
  Array.prototype.forEach.call(plots, function (svg, i) {
    var shapes = svg.querySelectorAll('rect,circle,polygon,line,path,image,text');
    var box = svg.getBBox();
    if (shapes.length === 0 || !(box.width > 0 && box.height > 0))
      problems.push('empty plot ' + i + ' (' + (svg.getAttribute('aria-label') || '') + ')');
  });
  var images = document.querySelectorAll('svg image');
  var decodes = Array.prototype.map.call(images, function (im, i) {
    var img = new Image();
    img.src = im.getAttribute('href');
    return img.decode().then(function () {
      if (!(img.naturalWidth > 0)) problems.push('image ' + i + ' is empty');
    }, function () { problems.push('image ' + i + ' does not decode'); });
  });
  Promise.all(decodes).then(function () {
    marker.setAttribute('data-plots', String(plots.length));
    marker.setAttribute('data-images', String(images.length));
    if (problems.length === 0) {
      marker.setAttribute('data-status', 'ok');
      marker.textContent = 'ok';
    } else {
      marker.setAttribute('data-status', 'failed');
      marker.textContent = 'self-check failed: ' + problems.join('; ');
      console.error('report self-check failed: ' + problems.join('; '));
    }
  });
})();
)JS";

std::string sky_section(const std::string& results_dir, std::vector<std::string>& ids, PageIds& page) {
  std::ostringstream s;
  std::vector<std::pair<FloatImage, std::string>> skies;
  for (const char* stem : {"sky_mean", "sky_hour"}) {
    const std::string path = join(results_dir, std::string(stem) + ".exr");
    if (!fs::exists(path)) continue;
    try {
      skies.emplace_back(read_exr(path), stem);
    } catch (const std::exception&) {
    }
  }
  if (skies.empty()) return {};
  ids.push_back("sky");
  s << "<section id=\"sky\"><h2>Sky</h2><div class=\"row\">";
  for (const auto& [image, stem] : skies) {
    double lo = std::numeric_limits<double>::infinity(), hi = 0;
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x) {
        if (image.at(3, x, y) <= 0) continue;
        const double l = rgb_to_photometric({image.at(0, x, y), image.at(1, x, y), image.at(2, x, y)});
        if (l > 0) {
          lo = std::min(lo, l);
          hi = std::max(hi, l);
        }
      }
    ColourScale scale{1, 10, true, "luminance", "cd/m2"};
    if (hi > 0) {
      scale.min = std::pow(10.0, std::floor(std::log10(lo)));
      scale.max = std::pow(10.0, std::ceil(std::log10(hi) + 1e-12));
    }
    auto it = image.string_attributes.find("dayphoton:time");
    const std::string time = it != image.string_attributes.end() ? it->second : stem;
    s << "<figure><div class=\"row\">" << sky_svg(image, scale, stem == "sky_mean" ? "annual mean sky" : "sky of one hour")
      << legend_svg(scale, page) << "</div><figcaption>" << (stem == "sky_mean" ? "Annual mean sky" : "One hour")
      << ": " << esc(time) << ". Luminance of the sky patches (cd/m&#178;, logarithmic), angular fisheye seen from "
                              "below (east left); the sun is spread into its patches as in the annual sky matrix."
      << "</figcaption></figure>";
  }
  s << "</div></section>";
  return s.str();
}

std::string report_html_of(const std::string& results_dir, const ResultsModel& model) {
  PageIds page;
  std::vector<GridData> grids;
  for (const study::CaseResult& c : model.cases)
    for (const GridResult& g : c.grids) grids.push_back(load_grid(results_dir, c, g));

  // Client order: the summary first, then what it rests on, the per-grid detail, and the
  // settings last.
  std::vector<std::string> ids{"summary", "verdicts", "building"};
  std::ostringstream body;
  body << summary_section(model) << verdicts_section(model) << sunlight_section(model) << building_section(model);
  const std::string variants = variants_section(model);
  if (!variants.empty()) ids.push_back("variants");
  body << variants;
  for (const GridData& g : grids) {
    body << grid_section(g, page);
    ids.push_back(g.id);
    for (const char* part : {"-df", "-da", "-udi", "-compliance", "-temporal", "-histograms", "-metrics"})
      ids.push_back(g.id + part);
  }
  body << sky_section(results_dir, ids, page);
  body << methods_section(model) << appendix_section(model, results_dir);
  ids.push_back("methods");
  ids.push_back("appendix");

  const std::string title = model.title.empty() ? model.project_name : model.title;
  std::ostringstream html;
  html << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
          "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">"
          "<meta name=\"generator\" content=\"dayphoton " DAYPHOTON_VERSION "\">"
       << "<title>Daylight report: " << esc(title) << "</title><style>" << Style << "</style></head>\n<body data-sections=\"";
  for (std::size_t i = 0; i < ids.size(); ++i) html << (i ? " " : "") << ids[i];
  html << "\"><svg width=\"0\" height=\"0\" style=\"position:absolute\" aria-hidden=\"true\"><defs>"
          "<marker id=\"arrowhead\" viewBox=\"0 0 10 10\" refX=\"5\" refY=\"5\" markerWidth=\"6\" markerHeight=\"6\" "
          "orient=\"auto-start-reverse\"><path d=\"M 0 0 L 10 5 L 0 10 z\"/></marker></defs></svg>\n";
  html << "<header><h1>Daylight report: " << esc(title) << "</h1><p class=\"meta\">"
       << (model.site_name.empty() ? std::string() : esc(model.site_name) + " &#8212; ")
       << (model.study == "annual" ? "annual climate-based study" : "daylight-factor study") << ", dayphoton "
       << esc(model.dayphoton_version)
       << "</p><p id=\"report-check\" data-status=\"pending\">pending</p></header>\n";
  html << "<nav class=\"screen-only\"><h2>Contents</h2><ul><li><a href=\"#summary\">Summary</a></li>"
          "<li><a href=\"#verdicts\">Compliance</a></li>";
  if (model.sunlight_exposure) html << "<li><a href=\"#sunlight\">Exposure to sunlight</a></li>";
  html << "<li><a href=\"#building\">Building, materials and sensors</a></li>";
  if (!variants.empty()) html << "<li><a href=\"#variants\">Variants side by side</a></li>";
  for (const GridData& g : grids) html << "<li><a href=\"#" << g.id << "\">" << esc(g.title()) << "</a></li>";
  if (std::find(ids.begin(), ids.end(), "sky") != ids.end()) html << "<li><a href=\"#sky\">Sky</a></li>";
  html << "<li><a href=\"#methods\">Methods, validation, uncertainty</a></li><li><a href=\"#appendix\">Appendix: "
          "settings, run time and versions</a></li></ul></nav>\n"
       << body.str() << "\n<script>" << Script << "</script>\n</body></html>\n";
  return html.str();
}

}  // namespace

std::string grid_section_id(const study::CaseResult& c, const study::GridResult& g) {
  return "grid-" + id_part(c.name.empty() ? g.name : c.name + "--" + g.name);
}

std::string case_label(const study::CaseResult& c) { return c.name.empty() ? std::string("base") : c.name; }

std::string report_html(const std::string& results_dir, const ResultsModel& model) {
  return report_html_of(results_dir, model);
}

std::string report_html(const std::string& results_dir) {
  return report_html_of(results_dir, study::read_results_model(results_dir));
}

std::string write_report(const std::string& results_dir, const std::string& output_path) {
  return write_report(results_dir, study::read_results_model(results_dir), output_path);
}

std::string write_report(const std::string& results_dir, const ResultsModel& model, const std::string& output_path) {
  const std::string path = output_path.empty() ? join(results_dir, "report.html") : output_path;
  write_file_atomically(path, report_html_of(results_dir, model));
  return path;
}

std::vector<std::string> write_images_and_report(const std::string& results_dir, const ViewOutputs& outputs) {
  return write_images_and_report(results_dir, study::read_results_model(results_dir), outputs);
}

std::vector<std::string> write_images_and_report(const std::string& results_dir, const ResultsModel& model,
                                                 const ViewOutputs& outputs) {
  std::vector<std::string> written;
  if (outputs.images) {
    for (const study::CaseResult& c : model.cases)
      for (const GridResult& g : c.grids) {
        const std::vector<std::string> w = write_grid_images(results_dir, c, g);
        written.insert(written.end(), w.begin(), w.end());
      }
    const std::vector<std::string> w = write_sky_images(results_dir, model, outputs.sky_hour);
    written.insert(written.end(), w.begin(), w.end());
  }
  if (outputs.report) {
    const std::string path = join(results_dir, "report.html");
    write_file_atomically(path, report_html_of(results_dir, model));
    written.push_back(path);
  }
  return written;
}

std::vector<std::string> write_views(const std::string& results_dir, const ResultsModel& model, bool images,
                                     bool report) {
  ViewOutputs outputs;
  outputs.images = images;
  outputs.report = report;
  return write_images_and_report(results_dir, model, outputs);
}

}  // namespace dayphoton::report
