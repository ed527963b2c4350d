// KlemsBasis: see klems_basis.h.
#include "dayphoton/core/klems_basis.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "dayphoton/core/units.h"

namespace dayphoton {
namespace {
constexpr double ThetaTolerance_rad = 1e-9;
double sin2(double theta) { return std::sin(theta) * std::sin(theta); }
}  // namespace

KlemsBasis::KlemsBasis(std::vector<KlemsRing> rings) : m_rings(std::move(rings)) {
  if (m_rings.empty()) throw std::invalid_argument("a Klems basis needs at least one ring");
  double expected_lower = 0;
  for (std::size_t r = 0; r < m_rings.size(); ++r) {
    const KlemsRing& ring = m_rings[r];
    const std::string which = "ring " + std::to_string(r + 1);
    if (!(std::fabs(ring.lower_theta_rad - expected_lower) <= ThetaTolerance_rad))
      throw std::invalid_argument(which + " starts at theta " + format_deg(ring.lower_theta_rad) +
                                  " degrees, not where the previous ring ends (" +
                                  format_deg(expected_lower) + ")");
    if (!(ring.upper_theta_rad > ring.lower_theta_rad))
      throw std::invalid_argument(which + ": its upper theta must exceed its lower theta");
    if (ring.phi_count < 1) throw std::invalid_argument(which + ": the number of patches must be >= 1");
    if (ring.phi_count == 1 && r > 0)
      throw std::invalid_argument(which + " has a single patch but is not the polar cap");
    expected_lower = ring.upper_theta_rad;
    m_first.push_back(m_size);
    m_size += ring.phi_count;
  }
  if (!(std::fabs(expected_lower - Pi / 2) <= ThetaTolerance_rad))
    throw std::invalid_argument("the last ring ends at theta " + format_deg(expected_lower) +
                                " degrees, not 90");
  m_rings.back().upper_theta_rad = Pi / 2;
}

std::string KlemsBasis::format_deg(double rad) {
  std::string s = std::to_string(rad * DegPerRad);
  s.erase(s.find_last_not_of('0') + 1);
  if (!s.empty() && s.back() == '.') s.pop_back();
  return s;
}

KlemsBasis KlemsBasis::full() {
  const double bounds_deg[] = {0, 5, 15, 25, 35, 45, 55, 65, 75, 90};
  const int counts[] = {1, 8, 16, 20, 24, 24, 24, 16, 12};
  std::vector<KlemsRing> rings;
  for (int r = 0; r < 9; ++r) rings.push_back({deg_to_rad(bounds_deg[r]), deg_to_rad(bounds_deg[r + 1]), counts[r]});
  return KlemsBasis(std::move(rings));
}

int KlemsBasis::patch(const Vec3& local) const {
  const double cos_theta = std::min(1.0, std::fabs(local.z) / length(local));
  const double theta = std::acos(cos_theta);
  std::size_t r = 0;
  while (r + 1 < m_rings.size() && theta >= m_rings[r].upper_theta_rad) ++r;
  const int n = m_rings[r].phi_count;
  if (n == 1) return m_first[r];
  double phi = std::atan2(local.y, local.x);
  if (phi < 0) phi += 2 * Pi;
  int k = static_cast<int>(std::floor(phi * n / (2 * Pi) + 0.5));
  if (k >= n) k -= n;
  if (k < 0) k = 0;
  return m_first[r] + k;
}

int KlemsBasis::ring_of(int index) const {
  if (index < 0 || index >= m_size) throw std::out_of_range("Klems patch index out of range");
  const auto it = std::upper_bound(m_first.begin(), m_first.end(), index);
  return static_cast<int>(it - m_first.begin()) - 1;
}

double KlemsBasis::projected_solid_angle(int index) const {
  const KlemsRing& ring = m_rings[static_cast<std::size_t>(ring_of(index))];
  return Pi * (sin2(ring.upper_theta_rad) - sin2(ring.lower_theta_rad)) / ring.phi_count;
}

double KlemsBasis::centre_theta_rad(int index) const {
  const KlemsRing& ring = m_rings[static_cast<std::size_t>(ring_of(index))];
  return ring.lower_theta_rad == 0 && ring.phi_count == 1 ? 0.0 : 0.5 * (ring.lower_theta_rad + ring.upper_theta_rad);
}

double KlemsBasis::centre_phi_rad(int index) const {
  const int r = ring_of(index);
  return 2 * Pi * (index - m_first[static_cast<std::size_t>(r)]) / m_rings[static_cast<std::size_t>(r)].phi_count;
}

Vec3 KlemsBasis::sample(int index, double u1, double u2) const {
  const int r = ring_of(index);
  const KlemsRing& ring = m_rings[static_cast<std::size_t>(r)];
  const double s2_low = sin2(ring.lower_theta_rad), s2_high = sin2(ring.upper_theta_rad);
  const double sin2_theta = s2_low + u1 * (s2_high - s2_low);
  const double sin_theta = std::sqrt(sin2_theta);
  const double cos_theta = std::sqrt(std::max(0.0, 1.0 - sin2_theta));
  const int k = index - m_first[static_cast<std::size_t>(r)];
  const double sector = 2 * Pi / ring.phi_count;
  const double phi = ring.phi_count == 1 ? 2 * Pi * u2 : sector * (k - 0.5 + u2);
  return {sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta};
}

bool KlemsBasis::operator==(const KlemsBasis& other) const {
  if (m_rings.size() != other.m_rings.size()) return false;
  for (std::size_t r = 0; r < m_rings.size(); ++r) {
    const KlemsRing &a = m_rings[r], &b = other.m_rings[r];
    if (a.phi_count != b.phi_count || std::fabs(a.lower_theta_rad - b.lower_theta_rad) > ThetaTolerance_rad ||
        std::fabs(a.upper_theta_rad - b.upper_theta_rad) > ThetaTolerance_rad)
      return false;
  }
  return true;
}

}  // namespace dayphoton
