// PhotonMap: a static, balanced 3-d tree over photon positions with k-nearest-neighbour
// lookup (seeds/000 section 3.1.4, digest section 2.4; seeds/001 section 5).
//
// Built once after the forward pass; immutable and thread-safe for lookups afterwards.
// Lookups take a maximum search radius (seeds/001 section 5: it bounds the cost of sparse
// regions and cuts the 1/r^2 tails of the estimate) and a filter (source, path classes,
// surface side), applied DURING the search so that the k found photons all pass it.
// Results are deterministic: photons at equal distance are ordered by their index.
//
// Layout (docs/photon-map.md has the measurements behind these choices): the photons are
// stored in one array in tree order, an implicit balanced tree with no child pointers. The
// node of a range [lo, hi) is the photon at mid = lo + (hi - lo) / 2, the median on the
// axis of largest extent of the range's photons (Bentley's k-d tree [Ben75] as Jensen lays
// it out, with the thesis's median split); [lo, mid) holds photons <= it and [mid+1, hi)
// photons >= it on that axis. Ranges of at most LeafSize photons are leaves, scanned
// linearly: cheaper than descending four more levels. One byte per photon holds the split
// axis (only the bytes of node photons are used; the simple indexing is worth the rest),
// so the map costs 33 bytes per photon in all.
//
// Tie-breaking (digest section 2.4: "ties are resolved by cyclic comparison in each
// dimension"): photons are ordered on the split axis a by (p[a], p[a+1], p[a+2], input
// index), a strict total order, so the build is a pure function of the input even when
// many photons coincide. The search keeps the k smallest (distance, index) pairs in a
// max-heap, so WHICH photons are returned does not depend on the traversal order either.
// Pruning compares the squared distance to the cell (Arya & Mount's incremental offsets,
// summed in the same order as photon distances, so rounding can never prune a photon that
// would have been accepted).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "dayphoton/core/vec3.h"
#include "dayphoton/engine/photon.h"

namespace dayphoton::engine {

class PlaneVisibility;
/// PlaneVisibility::sees(photon), out of line (plane_visibility.h).
bool visible_in_plane(const PlaneVisibility& visibility, const Photon& photon);

/// Which photons a lookup may return.
struct PhotonFilter {
  static constexpr std::uint32_t AnySource = 0xFFFFFFFFu;
  std::uint32_t source = AnySource;              ///< only photons of this source
  std::uint8_t path_classes = IndirectPathClasses;  ///< bit mask, see path_class_bit()
  bool check_normal = false;  ///< only photons whose normal has dot(normal, n) >= min_cos
  Vec3 normal{0, 0, 1};       ///< unit normal of the query surface (used if check_normal)
  double min_cos = 0.5;
  /// Receiver planes: only photons whose crossing point this visibility sees (a sensor's
  /// side of a partition, plane_visibility.h); null: any.
  const PlaneVisibility* visibility = nullptr;

  /// True if the photon may be returned (the stored normal is the x127 quantised one).
  bool accepts(const Photon& photon) const {
    if (source != AnySource && photon.source != source) return false;
    if ((path_classes & path_class_bit(photon.path_class)) == 0) return false;
    if (visibility && !visible_in_plane(*visibility, photon)) return false;
    if (check_normal) {
      const double dot127 = photon.normal[0] * normal.x + photon.normal[1] * normal.y +
                            photon.normal[2] * normal.z;
      if (!(dot127 >= min_cos * 127.0)) return false;
    }
    return true;
  }
};

/// One found photon: its index in PhotonMap::photons() and squared distance.
struct NeighbourPhoton {
  std::uint32_t index = 0;
  double distance_squared_m2 = 0;
};

class PhotonMap {
 public:
  /// Ranges of at most this many photons are leaves. Of 4, 8, 16 and 32, 16 was the best
  /// compromise over k = 50..1000, with and without a source filter (docs/photon-map.md).
  static constexpr std::size_t LeafSize = 16;
  /// Photon indices are 32-bit.
  static constexpr std::size_t MaxPhotons = 0xFFFFFFFFu;

  PhotonMap() = default;
  /// Build the tree; the photons are reordered into the tree's layout. Throws
  /// std::invalid_argument for a non-finite position and std::length_error above
  /// MaxPhotons. Large maps are built with several threads (oneTBB); the result does not
  /// depend on the thread count.
  explicit PhotonMap(std::vector<Photon> photons);
  /// The same, and `input_index` receives, for every photon in tree order, its index in
  /// `photons` (the permutation the build applied).
  PhotonMap(std::vector<Photon> photons, std::vector<std::uint32_t>& input_index);

  std::size_t size() const { return m_photons.size(); }
  bool empty() const { return m_photons.empty(); }
  const std::vector<Photon>& photons() const { return m_photons; }

  /// The (at most) k photons nearest to `point` with distance <= max_radius_m that pass
  /// `filter`, sorted by distance, ties by index. `out` is cleared first. k = 0 or an empty
  /// map gives no photons; k > size() gives every photon within the radius. max_radius_m
  /// may be +infinity; a negative or NaN radius throws std::invalid_argument.
  void nearest(const Vec3& point, std::size_t k, double max_radius_m, const PhotonFilter& filter,
               std::vector<NeighbourPhoton>& out) const;

  /// The same result as nearest(point, k, max_radius_m, filter, out), found faster when the
  /// caller knows a radius likely to hold k photons that pass the filter (e.g. the k-th
  /// distance found at a nearby point plus the distance between the two points, by the
  /// triangle inequality). The search first runs with min(hint_radius_m, max_radius_m) in
  /// place of the maximum radius: the pruning bound starts there instead of at the maximum.
  /// If it finds k photons, every one of the k nearest lies within the hint (k accepted
  /// photons do), the bound never fell below the true k-th distance, and the result is
  /// exactly nearest()'s; if it finds fewer, the search is repeated with max_radius_m. So the
  /// hint decides only the cost, never the photons returned. A hint equal to a finite
  /// max_radius_m collects every photon within it and selects the k nearest (no heap, no
  /// repeat): for a point whose neighbour, a step away, found fewer than k (a short lookup),
  /// where the search would reach the maximum anyway. A NaN or negative hint is taken as no
  /// hint, as is a wider one. Returns false if the repeat was needed (for tests and benches).
  bool nearest(const Vec3& point, std::size_t k, double max_radius_m, double hint_radius_m,
               const PhotonFilter& filter, std::vector<NeighbourPhoton>& out) const;

  /// Every photon within radius_m of `point` (distance <= radius_m) that passes `filter`, in
  /// the tree's order, not sorted (a fixed-radius range query: the order is deterministic, so
  /// sums over it are too). `out` is cleared first. A negative, NaN or infinite radius throws
  /// std::invalid_argument.
  void within(const Vec3& point, double radius_m, const PhotonFilter& filter,
              std::vector<NeighbourPhoton>& out) const;

  /// Bytes used by photons and tree (for bench/).
  std::size_t memory_bytes() const;

 private:
  void build(std::vector<std::uint32_t>* input_index);
  std::vector<Photon> m_photons;     ///< in tree order
  std::vector<std::uint8_t> m_axis;  ///< split axis of the node at each mid index (leaves unused)
};

}  // namespace dayphoton::engine
