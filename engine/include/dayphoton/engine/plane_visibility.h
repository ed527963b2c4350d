// Plane visibility: the part of a kernel disc on a receiver plane that its centre sees.
//
// The photons crossing a work plane are a Poisson process whose intensity, the irradiance,
// is smooth within a region of the plane but jumps across a partition (its lit side against
// its shadow) and around the re-entrant corner of an L-shaped room. A density estimate that
// averages or fits the photons of a disc spanning such a cut carries the other side's light
// to the sensor: a bias the standard error does not state, which more photons only shrink
// with the disc. So where something cuts a sensor's disc (plane_cuts.h, the outline's reflex
// vertices), the estimate keeps to the region R of the disc that the sensor's position sees
// in the plane: only photons in R count, and the fit's moments are R's (local linear and
// local quadratic fits divide by the region they sum over, local_quadratic_fit.h). It is the
// boundary correction of the outline clip (receiver_plane.h) with the boundary the cuts add.
//
// R is the union of Sectors wedges about the centre: wedge k reaches to the first cut or
// outline edge its middle ray meets (at most the largest radius asked for). A photon belongs
// to wedge k by its pseudo-angle, which is monotonic in the angle, so the photons counted and
// the region integrated are the same set, exactly; the wedges only approximate the true
// boundary by a sliver 2 pi d / Sectors wide at distance d (3 mm at 0.5 m), and an
// occluder narrower than a wedge can be missed. The moments of a wedge of radius rho between
// angles t0 and t1 are exact: int u^a v^b dA = int cos^a sin^b dt rho^(a+b+2) / (a+b+2).
//
// A disc of radius r: with w_k(a, b) the scaled moment of the unit wedge k and n = a + b,
//   m(a, b) = disc(a, b) - sum_{k: reach_k < r} w_k(a, b) (1 - (reach_k / r)^(n+2))
//           = disc(a, b) - W_i(a, b) + P_i(a, b) / r^(n+2),
// i the number of cut wedges reaching less than r, W_i and P_i the sums of w_k and of
// w_k reach_k^(n+2) over the i nearest (the summed-area idea of Crow, "Summed-area tables for
// texture mapping", SIGGRAPH 1984, over wedges sorted by reach). The cut wedges are sorted
// once per centre; W and P are kept at every PrefixStride-th of them, so a lookup costs one
// binary search, the sums at the stride below i and at most PrefixStride - 1 wedges summed
// directly: O(15 PrefixStride) against O(15 Sectors), in 1/PrefixStride of the memory of a
// sum kept at every wedge (30 doubles a wedge; PlaneVisibility objects are alive for a whole
// task's sensors at once).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "dayphoton/engine/photon.h"

#include "dayphoton/engine/receiver_plane.h"

namespace dayphoton::engine {

class PlaneVisibility {
 public:
  /// Wedges per full turn.
  static constexpr int Sectors = 1024;

  /// The visible region about (x, y) up to max_radius_m, or nothing when no interior cut of
  /// `plane` and no reflex vertex of its outline lies within max_radius_m (then the outline
  /// clip alone is exact). max_radius_m must be finite and positive.
  static std::optional<PlaneVisibility> around(const ReceiverPlane& plane, double x, double y, double max_radius_m);

  /// True if the centre sees the plane point (x, y) within the wedges' reach.
  bool sees(double x, double y) const;
  /// The area of the visible region within r_m of the centre, m^2.
  double area_m2(double r_m) const;
  /// Its area moments about the centre (receiver_plane.h).
  AreaMoments moments(double r_m) const;
  /// Its moments up to order 4 in the disc's scaled coordinates (receiver_plane.h).
  ScaledMoments4 moments4(double r_m) const;
  /// Cut wedges, in ascending reach, per prefix sum kept (header comment).
  static constexpr int PrefixStride = 16;
  /// Wedge k's reach, metres (k < Sectors).
  double reach_m(int k) const { return m_reach_m[static_cast<std::size_t>(k)]; }
  /// The scaled moments of wedge k of the unit disc: int over the wedge's angles of
  /// cos^a t sin^b t dt / (a + b + 2), so that a wedge reaching rho has rho^(a+b+2) times them.
  static const ScaledMoments4& unit_wedge_moments(int k);
  /// The wedge of a direction (dx, dy) from the centre, by its pseudo-angle.
  static int sector_of(double dx, double dy);
  /// For PhotonFilter: whether the centre sees a photon's crossing point.
  bool sees(const Photon& photon) const { return sees(double(photon.position[0]), double(photon.position[1])); }

 private:
  PlaneVisibility(double x, double y, double max_radius_m);
  void block(const PlanePoint& a, const PlanePoint& b);
  /// Sorts the cut wedges and sums their moments (header comment).
  void index_cut_wedges();
  ScaledMoments4 scaled_moments(double r_m, int order) const;
  double m_x = 0, m_y = 0;
  std::vector<double> m_reach_m;
  double m_max_radius_m = 0;
  /// The wedges something cuts within max_radius_m (reach below it), by ascending reach (ties
  /// by wedge), and their reaches.
  std::vector<std::uint16_t> m_cut_wedge;
  std::vector<double> m_cut_reach_m;
  /// For j = 0, 1, ...: the sums over the first j PrefixStride cut wedges of w_k (15 values)
  /// then of w_k reach_k^(n+2) (15 values), 30 doubles per j.
  std::vector<double> m_prefix;
  /// The square of the nearest reach over all wedges: every point nearer is seen (sees()
  /// answers it without finding the wedge).
  double m_clear_m2 = 0;
};

}  // namespace dayphoton::engine
