// The sun coefficients on RADIANCE's Reinhart patch basis: coefficients_sun_mf<N>.mtx, the
// matrix D that a sun-only sky matrix of RADIANCE's `gendaymtx -m N -d` multiplies (with
// dctimestep or rmtxop) into the direct + indirect sun of every hour (docs/sun.md, "The sun
// matrix for RADIANCE"; docs/outputs.md).
//
// gendaymtx -d puts the sun of an hour, of direct normal illuminance E_n, into the 4 patches
// nearest to it (sky/spread_sun.h) as radiance S_p = w_p E_n / (179 Omega_p). dayphoton's sun
// of that hour is a 0.533 deg disc of radiance L = E_n / (179 Omega_sun) whose irradiance at
// sensor s is L C(sun)[s], C = exact direct sun + interpolated sun bins (annual_sun.h). So with
//     D[s][p] = (Omega_p / Omega_sun) C(centre of p)[s]
// D S = L sum_p w_p C(centre of p): the sun's irradiance with the sun moved to the 4 patch
// centres and averaged with gendaymtx's weights (the approximation of RADIANCE's 5-phase
// method, at MF N's patch spacing). C(centre of p) = the direct sun traced at the patch centre
// (SunDirectSamples stratified rays over the disc) + the sun-bin coefficients of p (the sun
// bins are MF N patch centres; a patch without a bin takes the nearest bin's, counted).
// The ground bin (0) and patches no daytime sun of the site reaches are zero columns: gendaymtx
// -d puts nothing there for a weather file of the same site.
//
// For `gendaymtx -5 0.533 -d` (the sun in the one nearest patch with the disc's own solid
// angle) the matrix would be D[s][p] Omega_sun / Omega_p; not written.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "dayphoton/core/radiance_matrix.h"
#include "dayphoton/core/scene_description.h"
#include "dayphoton/engine/material.h"
#include "dayphoton/engine/scene.h"
#include "dayphoton/engine/sun_bins.h"
#include "dayphoton/sky/patch_basis.h"
#include "dayphoton/sky/sky_matrix.h"
#include "dayphoton/study/step_executor.h"
#include "dayphoton/study/content_hash.h"

namespace dayphoton::study {

/// The random streams of the patch-centre suns are those of steps PatchSunStepOffset + patch,
/// apart from every weather record's step.
constexpr std::size_t PatchSunStepOffset = std::size_t(1) << 30;

/// The file name for Reinhart MF `mf`: "coefficients_sun_mf6.mtx".
std::string radiance_sun_matrix_name(int mf);

/// The patches gendaymtx spreads these suns into (spread_sun_patches), sorted, once each.
std::vector<int> radiance_sun_patches(const sky::PatchBasis& basis, const std::vector<sky::SunRecord>& suns);

/// Suns at the centres of `patches` (step PatchSunStepOffset + patch, radiance 0): what
/// direct_sun_coefficients traces for D.
std::vector<sky::SunRecord> patch_centre_suns(const sky::PatchBasis& basis, const std::vector<int>& patches);

struct RadianceSunMatrix {
  RadianceMatrix matrix;               ///< sensors x basis.bin_count() x RGB
  std::size_t patches = 0;             ///< non-zero columns
  std::size_t patches_without_bin = 0; ///< of which took the nearest sun bin's coefficients
};

/// D from the direct sun at the patch centres (`direct`: sensors x patches.size() x RGB, per
/// unit disc radiance, direct_sun_coefficients of patch_centre_suns) and the sun bins'
/// coefficients (`bin_coefficients`: sensors x bins.size() x RGB). `bins` must be on the
/// basis of `patches` (Reinhart MF bins.multiplication_factor()). Throws std::invalid_argument
/// on shape mismatches.
RadianceSunMatrix radiance_sun_matrix(const std::vector<int>& patches, const RadianceMatrix& direct,
                                      const engine::SunBins& bins, const RadianceMatrix& bin_coefficients);

/// For one grid of a sun-bins run with outputs.coefficients: the patches of the site's daytime
/// suns (`daytime_suns`: every daytime position, with or without direct light), their direct
/// sun (a cached step of the executor, kind "sun-direct"), D, written to `path` in `format` with a
/// header saying what it is. Returns a line for the run log (patches, how many without a bin,
/// traced or cached). Where the executor does not write results (the ranks other than 0 of an
/// MPI run) only the step runs: nothing is written, the line is empty.
std::string write_radiance_sun_matrix(const engine::Scene& scene, const std::vector<engine::Material>& materials,
                                      const SensorGrid& grid, const ContentHash& scene_hash,
                                      const engine::SunBins& bins, const RadianceMatrix& bin_coefficients,
                                      const std::vector<sky::SunRecord>& daytime_suns, int samples,
                                      std::uint64_t seed, StepExecutor& executor, const std::string& path,
                                      MatrixFormat format);

}  // namespace dayphoton::study
