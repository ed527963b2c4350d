// The picture of a grid in its standalone PNG; see plan_picture.h.
#include "dayphoton/report/plan_picture.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/report/bitmap_font.h"
#include "dayphoton/report/result_images.h"

namespace dayphoton::report {

namespace {

using Point = std::array<double, 2>;

constexpr int MarginPx = 8;
constexpr double ArrowLengthPx = 40;
constexpr int ArrowBoxPx = 84;       ///< square of the arrow and its letter, any direction
constexpr int ScaleBandPx = 36;      ///< band of an elevation: the scale bar only
constexpr int ScaleBarHeightPx = 6;
constexpr int TextScale = 2;

/// `colour` over pixel (x, y) by its alpha.
void blend(study::RgbaImage& image, int x, int y, const std::array<std::uint8_t, 4>& colour) {
  if (x < 0 || y < 0 || x >= image.width || y >= image.height) return;
  auto& d = image.at(x, y);
  const double a = colour[3] / 255.0, da = d[3] / 255.0;
  const double out_a = a + da * (1 - a);
  if (out_a <= 0) return;
  for (int c = 0; c < 3; ++c)
    d[c] = static_cast<std::uint8_t>(std::lround((colour[c] * a + d[c] * da * (1 - a)) / out_a));
  d[3] = static_cast<std::uint8_t>(std::lround(255 * out_a));
}

/// Even-odd fill of the pixels whose centre is inside `poly`.
void fill_polygon(study::RgbaImage& image, const std::vector<Point>& poly, const std::array<std::uint8_t, 4>& colour) {
  if (poly.size() < 3) return;
  double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
  for (const Point& p : poly) {
    x0 = std::min(x0, p[0]);
    x1 = std::max(x1, p[0]);
    y0 = std::min(y0, p[1]);
    y1 = std::max(y1, p[1]);
  }
  for (int y = std::max(0, static_cast<int>(std::floor(y0))); y <= std::min(image.height - 1, static_cast<int>(y1)); ++y)
    for (int x = std::max(0, static_cast<int>(std::floor(x0))); x <= std::min(image.width - 1, static_cast<int>(x1)); ++x) {
      const double px = x + 0.5, py = y + 0.5;
      bool inside = false;
      for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
        const Point &a = poly[i], &b = poly[j];
        if ((a[1] > py) != (b[1] > py) && px < (b[0] - a[0]) * (py - a[1]) / (b[1] - a[1]) + a[0]) inside = !inside;
      }
      if (inside) blend(image, x, y, colour);
    }
}

/// The pixels whose centre is within width / 2 of segment ab.
void draw_segment(study::RgbaImage& image, Point a, Point b, double width, const std::array<std::uint8_t, 4>& colour) {
  const double r = 0.5 * width;
  const double dx = b[0] - a[0], dy = b[1] - a[1], len2 = dx * dx + dy * dy;
  for (int y = std::max(0, static_cast<int>(std::floor(std::min(a[1], b[1]) - r)));
       y <= std::min(image.height - 1, static_cast<int>(std::max(a[1], b[1]) + r)); ++y)
    for (int x = std::max(0, static_cast<int>(std::floor(std::min(a[0], b[0]) - r)));
         x <= std::min(image.width - 1, static_cast<int>(std::max(a[0], b[0]) + r)); ++x) {
      const double px = x + 0.5, py = y + 0.5;
      const double t = len2 > 0 ? std::clamp(((px - a[0]) * dx + (py - a[1]) * dy) / len2, 0.0, 1.0) : 0.0;
      const double ex = px - (a[0] + t * dx), ey = py - (a[1] + t * dy);
      if (ex * ex + ey * ey <= r * r) image.at(x, y) = colour;
    }
}

void draw_closed(study::RgbaImage& image, const std::vector<Point>& poly, double width,
                 const std::array<std::uint8_t, 4>& colour) {
  for (std::size_t i = 0; i < poly.size(); ++i) draw_segment(image, poly[i], poly[(i + 1) % poly.size()], width, colour);
}

double area_px2(const std::vector<Point>& poly) {
  double a = 0;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++)
    a += poly[j][0] * poly[i][1] - poly[i][0] * poly[j][1];
  return 0.5 * std::abs(a);
}

/// The lattice frame: unit axes along columns and rows.
struct Axes {
  Vec3 origin, u, v;
  double a(const Vec3& p) const { return dot(p - origin, u); }
  double b(const Vec3& p) const { return dot(p - origin, v); }
};

Axes axes_of(const study::SensorLattice& lattice) {
  return {lattice.origin_m, lattice.column_step_m / lattice.spacing_m, lattice.row_step_m / lattice.spacing_m};
}

struct Box {
  double a0 = std::numeric_limits<double>::infinity(), a1 = -a0, b0 = a0, b1 = -a0;
  void add(double a, double b) {
    a0 = std::min(a0, a);
    a1 = std::max(a1, a);
    b0 = std::min(b0, b);
    b1 = std::max(b1, b);
  }
  bool near(const Box& o, double reach) const {
    return a0 <= o.a1 + reach && o.a0 - reach <= a1 && b0 <= o.b1 + reach && o.b0 - reach <= b1;
  }
};

Box box_of(const Axes& f, const study::Polygon3& poly) {
  Box box;
  for (const Vec3& p : poly) box.add(f.a(p), f.b(p));
  return box;
}

std::string metres_label(double m) { return format_number(m) + " m"; }

}  // namespace

double scale_bar_length_m(double px_per_m, double max_px) {
  double best = 0.1;
  for (double decade = 0.1; decade < 1e5; decade *= 10)
    for (double step : {1.0, 2.0, 5.0})
      if (step * decade * px_per_m <= max_px) best = std::max(best, step * decade);
  return best;
}

PlanGeometry plan_geometry(const study::CaseResult& c, const study::GridResult& grid) {
  PlanGeometry g;
  g.plan = grid.plan;
  g.outline = grid.outline;
  std::vector<study::Polygon3> openings;
  for (int k : grid.openings_drawn)
    if (k >= 0 && static_cast<std::size_t>(k) < c.openings.size()) openings.push_back(c.openings[static_cast<std::size_t>(k)]);
  if (!grid.lattice.regular) {
    g.openings = openings;
    return g;
  }
  // Only what is near the grid: its cells and outline, within SystemReach_m; systems on a
  // plan only.
  const Axes f = axes_of(grid.lattice);
  Box near;
  for (const Vec3& p : grid.positions_m) near.add(f.a(p), f.b(p));
  for (const Vec3& p : grid.outline) near.add(f.a(p), f.b(p));
  for (const study::Polygon3& o : openings)
    if (box_of(f, o).near(near, SystemReach_m)) g.openings.push_back(o);
  for (const study::Polygon3& o : g.openings)
    for (const Vec3& p : o) near.add(f.a(p), f.b(p));
  if (grid.plan)
    for (const study::Polygon3& s : c.systems)
      if (box_of(f, s).near(near, SystemReach_m)) g.systems.push_back(s);
  return g;
}

std::array<double, 2> PlanPicture::pixel(const study::SensorLattice& lattice, const Vec3& p) const {
  const Axes f = axes_of(lattice);
  return {cells_x + (f.a(p) + 0.5 * lattice.spacing_m) * px_per_m, cells_y + (f.b(p) + 0.5 * lattice.spacing_m) * px_per_m};
}

PlanPicture plan_picture(const study::SensorLattice& lattice, const std::vector<double>& values, const ColourScale& scale,
                         int pixels_per_cell, const PlanGeometry& geometry) {
  PlanPicture out;
  const int k = std::max(1, pixels_per_cell);
  study::RgbaImage cells = false_colour_image(lattice, values, scale, k);
  outline_sensor_cells(cells, lattice, k);
  if (!lattice.regular || !(lattice.spacing_m > 0)) {
    out.image = cells;
    return out;
  }
  const Axes f = axes_of(lattice);
  const double s = lattice.spacing_m;
  out.px_per_m = k / s;
  // Extent in the lattice frame (m): the cells and everything drawn.
  Box box;
  box.add(-0.5 * s, -0.5 * s);
  box.add((lattice.columns - 0.5) * s, (lattice.rows - 0.5) * s);
  const auto add = [&](const study::Polygon3& poly) {
    for (const Vec3& p : poly) box.add(f.a(p), f.b(p));
  };
  add(geometry.outline);
  for (const auto& o : geometry.openings) add(o);
  for (const auto& o : geometry.systems) add(o);

  // North: world +Y in the picture's frame (x right = u, y down = v).
  const Vec3 north{0, 1, 0};
  const double nx = dot(north, f.u), ny = dot(north, f.v), nl = std::hypot(nx, ny);
  out.north_arrow = geometry.plan && nl > 0.3;
  const int band = out.north_arrow ? ArrowBoxPx : ScaleBandPx;

  const double ppm = out.px_per_m;
  out.cells_x = MarginPx + static_cast<int>(std::ceil((-0.5 * s - box.a0) * ppm - 1e-9)) + 3;
  out.cells_y = band + MarginPx + static_cast<int>(std::ceil((-0.5 * s - box.b0) * ppm - 1e-9)) + 3;
  int width = out.cells_x + static_cast<int>(std::ceil((box.a1 + 0.5 * s) * ppm)) + MarginPx + 3;
  const int height = out.cells_y + static_cast<int>(std::ceil((box.b1 + 0.5 * s) * ppm)) + MarginPx + 3;
  const int plan_width = width - 2 * MarginPx;

  // Scale bar: at most half the plan's width (or 120 px on a narrow plan), labelled.
  out.scale_bar_m = scale_bar_length_m(ppm, std::max(0.5 * plan_width, 120.0));
  out.scale_bar_px = static_cast<int>(std::lround(out.scale_bar_m * ppm));
  const std::string label = metres_label(out.scale_bar_m);
  const int label_width = text_width_px(label, TextScale);
  width = std::max(width, MarginPx + out.scale_bar_px + 8 + label_width + 12 + (out.north_arrow ? ArrowBoxPx : 0) + MarginPx);
  out.image = study::RgbaImage(width, height);
  study::RgbaImage& image = out.image;

  const auto px = [&](const Vec3& p) { return out.pixel(lattice, p); };
  const auto project = [&](const study::Polygon3& poly) {
    std::vector<Point> pts;
    for (const Vec3& p : poly) pts.push_back(px(p));
    return pts;
  };
  const std::vector<Point> room = project(geometry.outline);
  fill_polygon(image, room, RoomFill);
  for (int y = 0; y < cells.height; ++y)
    for (int x = 0; x < cells.width; ++x)
      if (cells.at(x, y)[3] > 0) blend(image, out.cells_x + x, out.cells_y + y, cells.at(x, y));
  for (const auto& sys : geometry.systems) {
    const std::vector<Point> p = project(sys);
    fill_polygon(image, p, SystemFill);
    draw_closed(image, p, 1.5, SystemEdge);
  }
  if (room.size() >= 3) draw_closed(image, room, 2, PlanInk);
  for (const auto& o : geometry.openings) {
    const std::vector<Point> p = project(o);
    double longest = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
      longest = std::max(longest, std::hypot(p[i][0] - p[(i + 1) % p.size()][0], p[i][1] - p[(i + 1) % p.size()][1]));
    // Seen edge-on (a window in a wall): a thick line; seen face-on (a skylight): its area.
    const bool edge_on = area_px2(p) < 3 * longest;
    if (!edge_on) fill_polygon(image, p, SkylightFill);
    draw_closed(image, p, edge_on ? 5 : 2, WindowBlue);
  }

  // The band: scale bar at the left, north arrow at the right.
  out.scale_bar_x = MarginPx;
  out.scale_bar_y = band / 2 - ScaleBarHeightPx / 2;
  for (int y = 0; y < ScaleBarHeightPx; ++y)
    for (int x = 0; x < out.scale_bar_px; ++x) image.at(out.scale_bar_x + x, out.scale_bar_y + y) = PlanInk;
  for (int y = -4; y < ScaleBarHeightPx + 4; ++y)  // end ticks
    for (int x : {out.scale_bar_x, out.scale_bar_x + 1, out.scale_bar_x + out.scale_bar_px - 2,
                  out.scale_bar_x + out.scale_bar_px - 1})
      image.at(x, out.scale_bar_y + y) = PlanInk;
  draw_text(image, out.scale_bar_x + out.scale_bar_px + 8, out.scale_bar_y + ScaleBarHeightPx / 2 - text_height_px(TextScale) / 2,
            label, TextScale, PlanInk);
  if (out.north_arrow) {
    const Point d{nx / nl, ny / nl}, n{-d[1], d[0]};
    const Point c{width - MarginPx - ArrowBoxPx / 2.0, band / 2.0};
    out.arrow_centre = c;
    out.arrow_direction = d;
    out.arrow_length_px = ArrowLengthPx;
    const double h = 0.5 * ArrowLengthPx;
    const Point tip{c[0] + d[0] * h, c[1] + d[1] * h}, tail{c[0] - d[0] * h, c[1] - d[1] * h};
    const Point base{tip[0] - d[0] * 14, tip[1] - d[1] * 14};
    draw_segment(image, tail, base, 3, PlanInk);
    fill_polygon(image, {tip, {base[0] + n[0] * 7, base[1] + n[1] * 7}, {base[0] - n[0] * 7, base[1] - n[1] * 7}}, PlanInk);
    const Point letter{c[0] + d[0] * (h + 13), c[1] + d[1] * (h + 13)};
    draw_text(image, static_cast<int>(std::lround(letter[0] - text_width_px("N", TextScale) / 2.0)),
              static_cast<int>(std::lround(letter[1] - text_height_px(TextScale) / 2.0)), "N", TextScale, PlanInk);
  }
  return out;
}

}  // namespace dayphoton::report
