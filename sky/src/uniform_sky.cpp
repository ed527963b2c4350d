// Uniform sky: constant luminance L over the upper hemisphere; horizontal illuminance pi L.
// It is ISO 15469 type 5 in shape and the closed-form oracle of the engine's tests
// (irradiance pi L under a constant sky; STYLE.md A.10(a)).
//
// Parameters: luminance_cd_m2 (cd/m^2, >= 0). Example: make_uniform_sky(1000 / Pi) gives 1000 lx.
#include "dayphoton/sky/sky_model.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "dayphoton/core/units.h"

namespace dayphoton::sky {
namespace {

class UniformSky final : public SkyModel {
 public:
  explicit UniformSky(double luminance_cd_m2) : m_luminance_cd_m2(luminance_cd_m2) {}

  double luminance_cd_m2(const Vec3& dir) const override {
    return dir.z > 0 ? m_luminance_cd_m2 : 0.0;
  }
  std::optional<double> analytic_horizontal_illuminance_lux() const override {
    return Pi * m_luminance_cd_m2;  // integral of cos(theta) over the hemisphere = pi
  }
  std::string description() const override {
    std::ostringstream s;
    s << "uniform sky, luminance " << m_luminance_cd_m2 << " cd/m2, horizontal illuminance "
      << Pi * m_luminance_cd_m2 << " lx";
    return s.str();
  }

 private:
  double m_luminance_cd_m2;
};

}  // namespace

std::unique_ptr<SkyModel> make_uniform_sky(double luminance_cd_m2) {
  if (!std::isfinite(luminance_cd_m2) || luminance_cd_m2 < 0)
    throw std::invalid_argument("uniform sky: luminance must be finite and >= 0 cd/m2");
  return std::make_unique<UniformSky>(luminance_cd_m2);
}

}  // namespace dayphoton::sky
