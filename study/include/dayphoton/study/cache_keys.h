// Cache keys of the pipeline's artefacts (docs/cache.md): what each step depends on, hashed.
//
//   photons of source p : the scene (materials, surfaces, ports), the receiver planes (height,
//                         facing, outline), the sky basis, source p, the tracing options
//   coefficients of a grid : the photon-pass key of every source, the grid's sensors,
//                         the estimate and direct-sampling options
//   sky matrix          : the weather file's bytes, the site the sun is computed for
//                         (latitude, longitude, time zone, elevation: the project's, or the
//                         header's with site.from_weather, so both give one key when they
//                         are equal), the basis, the ground reflectance, the sky mode (sun
//                         spread or excluded); in the sun-bins mode the hourly suns are
//                         stored under the same key
// Sun bins (`sun: bins`, study/annual_sun.h):
//   photons of a sun bin: the scene, the receiver planes, the bin's Reinhart MF and patch
//                         (its direction), the disc's radius, the tracing options; NOT the
//                         weather file, so another year's suns reuse every bin they share
//   sun coefficients of a grid: the photon key of every sun bin, the selection rule, the
//                         grid's sensors, the estimate options
//   direct sun of a grid : the scene, the grid's sensors, each sun's step and direction (not
//                         its radiance: the coefficients are per unit radiance), the number
//                         of shadow rays and the seed
// A changed sensor spacing therefore re-estimates without re-tracing (the plane is the same);
// a changed weather file re-multiplies only (and re-traces the direct sun only if a sun
// moved); a changed material re-traces everything.
#pragma once

#include <string>
#include <vector>

#include "dayphoton/core/scene_description.h"
#include "dayphoton/engine/daylight_coefficients.h"
#include "dayphoton/engine/photon_tracer.h"
#include "dayphoton/engine/receiver_plane.h"
#include "dayphoton/sky/patch_basis.h"
#include "dayphoton/sky/solar_position.h"
#include "dayphoton/study/annual_sun.h"
#include "dayphoton/study/content_hash.h"

namespace dayphoton::study {

/// Bumped whenever the engine's output for the same inputs changes (invalidates old caches).
/// 4: photons outdoors after leaving through a port are no longer stored (photon_tracer.h,
/// "Indoors and outdoors"). 5: sources the scaled low-yield cap starved while they carry the
/// light are traced again with the cap in raw attempts (docs/photon-tracing.md, "Low-yield cap").
/// 6: photon records carry their sky ratio (engine/photon.h) and the coefficients the photon
/// part under the daylight factor's continuous sky (engine/photon_part_on_sky.h).
/// 7: the coefficients carry the direct part's sub-patch shares and the annual sky its
/// quadrant deltas (engine/direct_component.h, "Sub-patch shares").
/// 8: a diffusing port (translucent, transmitted_specular < 1) keeps the Direct photons on its
/// sky side, and the photons on it are stored outside the region of interest too
/// (docs/photon-tracing.md, "Region of interest").
/// 9: a glass, glazing or opening port's outward reflection is traced outdoors where the scene
/// has outdoor scatterers (docs/photon-tracing.md, "The first scattering event").
constexpr int EngineCacheVersion = 9;

ContentHash scene_key(const SceneDescription& scene);
ContentHash planes_key(const std::vector<SensorGrid>& grids);
std::string photon_source_key(const ContentHash& scene, const ContentHash& planes,
                              const sky::PatchBasis& basis, std::size_t source,
                              const engine::TracingOptions& options);
/// `near_cut_sensors`: the grid's sensors gathered next to a cut (CaseLayout::near_cut_sensors;
/// with engine::NearCutGather_m in the key when there are any, so other grids' keys stay).
std::string coefficients_key(const std::vector<std::string>& photon_keys, const SensorGrid& grid,
                             const engine::CoefficientOptions& options, std::size_t near_cut_sensors = 0);

/// Sky matrix of a weather file for the sun of `site`: `sun_excluded` false = the
/// RADIANCE-compatible matrix with the sun spread into patches, true = the same without the
/// sun (and the suns beside it).
std::string sky_matrix_key(const std::string& weather_path, const sky::SolarSite& site,
                           const sky::PatchBasis& basis, double ground_reflectance, bool sun_excluded);
/// Photons of one sun bin: patch `patch` of Reinhart MF `mf`, a disc of `half_angle_rad`.
std::string sun_photon_key(const ContentHash& scene, const ContentHash& planes, int mf, int patch,
                           double half_angle_rad, const engine::TracingOptions& options);
/// Photon coefficients of a grid for the sun bins; `minimum_bound_fraction` is the rule that
/// selects the bins traced (annual_sun.h).
std::string sun_coefficients_key(const std::vector<std::string>& sun_photon_keys,
                                 double minimum_bound_fraction, const SensorGrid& grid,
                                 const engine::CoefficientOptions& options, std::size_t near_cut_sensors = 0);
/// Exact direct sun of a grid for these suns (steps and directions), RGB or luminance values.
std::string direct_sun_key(const ContentHash& scene, const SensorGrid& grid,
                           const std::vector<std::size_t>& steps, const std::vector<Vec3>& directions,
                           int samples, std::uint64_t seed, DirectSunValues values = DirectSunValues::Rgb);

}  // namespace dayphoton::study
