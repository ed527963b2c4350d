// ReceiverPlane geometry: front crossings, the outline test, and the exact area and moments
// of a kernel disc clipped by the outline, against closed forms.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <utility>
#include <vector>

#include "dayphoton/core/units.h"
#include "dayphoton/engine/receiver_plane.h"

namespace dayphoton::engine {
namespace {

const ReceiverPlane room(0.8, true, {{0, 0}, {4, 0}, {4, 3}, {0, 3}});

TEST(ReceiverPlane, FrontCrossingOnlyFromAbove) {
  EXPECT_NEAR(room.front_crossing({1, 1, 2}, {0, 0, -1}), 1.2, 1e-12);
  EXPECT_LT(room.front_crossing({1, 1, 0}, {0, 0, 1}), 0);   // from below: the back side
  EXPECT_LT(room.front_crossing({1, 1, 2}, {1, 0, 0}), 0);   // parallel
  EXPECT_TRUE(room.contains(3.9, 2.9));
  EXPECT_FALSE(room.contains(4.1, 1));
}

TEST(ReceiverPlane, WholeDiscMoments) {
  const double r = 0.5;
  const AreaMoments m = room.clipped_disc_moments(2, 1.5, r);
  EXPECT_NEAR(m.area, Pi * r * r, 1e-12);
  EXPECT_NEAR(m.mx, 0, 1e-12);
  EXPECT_NEAR(m.my, 0, 1e-12);
  EXPECT_NEAR(m.mxx, Pi * std::pow(r, 4) / 4, 1e-12);
  EXPECT_NEAR(m.myy, Pi * std::pow(r, 4) / 4, 1e-12);
  EXPECT_NEAR(m.mxy, 0, 1e-12);
  EXPECT_NEAR(room.disc_area_inside_m2(2, 1.5, r), Pi * r * r, 1e-12);
}

TEST(ReceiverPlane, HalfAndQuarterDiscMoments) {
  const double r = 0.5;
  // Centre on the wall x = 0: the half disc x > 0, centroid 4r / (3 pi) from the wall.
  const AreaMoments half = room.clipped_disc_moments(0, 1.5, r);
  EXPECT_NEAR(half.area, Pi * r * r / 2, 1e-12);
  EXPECT_NEAR(half.mx / half.area, 4 * r / (3 * Pi), 1e-12);
  EXPECT_NEAR(half.my, 0, 1e-12);
  EXPECT_NEAR(half.mxx, Pi * std::pow(r, 4) / 8, 1e-12);
  EXPECT_NEAR(half.myy, Pi * std::pow(r, 4) / 8, 1e-12);
  // Centre on the corner (4, 3): the quarter x < 4, y < 3; int xy = r^4 / 8.
  const AreaMoments quarter = room.clipped_disc_moments(4, 3, r);
  EXPECT_NEAR(quarter.area, Pi * r * r / 4, 1e-12);
  EXPECT_NEAR(quarter.mx / quarter.area, -4 * r / (3 * Pi), 1e-12);
  EXPECT_NEAR(quarter.my / quarter.area, -4 * r / (3 * Pi), 1e-12);
  EXPECT_NEAR(quarter.mxy, std::pow(r, 4) / 8, 1e-12);
  EXPECT_NEAR(room.disc_area_inside_m2(4, 3, r), quarter.area, 1e-12);
}

TEST(ReceiverPlane, OutlineInsideTheDiscAndAChordCut) {
  // A 1 x 1 square entirely inside a disc of radius 2 about its centre: the square's moments.
  const ReceiverPlane square(0, true, {{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  const AreaMoments s = square.clipped_disc_moments(0.5, 0.5, 2);
  EXPECT_NEAR(s.area, 1, 1e-12);
  EXPECT_NEAR(s.mx, 0, 1e-12);
  EXPECT_NEAR(s.mxx, 1.0 / 12, 1e-12);
  EXPECT_NEAR(s.mxy, 0, 1e-12);
  // Disc of radius 0.5 centred 0.3 from the wall x = 0: area = disc minus the circular segment
  // beyond the wall, r^2 acos(d / r) - d sqrt(r^2 - d^2) with d = 0.3.
  const double r = 0.5, d = 0.3;
  const double segment = r * r * std::acos(d / r) - d * std::sqrt(r * r - d * d);
  const AreaMoments cut = room.clipped_disc_moments(d, 1.5, r);
  EXPECT_NEAR(cut.area, Pi * r * r - segment, 1e-12);
  EXPECT_NEAR(room.disc_area_inside_m2(d, 1.5, r), cut.area, 1e-12);
  // First moment of the segment about the centre: -(2/3) (r^2 - d^2)^(3/2) on the x axis,
  // so the clipped disc's is its negative.
  EXPECT_NEAR(cut.mx, 2.0 / 3.0 * std::pow(r * r - d * d, 1.5), 1e-12);
}

TEST(ReceiverPlane, FourthOrderMomentsOfWholeHalfAndQuarterDiscs) {
  // Closed forms in the disc's scaled coordinates (u, v) = (q - p) / r, unit disc: whole
  // int u^2 = pi / 4, int u^4 = pi / 8, int u^2 v^2 = pi / 24, odd orders 0; the half disc
  // u > 0: int u = 2 / 3, int u^3 = 4 / 15 (int r^4 dr x int cos^3), int u v^2 = 2 / 15;
  // the quarter u, v < 0: int u v = 1 / 8, int u^3 v = int u v^3 = 1 / 24, int u^2 v^2 = pi / 96.
  const double r = 0.5;
  const ScaledMoments4 whole = room.clipped_disc_moments4(2, 1.5, r);
  EXPECT_NEAR(whole.at(0, 0), Pi, 1e-12);
  EXPECT_NEAR(whole.at(2, 0), Pi / 4, 1e-12);
  EXPECT_NEAR(whole.at(0, 2), Pi / 4, 1e-12);
  EXPECT_NEAR(whole.at(4, 0), Pi / 8, 1e-12);
  EXPECT_NEAR(whole.at(0, 4), Pi / 8, 1e-12);
  EXPECT_NEAR(whole.at(2, 2), Pi / 24, 1e-12);
  for (const auto& [a, b] : {std::pair{1, 0}, {0, 1}, {1, 1}, {3, 0}, {2, 1}, {1, 2}, {0, 3}, {3, 1}, {1, 3}})
    EXPECT_NEAR(whole.at(a, b), 0, 1e-12) << a << " " << b;
  const ScaledMoments4 half = room.clipped_disc_moments4(0, 1.5, r);
  EXPECT_NEAR(half.at(0, 0), Pi / 2, 1e-12);
  EXPECT_NEAR(half.at(1, 0), 2.0 / 3, 1e-12);
  EXPECT_NEAR(half.at(3, 0), 4.0 / 15, 1e-12);
  EXPECT_NEAR(half.at(1, 2), 2.0 / 15, 1e-12);
  EXPECT_NEAR(half.at(4, 0), Pi / 16, 1e-12);
  EXPECT_NEAR(half.at(0, 1), 0, 1e-12);
  const ScaledMoments4 quarter = room.clipped_disc_moments4(4, 3, r);
  EXPECT_NEAR(quarter.at(0, 0), Pi / 4, 1e-12);
  EXPECT_NEAR(quarter.at(1, 1), 1.0 / 8, 1e-12);
  EXPECT_NEAR(quarter.at(3, 1), 1.0 / 24, 1e-12);
  EXPECT_NEAR(quarter.at(1, 3), 1.0 / 24, 1e-12);
  EXPECT_NEAR(quarter.at(2, 2), Pi / 96, 1e-12);
  EXPECT_NEAR(quarter.at(1, 0), -2.0 / 3 / 2, 1e-12);  // -int_0^1 r^2 dr x int_0^{pi/2} cos
}

TEST(ReceiverPlane, FourthOrderMomentsAgreeWithTheSecondOrderOnesAndAQuadrature) {
  // An L-shaped outline and a disc cut by three of its edges and around its re-entrant corner
  // (1, 1), the centre 0.3 m from two walls: the orders up to 2 equal clipped_disc_moments
  // scaled by r^(2 + a + b), and every order up to 4 equals a polar quadrature: along each of
  // 2 x 10^5 directions (midpoint rule; the integrand is piecewise smooth, error O(h^2) ~ 1e-9)
  // the parts of the ray inside the outline, integrated in closed form in the radius.
  const std::vector<PlanePoint> outline = {{0, 0}, {3, 0}, {3, 1}, {1, 1}, {1, 3}, {0, 3}};
  const ReceiverPlane ell(0, true, outline);
  const double x = 0.7, y = 1.2, r = 0.9;
  const ScaledMoments4 m = ell.clipped_disc_moments4(x, y, r);
  const AreaMoments m2 = ell.clipped_disc_moments(x, y, r);
  EXPECT_NEAR(m.at(0, 0) * r * r, m2.area, 1e-12);
  EXPECT_NEAR(m.at(1, 0) * std::pow(r, 3), m2.mx, 1e-12);
  EXPECT_NEAR(m.at(0, 1) * std::pow(r, 3), m2.my, 1e-12);
  EXPECT_NEAR(m.at(2, 0) * std::pow(r, 4), m2.mxx, 1e-12);
  EXPECT_NEAR(m.at(1, 1) * std::pow(r, 4), m2.mxy, 1e-12);
  EXPECT_NEAR(m.at(0, 2) * std::pow(r, 4), m2.myy, 1e-12);
  const int n = 200000;
  double q[15] = {};
  for (int k = 0; k < n; ++k) {
    const double t = (k + 0.5) * 2 * Pi / n, c = std::cos(t), s = std::sin(t);
    std::vector<double> cuts;  // radii (scaled) where the ray crosses an edge
    for (std::size_t i = 0; i < outline.size(); ++i) {
      const PlanePoint a = outline[i], b = outline[(i + 1) % outline.size()];
      const double ax = (a.x - x) / r, ay = (a.y - y) / r, ex = (b.x - a.x) / r, ey = (b.y - a.y) / r;
      const double det = ex * s - ey * c;  // solve rho (c, s) = a + tau e
      if (std::fabs(det) < 1e-15) continue;
      const double rho = (ex * ay - ey * ax) / det, tau = (c * ay - s * ax) / det;
      if (rho > 0 && tau >= 0 && tau < 1) cuts.push_back(rho);
    }
    std::sort(cuts.begin(), cuts.end());
    bool inside = ell.contains(x, y);
    double from = 0;
    cuts.push_back(1e300);
    for (double cut : cuts) {
      const double to = std::min(cut, 1.0);
      if (inside && to > from)
        for (int a = 0; a <= 4; ++a)
          for (int b = 0; a + b <= 4; ++b) {
            const int p = a + b + 2;
            q[ScaledMoments4::index(a, b)] +=
                std::pow(c, a) * std::pow(s, b) * (std::pow(to, p) - std::pow(from, p)) / p * 2 * Pi / n;
          }
      if (cut >= 1.0) break;
      inside = !inside;
      from = cut;
    }
  }
  for (int a = 0; a <= 4; ++a)
    for (int b = 0; a + b <= 4; ++b) EXPECT_NEAR(m.at(a, b), q[ScaledMoments4::index(a, b)], 1e-7) << a << " " << b;
  EXPECT_GT(m.at(0, 0), 0.5 * Pi);   // the disc is cut, not whole...
  EXPECT_LT(m.at(0, 0), 0.95 * Pi);  // ...and not mostly gone
}

TEST(ReceiverPlane, MomentsDoNotDependOnTheCallsBefore) {
  // clipped_disc_moments reuses per-thread working lists and the whole circle's
  // trigonometric terms: interleaved calls on outlines of either winding, whole and clipped
  // discs, give bit-identical moments in any order.
  const ReceiverPlane ccw(0.8, true, {{0, 0}, {3, 0}, {3, 4}, {0, 4}});
  const ReceiverPlane cw(0.8, true, {{0, 0}, {0, 2}, {1, 2}, {1, 1}, {2, 1}, {2, 0}});  // an L, clockwise
  struct Query {
    const ReceiverPlane* plane;
    double x, y, r;
  };
  const std::vector<Query> queries = {{&ccw, 1.5, 2.0, 0.5}, {&cw, 0.5, 0.5, 0.4}, {&ccw, 0.2, 3.9, 1.0},
                                      {&cw, 1.5, 0.5, 2.5},  {&ccw, 1.5, 2.0, 0.7}, {&cw, 0.9, 1.5, 0.3}};
  std::vector<AreaMoments> forward, backward(queries.size());
  for (const Query& q : queries) forward.push_back(q.plane->clipped_disc_moments(q.x, q.y, q.r));
  for (std::size_t i = queries.size(); i-- > 0;)
    backward[i] = queries[i].plane->clipped_disc_moments(queries[i].x, queries[i].y, queries[i].r);
  for (std::size_t i = 0; i < queries.size(); ++i) {
    EXPECT_EQ(std::memcmp(&forward[i], &backward[i], sizeof(AreaMoments)), 0) << "query " << i;
    EXPECT_GT(forward[i].area, 0.0) << "query " << i;
  }
  // The whole disc inside: its area and zero first moments, whatever came before.
  EXPECT_NEAR(forward[0].area, Pi * 0.25, 1e-12);
  EXPECT_NEAR(forward[0].mx, 0.0, 1e-12);
}

}  // namespace
}  // namespace dayphoton::engine
