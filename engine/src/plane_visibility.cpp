// Plane visibility: see plane_visibility.h.
#include "dayphoton/engine/plane_visibility.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "dayphoton/core/units.h"

namespace dayphoton::engine {
namespace {

constexpr int N = PlaneVisibility::Sectors;

// The direction of pseudo-angle t in [0, 4] (the inverse of PlaneVisibility::sector_of's
// t = dy / (|dx| + |dy|) folded over the quadrants), not normalised.
PlanePoint pseudo_direction(double t) {
  const int q = std::min(3, static_cast<int>(std::floor(t)));
  const double f = t - q;
  switch (q) {
    case 0: return {1 - f, f};
    case 1: return {-f, 1 - f};
    case 2: return {-(1 - f), -f};
    default: return {f, -(1 - f)};
  }
}

double angle_of(const PlanePoint& d) {
  const double a = std::atan2(d.y, d.x);
  return a < 0 ? a + 2 * Pi : a;
}

/// Per wedge k: W[k](a, b) = int_{t_k}^{t_{k+1}} cos^a t sin^b t dt / (a + b + 2), the scaled
/// moment of the unit wedge; the whole disc's sums; each wedge's unit middle direction.
struct WedgeTable {
  std::vector<ScaledMoments4> unit;
  ScaledMoments4 disc;
  std::vector<PlanePoint> middle;

  WedgeTable() : unit(N), middle(N) {
    // 5-point Gauss-Legendre on each wedge: the integrand is a trigonometric polynomial of
    // degree 4 over less than 0.01 rad, integrated to rounding.
    static const double node[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831,
                                   0.9061798459386640};
    static const double weight[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889,
                                     0.4786286704993665, 0.2369268850561891};
    for (int k = 0; k < N; ++k) {
      const double t0 = angle_of(pseudo_direction(4.0 * k / N));
      const double t1 = k + 1 == N ? 2 * Pi : angle_of(pseudo_direction(4.0 * (k + 1) / N));
      const double half = 0.5 * (t1 - t0), mid = 0.5 * (t1 + t0);
      for (int i = 0; i < 5; ++i) {
        const double t = mid + half * node[i], c = std::cos(t), s = std::sin(t);
        for (int a = 0; a <= 4; ++a)
          for (int b = 0; a + b <= 4; ++b)
            unit[std::size_t(k)].at(a, b) += half * weight[i] * std::pow(c, a) * std::pow(s, b) / (a + b + 2);
      }
      for (int j = 0; j < 15; ++j) disc.value[j] += unit[std::size_t(k)].value[j];
      const PlanePoint d = pseudo_direction(4.0 * (k + 0.5) / N);
      const double length = std::hypot(d.x, d.y);
      middle[std::size_t(k)] = {d.x / length, d.y / length};
    }
  }
};

const WedgeTable& wedges() {
  static const WedgeTable table;
  return table;
}

// distance_to_segment_m(x, y, a, b) < r_m, the segments whose bounding box lies farther than
// r_m from the point (by a margin above the rounding) turned away without it: a disc about a
// sensor meets few of a plane's cuts.
bool within_m(double x, double y, const PlanePoint& a, const PlanePoint& b, double r_m) {
  const double margin = r_m * (1 + 1e-9);
  if (std::min(a.x, b.x) - x > margin || x - std::max(a.x, b.x) > margin || std::min(a.y, b.y) - y > margin ||
      y - std::max(a.y, b.y) > margin)
    return false;
  return distance_to_segment_m(x, y, a, b) < r_m;
}

// The order up to which moments are summed: 2 for AreaMoments, 4 for ScaledMoments4.
// The wedges that cut the disc of radius r_m (reach below it and below the largest radius),
// in ascending order; a run of BlockWedges wedges whose nearest reach is r_m or more cuts
// nothing and is passed over whole, so a small disc near one wall costs the wedges that face it.
ScaledMoments4 scaled_moments(const PlaneVisibility& v, double r_m, int order) {
  const WedgeTable& table = wedges();
  ScaledMoments4 m = table.disc;
  for (int block = 0; block < N / PlaneVisibility::BlockWedges; ++block) {
    if (!(v.block_min_reach_m(block) < r_m)) continue;
    for (int k = block * PlaneVisibility::BlockWedges; k < (block + 1) * PlaneVisibility::BlockWedges; ++k) {
      if (!v.cuts_wedge(k)) continue;
      const double rho = v.reach_m(k) / r_m;
      if (rho >= 1) continue;
      const ScaledMoments4& w = table.unit[std::size_t(k)];
      double power = rho * rho;  // rho^(a + b + 2)
      for (int n = 0; n <= order; ++n) {
        const double deficit = 1 - power;
        for (int a = 0; a <= n; ++a) m.at(a, n - a) -= w.at(a, n - a) * deficit;
        power *= rho;
      }
    }
  }
  return m;
}

}  // namespace

int PlaneVisibility::sector_of(double dx, double dy) {
  double t = 0;
  if (dy >= 0) {
    if (dx >= 0) {
      if (dx + dy > 0) t = dy / (dx + dy);
    } else {
      t = 1 - dx / (dy - dx);
    }
  } else {
    t = dx < 0 ? 2 - dy / (-dx - dy) : 3 + dx / (dx - dy);
  }
  return std::min(N - 1, static_cast<int>(t * (N / 4.0)));
}

PlaneVisibility::PlaneVisibility(double x, double y, double max_radius_m)
    : m_x(x), m_y(y), m_reach_m(std::size_t(N), max_radius_m), m_max_radius_m(max_radius_m) {
  m_block_min_reach_m.fill(std::numeric_limits<double>::infinity());
}

std::optional<PlaneVisibility> PlaneVisibility::around(const ReceiverPlane& plane, double x, double y,
                                                       double max_radius_m) {
  bool cut = false;
  for (const PlaneSegment& s : plane.interior_cuts())
    if (within_m(x, y, s.a, s.b, max_radius_m)) {
      cut = true;
      break;
    }
  for (const PlanePoint& p : plane.reflex_vertices())
    if (!cut && std::hypot(p.x - x, p.y - y) < max_radius_m) cut = true;
  if (!cut) return std::nullopt;
  PlaneVisibility v(x, y, max_radius_m);
  for (const PlaneSegment& s : plane.interior_cuts())
    if (within_m(x, y, s.a, s.b, max_radius_m)) v.block(s.a, s.b);
  const std::vector<PlanePoint>& outline = plane.outline();
  for (std::size_t i = 0; i < outline.size(); ++i) {
    const PlanePoint& a = outline[i];
    const PlanePoint& b = outline[(i + 1) % outline.size()];
    if (distance_to_segment_m(x, y, a, b) < max_radius_m) v.block(a, b);
  }
  for (int k = 0; k < N; ++k)
    if (v.cuts_wedge(k)) {
      double& nearest = v.m_block_min_reach_m[std::size_t(k / BlockWedges)];
      nearest = std::min(nearest, v.m_reach_m[std::size_t(k)]);
    }
  const double clear_m = *std::min_element(v.m_reach_m.begin(), v.m_reach_m.end());
  v.m_clear_m2 = clear_m * clear_m;
  return v;
}

void PlaneVisibility::block(const PlanePoint& a_world, const PlanePoint& b_world) {
  PlanePoint a{a_world.x - m_x, a_world.y - m_y}, b{b_world.x - m_x, b_world.y - m_y};
  double cross = a.x * b.y - a.y * b.x;
  // A segment in line with the centre hides no wedge of positive width.
  if (!(std::fabs(cross) > 1e-12 * std::hypot(a.x, a.y) * std::hypot(b.x, b.y))) return;
  if (cross < 0) std::swap(a, b);  // a -> b counter-clockwise about the centre, under pi
  const double ex = b.x - a.x, ey = b.y - a.y;
  const WedgeTable& table = wedges();
  const int first = sector_of(a.x, a.y), last = sector_of(b.x, b.y);
  for (int k = first;; k = (k + 1) % N) {
    const PlanePoint& d = table.middle[std::size_t(k)];
    // s d = a + u e: s = cross(a, e) / cross(d, e), u = cross(a, d) / cross(d, e).
    const double den = d.x * ey - d.y * ex;
    if (den != 0) {
      const double s = (a.x * ey - a.y * ex) / den, u = (a.x * d.y - a.y * d.x) / den;
      if (u >= 0 && u <= 1 && s >= 0) m_reach_m[std::size_t(k)] = std::min(m_reach_m[std::size_t(k)], s);
    }
    if (k == last) break;
  }
}

bool visible_in_plane(const PlaneVisibility& visibility, const Photon& photon) { return visibility.sees(photon); }

bool PlaneVisibility::sees(double x, double y) const {
  const double dx = x - m_x, dy = y - m_y;
  const double d2 = dx * dx + dy * dy;
  if (d2 <= m_clear_m2) return true;  // nearer than every wedge's reach
  const double reach = m_reach_m[std::size_t(sector_of(dx, dy))];
  return d2 <= reach * reach;
}

double PlaneVisibility::area_m2(double r_m) const {
  if (!(r_m > 0)) return 0;
  return scaled_moments(*this, r_m, 0).at(0, 0) * r_m * r_m;
}

AreaMoments PlaneVisibility::moments(double r_m) const {
  AreaMoments m;
  if (!(r_m > 0)) return m;
  const ScaledMoments4 s = scaled_moments(*this, r_m, 2);
  const double r2 = r_m * r_m, r3 = r2 * r_m, r4 = r2 * r2;
  m.area = s.at(0, 0) * r2;
  m.mx = s.at(1, 0) * r3;
  m.my = s.at(0, 1) * r3;
  m.mxx = s.at(2, 0) * r4;
  m.mxy = s.at(1, 1) * r4;
  m.myy = s.at(0, 2) * r4;
  return m;
}

ScaledMoments4 PlaneVisibility::moments4(double r_m) const {
  if (!(r_m > 0)) return {};
  return scaled_moments(*this, r_m, 4);
}

}  // namespace dayphoton::engine
