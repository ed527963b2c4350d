// ISO 15469:2004 / CIE S 011/E:2003 "Spatial distribution of daylight -- CIE standard general
// sky": 15 sky types from overcast to cloudless turbid. Formulas and parameter table restated
// from ../shared/facts/sky-and-metrics.md §3.4 (the 2004 parameters, identical in >= 4
// independent code bases; Darula & Kittler 2002):
//   gradation   phi(Z)  = 1 + a exp(b / cos Z)  for 0 <= Z < pi/2,  phi(pi/2) = 1
//   indicatrix  f(chi)  = 1 + c [exp(d chi) - exp(d pi/2)] + e cos^2 chi
//   L(Z, alpha) / Lz = f(chi) phi(Z) / (f(Zs) phi(0)),
//   cos chi = cos Zs cos Z + sin Zs sin Z cos|alpha - alpha_s|  (= dir . sun)
// Z: zenith angle of the sky element, Zs: of the sun, chi: angle between element and sun.
//
// Parameters: type 1..15; sun direction (unit vector, +Z up; irrelevant for types 1, 3, 5);
// the level, as zenith luminance Lz (cd/m^2) or as horizontal illuminance of the sky (lux).
// Decision (facts §3.5): the CIE 215 / Darula-Kittler zenith-luminance parametrisations are not
// verified, so we do not guess a zenith luminance: the caller gives Lz or, as in CBDM, the
// diffuse horizontal illuminance D_v, and Lz = D_v / integral (L/Lz) cos Z d omega with the
// integral computed by integrate_cosine_weighted_hemisphere (closed form for 1, 3, 5:
// 2 pi [1/2 + a E3(-b)] / (1 + a e^b), E3 the exponential integral of order 3).
// Tests: D_v/Lz for all 15 types at sun altitudes 15..75 deg (facts §3.5 table), type 12
// against the CIE 110 clear-sky formula (§3.2), type 1 and 5 closed forms.
#include "dayphoton/sky/sky_model.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "dayphoton/core/units.h"

namespace dayphoton::sky {
namespace {

// facts §3.4: type, a, b, c, d, e, description (ISO 15469:2004 Table 1 and 2).
const CieGeneralSkyParameters ParameterTable[15] = {
    {1, 4.0, -0.70, 0, -1.0, 0.00,
     "CIE standard overcast sky, steep luminance gradation towards zenith, azimuthal uniformity"},
    {2, 4.0, -0.70, 2, -1.5, 0.15,
     "overcast, steep luminance gradation and slight brightening towards the sun"},
    {3, 1.1, -0.80, 0, -1.0, 0.00, "overcast, moderately graded with azimuthal uniformity"},
    {4, 1.1, -0.80, 2, -1.5, 0.15, "overcast, moderately graded and slight brightening towards the sun"},
    {5, 0.0, -1.00, 0, -1.0, 0.00, "sky of uniform luminance"},
    {6, 0.0, -1.00, 2, -1.5, 0.15,
     "partly cloudy sky, no gradation towards zenith, slight brightening towards the sun"},
    {7, 0.0, -1.00, 5, -2.5, 0.30,
     "partly cloudy sky, no gradation towards zenith, brighter circumsolar region"},
    {8, 0.0, -1.00, 10, -3.0, 0.45,
     "partly cloudy sky, no gradation towards zenith, distinct solar corona"},
    {9, -1.0, -0.55, 2, -1.5, 0.15, "partly cloudy, with the obscured sun"},
    {10, -1.0, -0.55, 5, -2.5, 0.30, "partly cloudy, with brighter circumsolar region"},
    {11, -1.0, -0.55, 10, -3.0, 0.45, "white-blue sky with distinct solar corona"},
    {12, -1.0, -0.32, 10, -3.0, 0.45, "CIE standard clear sky, low illuminance turbidity"},
    {13, -1.0, -0.32, 16, -3.0, 0.30, "CIE standard clear sky, polluted atmosphere"},
    {14, -1.0, -0.15, 16, -3.0, 0.30, "cloudless turbid sky with broad solar corona"},
    {15, -1.0, -0.15, 24, -2.8, 0.15, "white-blue turbid sky with broad solar corona"},
};

bool depends_on_sun(const CieGeneralSkyParameters& p) { return p.c != 0 || p.e != 0; }

/// Exponential integral E3(x), x > 0, from E1 by the recurrence E_{n+1} = (e^-x - x E_n) / n.
double exponential_integral_e3(double x) {
  const double e1 = -std::expint(-x);  // std::expint is Ei; E1(x) = -Ei(-x) for x > 0
  const double e2 = std::exp(-x) - x * e1;
  return 0.5 * (std::exp(-x) - x * e2);
}

class CieGeneralSky final : public SkyModel {
 public:
  CieGeneralSky(const CieGeneralSkyParameters& p, const Vec3& sun)
      : m_p(p), m_sun(sun), m_sun_dependent(depends_on_sun(p)) {
    const double sun_zenith = std::acos(std::clamp(sun.z, -1.0, 1.0));
    m_relative_norm = 1.0 / (indicatrix(sun_zenith) * gradation(1.0));
  }

  void set_zenith_luminance(double lz) { m_zenith_cd_m2 = lz; }

  /// L / Lz along dir (dir.z > 0).
  double relative_luminance(const Vec3& dir) const {
    if (!(dir.z > 0)) return 0.0;
    double f = 1.0;
    if (m_sun_dependent) f = indicatrix(std::acos(std::clamp(dot(dir, m_sun), -1.0, 1.0)));
    return f * gradation(dir.z) * m_relative_norm;
  }

  /// integral of (L/Lz) cos Z d omega: closed form for the sun-independent types.
  std::optional<double> analytic_relative_horizontal() const {
    if (m_sun_dependent) return std::nullopt;
    const double integral = 0.5 + (m_p.a != 0 ? m_p.a * exponential_integral_e3(-m_p.b) : 0.0);
    return 2 * Pi * integral * m_relative_norm;
  }

  double luminance_cd_m2(const Vec3& dir) const override {
    return m_zenith_cd_m2 * relative_luminance(dir);
  }
  std::optional<Vec3> sun_direction() const override {
    if (m_sun_dependent) return m_sun;
    return std::nullopt;
  }
  std::optional<double> analytic_horizontal_illuminance_lux() const override {
    if (auto r = analytic_relative_horizontal()) return *r * m_zenith_cd_m2;
    return std::nullopt;
  }
  std::string description() const override {
    std::ostringstream s;
    s << "ISO 15469 / CIE S 011 general sky type " << m_p.type << " (" << m_p.description
      << "; a=" << m_p.a << " b=" << m_p.b << " c=" << m_p.c << " d=" << m_p.d << " e=" << m_p.e
      << ")";
    if (m_sun_dependent)
      s << ", sun altitude " << rad_to_deg(std::asin(std::clamp(m_sun.z, -1.0, 1.0))) << " deg";
    s << ", zenith luminance " << m_zenith_cd_m2 << " cd/m2";
    return s.str();
  }

 private:
  /// phi(Z) from cos Z; phi(pi/2) = 1 (b < 0 for every type, so exp(b / cos Z) -> 0).
  double gradation(double cos_z) const {
    if (!(cos_z > 0)) return 1.0;
    return 1.0 + m_p.a * std::exp(m_p.b / cos_z);
  }
  double indicatrix(double chi) const {
    const double cos_chi = std::cos(chi);
    return 1.0 + m_p.c * (std::exp(m_p.d * chi) - std::exp(m_p.d * 0.5 * Pi)) +
           m_p.e * cos_chi * cos_chi;
  }

  CieGeneralSkyParameters m_p;
  Vec3 m_sun;
  bool m_sun_dependent;
  double m_relative_norm = 1;  ///< 1 / (f(Zs) phi(0))
  double m_zenith_cd_m2 = 0;
};

}  // namespace

const CieGeneralSkyParameters& cie_general_sky_parameters(int type) {
  if (type < 1 || type > 15)
    throw std::invalid_argument("CIE general sky: type must be 1..15, got " + std::to_string(type));
  return ParameterTable[type - 1];
}

std::unique_ptr<SkyModel> make_cie_general_sky(int type, const Vec3& sun_direction,
                                               const SkyScale& scale) {
  const CieGeneralSkyParameters& p = cie_general_sky_parameters(type);
  if (!std::isfinite(scale.value) || scale.value < 0)
    throw std::invalid_argument("CIE general sky: the scale must be finite and >= 0");
  Vec3 sun{0, 0, 1};
  if (depends_on_sun(p)) {
    if (!is_finite(sun_direction) || std::abs(length(sun_direction) - 1.0) > 1e-6)
      throw std::invalid_argument("CIE general sky: the sun direction must be a unit vector");
    if (sun_direction.z < 0)
      throw std::invalid_argument("CIE general sky type " + std::to_string(type) +
                                  ": the sun must not be below the horizon (ISO 15469)");
    sun = sun_direction;
  }
  auto sky = std::make_unique<CieGeneralSky>(p, sun);
  double zenith = scale.value;
  if (scale.kind == SkyScale::Kind::HorizontalIlluminance) {
    double relative = 0;
    if (auto r = sky->analytic_relative_horizontal()) {
      relative = *r;
    } else {
      const CieGeneralSky& s = *sky;
      relative = integrate_cosine_weighted_hemisphere(
          [&s](const Vec3& d) { return s.relative_luminance(d); }, sun);
    }
    zenith = scale.value / relative;
  }
  sky->set_zenith_luminance(zenith);
  return sky;
}

}  // namespace dayphoton::sky
