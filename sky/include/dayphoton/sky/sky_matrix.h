// Sky vectors and annual sky matrices in a patch basis (RADIANCE row order: bin 0 = ground,
// then the Tregenza/Reinhart sky patches), one column per weather record, RGB radiance in
// W/(sr m^2) ("visible" units: luminance / 179), so that E = C . S with a daylight-coefficient
// matrix C, exactly as dctimestep computes it. Sources: ../shared/facts/sky-and-metrics.md
// sections 2.4, 2.6, 4.3, 4.4 and 6.1 (what gendaymtx does, restated from its source).
//
// Two ways to turn a sky into patch values:
//  - PatchValue::Mean (dayphoton's default): the mean radiance over each patch, by a
//    stratified midpoint rule in solid angle, of the continuous Perez sky, then scaled so
//    that sum(L_i x projected solid angle_i) equals the Perez diffuse horizontal illuminance
//    of the record (the discrete sky keeps the measured diffuse light exactly; the scale
//    corrects the in-patch variation of L with altitude, a few % at low suns for Tregenza).
//  - PatchValue::Centre (gendaymtx compatibility): the Perez relative luminance at each patch
//    centre, normalised by the discrete sum of lv sin(h) Omega over the patches (gendaymtx's
//    rule), times the gendaymtx default sky colour.
// The sun (direct normal illuminance from the Perez 1990 direct efficacy) is either spread
// into the 4 nearest patches (gendaymtx default), left out (gendaymtx -s), kept alone
// (gendaymtx -d), and is always reported as a list of SunRecords for engines that treat the
// sun as its own source.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "dayphoton/core/radiance_matrix.h"
#include "dayphoton/core/vec3.h"
#include "dayphoton/sky/patch_basis.h"
#include "dayphoton/sky/sky_model.h"
#include "dayphoton/sky/solar_position.h"
#include "dayphoton/weather/hourly_weather.h"

namespace dayphoton::sky {

enum class SunInMatrix {
  Spread,  ///< sun added to the 4 nearest sky patches, conserving direct normal illuminance
  None,    ///< sky and ground only (gendaymtx -s)
  Only,    ///< sun only, sky and ground zero (gendaymtx -d)
};

enum class PatchValue { Mean, Centre };

/// gendaymtx's default sky colour (-c 0.960 1.004 1.118), applied to sky patches only.
constexpr Vec3 GendaymtxSkyColour{0.960, 1.004, 1.118};

struct SkyMatrixOptions {
  SunInMatrix sun = SunInMatrix::Spread;
  PatchValue patch_value = PatchValue::Mean;
  SolarPositionOptions solar;           ///< algorithm (SPA or RADIANCE's formulas), refraction
  double ground_reflectance = 0.2;      ///< grey ground, RADIANCE default
  Vec3 sky_colour{1, 1, 1};             ///< multiplies sky patches (not ground, not sun)
  /// Dew point from the weather file (falls back to 11 C where missing) or gendaymtx's fixed 11 C.
  bool dew_point_from_weather = true;
  /// Day of year for the extraterrestrial irradiance: RADIANCE's (ignores 29 Feb) or the calendar's.
  bool radiance_day_of_year = false;
  /// PatchValue::Mean: n x n midpoints per Tregenza-sized patch; ceil(n / MF), at least 2,
  /// for Reinhart MF patches (same sample spacing).
  int mean_samples_per_axis = 6;
  /// Also give SkyMatrix::quadrant_deltas (the annual product's sub-patch correction).
  bool quadrant_deltas = false;

  /// Everything gendaymtx -m MF does by default: RADIANCE sun formulas, centre values, sky
  /// colour, 11 C dew point, RADIANCE day of year.
  static SkyMatrixOptions gendaymtx_compatible();
};

/// The sun of one time step, for engines with their own sun sources.
struct SunRecord {
  std::size_t step = 0;          ///< column of the matrix
  Vec3 direction;                ///< unit vector to the sun
  double direct_normal_illuminance_lux = 0;
  /// Radiance of a 0.533 degree disc giving that illuminance, W/(sr m^2) visible units.
  double disc_radiance = 0;
};

/// The SunRecord of a sun of `direct_normal_illuminance_lux` along `direction` at `step`: its
/// disc radiance spreads the illuminance over the 0.533 degree disc (SunHalfAngle_rad).
SunRecord sun_record(std::size_t step, const Vec3& direction, double direct_normal_illuminance_lux);

/// Records whose direct normal irradiance is > 0 while the centre of the sun is below the
/// horizon at the site (altitude <= 0 by the options' algorithm, at the record's mid-hour):
/// measured direct light that the site's sun cannot bring at that time. build_sky_matrix
/// still spreads their sun into the sky patches nearest to it (SunInMatrix::Spread and Only,
/// as gendaymtx does: facts section 2.6) but lists no SunRecord for them, so an engine with
/// sun sources of its own (the sun-bins mode) leaves their direct light out.
struct BelowHorizonDirect {
  std::size_t records = 0;
  std::size_t records_over_20_W_m2 = 0;  ///< those gendaymtx warns about (GendaymtxBelowHorizonWarning_W_m2)
  double direct_normal_Wh_m2 = 0;        ///< their direct normal irradiation (hourly records)
  double largest_W_m2 = 0;               ///< their largest direct normal irradiance
  double file_direct_normal_Wh_m2 = 0;   ///< the whole file's, for scale
};

struct SkyMatrix {
  RadianceMatrix matrix;            ///< bins x steps x RGB
  /// Steps whose sun centre is above the horizon and whose direct illuminance is > 0. With
  /// SunInMatrix::Spread or Only the same sun is also in the matrix: use one or the other.
  std::vector<SunRecord> suns;
  BelowHorizonDirect below_horizon_direct;
  /// With SkyMatrixOptions::quadrant_deltas: (4 x bins) x steps x 1, row 4 p + q the
  /// luminance (W/(sr m^2), visible units: x 179 lux) of the sky's mean radiance over
  /// quadrant q of patch p (PatchBasis::quadrant) less the matrix's value of the patch, the
  /// sky alone (without the spread sun); zero for the ground, at night and for a uniform
  /// fallback sky. The quadrant means by a QuadrantSamplesPerAxis^2 midpoint rule per
  /// quadrant of a Tregenza-sized patch (the same spacing for Reinhart patches, at least 1),
  /// of the very Perez shape of the patch values, normalised so that the sky of quadrants
  /// keeps the record's Perez diffuse horizontal illuminance (sum of mean x the quadrant's
  /// projected solid angle). Empty otherwise.
  RadianceMatrix quadrant_deltas;
};

/// Midpoints per axis of a Tregenza-sized patch's quadrant for SkyMatrix::quadrant_deltas
/// (the spacing of the patch means' default 6 x 6 per patch).
constexpr int QuadrantSamplesPerAxis = 3;

/// The weather file header's site (position, time zone, elevation): what RADIANCE's gendaymtx
/// computes the sun for. A project computes it for its own site (study/sun_site.h).
SolarSite solar_site_of(const weather::HourlyWeather& weather);

/// The annual sky matrix of a weather file, with the sun of `site` and the file's irradiance.
/// The records' hours are local standard time of the file's time zone (its header), so
/// site.time_zone_h must equal it (std::invalid_argument otherwise: a record would be paired
/// with the sun of another instant). Throws InputError naming the record and field when a
/// record needed for a daytime sky lacks its direct normal or diffuse horizontal irradiance.
SkyMatrix build_sky_matrix(const weather::HourlyWeather& weather, const SolarSite& site, const PatchBasis& basis,
                           const SkyMatrixOptions& options);

/// The sun of every record whose sun centre is above the horizon at `site`, whatever the
/// record's irradiance (direct normal illuminance and disc radiance 0): the positions, at the
/// same instants and by the same formulas (options.solar) as build_sky_matrix's suns, so
/// every SkyMatrix::suns direction of a weather file on this clock is among them. For
/// engines that prepare the direct sun of any weather file of the site (a night record, or
/// one without direct light in this file, may have it in another). Throws as build_sky_matrix
/// for a site on another clock.
std::vector<SunRecord> daytime_sun_positions(const weather::HourlyWeather& weather, const SolarSite& site,
                                             const SkyMatrixOptions& options);

/// BelowHorizonDirect of build_sky_matrix(weather, site, basis, options) without building the
/// matrix (the sun positions alone: milliseconds for a year). Same time-zone rule.
BelowHorizonDirect below_horizon_direct(const weather::HourlyWeather& weather, const SolarSite& site,
                                        const SkyMatrixOptions& options);

/// A sky vector (bins x 1 x RGB) for one sky model with a uniform ground of the given radiance.
RadianceMatrix sky_vector(const SkyModel& sky, const PatchBasis& basis, const Vec3& ground_radiance_rgb,
                          PatchValue patch_value = PatchValue::Mean, int mean_samples_per_axis = 6);

/// The quadrant deltas of one sky model's vector (sky_vector, PatchValue::Mean), in
/// SkyMatrix::quadrant_deltas' layout and units ((4 x bins) x 1 x 1, luminance): the sky's
/// mean luminance over each quadrant of each sky bin by the same QuadrantSamplesPerAxis^2
/// midpoint rule, normalised so that the sky of quadrants keeps the model's horizontal
/// illuminance, less the vector's bin value; zero for the ground. For the sub-patch correction
/// of one sky's photon part (a point-in-time case's CIE sky). std::invalid_argument unless
/// `vector` is bins x 1 x 3.
RadianceMatrix sky_vector_quadrant_deltas(const SkyModel& sky, const PatchBasis& basis, const RadianceMatrix& vector);

/// Horizontal illuminance (lux) of a sky column: sum over sky patches of 179 L x (integral of
/// cos(theta) over the patch), L the RADIANCE luminance of the RGB triple; ground excluded.
/// Exact for PatchValue::Mean columns; Centre columns are normalised with gendaymtx's
/// sin(h_centre) Omega weights instead and differ from it by up to ~1 % (horizon band).
double column_horizontal_illuminance_lux(const RadianceMatrix& matrix, std::size_t column,
                                         const PatchBasis& basis);

}  // namespace dayphoton::sky
