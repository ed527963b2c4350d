// The picture of a grid in its PNG (report/plan_picture.h): the north arrow points along world
// +Y as seen in the lattice's frame (straight up for a lattice along the axes, turned with a
// turned lattice, none on an elevation), the scale bar has the length it says, the window in the
// south wall is a blue line on the outline's south edge, a light shelf outside it is drawn in
// half-transparent grey, a system far from the grid is left out, and the cells sit where the
// picture says.
#include "dayphoton/report/plan_picture.h"

#include <gtest/gtest.h>

#include <cmath>

#include "dayphoton/core/units.h"
#include "dayphoton/report/result_images.h"

using namespace dayphoton;
using namespace dayphoton::report;

namespace {

/// A room of 2.5 x 1.5 m (x -0.5..2, y 0..1.5), sensors every 0.5 m from (0.25, 0.25), turned by
/// `turn_deg` counter-clockwise about the origin; a window in the south wall (y = 0, x 0.5..1.5,
/// z 1..2), a light shelf outside it (y -0.6..0, z 2), and a window and a panel 20 m away.
struct Room {
  study::CaseResult c;
  study::GridResult grid;
};

Vec3 turn(const Vec3& p, double deg) {
  const double a = deg_to_rad(deg);
  return {p.x * std::cos(a) - p.y * std::sin(a), p.x * std::sin(a) + p.y * std::cos(a), p.z};
}

Room room(double turn_deg) {
  Room r;
  study::SensorLattice& l = r.grid.lattice;
  l.regular = true;
  l.columns = 4;
  l.rows = 3;
  l.spacing_m = 0.5;
  l.origin_m = turn({0.25, 1.25, 0.8}, turn_deg);  // north-west sensor
  l.column_step_m = turn({0.5, 0, 0}, turn_deg);
  l.row_step_m = turn({0, -0.5, 0}, turn_deg);
  for (int row = 0; row < 3; ++row)
    for (int col = 0; col < 4; ++col) {
      l.column_of.push_back(col);
      l.row_of.push_back(row);
      r.grid.positions_m.push_back(l.origin_m + l.column_step_m * col + l.row_step_m * row);
    }
  r.grid.plan = true;
  for (const Vec3& p : {Vec3{-0.5, 0, 0.8}, Vec3{2, 0, 0.8}, Vec3{2, 1.5, 0.8}, Vec3{-0.5, 1.5, 0.8}})
    r.grid.outline.push_back(turn(p, turn_deg));
  r.c.openings.push_back({turn({0.5, 0, 1}, turn_deg), turn({1.5, 0, 1}, turn_deg), turn({1.5, 0, 2}, turn_deg),
                          turn({0.5, 0, 2}, turn_deg)});
  // Another room's window 20 m away.
  r.c.openings.push_back({turn({20, 0, 1}, turn_deg), turn({21, 0, 1}, turn_deg), turn({21, 0, 2}, turn_deg),
                          turn({20, 0, 2}, turn_deg)});
  r.grid.openings_drawn = {0, 1};
  r.c.systems.push_back({turn({0.5, -0.6, 2}, turn_deg), turn({1.5, -0.6, 2}, turn_deg), turn({1.5, 0, 2}, turn_deg),
                         turn({0.5, 0, 2}, turn_deg)});
  r.c.systems.push_back({turn({20, 20, 2}, turn_deg), turn({21, 20, 2}, turn_deg), turn({21, 21, 2}, turn_deg)});
  return r;
}

bool ink(const study::RgbaImage& im, double x, double y) {
  const auto& p = im.at(static_cast<int>(x), static_cast<int>(y));
  return p[3] == 255 && p[0] == PlanInk[0] && p[1] == PlanInk[1] && p[2] == PlanInk[2];
}

}  // namespace

TEST(PlanPicture, NorthArrowPointsUpOnAnAxisAlignedPlan) {
  const Room r = room(0);
  const PlanGeometry g = plan_geometry(r.c, r.grid);
  ASSERT_EQ(g.openings.size(), 1u);  // the south window; the one 20 m away is left out
  ASSERT_EQ(g.systems.size(), 1u);   // the shelf; the panel 20 m away is left out
  const PlanPicture p = plan_picture(r.grid.lattice, std::vector<double>(12, 5.0), daylight_factor_scale(), 32, g);
  ASSERT_TRUE(p.north_arrow);
  EXPECT_NEAR(p.arrow_direction[0], 0, 1e-12);
  EXPECT_NEAR(p.arrow_direction[1], -1, 1e-12);
  const auto [cx, cy] = p.arrow_centre;
  const double h = 0.5 * p.arrow_length_px;
  // Shaft and head above the centre, nothing below the tail or beside the shaft.
  for (double t : {-0.8 * h, -0.3 * h, 0.2 * h, 0.6 * h, 0.9 * h}) EXPECT_TRUE(ink(p.image, cx, cy - t)) << t;
  EXPECT_FALSE(ink(p.image, cx, cy + h + 4));
  EXPECT_FALSE(ink(p.image, cx + 6, cy));
  EXPECT_FALSE(ink(p.image, cx - 6, cy));
  // The letter N above the tip.
  int letter = 0;
  for (int y = static_cast<int>(cy - h - 22); y < cy - h - 2; ++y)
    for (int x = static_cast<int>(cx - 8); x < cx + 8; ++x) letter += ink(p.image, x, y);
  EXPECT_GT(letter, 40);
  // The arrow sits in the band above the plan.
  EXPECT_LT(cy + h, p.cells_y);
}

TEST(PlanPicture, NorthArrowTurnsWithTheLattice) {
  // The building (and its lattice) turned 30 degrees counter-clockwise: in the picture's frame
  // true north lies 30 degrees clockwise of up.
  const Room r = room(30);
  const PlanPicture p =
      plan_picture(r.grid.lattice, std::vector<double>(12, 5.0), daylight_factor_scale(), 32, plan_geometry(r.c, r.grid));
  ASSERT_TRUE(p.north_arrow);
  EXPECT_NEAR(p.arrow_direction[0], std::sin(deg_to_rad(30.0)), 1e-9);
  EXPECT_NEAR(p.arrow_direction[1], -std::cos(deg_to_rad(30.0)), 1e-9);
  const auto [cx, cy] = p.arrow_centre;
  const auto [dx, dy] = p.arrow_direction;
  for (double t : {-15.0, -5.0, 5.0, 15.0}) EXPECT_TRUE(ink(p.image, cx + dx * t, cy + dy * t)) << t;
  // Straight up from the centre (where an unturned arrow would be) is empty near the tip.
  EXPECT_FALSE(ink(p.image, cx, cy - 17));
}

TEST(PlanPicture, ElevationHasAScaleBarButNoArrow) {
  Room r = room(0);
  r.grid.plan = false;
  const PlanPicture p =
      plan_picture(r.grid.lattice, std::vector<double>(12, 5.0), daylight_factor_scale(), 32, plan_geometry(r.c, r.grid));
  EXPECT_FALSE(p.north_arrow);
  EXPECT_GT(p.scale_bar_px, 0);
}

TEST(PlanPicture, ScaleBarWindowAndShelf) {
  const Room r = room(0);
  const PlanPicture p =
      plan_picture(r.grid.lattice, std::vector<double>(12, 5.0), daylight_factor_scale(), 32, plan_geometry(r.c, r.grid));
  // 32 px per 0.5 m cell: 64 px/m; the plan is about 2.5 m = 160 px wide, so the bar may be
  // up to 120 px: 1 m = 64 px.
  EXPECT_DOUBLE_EQ(p.px_per_m, 64);
  EXPECT_DOUBLE_EQ(p.scale_bar_m, 1.0);
  EXPECT_EQ(p.scale_bar_px, 64);
  for (int x = p.scale_bar_x; x < p.scale_bar_x + p.scale_bar_px; ++x) EXPECT_TRUE(ink(p.image, x, p.scale_bar_y + 3)) << x;
  EXPECT_FALSE(ink(p.image, p.scale_bar_x + p.scale_bar_px + 2, p.scale_bar_y + 3));
  EXPECT_DOUBLE_EQ(scale_bar_length_m(64, 150), 2.0);
  EXPECT_DOUBLE_EQ(scale_bar_length_m(64, 63), 0.5);
  EXPECT_DOUBLE_EQ(scale_bar_length_m(10, 120), 10.0);

  const study::SensorLattice& l = r.grid.lattice;
  // The window's middle on the south wall (1, 0): blue; the wall beside it (0.2, 0): ink.
  const auto w = p.pixel(l, {1, 0, 0.8});
  EXPECT_EQ(p.image.at(static_cast<int>(w[0]), static_cast<int>(w[1])), WindowBlue);
  const auto wall = p.pixel(l, {0.2, 0, 0.8});
  EXPECT_TRUE(ink(p.image, wall[0], wall[1]));
  // The shelf's middle (1, -0.3): half-transparent grey over nothing.
  const auto s = p.pixel(l, {1, -0.3, 2});
  EXPECT_EQ(p.image.at(static_cast<int>(s[0]), static_cast<int>(s[1])), SystemFill);
  // A cell's centre has the scale's colour of its value, where the picture says cell (1, 1) is.
  const auto cell = p.pixel(l, l.origin_m + l.column_step_m + l.row_step_m);
  const auto c = daylight_factor_scale().colour(5.0);
  EXPECT_EQ(p.image.at(static_cast<int>(cell[0]), static_cast<int>(cell[1])),
            (std::array<std::uint8_t, 4>{c[0], c[1], c[2], 255}));
  EXPECT_EQ(p.cells_x + 32 + 16, static_cast<int>(cell[0]));
  // The room between the sensor area and the wall: light grey.
  const auto floor = p.pixel(l, {-0.25, 0.75, 0.8});
  EXPECT_EQ(p.image.at(static_cast<int>(floor[0]), static_cast<int>(floor[1])), RoomFill);
}
