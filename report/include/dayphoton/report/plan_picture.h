// The picture of a grid in its standalone PNG: the false-colour cells of the sensors drawn to
// scale in the frame of the grid's lattice (columns along the lattice axis closest to east,
// rows toward the south, or downward on a wall: study/sensor_lattice.h), with what the run
// recorded about the building around them (results.json, study/results_model.h):
//   - the grid's outline (room floor, polygon, wall or rectangle): filled light grey under the
//     cells, then a 2-pixel dark line;
//   - outdoor daylight systems of the case (light shelves, louvres, panels: `systems`),
//     projected onto the plan, half-transparent grey with a dark edge; on a plan only, and only
//     those near the grid (within SystemReach_m of its cells, outline and windows), since
//     another room's shelf would widen the picture without explaining this grid;
//   - the openings drawn on the grid (`openings_drawn`) within SystemReach_m of it: a window in
//     a wall is seen edge-on as a thick blue line, a skylight as a light-blue polygon with a
//     blue edge (on an elevation the windows in its wall, face-on);
//   - above the picture a band with a scale bar (a round length, 1-2-5 steps, labelled in
//     metres) and, on a plan, a north arrow: world +Y (true north: the run's world coordinates
//     are already turned by the site's north angle, docs/project-format.md "North and UTM
//     grids") seen in the picture's frame, so a lattice turned with the building turns the
//     arrow. An elevation (a wall grid) gets no arrow.
// Sensors not on a lattice (one row in sensor order) have no frame to draw in: cells only.
#pragma once

#include <array>
#include <vector>

#include "dayphoton/report/colour_scale.h"
#include "dayphoton/study/image_files.h"
#include "dayphoton/study/results_model.h"

namespace dayphoton::report {

/// Openings farther than this from a grid's cells and outline, and systems farther than this
/// from a plan's cells, outline and windows, are not drawn on its picture.
inline constexpr double SystemReach_m = 3.0;

/// What is drawn around the cells, world coordinates.
struct PlanGeometry {
  bool plan = false;  ///< a plan (north arrow) rather than an elevation
  study::Polygon3 outline;
  std::vector<study::Polygon3> openings, systems;
};

/// The geometry `c` records for `grid` (its outline, the openings it draws, the systems near it
/// on a plan).
PlanGeometry plan_geometry(const study::CaseResult& c, const study::GridResult& grid);

struct PlanPicture {
  study::RgbaImage image;           ///< transparent where nothing is drawn
  int cells_x = 0, cells_y = 0;     ///< top-left pixel of lattice cell (0, 0)
  double px_per_m = 0;
  bool north_arrow = false;
  std::array<double, 2> arrow_centre{0, 0}, arrow_direction{0, -1};  ///< pixels; unit vector toward north
  double arrow_length_px = 0;
  double scale_bar_m = 0;           ///< 0: none
  int scale_bar_x = 0, scale_bar_y = 0, scale_bar_px = 0;  ///< left end, top row, length

  /// Pixel position (x right, y down) of a world point in the picture.
  std::array<double, 2> pixel(const study::SensorLattice& lattice, const Vec3& p) const;
};

/// Picture colours.
inline constexpr std::array<std::uint8_t, 4> WindowBlue{21, 101, 192, 255}, SkylightFill{127, 200, 255, 255},
    RoomFill{242, 242, 242, 255}, PlanInk{34, 34, 34, 255}, SystemFill{128, 128, 128, 150},
    SystemEdge{70, 70, 70, 255};

/// The picture of `values` (one per sensor) at `pixels_per_cell` pixels per lattice cell with
/// the sensor-area outline (outline_sensor_cells) and `geometry`.
PlanPicture plan_picture(const study::SensorLattice& lattice, const std::vector<double>& values, const ColourScale& scale,
                         int pixels_per_cell, const PlanGeometry& geometry);

/// The scale bar's length: the largest of 0.1, 0.2, 0.5, 1, 2, 5, 10, ... m that is at most
/// `max_px` pixels long at `px_per_m` (the smallest step if none is).
double scale_bar_length_m(double px_per_m, double max_px);

}  // namespace dayphoton::report
