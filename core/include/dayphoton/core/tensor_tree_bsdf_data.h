// TensorTreeBsdfData: a tensor-tree BSDF (IncidentDataStructure TensorTree3, isotropic, or
// TensorTree4, anisotropic; angle basis LBNL/Shirley-Chiu) as read by core/bsdf_xml.h, with the per-incidence tables the
// engine samples from (engine/src/tensor_tree_bsdf.h; docs/materials.md "Tensor-tree BSDF").
//
// Coordinates (G. Ward, RADIANCE src/common/bsdf_t.c, SDqueryTre; the frame and the
// front/back convention are KlemsBsdfData's, klems_bsdf_data.h): for light propagating along
// the local direction d (incoming) and leaving along o, with r = sqrt(d.x^2 + d.y^2) and
// phi_d = atan2(d.y, d.x),
//   u0       = 1/2 - r/2                          (only [0, 1/2) is used; normal incidence
//                                                   is the cell just below 1/2)
//   (u1, u2) = Shirley-Chiu square of (o'.x, o'.y), o' = o turned by -phi_d about z,
// i.e. the tree holds f for incidence in one azimuth and the outgoing direction relative to
// the plane of incidence: the incident azimuth is folded out (isotropy). In RADIANCE's own
// vectors (inVec towards the source, outVec = o) this is u0 = 1/2 - |inVec.xy| / 2 and the
// spin by -atan2(-inVec.y, -inVec.x). Values are the BSDF in 1/sr.
//
// Blocks, in KlemsBsdfData's order: trees[0] Transmission Front (d.z > 0, o.z > 0),
// trees[1] Transmission Back (d.z < 0, o.z < 0), trees[2] Reflection Front (d.z > 0,
// o.z < 0), trees[3] Reflection Back (d.z < 0, o.z > 0).
//
// TensorTree4 (anisotropic; same file, IncidentDataStructure TensorTree4): four coordinates,
//   (u0, u1) = Shirley-Chiu square of (d.x, d.y),  (u2, u3) = square of (o.x, o.y),
// nothing folded (SDqueryTre: SDdisk2square(-inVec) and SDdisk2square(outVec)).
//
// Slices: for each side (0 front: d.z > 0; 1 back) and each incident cell of width 2^-L
// (L the finer of the side's two trees' depths; TensorTree3: the 2^(L-1) cells of [0, 1/2),
// TensorTree4: the 4^L cells of the incident square), the leaf cells of the outgoing square
// at that cell's centre, transmitted then reflected, each weighing
//   value * pi * size^2  (a square cell of side s is projected solid angle pi s^2),
// with their running sum: the piecewise-constant distribution the engine samples exactly.
#pragma once

#include <cstddef>
#include <vector>

#include "dayphoton/core/tensor_tree.h"
#include "dayphoton/core/vec3.h"

namespace dayphoton {

/// Most slice cells over both sides (4 Mi cells, ~80 MiB): bounds the tables built from a file.
constexpr std::size_t MaxTensorTreeSliceCells = std::size_t{1} << 22;

class TensorTreeBsdfData {
 public:
  struct Cell {
    float u = 0, v = 0, size = 0;  ///< corner and side in the outgoing square
    float value = 0;               ///< BSDF, 1/sr
  };
  struct Slice {
    std::vector<Cell> cells;         ///< transmitted cells first, then reflected
    std::vector<double> cumulative;  ///< running sum of value * pi * size^2
    std::size_t transmitted = 0;     ///< how many of the cells are transmitted
    double transmittance = 0, albedo = 0;
  };

  int ndim = 3;  ///< 3 (TensorTree3, isotropic) or 4 (TensorTree4)
  TensorTree trees[4];
  int incident_log2[2] = {1, 1};
  std::vector<Slice> slices[2];

  /// How many slice cells build_slices() would make (allocates nothing).
  std::size_t slice_cell_count() const;
  /// Build both sides' slices.
  void build_slices();

  /// Side of a local propagation direction: 0 front (z > 0), 1 back (z < 0), -1 grazing.
  static int side_of(const Vec3& local_incoming) { return local_incoming.z > 0 ? 0 : local_incoming.z < 0 ? 1 : -1; }
  /// The slice of local incoming direction d on `side`.
  int slice_of(int side, const Vec3& d) const;
  /// The incident coordinates (ndim - 2 of them) of slice k's centre.
  void slice_incident(int side, int k, double* incident) const;
  /// The outgoing square point of o for incoming d (TensorTree3: o turned by -phi_d first).
  void outgoing_square(const Vec3& d, const Vec3& o, double& u, double& v) const;
  /// The local outgoing direction of square point (u, v) for incoming d, on the z side `z_sign`.
  Vec3 outgoing_direction(const Vec3& d, double u, double v, double z_sign) const;
  /// f(d, o), 1/sr (0 at grazing incidence or exit).
  double value(const Vec3& d, const Vec3& o) const;

 private:
  int side_log2(int side) const;
  int slice_count_of(int l) const;
  void incident_of(int l, int k, double* incident) const;
};

}  // namespace dayphoton
