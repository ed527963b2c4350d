// `dayphoton annual` in the exact-sun mode: the annual study of a sun-bins run (docs/sun.md)
// recomputed from what the run exported into a grid folder, without the project's geometry:
//   coefficients_sky.mtx   sky coefficients (times the sky matrix without the sun, gendaymtx -s)
//   coefficients_sun.mtx   sun-bin coefficients (indirect sun, interpolated per hour's sun)
//   sun_bins.csv           the bins' Reinhart patches (the columns of coefficients_sun.mtx)
//   direct_sun.bin.gz      the exact direct sun per sensor and daytime sun position
//                          (direct_sun_file.h), which also gives ASE.
// With the run's weather file and site every hour is computed as the run computed it
// (compute_annual_study_with_sun on the same numbers), so metrics.csv is the run's.
//
// Another weather file: its sky is rebuilt and its suns computed at the run's site. A sun at
// a position the run exported (the same site and clock: every daytime record is exported,
// lit or not in the run's file) is exact. Otherwise:
//  - direct sun: the exported position nearest to it is used when it lies within
//    NearestSunLimit_deg (a leap-day shift of the calendar moves the sun by less than
//    0.4 deg from one day to the next); farther, it is an InputError: the direct sun of
//    that position needs the geometry (run the project with that weather file);
//  - indirect sun: a stencil that needs a bin the run did not trace is renormalised over
//    the bins it did trace (or the nearest bin when it traced none of them).
// Every such sun is counted in ExactSunNotes, and `annual` prints a warning with the counts.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "dayphoton/core/radiance_matrix.h"
#include "dayphoton/engine/sun_bins.h"
#include "dayphoton/metrics/illuminance_table.h"
#include "dayphoton/study/annual_study.h"
#include "dayphoton/study/annual_sun.h"
#include "dayphoton/study/direct_sun_file.h"

namespace dayphoton::study {

/// Farthest an hour's sun may be from an exported sun position whose direct sun stands in for
/// it (a policy: 1 deg is two disc diameters, and three times the largest day-to-day motion of
/// the sun at a fixed clock hour; beyond it a shadow edge may move by more than a sensor
/// spacing at a few metres).
constexpr double NearestSunLimit_deg = 1.0;

/// What a grid folder exports for the exact-sun mode, read and checked against each other.
struct ExactSunExport {
  RadianceMatrix sun_coefficients;          ///< sensors x bins x RGB
  std::optional<engine::SunBins> bins;      ///< from sun_bins.csv and the export's MF
  DirectSunExport direct;
};

/// True if `grid_dir` holds the files of the exact-sun mode (direct_sun.bin.gz; the others
/// are then required by read_exact_sun_export).
bool has_exact_sun_export(const std::string& grid_dir);

/// Read coefficients_sun.mtx, sun_bins.csv and direct_sun.bin.gz of `grid_dir` for a grid of
/// `sensors` sensors. InputError naming the file for a missing or malformed file or counts
/// that disagree (sensors, bins).
ExactSunExport read_exact_sun_export(const std::string& grid_dir, std::size_t sensors,
                                     const MatrixReadOptions& read_options, std::uint64_t max_decompressed_bytes);

/// How the weather file's suns were found in the export.
struct ExactSunNotes {
  std::size_t suns = 0;                  ///< hours with direct light and the sun above the horizon
  std::size_t suns_exact = 0;            ///< at an exported position
  std::size_t suns_nearest = 0;          ///< direct sun from the nearest exported position
  double largest_nearest_deg = 0;        ///< the largest angle to it
  std::size_t suns_renormalised = 0;     ///< indirect sun from the traced part of its stencil
  std::size_t suns_nearest_bin = 0;      ///< indirect sun from the nearest bin alone
  bool exact() const { return suns_exact == suns && suns_renormalised == 0 && suns_nearest_bin == 0; }
  /// The warnings `annual` prints (empty when exact()).
  std::vector<std::string> warnings() const;
};

/// Direct-sun illuminance (lux), steps x sensors, of `suns` from the export: e[s][k] L for
/// the exported position k of each sun (direct_sun_table's arithmetic). InputError naming
/// `export_path` for a sun farther than NearestSunLimit_deg from every exported position.
metrics::IlluminanceTable exported_direct_sun_table(const DirectSunExport& e, const std::vector<sky::SunRecord>& suns,
                                                    const std::vector<metrics::TimeStamp>& steps,
                                                    const std::string& export_path, ExactSunNotes& notes);

/// Indirect-sun illuminance (lux): indirect_sun_table when every sun's stencil is among the
/// bins, else the same sums over the traced part of each stencil, renormalised.
metrics::IlluminanceTable exported_indirect_sun_table(const RadianceMatrix& bin_coefficients,
                                                      const engine::SunBins& bins,
                                                      const std::vector<sky::SunRecord>& suns,
                                                      const std::vector<metrics::TimeStamp>& steps,
                                                      ExactSunNotes& notes);

/// The annual study of the exact-sun mode: sky coefficients x `ss.sky` (without the sun) +
/// the exported direct sun + the interpolated indirect sun, ASE from the direct sun
/// (compute_annual_study_with_sun); `shares`: the exported sub-patch shares, if any.
AnnualStudy annual_study_exact_sun(const RadianceMatrix& sky_coefficients, const ExactSunExport& exported,
                                   const SkyAndSuns& ss, const AnnualStudySettings& settings,
                                   const std::string& grid_dir, ExactSunNotes& notes,
                                   const SubPatchShares* shares = nullptr);

}  // namespace dayphoton::study
