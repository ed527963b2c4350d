// KlemsBasis: the angle basis of a Klems BSDF matrix (J. H. Klems, "A new method for
// predicting the solar heat gain of complex fenestration systems", ASHRAE Transactions
// 100(1), 1994; the basis of LBNL WINDOW's BSDF XML files, DataDefinition/AngleBasis).
//
// A hemisphere is cut into rings of polar angle theta (from the axis), each ring into
// `phi_count` equal azimuth sectors. The first ring is a polar cap of one patch; in every
// other ring patch k is CENTRED on azimuth 360 k / phi_count degrees (it spans half a sector
// either side). Patches are numbered ring by ring from the pole, azimuth 0 first. The
// standard LBNL full basis has 145 patches in 9 rings (theta bounds 0, 5, 15, ..., 75, 90
// degrees; 1, 8, 16, 20, 24, 24, 24, 16, 12 patches).
//
// Projected solid angle of a patch of ring [theta_l, theta_u] with n sectors ("Lambda"):
//   Lambda = pi (sin^2 theta_u - sin^2 theta_l) / n,   sum over the basis = pi.
// A BSDF matrix value f(i, j) (1/sr) is constant over each patch pair, so the fraction of the
// light arriving in patch i that leaves in patch j is f(i, j) Lambda_j.
//
// Directions here are LOCAL unit vectors (z along the basis' axis); `patch()` ignores the
// sign of z (each hemisphere has the same basis) and uses the azimuth atan2(y, x). How a
// matrix's incoming and outgoing directions map onto this (the propagation-direction rule
// under which a clear pane is a diagonal matrix) is in klems_bsdf_data.h.
#pragma once

#include <string>
#include <vector>

#include "dayphoton/core/vec3.h"

namespace dayphoton {

struct KlemsRing {
  double lower_theta_rad = 0, upper_theta_rad = 0;
  int phi_count = 0;
};

class KlemsBasis {
 public:
  KlemsBasis() = default;
  /// Rings from the pole outwards. Throws std::invalid_argument unless the rings are
  /// contiguous from 0 to pi/2 (to 1e-9 rad), each has phi_count >= 1, and only the first
  /// (a cap starting at 0) may have a single patch.
  explicit KlemsBasis(std::vector<KlemsRing> rings);
  /// The standard LBNL/Klems Full basis (145 patches).
  static KlemsBasis full();

  int size() const { return m_size; }
  const std::vector<KlemsRing>& rings() const { return m_rings; }
  /// Patch index of a local direction (|z| gives theta, atan2(y, x) the azimuth).
  int patch(const Vec3& local) const;
  /// Ring of patch `index` and the index of its sector in the ring.
  int ring_of(int index) const;
  int first_of_ring(int ring) const { return m_first[static_cast<std::size_t>(ring)]; }
  /// Projected solid angle Lambda of patch `index`, sr.
  double projected_solid_angle(int index) const;
  /// Polar angle (ring middle) and azimuth (sector centre) of a patch, radians, for messages.
  double centre_theta_rad(int index) const;
  double centre_phi_rad(int index) const;
  /// A local direction in patch `index` with z >= 0, uniform in projected solid angle over
  /// the patch (sin^2 theta uniform in [sin^2 theta_l, sin^2 theta_u], azimuth uniform in the
  /// sector), from two uniform numbers in [0, 1).
  Vec3 sample(int index, double u1, double u2) const;

  /// Same rings (bounds to 1e-9 rad, same counts).
  bool operator==(const KlemsBasis& other) const;

 private:
  static std::string format_deg(double rad);
  std::vector<KlemsRing> m_rings;
  std::vector<int> m_first;  ///< first patch index of each ring
  int m_size = 0;
};

}  // namespace dayphoton
