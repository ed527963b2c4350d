// KlemsBsdf: see klems_bsdf.h.
#include "klems_bsdf.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "bsdf_frame.h"

namespace dayphoton::engine {

bool KlemsBsdf::frame_defined(const Vec3& up, const Vec3& normal) {
  const double lu = length(up), ln = length(normal);
  if (!(lu > 0) || !(ln > 0)) return false;
  return length(cross(up, normal)) > UpFrame::MinUpSine * lu * ln;
}

KlemsBsdf::KlemsBsdf(std::shared_ptr<const KlemsBsdfData> data, const Vec3& up) : m_data(std::move(data)), m_up(up) {
  if (!m_data) throw std::invalid_argument("a BSDF material needs its BSDF data");
  m_n = m_data->basis.size();
  const std::size_t n = static_cast<std::size_t>(m_n);
  for (const auto* m : {&m_data->transmission_front, &m_data->transmission_back, &m_data->reflection_front,
                        &m_data->reflection_back})
    if (m->size() != n * n) throw std::invalid_argument("BSDF data: a matrix is not " + std::to_string(n) + " x " + std::to_string(n));
  m_lambda.resize(n);
  for (int j = 0; j < m_n; ++j) m_lambda[static_cast<std::size_t>(j)] = m_data->basis.projected_solid_angle(j);
  for (int side = 0; side < 2; ++side) {
    const std::vector<double>& t = side == 0 ? m_data->transmission_front : m_data->transmission_back;
    const std::vector<double>& r = side == 0 ? m_data->reflection_front : m_data->reflection_back;
    std::vector<double>& c = m_cumulative[side];
    c.resize(n * 2 * n);
    for (std::size_t i = 0; i < n; ++i) {
      double sum = 0;
      for (std::size_t j = 0; j < n; ++j) c[i * 2 * n + j] = sum += t[i * n + j] * m_lambda[j];
      for (std::size_t j = 0; j < n; ++j) c[i * 2 * n + n + j] = sum += r[i * n + j] * m_lambda[j];
    }
  }
}

int KlemsBsdf::side_of(const Vec3& local_incoming) const {
  if (local_incoming.z > 0) return 0;  // moving toward +z: arrives from -z, WINDOW's front
  if (local_incoming.z < 0) return 1;
  return -1;
}

std::optional<KlemsBsdf::Sample> KlemsBsdf::sample(const Vec3& incoming, const Vec3& normal, double u_patch,
                                                   double u1, double u2) const {
  const UpFrame f(m_up, normal);
  const Vec3 d = f.to_local(incoming);
  const int side = side_of(d);
  if (side < 0) return std::nullopt;
  const std::size_t n = static_cast<std::size_t>(m_n);
  const std::size_t i = static_cast<std::size_t>(m_data->basis.patch(d));
  const double* c = &m_cumulative[side][i * 2 * n];
  const double total = c[2 * n - 1];
  if (!(total > 0)) return std::nullopt;
  const double target = u_patch * total;
  std::size_t k = static_cast<std::size_t>(std::upper_bound(c, c + 2 * n, target) - c);
  if (k >= 2 * n) k = 2 * n - 1;
  while (k > 0 && c[k] == c[k - 1]) --k;  // never a zero-probability event (rounding at the top)
  const bool transmitted = k < n;
  const int j = static_cast<int>(transmitted ? k : k - n);
  Vec3 local = m_data->basis.sample(j, u1, u2);
  // Transmitted light keeps the z sign of its propagation, reflected light reverses it.
  const double sign = (d.z > 0) == transmitted ? 1.0 : -1.0;
  local.z *= sign;
  return Sample{normalize(f.to_world(local)), total, transmitted};
}

double KlemsBsdf::eval(const Vec3& incoming, const Vec3& outgoing, const Vec3& normal) const {
  const UpFrame f(m_up, normal);
  const Vec3 d = f.to_local(incoming), o = f.to_local(outgoing);
  const int side = side_of(d);
  if (side < 0 || o.z == 0) return 0.0;
  const bool transmitted = (o.z > 0) == (d.z > 0);
  const std::vector<double>& m = transmitted ? (side == 0 ? m_data->transmission_front : m_data->transmission_back)
                                             : (side == 0 ? m_data->reflection_front : m_data->reflection_back);
  return m_data->value(m, m_data->basis.patch(d), m_data->basis.patch(o));
}

double KlemsBsdf::pdf(const Vec3& incoming, const Vec3& outgoing, const Vec3& normal) const {
  const double a = albedo(incoming, normal);
  if (!(a > 0)) return 0.0;
  return eval(incoming, outgoing, normal) * std::fabs(dot(outgoing, normalize(normal))) / a;
}

double KlemsBsdf::albedo(const Vec3& incoming, const Vec3& normal) const {
  const UpFrame f(m_up, normal);
  const Vec3 d = f.to_local(incoming);
  const int side = side_of(d);
  if (side < 0) return 0.0;
  const std::size_t n = static_cast<std::size_t>(m_n);
  const std::size_t i = static_cast<std::size_t>(m_data->basis.patch(d));
  return m_cumulative[side][i * 2 * n + 2 * n - 1];
}

double KlemsBsdf::transmittance(const Vec3& incoming, const Vec3& normal) const {
  const UpFrame f(m_up, normal);
  const Vec3 d = f.to_local(incoming);
  const int side = side_of(d);
  if (side < 0) return 0.0;
  const std::size_t n = static_cast<std::size_t>(m_n);
  const std::size_t i = static_cast<std::size_t>(m_data->basis.patch(d));
  return m_cumulative[side][i * 2 * n + n - 1];
}

}  // namespace dayphoton::engine
