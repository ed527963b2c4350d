// Plane visibility: see plane_visibility.h.
#include "dayphoton/engine/plane_visibility.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

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

// Moments per order n = a + b: n + 1 of them, the first at ScaledMoments4::index(n, 0).
constexpr int Moments4 = 15;
constexpr int PrefixDoubles = 2 * Moments4;  // W then P (plane_visibility.h)

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
    : m_x(x), m_y(y), m_reach_m(std::size_t(N), max_radius_m), m_max_radius_m(max_radius_m) {}

const ScaledMoments4& PlaneVisibility::unit_wedge_moments(int k) { return wedges().unit[std::size_t(k)]; }

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
  v.index_cut_wedges();
  const double clear_m = *std::min_element(v.m_reach_m.begin(), v.m_reach_m.end());
  v.m_clear_m2 = clear_m * clear_m;
  return v;
}

void PlaneVisibility::index_cut_wedges() {
  static_assert(N <= 65536, "wedge indices are kept in 16 bits");
  std::vector<std::pair<double, std::uint16_t>> cut;  // (reach, wedge): sorted by reach, ties by wedge
  for (int k = 0; k < N; ++k)
    if (m_reach_m[std::size_t(k)] < m_max_radius_m) cut.emplace_back(m_reach_m[std::size_t(k)], std::uint16_t(k));
  std::sort(cut.begin(), cut.end());
  m_cut_wedge.reserve(cut.size());
  m_cut_reach_m.reserve(cut.size());
  for (const auto& [reach, k] : cut) {
    m_cut_reach_m.push_back(reach);
    m_cut_wedge.push_back(k);
  }
  // Sums over the first j PrefixStride wedges, j = 0 .. cut / PrefixStride.
  const std::size_t kept = m_cut_wedge.size() / PrefixStride + 1;
  m_prefix.assign(kept * PrefixDoubles, 0.0);
  double sum[PrefixDoubles] = {};
  const WedgeTable& table = wedges();
  for (std::size_t j = 0; j < m_cut_wedge.size(); ++j) {
    if (j % PrefixStride == 0) std::copy(sum, sum + PrefixDoubles, &m_prefix[j / PrefixStride * PrefixDoubles]);
    const ScaledMoments4& w = table.unit[m_cut_wedge[j]];
    const double reach = m_cut_reach_m[j];
    double power = reach * reach;  // reach^(n + 2)
    for (int n = 0; n <= 4; ++n) {
      for (int i = ScaledMoments4::index(n, 0); i <= ScaledMoments4::index(0, n); ++i) {
        sum[i] += w.value[i];
        sum[Moments4 + i] += w.value[i] * power;
      }
      power *= reach;
    }
  }
  if (m_cut_wedge.size() % PrefixStride == 0)
    std::copy(sum, sum + PrefixDoubles, &m_prefix[(kept - 1) * PrefixDoubles]);
}

// The moments up to `order` (0: the area; 2: AreaMoments; 4: ScaledMoments4) of the disc of
// radius r_m, scaled (header comment): the sums kept at the last stride below the i cut
// wedges nearer than r_m, then those after it one by one, in ascending reach. Where
// r_m^(order+2) is not a normal double (a disc under 1e-51 m or over 1e51 m), the sums kept
// could divide 0 by 0 or overflow: every cut wedge is then summed one by one, as rho = reach / r_m.
ScaledMoments4 PlaneVisibility::scaled_moments(double r_m, int order) const {
  const WedgeTable& table = wedges();
  ScaledMoments4 m = table.disc;
  const std::size_t cut =
      std::size_t(std::lower_bound(m_cut_reach_m.begin(), m_cut_reach_m.end(), r_m) - m_cut_reach_m.begin());
  if (cut == 0) return m;
  double scale = r_m * r_m;  // r_m^(order + 2)
  for (int n = 0; n < order; ++n) scale *= r_m;
  std::size_t first = 0;  // the first cut wedge summed one by one
  if (std::isnormal(scale) && scale < std::numeric_limits<double>::max() / 16) {
    first = cut / PrefixStride * PrefixStride;
    const double* sums = &m_prefix[first / PrefixStride * PrefixDoubles];
    double power = r_m * r_m;  // r_m^(n + 2)
    for (int n = 0; n <= order; ++n) {
      for (int i = ScaledMoments4::index(n, 0); i <= ScaledMoments4::index(0, n); ++i)
        m.value[i] += sums[Moments4 + i] / power - sums[i];
      power *= r_m;
    }
  }
  for (std::size_t j = first; j < cut; ++j) {
    const ScaledMoments4& w = table.unit[m_cut_wedge[j]];
    const double rho = m_cut_reach_m[j] / r_m;
    double power = rho * rho;  // rho^(n + 2)
    for (int n = 0; n <= order; ++n) {
      const double deficit = 1 - power;
      for (int i = ScaledMoments4::index(n, 0); i <= ScaledMoments4::index(0, n); ++i) m.value[i] -= w.value[i] * deficit;
      power *= rho;
    }
  }
  return m;
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
  return scaled_moments(r_m, 0).at(0, 0) * r_m * r_m;
}

AreaMoments PlaneVisibility::moments(double r_m) const {
  AreaMoments m;
  if (!(r_m > 0)) return m;
  const ScaledMoments4 s = scaled_moments(r_m, 2);
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
  return scaled_moments(r_m, 4);
}

}  // namespace dayphoton::engine
