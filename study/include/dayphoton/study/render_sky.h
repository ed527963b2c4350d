// The sky of a rendering (`dayphoton render --sky ...`, issue 7 item 3): one specification
// turned into what engine::PhotonRenderer needs (renderer.h): the continuous sky and ground
// radiance for directions seen through the glazing, the per-bin radiances that weight the
// photons (the sky vector of the same sky, as the daylight factor uses it), and the sun disc.
//
//   overcast   CIE standard overcast sky (no sun), diffuse horizontal illuminance E (lux)
//   uniform    uniform sky of luminance E / pi
//   cie:N      ISO 15469 general sky type N (1..15) with the sun position given; its sun
//              disc is not part of the standard sky (as gensky's skies without +s)
//   hour:M/D/H one record of the project's weather file (the record whose interval
//              (h - 1, h] holds H, local standard time): the Perez all-weather sky of that
//              record (NREL SPA sun position at the record's mid-hour for the project's
//              site, study/sun_site.h; the weather file's dew point) and its sun disc (0.533 deg, Perez 1990 direct efficacy). The sun is
//              not in the bins' radiances: add_sun_source() makes it a photon source of its
//              own (its inter-reflected light then has photons of its own, instead of a few
//              heavy photons of the bin that holds it); the directly lit patches come from
//              the disc itself (shadow rays).
// The ground below the horizon is RADIANCE's ground glow: a Lambertian ground of the
// project's ground reflectance lit by the sky and the sun (sky_model.h ground_radiance_rgb).
#pragma once

#include <string>
#include <vector>

#include "dayphoton/engine/distant_source.h"
#include "dayphoton/engine/renderer.h"
#include "dayphoton/project/project.h"
#include "dayphoton/sky/patch_basis.h"

namespace dayphoton::study {

struct RenderSkySettings {
  std::string spec = "overcast";           ///< see the header comment
  double horizontal_illuminance_lux = 10000;  ///< overcast, uniform, cie:N
  double sun_altitude_deg = 45, sun_azimuth_deg = 180;  ///< cie:N (azimuth clockwise from north)
};

struct RenderSkyResult {
  engine::RenderSky sky;
  std::string description;  ///< one line for the EXR header and the log
};

/// Photons of the sun source relative to a sky bin: through a window the direct sun brings
/// typically hundreds of times the light of one Tregenza bin, so by the Neyman allocation
/// argument of engine::TracingOptions::source_photon_factor it deserves many more photons;
/// 64 keeps the photon pass within a few times that of the sky alone.
constexpr double SunPhotonFactor = 64.0;

/// If the sky has a sun: append its disc to `sources` (SourceSet::add_sun_disc), its radiance
/// to sky.source_radiance and SunPhotonFactor to `photon_factor` (one entry per source).
/// Nothing otherwise.
void add_sun_source(engine::RenderSky& sky, engine::SourceSet& sources, std::vector<double>& photon_factor);

/// Build the sky. Throws std::invalid_argument for a bad specification (the message says
/// what is expected) and InputError if the hour is not in the weather file or the record
/// lacks its irradiances.
RenderSkyResult make_render_sky(const RenderSkySettings& settings, const project::Project& project,
                                const sky::PatchBasis& basis);

}  // namespace dayphoton::study
