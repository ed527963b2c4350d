// Perez all-weather sky (Perez, Seals & Michalsky 1993, Solar Energy 50(3):235-245, Table 1
// with the erratum in Solar Energy 51(5):423) and the Perez 1990 luminous efficacies (Perez,
// Ineichen, Seals, Michalsky & Stewart 1990, Solar Energy 44(5):271-289, eqs. 1-3, 7, 8).
// Numbers, clamps and edge cases as RADIANCE's gendaymtx applies them (LBNL-ETA/Radiance
// 2025), restated in ../shared/facts/sky-and-metrics.md §2. docs/sky-models.md has the
// decisions.
//
// Inputs are plain numbers (no weather types): direct normal and diffuse horizontal
// irradiance (W/m^2, hourly means of an EPW record), the sun direction used for the record,
// the day of year and the dew point.
//
// The sky is the continuous Perez function, normalised so that its horizontal illuminance
// (numerical quadrature over the hemisphere) equals E_d * eta_diffuse. The sun disc is not
// part of the sky; direct_normal_illuminance_lux in the state is what a sun source needs.
#pragma once

#include <memory>
#include <optional>

#include "dayphoton/core/vec3.h"
#include "dayphoton/sky/sky_model.h"

namespace dayphoton::sky {

/// gendaymtx's fixed dew point (NREL gendaymtx: 11 deg C, i.e. precipitable water 2.0037 cm);
/// used when no dew point is given.
constexpr double PerezDefaultDewPoint_C = 11.0;

/// gendaymtx warns about direct normal irradiance above this while the sun is below the
/// horizon (facts section 2.6); it keeps their sun in the nearest patches all the same.
constexpr double GendaymtxBelowHorizonWarning_W_m2 = 20.0;

struct PerezInputs {
  double direct_normal_irradiance_W_m2 = 0;     ///< I, >= 0
  double diffuse_horizontal_irradiance_W_m2 = 0;  ///< E_d, >= 0
  Vec3 sun_direction{0, 0, 1};  ///< unit vector toward the sun (+Z up); may be below the horizon
  int day_of_year = 1;          ///< J in 1..366, for the extraterrestrial irradiance
  std::optional<double> dew_point_C;  ///< surface dew point (deg C); default 11 deg C
};

/// Everything the model derived from its inputs, including which clamps acted.
struct PerezState {
  // Geometry.
  double sun_altitude_rad = 0;       ///< of the given direction
  double sun_zenith_rad = 0;         ///< Z used by the model (clamped to [3 deg, 90 deg])
  bool sun_zenith_clamped = false;   ///< altitude <= 0 (Z := 90 deg) or >= 87 deg (Z := 3 deg)
  Vec3 model_sun_direction{0, 0, 1};  ///< the direction at zenith angle Z, same azimuth
  bool sun_below_horizon_with_direct = false;  ///< altitude <= 0 and I > 20 W/m^2 (gendaymtx warns)
  bool night = false;                ///< I + E_d <= 1e-4 W/m^2: zero sky

  // Atmosphere.
  double air_mass = 0;               ///< Kasten 1966
  double eccentricity = 0;           ///< E0 (Sen 2008 series)
  double dew_point_C = PerezDefaultDewPoint_C;
  bool dew_point_defaulted = false;
  double precipitable_water_cm = 0;  ///< W = exp(0.07 T_d - 0.075)

  // Sky condition.
  double epsilon_unclamped = 0;  ///< sky clearness before clamping (inf if E_d = 0)
  double epsilon = 0;            ///< clamped to [1, 11.9]
  bool epsilon_clamped = false;
  double delta_unclamped = 0;    ///< sky brightness before clamping
  double delta = 0;              ///< clamped to [0.01, 0.6]; used by the efficacies
  bool delta_clamped = false;
  double delta_luminance = 0;    ///< delta used for a..e (raised to 0.2 if 1.065 < eps < 2.8)
  bool delta_raised_to_0_2 = false;
  int bin = 1;                   ///< clearness bin 1..8 (Perez 1990 Table 1)

  // Luminance distribution parameters lv = [1 + a e^(b/cos zeta)][1 + c e^(d gamma) + e cos^2 gamma].
  double a = 0, b = 0, c = 0, d = 0, e = 0;
  bool b_positive_clamped = false;  ///< b > 0 (diverges at the horizon) was set to 0

  // Photometry.
  double diffuse_efficacy_lm_W = 0;  ///< Perez 1990 eq. 7
  double direct_efficacy_lm_W = 0;   ///< Perez 1990 eq. 8 (>= 0)
  double diffuse_horizontal_illuminance_lux = 0;  ///< E_d * eta_diffuse: the sky's target
  double direct_normal_illuminance_lux = 0;       ///< I * eta_direct: for the sun source
};

/// The derived state, without building a sky (cheap: no quadrature).
/// Throws std::invalid_argument for negative or non-finite irradiances, a non-unit sun
/// direction, a day of year outside 1..366 or a non-finite dew point.
PerezState perez_state(const PerezInputs& inputs);

/// Perez 1993 relative luminance lv(zeta, gamma) for the parameters of `state`, clamped at 0
/// as gendaymtx does. zeta: zenith angle of the sky element, gamma: its angle to the sun.
double perez_relative_luminance(const PerezState& state, double zeta_rad, double gamma_rad);

/// Perez 1990 efficacies (lm/W) for a clearness bin 1..8, precipitable water W (cm), sun
/// zenith Z (rad) and sky brightness Delta. Global (not needed for the sky), diffuse (eq. 7),
/// direct (eq. 8, clamped at 0).
double perez_global_efficacy_lm_W(int bin, double water_cm, double zenith_rad, double delta);
double perez_diffuse_efficacy_lm_W(int bin, double water_cm, double zenith_rad, double delta);
double perez_direct_efficacy_lm_W(int bin, double water_cm, double zenith_rad, double delta);

/// Clearness bin 1..8 of a (clamped) epsilon: lower <= eps < upper, Perez 1990 Table 1.
int perez_clearness_bin(double epsilon);

struct PerezSky {
  std::unique_ptr<SkyModel> sky;  ///< luminance over the hemisphere (zero at night)
  PerezState state;               ///< diagnostics: epsilon, delta, bin, parameters, clamps
  /// integral of lv cos(zeta) d omega over the hemisphere (the normalisation divisor);
  /// 0 if the sky is zero; pi if lv vanished everywhere and the uniform fallback was used.
  double relative_horizontal_integral = 0;
  bool uniform_fallback = false;  ///< lv integrated to ~0: uniform sky (as gendaymtx)
};

/// Perez all-weather sky for one time step, normalised to E_d * eta_diffuse (lux).
PerezSky make_perez_sky(const PerezInputs& inputs);

}  // namespace dayphoton::sky
