// CIE standard overcast sky (Moon & Spencer 1942; CIE S 003; ISO 15469 keeps it as a separate
// formula next to the 15 general skies), ../shared/facts/sky-and-metrics.md §3.1:
//   L(theta) = Lz (1 + 2 cos theta) / 3,   theta = zenith angle of the sky element,
//   E_h = integral L cos theta d omega = 2 pi Lz (1/2 + 2/3) / 3 = 7 pi / 9 Lz.
// No azimuth dependence, no sun. This is the sky of the daylight factor.
//
// Parameters: either the zenith luminance Lz (cd/m^2) or the horizontal illuminance E_h (lux);
// Lz = 9 E_h / (7 pi) (10 000 lx -> 4092.56 cd/m^2).
// Decision (facts §3.1, §7.7): no default zenith luminance of gensky's kind (Krochmann
// 8.6 sin h + 0.123 kcd/m^2, converted by gensky with 203 lm/W); the caller always states the
// level, as `gensky -c -B E/179` does.
#include "dayphoton/sky/sky_model.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "dayphoton/core/units.h"

namespace dayphoton::sky {
namespace {

/// E_h / Lz of the overcast sky: 2 pi * integral_0^1 (1 + 2u)/3 * u du = 2 pi (1/2 + 2/3)/3.
constexpr double OvercastIlluminancePerZenithLuminance = 7.0 * Pi / 9.0;

class CieOvercastSky final : public SkyModel {
 public:
  explicit CieOvercastSky(double zenith_luminance_cd_m2) : m_zenith_cd_m2(zenith_luminance_cd_m2) {}

  double luminance_cd_m2(const Vec3& dir) const override {
    if (!(dir.z > 0)) return 0.0;
    return m_zenith_cd_m2 * (1.0 + 2.0 * dir.z) / 3.0;  // dir.z = cos(theta) for a unit dir
  }
  std::optional<double> analytic_horizontal_illuminance_lux() const override {
    return OvercastIlluminancePerZenithLuminance * m_zenith_cd_m2;
  }
  std::string description() const override {
    std::ostringstream s;
    s << "CIE standard overcast sky (Moon & Spencer), zenith luminance " << m_zenith_cd_m2
      << " cd/m2, horizontal illuminance " << OvercastIlluminancePerZenithLuminance * m_zenith_cd_m2
      << " lx";
    return s.str();
  }

 private:
  double m_zenith_cd_m2;
};

}  // namespace

std::unique_ptr<SkyModel> make_cie_overcast_sky(const SkyScale& scale) {
  if (!std::isfinite(scale.value) || scale.value < 0)
    throw std::invalid_argument("CIE overcast sky: the scale must be finite and >= 0");
  const double zenith = scale.kind == SkyScale::Kind::ZenithLuminance
                            ? scale.value
                            : scale.value / OvercastIlluminancePerZenithLuminance;
  return std::make_unique<CieOvercastSky>(zenith);
}

}  // namespace dayphoton::sky
