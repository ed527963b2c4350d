// TensorTreeBsdf: see tensor_tree_bsdf.h.
#include "tensor_tree_bsdf.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "bsdf_frame.h"

namespace dayphoton::engine {

TensorTreeBsdf::TensorTreeBsdf(std::shared_ptr<const KlemsBsdfData> data, const Vec3& up)
    : m_data(std::move(data)), m_up(up) {
  if (!m_data || !m_data->tensor_tree) throw std::invalid_argument("a tensor-tree BSDF needs its tree");
  m_tree = m_data->tensor_tree.get();
}

const TensorTreeBsdfData::Slice* TensorTreeBsdf::slice(const Vec3& d) const {
  const int side = TensorTreeBsdfData::side_of(d);
  if (side < 0) return nullptr;
  return &m_tree->slices[side][static_cast<std::size_t>(m_tree->slice_of(side, d))];
}

std::optional<KlemsBsdf::Sample> TensorTreeBsdf::sample(const Vec3& incoming, const Vec3& normal, double u_cell,
                                                        double u1, double u2) const {
  const UpFrame f(m_up, normal);
  const Vec3 d = f.to_local(incoming);
  const TensorTreeBsdfData::Slice* s = slice(d);
  if (!s || !(s->albedo > 0)) return std::nullopt;
  const std::vector<double>& c = s->cumulative;
  std::size_t k = static_cast<std::size_t>(std::upper_bound(c.begin(), c.end(), u_cell * s->albedo) - c.begin());
  if (k >= c.size()) k = c.size() - 1;
  while (k > 0 && c[k] == c[k - 1]) --k;  // never a zero-probability cell (rounding at the top)
  const TensorTreeBsdfData::Cell& cell = s->cells[k];
  const bool transmitted = k < s->transmitted;
  // Transmitted light keeps the z sign of its propagation, reflected light reverses it.
  const double z_sign = (d.z > 0) == transmitted ? 1.0 : -1.0;
  const Vec3 local = m_tree->outgoing_direction(d, cell.u + u1 * cell.size, cell.v + u2 * cell.size, z_sign);
  return KlemsBsdf::Sample{normalize(f.to_world(local)), s->albedo, transmitted};
}

double TensorTreeBsdf::eval(const Vec3& incoming, const Vec3& outgoing, const Vec3& normal) const {
  const UpFrame f(m_up, normal);
  return m_tree->value(f.to_local(incoming), f.to_local(outgoing));
}

double TensorTreeBsdf::pdf(const Vec3& incoming, const Vec3& outgoing, const Vec3& normal) const {
  const double a = albedo(incoming, normal);
  if (!(a > 0)) return 0.0;
  return eval(incoming, outgoing, normal) * std::fabs(dot(outgoing, normalize(normal))) / a;
}

double TensorTreeBsdf::albedo(const Vec3& incoming, const Vec3& normal) const {
  const TensorTreeBsdfData::Slice* s = slice(UpFrame(m_up, normal).to_local(incoming));
  return s ? s->albedo : 0.0;
}

double TensorTreeBsdf::transmittance(const Vec3& incoming, const Vec3& normal) const {
  const TensorTreeBsdfData::Slice* s = slice(UpFrame(m_up, normal).to_local(incoming));
  return s ? s->transmittance : 0.0;
}

}  // namespace dayphoton::engine
