// `annual` in the exact-sun mode: a sun-bins run's annual study recomputed from its exported
// files. Conventions and the handling of other weather files: annual_exact_sun.h.
#include "dayphoton/study/annual_exact_sun.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/input_file.h"
#include "dayphoton/core/units.h"

namespace dayphoton::study {
namespace {

namespace fs = std::filesystem;

/// Two exported and recomputed directions of the same sun differ by float rounding only
/// (about 1e-7 rad); different records' suns by far more than this (1e-5 rad).
constexpr double SamePositionCos = 1.0 - 5e-11;

std::string in_folder(const std::string& dir, const char* name) { return (fs::path(dir) / name).string(); }

/// The patches of sun_bins.csv (its `patch` column, rows in `bin` order 0, 1, ...).
std::vector<int> read_sun_bin_patches(const std::string& path) {
  if (const std::string problem = input_file_problem(path); !problem.empty())
    throw InputError(SourceLocation{path, 0, 0}, problem);
  std::ifstream in(path);
  std::string line;
  if (!std::getline(in, line) || line.rfind("bin,patch,", 0) != 0)
    throw InputError(SourceLocation{path, 1, 1}, "expected the header 'bin,patch,altitude_deg,...' of sun_bins.csv");
  std::vector<int> patches;
  for (int line_no = 2; std::getline(in, line); ++line_no) {
    if (line.empty()) continue;
    std::istringstream fields(line);
    std::string bin, patch;
    std::getline(fields, bin, ',');
    std::getline(fields, patch, ',');
    std::size_t used_bin = 0, used_patch = 0;
    long b = -1, p = -1;
    try {
      b = std::stol(bin, &used_bin);
      p = std::stol(patch, &used_patch);
    } catch (const std::exception&) {
      used_bin = 0;
    }
    if (used_bin == 0 || used_bin != bin.size() || used_patch != patch.size() || b != long(patches.size()) || p < 1)
      throw InputError(SourceLocation{path, line_no, 1},
                       "expected bin " + std::to_string(patches.size()) + " and its patch number, not '" +
                           line.substr(0, 60) + "'");
    patches.push_back(static_cast<int>(p));
  }
  return patches;
}

double angle_deg(const Vec3& a, const Vec3& b) { return rad_to_deg(std::acos(std::clamp(dot(a, b), -1.0, 1.0))); }

}  // namespace

bool has_exact_sun_export(const std::string& grid_dir) {
  std::error_code ec;
  return fs::exists(fs::path(grid_dir) / DirectSunFileName, ec);
}

ExactSunExport read_exact_sun_export(const std::string& grid_dir, std::size_t sensors,
                                     const MatrixReadOptions& read_options, std::uint64_t max_decompressed_bytes) {
  ExactSunExport x;
  const std::string direct_path = in_folder(grid_dir, DirectSunFileName);
  const std::string coefficients_path = in_folder(grid_dir, "coefficients_sun.mtx");
  const std::string bins_path = in_folder(grid_dir, "sun_bins.csv");
  x.direct = read_direct_sun_file(direct_path, max_decompressed_bytes);
  if (x.direct.sensors != sensors)
    throw InputError(SourceLocation{direct_path, 0, 0}, "holds " + std::to_string(x.direct.sensors) +
                                                            " sensors, the grid's sensors.csv " + std::to_string(sensors));
  for (const std::string& path : {coefficients_path, bins_path})
    if (!fs::exists(path))
      throw InputError(SourceLocation{path, 0, 0}, "missing: the exact-sun mode needs it beside " + direct_path +
                                                       " (`dayphoton run` writes both with outputs.coefficients)");
  x.sun_coefficients = RadianceMatrix::read_file(coefficients_path, read_options);
  const std::vector<int> patches = read_sun_bin_patches(bins_path);
  try {
    x.bins = engine::SunBins::from_patches(patches, x.direct.sun_bins_mf);
  } catch (const std::invalid_argument& e) {
    throw InputError(SourceLocation{bins_path, 0, 0}, std::string(e.what()) + " (MF " +
                                                          std::to_string(x.direct.sun_bins_mf) + " from " +
                                                          direct_path + ")");
  }
  if (x.sun_coefficients.rows() != sensors || x.sun_coefficients.columns() != patches.size() ||
      x.sun_coefficients.components() != 3)
    throw InputError(SourceLocation{coefficients_path, 0, 0},
                     "is " + std::to_string(x.sun_coefficients.rows()) + " x " +
                         std::to_string(x.sun_coefficients.columns()) + " x " +
                         std::to_string(x.sun_coefficients.components()) + "; expected " + std::to_string(sensors) +
                         " sensors x " + std::to_string(patches.size()) + " bins of " + bins_path + " x 3 (RGB)");
  return x;
}

std::vector<std::string> ExactSunNotes::warnings() const {
  std::vector<std::string> w;
  if (suns_nearest > 0) {
    std::ostringstream s;
    s << suns_nearest << " of " << suns << " suns of the weather file are not at a sun position the run exported "
      << "(another site, clock or calendar): their direct sun is that of the nearest exported position, up to "
      << format_number(std::round(largest_nearest_deg * 1000) / 1000) << " deg away (interpolated, not exact; run the "
      << "project with this weather file for the exact direct sun)";
    w.push_back(s.str());
  }
  if (suns_renormalised + suns_nearest_bin > 0) {
    std::ostringstream s;
    s << suns_renormalised + suns_nearest_bin << " of " << suns << " suns need sun bins the run did not trace (its "
      << "weather file had no sun there): their indirect sun comes from the traced bins of their stencil, "
      << "renormalised";
    if (suns_nearest_bin) s << " (" << suns_nearest_bin << " from the nearest bin alone)";
    w.push_back(s.str());
  }
  return w;
}

metrics::IlluminanceTable exported_direct_sun_table(const DirectSunExport& e, const std::vector<sky::SunRecord>& suns,
                                                    const std::vector<metrics::TimeStamp>& steps,
                                                    const std::string& export_path, ExactSunNotes& notes) {
  const std::size_t n = e.sun_count();
  // Column of each weather sun in the export.
  std::vector<std::size_t> column(suns.size());
  std::size_t too_far = 0;
  double farthest = 0;
  for (std::size_t i = 0; i < suns.size(); ++i) {
    const sky::SunRecord& sun = suns[i];
    if (sun.step >= steps.size())
      throw std::invalid_argument("exact sun: a sun at step " + std::to_string(sun.step) + " of " +
                                  std::to_string(steps.size()));
    const auto at = std::lower_bound(e.steps.begin(), e.steps.end(), sun.step);
    const std::size_t k = static_cast<std::size_t>(at - e.steps.begin());
    if (k < n && e.steps[k] == sun.step && dot(e.directions[k], sun.direction) >= SamePositionCos) {
      column[i] = k;
      ++notes.suns_exact;
      continue;
    }
    std::size_t best = n;
    double best_cos = -2;
    for (std::size_t j = 0; j < n; ++j) {
      const double c = dot(e.directions[j], sun.direction);
      if (c > best_cos) best_cos = c, best = j;
    }
    const double angle = best < n ? angle_deg(e.directions[best], sun.direction) : 180.0;
    if (best == n || angle > NearestSunLimit_deg) {
      ++too_far;
      farthest = std::max(farthest, angle);
      continue;
    }
    column[i] = best;
    ++notes.suns_nearest;
    notes.largest_nearest_deg = std::max(notes.largest_nearest_deg, angle);
  }
  notes.suns += suns.size();
  if (too_far > 0)
    throw InputError(SourceLocation{export_path, 0, 0},
                     std::to_string(too_far) + " of " + std::to_string(suns.size()) +
                         " suns of the weather file are farther than " + format_number(NearestSunLimit_deg) +
                         " deg (up to " + format_number(std::round(farthest * 10) / 10) +
                         " deg) from every sun position the run exported (" + e.site +
                         "): their direct sun needs the geometry; run the project with this weather file, or use "
                         "--sun spread (the sun spread into the sky patches, no ASE)");
  // Dense per-sensor rows of e for the exported suns used, as direct_sun_table multiplies.
  metrics::IlluminanceTable table(steps, e.sensors);
  std::vector<double> row(n);
  for (std::size_t s = 0; s < e.sensors; ++s) {
    std::fill(row.begin(), row.end(), 0.0);
    for (std::size_t i = e.row_start[s]; i < e.row_start[s + 1]; ++i) row[e.sun[i]] = e.lux[i];
    for (std::size_t i = 0; i < suns.size(); ++i)
      table.lux(suns[i].step, s) = static_cast<float>(row[column[i]] * suns[i].disc_radiance);
  }
  return table;
}

metrics::IlluminanceTable exported_indirect_sun_table(const RadianceMatrix& bin_coefficients,
                                                      const engine::SunBins& bins,
                                                      const std::vector<sky::SunRecord>& suns,
                                                      const std::vector<metrics::TimeStamp>& steps,
                                                      ExactSunNotes& notes) {
  std::vector<engine::SunStencil> stencils(suns.size());
  bool all_inside = true;
  for (std::size_t i = 0; i < suns.size(); ++i) {
    try {
      stencils[i] = bins.weights(suns[i].direction);
      continue;
    } catch (const std::out_of_range&) {
      all_inside = false;
    }
    const engine::SunStencil patches = engine::patch_stencil(bins.basis(), suns[i].direction);
    engine::SunStencil kept;
    double sum = 0;
    for (int k = 0; k < patches.count; ++k)
      for (std::size_t b = 0; b < bins.size(); ++b)
        if (bins.patch(b) == patches.index[std::size_t(k)]) {
          kept.index[std::size_t(kept.count)] = static_cast<int>(b);
          kept.weight[std::size_t(kept.count)] = patches.weight[std::size_t(k)];
          sum += patches.weight[std::size_t(k)];
          ++kept.count;
        }
    if (kept.count > 0) {
      for (int k = 0; k < kept.count; ++k) kept.weight[std::size_t(k)] /= sum;
      ++notes.suns_renormalised;
    } else {
      std::size_t best = 0;
      for (std::size_t b = 1; b < bins.size(); ++b)
        if (dot(bins.direction(b), suns[i].direction) > dot(bins.direction(best), suns[i].direction)) best = b;
      kept.count = bins.size() ? 1 : 0;
      kept.index[0] = static_cast<int>(best);
      kept.weight[0] = 1.0;
      ++notes.suns_nearest_bin;
    }
    stencils[i] = kept;
  }
  if (all_inside) return indirect_sun_table(bin_coefficients, bins, suns, steps);
  // indirect_sun_table's sums with these stencils.
  const Vec3 w = RgbLuminanceWeights * RadianceWhiteEfficacy_lm_per_W;
  const std::size_t n_sensors = bin_coefficients.rows(), n_bins = bins.size();
  std::vector<double> lux(n_sensors * n_bins);
  for (std::size_t s = 0; s < n_sensors; ++s)
    for (std::size_t j = 0; j < n_bins; ++j) {
      double e = 0;
      for (int c = 0; c < 3; ++c) e += w[c] * double(bin_coefficients.at(s, j, c));
      lux[s * n_bins + j] = e;
    }
  metrics::IlluminanceTable table(steps, n_sensors);
  for (std::size_t i = 0; i < suns.size(); ++i)
    for (std::size_t s = 0; s < n_sensors; ++s) {
      double e = 0;
      for (int k = 0; k < stencils[i].count; ++k)
        e += stencils[i].weight[std::size_t(k)] * lux[s * n_bins + std::size_t(stencils[i].index[std::size_t(k)])];
      table.lux(suns[i].step, s) = static_cast<float>(e * suns[i].disc_radiance);
    }
  return table;
}

AnnualStudy annual_study_exact_sun(const RadianceMatrix& sky_coefficients, const ExactSunExport& exported,
                                   const SkyAndSuns& ss, const AnnualStudySettings& settings,
                                   const std::string& grid_dir, ExactSunNotes& notes,
                                   const SubPatchShares* shares) {
  const metrics::IlluminanceTable direct = exported_direct_sun_table(
      exported.direct, ss.suns, ss.sky.steps, in_folder(grid_dir, DirectSunFileName), notes);
  const metrics::IlluminanceTable indirect =
      exported_indirect_sun_table(exported.sun_coefficients, *exported.bins, ss.suns, ss.sky.steps, notes);
  return compute_annual_study_with_sun(sky_coefficients, ss.sky, direct, indirect, settings, shares);
}

}  // namespace dayphoton::study
