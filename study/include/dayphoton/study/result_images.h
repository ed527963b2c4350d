// Result images (issue 7 item 2): per grid, the sensor values as float EXR files (one pixel
// per sensor) and false-colour PNGs; the sky of the weather file as fisheye EXR images (the
// annual mean sky and one chosen hour); the tone mapping of radiance pictures to PNG.
// File names and attributes: docs/report.md.
//
// One pixel per sensor: the sensors of a generated grid lie on a square lattice (possibly
// rotated by the site's north angle), found again from sensors.csv by sensor_lattice(); the
// image's columns run along the lattice axis closest to east, its rows from north to south,
// so that the image reads like a plan. Lattice cells without a sensor (an L-shaped room) have
// value 0 and alpha 0 (channel "A"). Sensors that are not on a lattice (points files) give a
// one-row image in sensor order. The EXR header says where every pixel is:
//   "dayphoton:origin_m"      v3f  world position of the centre of pixel (0, 0)
//   "dayphoton:column_step_m" v3f  world step from one column to the next
//   "dayphoton:row_step_m"    v3f  world step from one row to the next (southward)
//   "dayphoton:layout"        "lattice" or "sensor order"
// plus "quantity", "unit", "dayphoton:grid" and "dayphoton:source" (the CSV file and column).
#pragma once

#include <string>
#include <vector>

#include "dayphoton/core/radiance_matrix.h"
#include "dayphoton/core/scene_description.h"
#include "dayphoton/sky/patch_basis.h"
#include "dayphoton/study/colour_scale.h"
#include "dayphoton/study/image_files.h"

namespace dayphoton::study {

/// Where each sensor sits on the image.
struct SensorLattice {
  bool regular = false;      ///< a lattice was found (else one row in sensor order)
  int columns = 0, rows = 0;
  double spacing_m = 0;      ///< lattice spacing (regular only)
  Vec3 origin_m;             ///< centre of pixel (0, 0)
  Vec3 column_step_m;        ///< world step per column
  Vec3 row_step_m;           ///< world step per row
  std::vector<int> column_of, row_of;  ///< per sensor
};

/// Find the lattice of `sensors`: all on one plane (positions within 1 mm of it), spacing =
/// the nearest-neighbour distance, every sensor within 1 % of a spacing of a lattice point,
/// no two on the same point, and at most 4 times as many cells as sensors. Otherwise (or
/// with fewer than 2 sensors) the one-row layout.
SensorLattice sensor_lattice(const std::vector<SensorPoint>& sensors);

/// One pixel per sensor: channels "Y" (the value) and "A" (1 where a sensor is), with the
/// lattice attributes of the header comment. Throws std::invalid_argument on a size mismatch.
FloatImage sensor_value_image(const SensorLattice& lattice, const std::vector<double>& values);

/// False colour, `pixels_per_cell` x `pixels_per_cell` pixels per sensor, transparent where
/// there is no sensor.
RgbaImage false_colour_image(const SensorLattice& lattice, const std::vector<double>& values,
                             const ColourScale& scale, int pixels_per_cell);

/// One grid quantity drawn as an image.
struct GridQuantity {
  std::string stem;      ///< file name without extension, e.g. "daylight_factor"
  std::string table;     ///< CSV in the grid folder, e.g. "daylight_factor.csv"
  std::string column;    ///< its column, e.g. "df_percent"
  std::string quantity;  ///< what it is, e.g. "daylight factor"
  std::string unit;      ///< e.g. "%"
  ColourScale scale;
};

/// The quantities of a grid folder that exist on disk, in a fixed order: daylight factor,
/// then from metrics.csv DA (its threshold from the column name), UDI 100-2000 (original
/// convention), UDI autonomous (revised) and mean occupied illuminance.
std::vector<GridQuantity> grid_quantities(const std::string& grid_dir);

/// Write <stem>.exr and <stem>.png (32 px per sensor, at least 256 px wide) for every
/// quantity of grid_quantities() into `grid_dir`; returns the paths written. Reads
/// sensors.csv and the tables from disk (InputError, located, if they are malformed).
std::vector<std::string> write_grid_images(const std::string& grid_dir);

/// Angular (equidistant) fisheye of the upper hemisphere of one sky column (`column` >= 0)
/// or of the mean over all columns (`column` = -1) of a sky matrix (bins x steps x RGB,
/// RADIANCE bin order of `basis`): `size` x `size` pixels, zenith at the centre, north up and
/// east LEFT (the sky seen from below, as a sky map), channels R, G, B (radiance,
/// W/(sr m^2)) and A (1 inside the horizon circle). Each pixel takes its patch's value.
FloatImage sky_fisheye(const RadianceMatrix& sky_matrix, int column, const sky::PatchBasis& basis, int size);

/// Luminance (cd/m^2) false colour of an RGB radiance image on a logarithmic scale, pixels
/// with A = 0 transparent.
RgbaImage luminance_false_colour(const FloatImage& rgb, const ColourScale& scale);

/// Tone mapping for viewing: luminance L = 179 (0.265 R + 0.670 G + 0.065 B); Reinhard et
/// al.'s global operator (SIGGRAPH 2002, eq. 3-4: key a = 0.18 over the log-average
/// luminance, Ld = Ls (1 + Ls / Lwhite^2) / (1 + Ls), Lwhite = the largest scaled luminance
/// after discarding the brightest 0.1 % of pixels), colours scaled by Ld / L, then the sRGB
/// transfer function. Non-finite or negative pixels are shown black.
RgbaImage tone_map(const FloatImage& rgb);

/// A time of the weather year, "M/D/H": month, day, hour of local standard time (decimal).
/// The record is the one whose interval (h - 1, h] contains H (EPW hour h), so "6/21/12.5"
/// is the record stamped 12.5 (EPW hour 13). Throws std::invalid_argument for bad text.
struct YearHour {
  int month = 6, day = 21;
  double hour = 12.5;
  std::string text() const;  ///< "6/21/12.5"
};
YearHour parse_year_hour(const std::string& text);

/// Write the sky images of a results folder: sky_mean.exr and sky_hour.exr (fisheyes of
/// `size` pixels, with attributes naming the weather file, the time and the sky model),
/// plus false-colour PNGs beside them. The sky matrix is rebuilt from the weather file named in
/// summary.json, exactly as `dayphoton run` builds it (RADIANCE-compatible mode, the run's
/// basis, ground reflectance and sun site: study/sun_site.h recorded_sun_site). Returns the paths written; none if summary.json names no
/// weather file. InputError if the hour is not in the weather file.
std::vector<std::string> write_sky_images(const std::string& results_dir, const YearHour& hour, int size = 256);

/// The same with summary.json's text given (`summary_path` names it in messages), for a run
/// that writes summary.json after its images.
std::vector<std::string> write_sky_images(const std::string& results_dir, const YearHour& hour,
                                          const std::string& summary_text, const std::string& summary_path,
                                          int size = 256);

}  // namespace dayphoton::study
