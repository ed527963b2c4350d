// SkyModel: the luminance distribution of a sky (without the sun disc), and the factories of
// the analytic skies: uniform, CIE standard overcast, the 15 ISO 15469 / CIE S 011 general
// skies. The Perez all-weather sky has its own header (perez.h) because it carries inputs and
// diagnostics of its own.
//
// Conventions (../shared/facts/sky-and-metrics.md section 0, DESIGN.md section 4):
//  - directions are unit vectors in RADIANCE axes: +X east, +Y north, +Z up (zenith);
//  - a sky is defined on the upper hemisphere only (dir.z > 0); below the horizon every sky
//    returns 0 -- the ground is a separate source, see ground_radiance_rgb();
//  - radiance is RADIANCE RGB in W/(sr m^2); our skies are grey (R = G = B) and the value is
//    luminance / 179 lm/W, so that rgb_to_photometric(radiance_rgb(d)) == luminance_cd_m2(d)
//    (core/units.h: the RGB weights sum to 1);
//  - the sun disc is never part of a SkyModel (it is a separate source of the engine).
//
// Coarse objects, so plain virtual dispatch (STYLE.md A.8); concrete classes live in
// anonymous namespaces of their .cpp files and only the factories are exported.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "dayphoton/core/vec3.h"

namespace dayphoton::sky {

/// A sky luminance distribution over the upper hemisphere.
class SkyModel {
 public:
  virtual ~SkyModel() = default;

  /// Luminance (cd/m^2) seen when looking along `dir` (unit vector, +Z up).
  /// Returns 0 for dir.z <= 0 (below the horizon: the ground is not part of the sky).
  virtual double luminance_cd_m2(const Vec3& dir) const = 0;

  /// RADIANCE RGB radiance (W/(sr m^2)) along `dir`. The default is the grey value
  /// luminance / 179 in each channel, so rgb_to_photometric() of the result is the luminance.
  virtual Vec3 radiance_rgb(const Vec3& dir) const;

  /// Direction the luminance peaks around (the sun), if the model has one. Used to place
  /// the breakpoints of the quadrature; it is the direction the model *uses*, which for the
  /// Perez sky may be the clamped one (see perez.h).
  virtual std::optional<Vec3> sun_direction() const { return std::nullopt; }

  /// Horizontal illuminance (lux) on an unobstructed horizontal plane from this sky alone
  /// (no sun disc, no ground), E = integral of L cos(theta) d omega over the hemisphere,
  /// computed numerically by integrate_cosine_weighted_hemisphere (relative error well
  /// below 1e-4; the tests compare with closed forms and published tables).
  double horizontal_illuminance_lux() const;

  /// The same quantity in closed form, where the model has one (uniform: pi L;
  /// CIE overcast: 7 pi / 9 Lz; ISO 15469 types 1, 3, 5 through the exponential integral E3).
  virtual std::optional<double> analytic_horizontal_illuminance_lux() const { return std::nullopt; }

  /// Luminance at the zenith (cd/m^2).
  double zenith_luminance_cd_m2() const { return luminance_cd_m2(Vec3{0, 0, 1}); }

  /// One line saying what the sky is, with its parameters and units (for run logs).
  virtual std::string description() const = 0;
};

/// Integral over the upper hemisphere of f(dir) cos(theta) d omega, by nested adaptive
/// Gauss-Kronrod (7/15) quadrature in (zenith angle theta, azimuth measured from the peak).
/// `peak` (unit, optional) puts breakpoints at its zenith angle and azimuth, where the
/// circumsolar term of a sky has its kink. The error target is `relative_tolerance` of the
/// result (1e-6 by default; measured errors on Perez and CIE skies are ~1e-10 there).
double integrate_cosine_weighted_hemisphere(const std::function<double(const Vec3&)>& f,
                                            const std::optional<Vec3>& peak,
                                            double relative_tolerance = 1e-6);

/// How to set the absolute level of a sky whose shape is given.
struct SkyScale {
  enum class Kind { ZenithLuminance, HorizontalIlluminance };
  Kind kind = Kind::HorizontalIlluminance;
  double value = 0;  ///< cd/m^2 for ZenithLuminance, lux for HorizontalIlluminance

  static SkyScale zenith_luminance_cd_m2(double v) { return {Kind::ZenithLuminance, v}; }
  /// Diffuse horizontal illuminance of the sky alone (lux), the usual CBDM choice (facts §3.5).
  static SkyScale horizontal_illuminance_lux(double v) { return {Kind::HorizontalIlluminance, v}; }
};

/// Sky of constant luminance (cd/m^2). E_h = pi L.
/// Throws std::invalid_argument for a negative or non-finite luminance.
std::unique_ptr<SkyModel> make_uniform_sky(double luminance_cd_m2);

/// CIE standard overcast sky (Moon & Spencer 1942): L(theta) = Lz (1 + 2 cos theta) / 3,
/// E_h = 7 pi / 9 Lz. Throws std::invalid_argument for a negative or non-finite scale.
std::unique_ptr<SkyModel> make_cie_overcast_sky(const SkyScale& scale);

/// ISO 15469:2004 / CIE S 011/E:2003 standard general sky of `type` 1..15 with the sun
/// along `sun_direction` (unit, +Z up). Relative luminance
///   L/Lz = f(chi) phi(Z) / (f(Zs) phi(0)),  phi(Z) = 1 + a exp(b / cos Z),
///   f(chi) = 1 + c (exp(d chi) - exp(d pi/2)) + e cos^2 chi.
/// With SkyScale::horizontal_illuminance_lux the zenith luminance is chosen so that the
/// numerically integrated horizontal illuminance equals the given value (facts §3.5).
/// Throws std::invalid_argument for a type outside 1..15, a non-unit or non-finite sun
/// direction, a sun below the horizon (the standard defines the sky for a sun above it;
/// types 1, 3 and 5 do not depend on the sun and accept any direction), or a bad scale.
std::unique_ptr<SkyModel> make_cie_general_sky(int type, const Vec3& sun_direction,
                                               const SkyScale& scale);

/// Gradation and indicatrix parameters of an ISO 15469 sky type (facts §3.4).
struct CieGeneralSkyParameters {
  int type = 0;
  double a = 0, b = 0, c = 0, d = 0, e = 0;
  const char* description = "";
};
/// Parameters of `type` 1..15; throws std::invalid_argument otherwise.
const CieGeneralSkyParameters& cie_general_sky_parameters(int type);

/// Ground radiance as RADIANCE computes it (gendaymtx ComputeSky, gensky/gendaylit ground
/// glow; facts §2.4 step 5 and §4.3): a Lambertian ground of reflectance rho lit by the sky
/// and, when the sun is above the horizon (sun_direction.z > 0), by the direct sun:
///   L_ground = rho * (E_sky,h + E_sun,normal * sin(sun altitude)) / (pi * 179)  per channel,
/// in RADIANCE RGB W/(sr m^2). Illuminances in lux; rho per channel in [0, 1].
/// Throws std::invalid_argument for negative or non-finite inputs.
Vec3 ground_radiance_rgb(const Vec3& ground_reflectance_rgb,
                         double sky_horizontal_illuminance_lux,
                         double direct_normal_illuminance_lux, const Vec3& sun_direction);

}  // namespace dayphoton::sky
