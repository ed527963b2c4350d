// Opening (type `opening`): a fully transparent aperture, straight transmission with weight 1
// (a room window's transmittance factor, when it has one). Stores no photons.
// docs/materials.md ("Opening").
#include <memory>
#include <optional>

#include "builtin_materials.h"

namespace dayphoton::engine {
namespace {

class OpeningMaterial final : public MaterialModel {
 public:
  explicit OpeningMaterial(const MaterialSpec& spec) : m_factor(spec.transmittance_factor) {}

  std::optional<ScatterSample> sample(const Vec3& incoming, const Vec3&, double, double, double) const override {
    return ScatterSample{incoming, Vec3{m_factor, m_factor, m_factor}, ScatterType::StraightTransmission, true};
  }
  Vec3 eval(const Vec3&, const Vec3&, const Vec3&) const override { return {0, 0, 0}; }
  double pdf(const Vec3&, const Vec3&, const Vec3&) const override { return 0.0; }
  Vec3 albedo(const Vec3&, const Vec3&) const override { return {m_factor, m_factor, m_factor}; }
  Vec3 straight_transmittance(const Vec3&, const Vec3&) const override { return {m_factor, m_factor, m_factor}; }

 private:
  double m_factor;  // the window's transmittance factor, 1 for a plain opening
};

}  // namespace

std::shared_ptr<const MaterialModel> make_opening_material(const MaterialSpec& spec) {
  return std::make_shared<OpeningMaterial>(spec);
}

}  // namespace dayphoton::engine
