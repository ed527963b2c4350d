// Result images (issue 7 item 2): per grid, the sensor values as float EXR files (one pixel
// per sensor) and false-colour PNGs; the sky of the weather file as fisheye EXR images (the
// annual mean sky and one chosen hour). File names and attributes: docs/report.md.
//
// Made from the results model (study/results_model.h) alone: one pixel per cell of the grid's
// recorded lattice (study/sensor_lattice.h; the run found it once from the sensor positions);
// the image's columns run along the lattice axis closest to east, its rows from north to south,
// so that the image reads like a plan. Lattice cells without a sensor (an L-shaped room) have
// value 0 and alpha 0 (channel "A"). Sensors that are not on a lattice (points files) give a
// one-row image in sensor order. The per-sensor values are the table columns the model names
// (study::read_quantity_values). The EXR header says where every pixel is:
//   "dayphoton:origin_m"      v3f  world position of the centre of pixel (0, 0)
//   "dayphoton:column_step_m" v3f  world step from one column to the next
//   "dayphoton:row_step_m"    v3f  world step from one row to the next (southward)
//   "dayphoton:layout"        "lattice" or "sensor order"
// plus "quantity", "unit", "dayphoton:grid" and "dayphoton:source" (the CSV file and column).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "dayphoton/core/radiance_matrix.h"
#include "dayphoton/sky/patch_basis.h"
#include "dayphoton/report/colour_scale.h"
#include "dayphoton/report/plan_picture.h"
#include "dayphoton/study/image_files.h"
#include "dayphoton/study/results_model.h"
#include "dayphoton/study/year_hour.h"

namespace dayphoton::report {

using study::FloatImage;
using study::RgbaImage;
using study::SensorLattice;
using study::YearHour;

/// One pixel per sensor: channels "Y" (the value) and "A" (1 where a sensor is), with the
/// lattice attributes of the header comment. Throws std::invalid_argument on a size mismatch.
FloatImage sensor_value_image(const SensorLattice& lattice, const std::vector<double>& values);

/// False colour, `pixels_per_cell` x `pixels_per_cell` pixels per sensor, transparent where
/// there is no sensor.
RgbaImage false_colour_image(const SensorLattice& lattice, const std::vector<double>& values,
                             const ColourScale& scale, int pixels_per_cell);

/// Grey level of the outline of the sensor area (dark on every colour of the viridis scale).
inline constexpr std::uint8_t OutlineGrey = 20;

/// Outline of the lattice cells that hold a sensor in a false_colour_image: every cell side
/// facing a cell without a sensor (or the lattice's edge) becomes a 1-pixel line of
/// OutlineGrey, drawn on the cell's own edge pixels. Nothing for sensors not on a lattice or
/// fewer than 4 pixels per cell.
void outline_sensor_cells(RgbaImage& image, const SensorLattice& lattice, int pixels_per_cell);

/// "<Quantity>, <unit>" for a legend, from the model's typed fields; the percent scale's unit
/// reads "% of occupied hours" (e.g. "Daylight autonomy (300 lx), % of occupied hours").
std::string legend_title(const study::SensorQuantity& quantity);

/// The standalone PNG of one quantity: the outlined false-colour plan with the building
/// around it, scale bar and north arrow (plan_picture.h), and its legend (image_legend.h)
/// with the cell size ("1 cell = 0.5 m") as the note.
RgbaImage grid_png(const SensorLattice& lattice, const std::vector<double>& values,
                   const study::SensorQuantity& quantity, int pixels_per_cell, const PlanGeometry& geometry);

/// The colour scale of a quantity of the model (colour_scale.h).
ColourScale scale_of(const study::SensorQuantity& quantity);

/// Write <stem>.exr and <stem>.png (grid_png: 32 px per sensor, the plan at least 256 px
/// wide, with outline, the geometry `c` records for the grid (plan_geometry), scale bar,
/// north arrow and legend) for every quantity the model lists for `grid` (a grid of case `c`)
/// into its folder, and temporal_map.png (temporal_map.h) if the grid has an illuminance
/// table; returns the paths written. InputError (located) if a value table is
/// missing or malformed.
std::vector<std::string> write_grid_images(const std::string& results_dir, const study::CaseResult& c,
                                           const study::GridResult& grid);

/// Angular (equidistant) fisheye of the upper hemisphere of one sky column (`column` >= 0)
/// or of the mean over all columns (`column` = -1) of a sky matrix (bins x steps x RGB,
/// RADIANCE bin order of `basis`): `size` x `size` pixels, zenith at the centre, north up and
/// east LEFT (the sky seen from below, as a sky map), channels R, G, B (radiance,
/// W/(sr m^2)) and A (1 inside the horizon circle). Each pixel takes its patch's value.
FloatImage sky_fisheye(const RadianceMatrix& sky_matrix, int column, const sky::PatchBasis& basis, int size);

/// Luminance (cd/m^2) false colour of an RGB radiance image on a logarithmic scale, pixels
/// with A = 0 transparent.
RgbaImage luminance_false_colour(const FloatImage& rgb, const ColourScale& scale);

/// Write the sky images of a results folder: sky_mean.exr and sky_hour.exr (fisheyes of
/// `size` pixels, with attributes naming the weather file, the time and the sky model),
/// plus false-colour PNGs beside them. The sky matrix is rebuilt from the weather file the
/// model names, exactly as `dayphoton run` builds it (RADIANCE-compatible mode, the run's
/// basis, ground reflectance and the site of its sun, all from the model). Returns the paths
/// written; none for a daylight-factor study or when the weather file is not there any more.
/// InputError if the hour is not in the weather file.
std::vector<std::string> write_sky_images(const std::string& results_dir, const study::ResultsModel& model,
                                          const YearHour& hour, int size = 256);

}  // namespace dayphoton::report
