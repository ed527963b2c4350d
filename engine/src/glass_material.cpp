// Thin glass (RADIANCE glass, type `glass`): delta reflection about the normal and straight
// transmission, with the thin-pane Fresnel series of thin_glass_fresnel.h per RGB channel.
// The project file gives the normal transmittance Tn of glazing data sheets; the pane's
// per-pass transmissivity is solved from it for the pane's index. Symmetric: both sides
// behave alike. Formulas and the transmissivity convention: docs/materials.md ("Thin glass").
#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "builtin_materials.h"
#include "material_common.h"
#include "thin_glass_fresnel.h"

namespace dayphoton::engine {
namespace {

using namespace detail;

class GlassMaterial final : public PaneModel<GlassMaterial> {
 public:
  explicit GlassMaterial(const MaterialSpec& spec)
      : m_refractive_index(spec.refractive_index), m_transmittance_factor(spec.transmittance_factor) {
    check_unit_range(spec, "transmittance", spec.transmittance);
    if (!(spec.refractive_index >= 1.0) || !std::isfinite(spec.refractive_index))
      throw std::invalid_argument("material '" + spec.name + "': glass refractive index " +
                                  std::to_string(spec.refractive_index) + " must be >= 1");
    try {
      for (int c = 0; c < 3; ++c)
        m_transmissivity[c] = glass_transmissivity(spec.transmittance[c], spec.refractive_index);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("material '" + spec.name + "': " + e.what());
    }
  }

 private:
  friend class PaneModel<GlassMaterial>;
  ThinGlassResponse channel(double cos_i, int c) const {
    return thin_glass_response(cos_i, m_refractive_index, m_transmissivity[c]);
  }
  // Transmittance (times the window's transmittance factor) and reflectance per channel for
  // light along a direction with cosine cos_in to the normal. Grey panes (the usual case)
  // evaluate the series once instead of three times: this is on every photon's path through
  // a port.
  void response(double cos_in, Vec3& t, Vec3& r) const {
    const double cos_i = std::fabs(cos_in);
    const ThinGlassResponse g0 = channel(cos_i, 0);
    t = {g0.transmittance, g0.transmittance, g0.transmittance};
    r = {g0.reflectance, g0.reflectance, g0.reflectance};
    for (int c = 1; c < 3; ++c) {
      if (m_transmissivity[c] == m_transmissivity[0]) continue;
      const ThinGlassResponse g = channel(cos_i, c);
      t[c] = g.transmittance;
      r[c] = g.reflectance;
    }
    if (m_transmittance_factor != 1.0) t = t * m_transmittance_factor;
  }

  double m_refractive_index;
  double m_transmittance_factor;
  Vec3 m_transmissivity{0, 0, 0};  // per-pass transmissivity tn per channel
};

}  // namespace

std::shared_ptr<const MaterialModel> make_glass_material(const MaterialSpec& spec) {
  return std::make_shared<GlassMaterial>(spec);
}

}  // namespace dayphoton::engine
