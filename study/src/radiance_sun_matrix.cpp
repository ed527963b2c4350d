// The sun coefficients on RADIANCE's Reinhart patch basis; see radiance_sun_matrix.h.
#include "dayphoton/study/radiance_sun_matrix.h"

#include <algorithm>
#include <set>
#include <stdexcept>

#include "dayphoton/sky/solar_position.h"
#include "dayphoton/sky/spread_sun.h"
#include "dayphoton/study/annual_sun.h"
#include "dayphoton/study/artifact_codec.h"
#include "dayphoton/study/sensor_blocks.h"
#include "dayphoton/study/cache_keys.h"
#include "dayphoton/study/plan_step.h"

namespace dayphoton::study {

std::string radiance_sun_matrix_name(int mf) { return "coefficients_sun_mf" + std::to_string(mf) + ".mtx"; }

std::vector<int> radiance_sun_patches(const sky::PatchBasis& basis, const std::vector<sky::SunRecord>& suns) {
  std::set<int> patches;
  for (const sky::SunRecord& sun : suns) {
    const sky::SpreadSunPatches spread = sky::spread_sun_patches(basis, sun.direction);
    patches.insert(spread.bin.begin(), spread.bin.end());
  }
  return {patches.begin(), patches.end()};
}

std::vector<sky::SunRecord> patch_centre_suns(const sky::PatchBasis& basis, const std::vector<int>& patches) {
  std::vector<sky::SunRecord> suns;
  for (int p : patches) suns.push_back(sky::sun_record(PatchSunStepOffset + static_cast<std::size_t>(p), basis.centre(p), 0));
  return suns;
}

RadianceSunMatrix radiance_sun_matrix(const std::vector<int>& patches, const RadianceMatrix& direct,
                                      const engine::SunBins& bins, const RadianceMatrix& bin_coefficients) {
  const sky::PatchBasis& basis = bins.basis();
  const std::size_t sensors = direct.rows();
  if (direct.columns() != patches.size() || direct.components() != 3)
    throw std::invalid_argument("radiance_sun_matrix: direct has " + std::to_string(direct.columns()) + " columns for " +
                                std::to_string(patches.size()) + " patches");
  if (bin_coefficients.rows() != sensors || bin_coefficients.columns() != bins.size() || bin_coefficients.components() != 3)
    throw std::invalid_argument("radiance_sun_matrix: the sun-bin coefficients do not match the bins and sensors");
  // The bin of each patch, or the nearest bin (largest cosine between the centres).
  std::vector<int> bin_of_patch(static_cast<std::size_t>(basis.bin_count()), -1);
  for (std::size_t i = 0; i < bins.size(); ++i) bin_of_patch[static_cast<std::size_t>(bins.patch(i))] = static_cast<int>(i);
  RadianceSunMatrix r;
  r.matrix = RadianceMatrix(sensors, static_cast<std::size_t>(basis.bin_count()), 3);
  for (std::size_t k = 0; k < patches.size(); ++k) {
    const int p = patches[k];
    if (p < 1 || p >= basis.bin_count()) throw std::invalid_argument("radiance_sun_matrix: patch out of the basis");
    int bin = bin_of_patch[static_cast<std::size_t>(p)];
    if (bin < 0 && bins.size() > 0) {
      ++r.patches_without_bin;
      double best = -2;
      for (std::size_t i = 0; i < bins.size(); ++i) {
        const double c = dot(bins.direction(i), basis.centre(p));
        if (c > best) {
          best = c;
          bin = static_cast<int>(i);
        }
      }
    }
    // Radiance x solid angle is conserved: a patch of radiance S_p stands for a disc of
    // radiance S_p Omega_p / Omega_sun.
    const double scale = basis.solid_angle_sr(p) / sky::sun_disc_solid_angle_sr();
    for (std::size_t s = 0; s < sensors; ++s)
      for (int c = 0; c < 3; ++c) {
        double v = direct.at(s, k, c);
        if (bin >= 0) v += bin_coefficients.at(s, static_cast<std::size_t>(bin), c);
        r.matrix.at(s, static_cast<std::size_t>(p), c) = static_cast<float>(scale * v);
      }
  }
  r.patches = patches.size();
  return r;
}

std::string write_radiance_sun_matrix(const engine::Scene& scene, const std::vector<engine::Material>& materials,
                                      const SensorGrid& grid, const ContentHash& scene_hash,
                                      const engine::SunBins& bins, const RadianceMatrix& bin_coefficients,
                                      const std::vector<sky::SunRecord>& daytime_suns, int samples,
                                      std::uint64_t seed, StepExecutor& executor, const std::string& path,
                                      MatrixFormat format) {
  const std::vector<int> patches = radiance_sun_patches(bins.basis(), daytime_suns);
  const std::vector<sky::SunRecord> suns = patch_centre_suns(bins.basis(), patches);
  std::vector<std::size_t> steps;
  std::vector<Vec3> directions;
  for (const sky::SunRecord& s : suns) {
    steps.push_back(s.step);
    directions.push_back(s.direction);
  }
  const std::string key = direct_sun_key(scene_hash, grid, steps, directions, samples, seed);
  RadianceMatrix direct;
  Step step = make_step(
      StepKind::DirectSun, 0, ArtifactId{"sun-direct", key}, direct,
      [&] { return direct_sun_coefficients(scene, materials, grid.points, suns, samples, seed); }, encode_matrix,
      decode_matrix,
      [&](const RadianceMatrix& m) { return m.rows() == grid.points.size() && m.columns() == suns.size(); });
  step.blocks = matrix_sensor_blocks(grid.points.size(), [&](engine::SensorRange rows) {
    return direct_sun_coefficients(scene, materials, grid.points, suns, samples, seed, DirectSunValues::Rgb, rows);
  });
  const bool cached = !executor.run(step);
  if (!executor.writes_results()) return {};  // another rank than 0 of an MPI run: rank 0 writes the file
  RadianceSunMatrix d = radiance_sun_matrix(patches, direct, bins, bin_coefficients);
  const int mf = bins.multiplication_factor();
  d.matrix.header_lines().push_back(
      "dayphoton sun matrix: irradiance per unit patch radiance of `gendaymtx -m " + std::to_string(mf) +
      " -d` (sun only): (patch solid angle / sun disc solid angle) x (direct sun at the patch centre + sun-bin "
      "coefficients); rows = sensors.csv, columns = Reinhart MF " + std::to_string(mf) + " patches (0 = ground)");
  d.matrix.write_file(path, format);
  return radiance_sun_matrix_name(mf) + ": " + std::to_string(d.patches) + " patches of Reinhart MF " +
         std::to_string(mf) + " reached by the site's daytime suns (" + std::to_string(d.patches_without_bin) +
         " without a sun bin, given the nearest bin's indirect sun); their direct sun " +
         (cached ? std::string("cached") : "traced at " + std::to_string(grid.points.size()) + " sensors");
}

}  // namespace dayphoton::study
