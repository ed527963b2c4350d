// PhotonMap: balanced static 3-d tree and k-nearest-neighbour search. Layout, tie-breaking
// and pruning rules: see photon_map.h (seeds/000 section 3.1.4, digest section 2.4;
// seeds/001 section 5 for the maximum search radius).
#include "dayphoton/engine/photon_map.h"

#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace dayphoton::engine {
namespace {

/// Build-time record: position and input index only (16 bytes), so the median selections
/// move a third as much memory as whole photons would.
struct Key {
  float p[3];
  std::uint32_t index;
};

/// Strict total order on axis a: (p[a], p[a+1], p[a+2], input index), axes cyclic.
struct KeyLess {
  int a;
  bool operator()(const Key& l, const Key& r) const {
    for (int i = 0; i < 3; ++i) {
      const int axis = (a + i) % 3;
      if (l.p[axis] < r.p[axis]) return true;
      if (r.p[axis] < l.p[axis]) return false;
    }
    return l.index < r.index;
  }
};

/// Below this many keys a subtree is built on the calling thread.
constexpr std::size_t ParallelBuildThreshold = 1u << 16;

void build_range(Key* keys, std::uint8_t* axis_of, std::size_t lo, std::size_t hi) {
  if (hi - lo <= PhotonMap::LeafSize) return;
  float lower[3] = {keys[lo].p[0], keys[lo].p[1], keys[lo].p[2]};
  float upper[3] = {lower[0], lower[1], lower[2]};
  for (std::size_t i = lo + 1; i < hi; ++i)
    for (int a = 0; a < 3; ++a) {
      lower[a] = std::min(lower[a], keys[i].p[a]);
      upper[a] = std::max(upper[a], keys[i].p[a]);
    }
  int axis = 0;  // largest extent; the lowest axis on equal extents
  for (int a = 1; a < 3; ++a)
    if (upper[a] - lower[a] > upper[axis] - lower[axis]) axis = a;
  const std::size_t mid = lo + (hi - lo) / 2;
  std::nth_element(keys + lo, keys + mid, keys + hi, KeyLess{axis});
  axis_of[mid] = static_cast<std::uint8_t>(axis);
  if (hi - lo >= ParallelBuildThreshold) {
    tbb::parallel_invoke([=] { build_range(keys, axis_of, lo, mid); },
                         [=] { build_range(keys, axis_of, mid + 1, hi); });
  } else {
    build_range(keys, axis_of, lo, mid);
    build_range(keys, axis_of, mid + 1, hi);
  }
}

/// (distance, index) order of the result heap: a max-heap on it keeps the k smallest pairs.
/// A function object rather than a function, so that std::push_heap and std::sort_heap
/// inline it (through a function pointer they called it for every comparison).
struct Closer {
  bool operator()(const NeighbourPhoton& l, const NeighbourPhoton& r) const {
    return l.distance_squared_m2 < r.distance_squared_m2 ||
           (l.distance_squared_m2 == r.distance_squared_m2 && l.index < r.index);
  }
};
constexpr Closer closer{};

/// The k-d tree traversal of every lookup, with the acceptance of a found photon as a policy
/// (a template parameter, so it inlines as the code written for it alone would). The
/// traversal owns the pruning bound: it starts at the squared search radius, visits the near
/// side first, tests each photon's squared distance and the filter, and prunes a far side
/// whose cell lies beyond the bound. A photon within the bound that passes the filter goes to
/// `accept(found, bound2)`, which may lower the bound (never raise it). Both lookups prune by
/// this one rule; the hinted lookup's exactness rests on that (photon_map.h). Nothing is added
/// per lookup: the policy is held by value and called directly.
template <typename Accept>
class Traversal {
 public:
  Traversal(const Photon* photons, const std::uint8_t* axis_of, const Vec3& point, double radius_m,
            const PhotonFilter& filter, Accept accept)
      : m_photons(photons), m_axis_of(axis_of), m_q{point.x, point.y, point.z}, m_bound2(radius_m * radius_m),
        m_filter(filter), m_accept(accept) {}

  void visit(std::size_t lo, std::size_t hi, const double offset[3]) {
    if (hi - lo <= PhotonMap::LeafSize) {
      for (std::size_t i = lo; i < hi; ++i) consider(i);
      return;
    }
    const std::size_t mid = lo + (hi - lo) / 2;
    const int a = m_axis_of[mid];
    const double d = m_q[a] - static_cast<double>(m_photons[mid].position[a]);
    // Near side first: it shrinks the bound before the far side is tested.
    if (d < 0) visit(lo, mid, offset); else visit(mid + 1, hi, offset);
    consider(mid);
    double far_offset[3] = {offset[0], offset[1], offset[2]};
    far_offset[a] = std::fabs(d);
    // Lower bound of the squared distance to every photon on the far side, summed like
    // the photon distances in consider() so that it never rounds above one of them.
    const double far2 = far_offset[0] * far_offset[0] + far_offset[1] * far_offset[1] +
                        far_offset[2] * far_offset[2];
    if (far2 <= m_bound2) {
      if (d < 0) visit(mid + 1, hi, far_offset); else visit(lo, mid, far_offset);
    }
  }

 private:
  void consider(std::size_t i) {
    const Photon& photon = m_photons[i];
    const double dx = static_cast<double>(photon.position[0]) - m_q[0];
    const double dy = static_cast<double>(photon.position[1]) - m_q[1];
    const double dz = static_cast<double>(photon.position[2]) - m_q[2];
    const double d2 = dx * dx + dy * dy + dz * dz;
    if (d2 > m_bound2) return;
    if (!m_filter.accepts(photon)) return;
    m_accept(NeighbourPhoton{static_cast<std::uint32_t>(i), d2}, m_bound2);
  }

  const Photon* m_photons;
  const std::uint8_t* m_axis_of;
  double m_q[3];
  double m_bound2;  ///< squared radius, lowered by the acceptance
  const PhotonFilter& m_filter;
  Accept m_accept;  ///< held by value: it refers to the caller's vector, one indirection as hand-written code
};

/// Acceptance of the k-NN query: the k smallest (distance, index) pairs in a max-heap kept in
/// the caller's vector (so a lookup allocates nothing once `out` has grown to k); once it
/// holds k, the bound is the k-th distance.
class KeepNearest {
 public:
  KeepNearest(std::size_t k, std::vector<NeighbourPhoton>& heap) : m_k(k), m_heap(heap) {}

  void operator()(const NeighbourPhoton& found, double& bound2) {
    if (m_heap.size() < m_k) {
      m_heap.push_back(found);
      std::push_heap(m_heap.begin(), m_heap.end(), closer);
      if (m_heap.size() == m_k) bound2 = m_heap.front().distance_squared_m2;
      return;
    }
    if (!closer(found, m_heap.front())) return;  // equal distance, larger index
    replace_top(found);
    bound2 = m_heap.front().distance_squared_m2;
  }

 private:
  /// Put `item` in place of the heap's maximum and sift it down (one pass instead of the
  /// two of pop_heap + push_heap).
  void replace_top(const NeighbourPhoton& item) {
    NeighbourPhoton* heap = m_heap.data();
    const std::size_t n = m_heap.size();
    std::size_t i = 0;
    for (;;) {
      std::size_t child = 2 * i + 1;
      if (child >= n) break;
      if (child + 1 < n && closer(heap[child], heap[child + 1])) ++child;
      if (!closer(item, heap[child])) break;
      heap[i] = heap[child];
      i = child;
    }
    heap[i] = item;
  }

  std::size_t m_k;
  std::vector<NeighbourPhoton>& m_heap;
};

/// Acceptance of the hinted lookup's first pass: every photon within the fixed radius that
/// passes the filter, appended in traversal order (the bound stays the radius); the k nearest
/// are then selected from them without a heap.
struct CollectWithin {
  std::vector<NeighbourPhoton>& found;
  void operator()(const NeighbourPhoton& photon, double&) { found.push_back(photon); }
};

}  // namespace

PhotonMap::PhotonMap(std::vector<Photon> photons) : m_photons(std::move(photons)) { build(nullptr); }

PhotonMap::PhotonMap(std::vector<Photon> photons, std::vector<std::uint32_t>& input_index)
    : m_photons(std::move(photons)) {
  build(&input_index);
}

void PhotonMap::build(std::vector<std::uint32_t>* input_index) {
  const std::size_t n = m_photons.size();
  if (n > MaxPhotons)
    throw std::length_error("PhotonMap: " + std::to_string(n) + " photons exceed the 32-bit index");
  std::vector<Key> keys(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto& p = m_photons[i].position;
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      throw std::invalid_argument("PhotonMap: photon " + std::to_string(i) +
                                  " has a non-finite position");
    keys[i] = Key{{p[0], p[1], p[2]}, static_cast<std::uint32_t>(i)};
  }
  m_axis.assign(n, 0);
  build_range(keys.data(), m_axis.data(), 0, n);
  if (input_index) {
    input_index->resize(n);
    for (std::size_t i = 0; i < n; ++i) (*input_index)[i] = keys[i].index;
  }

  // Permute the photons into tree order in place (cycle by cycle): slot i receives input
  // photon keys[i].index. A finished slot is marked by keys[i].index = i.
  for (std::size_t start = 0; start < n; ++start) {
    if (keys[start].index == start) continue;
    const Photon first = m_photons[start];
    std::size_t slot = start;
    for (;;) {
      const std::size_t from = keys[slot].index;
      keys[slot].index = static_cast<std::uint32_t>(slot);
      if (from == start) {
        m_photons[slot] = first;
        break;
      }
      m_photons[slot] = m_photons[from];
      slot = from;
    }
  }
}

void PhotonMap::nearest(const Vec3& point, std::size_t k, double max_radius_m,
                        const PhotonFilter& filter, std::vector<NeighbourPhoton>& out) const {
  nearest(point, k, max_radius_m, std::numeric_limits<double>::infinity(), filter, out);
}

bool PhotonMap::nearest(const Vec3& point, std::size_t k, double max_radius_m, double hint_radius_m,
                        const PhotonFilter& filter, std::vector<NeighbourPhoton>& out) const {
  out.clear();
  if (!(max_radius_m >= 0))
    throw std::invalid_argument("PhotonMap::nearest: the maximum search radius must be >= 0");
  if (k == 0 || m_photons.empty()) return true;
  const double no_offset[3] = {0, 0, 0};
  // The result is sorted with std::sort rather than std::sort_heap: (distance, index) is a
  // strict total order on distinct photons, so any correct sort gives the same list, and
  // introsort is about three times faster than heapsort on these short lists.
  if (hint_radius_m >= 0 && hint_radius_m < max_radius_m) {
    Traversal<CollectWithin>(m_photons.data(), m_axis.data(), point, hint_radius_m, filter, CollectWithin{out})
        .visit(0, m_photons.size(), no_offset);
    if (out.size() >= k) {
      // At least k photons within the hint: the k nearest are among them (header).
      if (out.size() > k) {
        std::nth_element(out.begin(), out.begin() + static_cast<std::ptrdiff_t>(k - 1), out.end(), closer);
        out.resize(k);
      }
      std::sort(out.begin(), out.end(), closer);
      return true;
    }
    out.clear();
  } else if (hint_radius_m == max_radius_m && std::isfinite(max_radius_m)) {
    // A hint of the (finite) maximum itself: every photon within the maximum radius is
    // collected, without the heap. Fewer than k is the whole result (a short lookup), more
    // are selected as above: either way nearest()'s photons, and no repeat.
    Traversal<CollectWithin>(m_photons.data(), m_axis.data(), point, max_radius_m, filter, CollectWithin{out})
        .visit(0, m_photons.size(), no_offset);
    if (out.size() > k) {
      std::nth_element(out.begin(), out.begin() + static_cast<std::ptrdiff_t>(k - 1), out.end(), closer);
      out.resize(k);
    }
    std::sort(out.begin(), out.end(), closer);
    return true;
  } else {
    hint_radius_m = max_radius_m;  // no hint, or one no tighter than the maximum
  }
  out.reserve(std::min(k, m_photons.size()));
  Traversal<KeepNearest>(m_photons.data(), m_axis.data(), point, max_radius_m, filter, KeepNearest(k, out))
      .visit(0, m_photons.size(), no_offset);
  std::sort(out.begin(), out.end(), closer);
  return hint_radius_m == max_radius_m;
}

void PhotonMap::within(const Vec3& point, double radius_m, const PhotonFilter& filter,
                       std::vector<NeighbourPhoton>& out) const {
  out.clear();
  if (!(radius_m >= 0) || !std::isfinite(radius_m))
    throw std::invalid_argument("PhotonMap::within: the radius must be finite and >= 0");
  if (m_photons.empty()) return;
  const double no_offset[3] = {0, 0, 0};
  Traversal<CollectWithin>(m_photons.data(), m_axis.data(), point, radius_m, filter, CollectWithin{out})
      .visit(0, m_photons.size(), no_offset);
}

std::size_t PhotonMap::memory_bytes() const {
  return m_photons.capacity() * sizeof(Photon) + m_axis.capacity() * sizeof(std::uint8_t);
}

}  // namespace dayphoton::engine
