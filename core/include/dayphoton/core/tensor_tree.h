// TensorTree: one block of a tensor-tree BSDF file (<ScatteringData> of an LBNL/Shirley-Chiu
// block, IncidentDataStructure TensorTree3 or TensorTree4), parsed into nodes and leaf values.
//
// The text format, as RADIANCE reads it (G. Ward, src/common/bsdf_t.c, load_tree_data and
// SDlookupTre) and writes it (bsdf2ttree.c, rttree_reduce.c):
//   - a node is '{' ... '}' (an optional ',' may follow it);
//   - a BRANCH holds exactly 2^ndim nodes, the halves of its hypercube: child n covers the
//     upper half of dimension i where bit i of n is set (dimension 0 is bit 0), so children
//     come in the order n = 0, 1, ..., 2^ndim - 1;
//   - a LEAF holds 2^(ndim * k) numbers, k >= 0: a uniform grid of 2^k cells per dimension
//     over its hypercube, in row-major order with dimension 0 the slowest (index =
//     sum_i c_i 2^((ndim - 1 - i) k));
//   - numbers are separated by white space or commas.
// The coordinates are [0,1)^ndim; what they mean is in tensor_tree_bsdf_data.h.
//
// Bounds, checked while parsing and before anything is allocated (a hostile file must not
// exhaust memory or the stack): the depth of the finest cell (branch levels plus a leaf's k)
// at most MaxTensorTreeLog2, at most MaxTensorTreeValues numbers and MaxTensorTreeNodes nodes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace dayphoton {

/// Finest cell: 2^8 = 256 per dimension (RADIANCE's bsdf2ttree samples at most 2^7).
constexpr int MaxTensorTreeLog2 = 8;
/// Most leaf values of one block (16 Mi floats, 64 MiB).
constexpr std::size_t MaxTensorTreeValues = std::size_t{1} << 24;
/// Most nodes (branches and leaves) of one block.
constexpr std::size_t MaxTensorTreeNodes = std::size_t{1} << 22;

/// A parse error at byte `offset` of the parsed text.
struct TensorTreeError {
  std::size_t offset = 0;
  std::string message;
};

class TensorTree {
 public:
  struct Node {
    std::int32_t first = 0;     ///< branch: index of child 0 (2^ndim consecutive); leaf: of value 0
    std::int8_t log2_grid = -1;  ///< -1 for a branch; k for a leaf of 2^(ndim k) values
  };

  int ndim = 3;
  std::vector<Node> nodes;  ///< nodes[0] is the root
  std::vector<float> values;
  int max_log2 = 0;  ///< depth of the finest cell: 2^max_log2 cells per dimension there

  /// The value at `pos` (ndim coordinates, each in [0, 1)).
  float lookup(const double* pos) const;

  /// Every leaf cell whose extent in the first ndim - 2 (incident) dimensions contains
  /// `incident`: f(u_min, v_min, size, value) with (u_min, v_min) its corner in the last two
  /// (outgoing) dimensions and `size` its side. The cells visited tile [0,1)^2 once.
  void for_each_slice_cell(const double* incident,
                           const std::function<void(double, double, double, float)>& f) const;
  /// How many cells for_each_slice_cell would visit (allocates nothing).
  std::size_t slice_cell_count(const double* incident) const;
};

/// Parse the text of a <ScatteringData> element; throws TensorTreeError (offset into `text`):
/// a missing '{' or '}', a branch without 2^ndim sub-trees, a leaf whose value count is not a
/// power of 2^ndim, a depth, value count or node count over the bounds, a value that is not
/// a finite number >= 0, or characters after the tree.
TensorTree parse_tensor_tree(std::string_view text, int ndim);

}  // namespace dayphoton
