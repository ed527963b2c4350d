// Glazing system (type `glazing`): a stack of panes, from the outside in, combined by the
// multi-layer formulas of glazing_system.h. Delta reflection with the reflectance of the side
// hit and straight transmission (the same both ways). Pane 1 faces the side the normal
// points away from. Formulas, sources and the deviations: docs/materials.md ("Glazing
// systems").
#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>
#include <vector>

#include "builtin_materials.h"
#include "glazing_system.h"
#include "material_common.h"

namespace dayphoton::engine {
namespace {

using namespace detail;

class GlazingMaterial final : public PaneModel<GlazingMaterial> {
 public:
  explicit GlazingMaterial(const MaterialSpec& spec) : m_transmittance_factor(spec.transmittance_factor) {
    try {
      m_panes = resolve_panes(spec.panes);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("material '" + spec.name + "': " + e.what());
    }
    m_grey_panes = is_grey(m_panes);
  }

 private:
  friend class PaneModel<GlazingMaterial>;
  // Transmittance (times the window's transmittance factor) and the reflectance of the side
  // the light arrives from. Light with dot(incoming, normal) > 0 (arriving against the back
  // of the surface) meets pane 1 first.
  void response(double cos_in, Vec3& t, Vec3& r) const {
    const bool from_outside = cos_in > 0;
    const double cos_i = std::fabs(cos_in);
    for (int c = 0; c < 3; ++c) {
      if (c > 0 && m_grey_panes) {
        t[c] = t[0];
        r[c] = r[0];
        continue;
      }
      const LayerOptics o = glazing_optics(m_panes, cos_i, c);
      t[c] = o.transmittance;
      r[c] = from_outside ? o.outer_reflectance : o.inner_reflectance;
    }
    if (m_transmittance_factor != 1.0) t = t * m_transmittance_factor;
  }

  double m_transmittance_factor;
  std::vector<ResolvedPane> m_panes;  // from the outside in
  bool m_grey_panes = true;           // all channels equal: evaluate one
};

}  // namespace

std::shared_ptr<const MaterialModel> make_glazing_material(const MaterialSpec& spec) {
  return std::make_shared<GlazingMaterial>(spec);
}

}  // namespace dayphoton::engine
