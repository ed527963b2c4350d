// TensorTree: see tensor_tree.h.
#include "dayphoton/core/tensor_tree.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace dayphoton {
namespace {

bool separator(char c) { return std::isspace(static_cast<unsigned char>(c)) || c == ','; }

class Parser {
 public:
  Parser(std::string_view text, int ndim, TensorTree& tree) : m_text(text), m_ndim(ndim), m_tree(tree) {}

  void parse() {
    skip_space();
    m_tree.nodes.emplace_back();
    node(0, 0);
    skip_space_and_commas();
    if (m_pos < m_text.size())
      fail(m_pos, "characters after the tensor tree's closing '}': '" + std::string(m_text.substr(m_pos, 20)) + "'");
  }

 private:
  [[noreturn]] void fail(std::size_t offset, std::string message) { throw TensorTreeError{offset, std::move(message)}; }
  void skip_space() {
    while (m_pos < m_text.size() && std::isspace(static_cast<unsigned char>(m_text[m_pos]))) ++m_pos;
  }
  void skip_space_and_commas() {
    while (m_pos < m_text.size() && separator(m_text[m_pos])) ++m_pos;
  }

  // Parse the node starting at m_pos (a '{') into nodes[index]; `depth` branch levels above.
  void node(std::size_t index, int depth) {
    const std::size_t open = m_pos;
    if (m_pos >= m_text.size() || m_text[m_pos] != '{')
      fail(m_pos, m_pos >= m_text.size() ? "the tensor tree ends where a '{' was expected"
                                         : "expected '{' in the tensor tree, found '" + std::string(1, m_text[m_pos]) + "'");
    ++m_pos;
    skip_space();
    const std::size_t children = std::size_t{1} << m_ndim;
    if (m_pos < m_text.size() && m_text[m_pos] == '{') {  // a branch
      if (depth + 1 > MaxTensorTreeLog2)
        fail(open, "the tensor tree is deeper than " + std::to_string(MaxTensorTreeLog2) +
                       " levels (cells finer than 1/" + std::to_string(1 << MaxTensorTreeLog2) + ")");
      if (m_tree.nodes.size() + children > MaxTensorTreeNodes)
        fail(open, "the tensor tree has more than " + std::to_string(MaxTensorTreeNodes) + " nodes");
      const std::size_t first = m_tree.nodes.size();
      m_tree.nodes[index].first = static_cast<std::int32_t>(first);
      m_tree.nodes[index].log2_grid = -1;
      m_tree.nodes.resize(first + children);
      std::size_t count = 0;
      while (true) {
        skip_space_and_commas();
        if (m_pos >= m_text.size()) fail(open, "this '{' of the tensor tree is never closed");
        if (m_text[m_pos] == '}') break;
        if (count == children)
          fail(m_pos, "a branch of the tensor tree has more than " + std::to_string(children) +
                          " sub-trees (2^" + std::to_string(m_ndim) + " for TensorTree" + std::to_string(m_ndim) + ")");
        node(first + count, depth + 1);
        ++count;
      }
      if (count != children)
        fail(open, "a branch of the tensor tree has " + std::to_string(count) + " sub-trees, not " +
                       std::to_string(children) + " (2^" + std::to_string(m_ndim) + " for TensorTree" +
                       std::to_string(m_ndim) + ")");
      ++m_pos;  // '}'
      return;
    }
    // A leaf: count the values first, so a wrong count allocates nothing.
    std::size_t count = 0;
    std::size_t i = m_pos;
    while (true) {
      while (i < m_text.size() && separator(m_text[i])) ++i;
      if (i >= m_text.size()) fail(open, "this '{' of the tensor tree is never closed");
      if (m_text[i] == '}') break;
      if (m_text[i] == '{') fail(i, "a '{' among the values of a tensor-tree leaf");
      ++count;
      while (i < m_text.size() && !separator(m_text[i]) && m_text[i] != '}' && m_text[i] != '{') ++i;
    }
    int k = -1;
    for (int kk = 0; kk * m_ndim < 63 && (std::size_t{1} << (kk * m_ndim)) <= count; ++kk)
      if ((std::size_t{1} << (kk * m_ndim)) == count) k = kk;
    if (k < 0)
      fail(open, "a tensor-tree leaf has " + std::to_string(count) + " values; a leaf has 2^(" +
                     std::to_string(m_ndim) + " k) values (1, " + std::to_string(1 << m_ndim) + ", " +
                     std::to_string(1 << (2 * m_ndim)) + " ...)");
    if (depth + k > MaxTensorTreeLog2)
      fail(open, "the tensor tree is deeper than " + std::to_string(MaxTensorTreeLog2) +
                     " levels (cells finer than 1/" + std::to_string(1 << MaxTensorTreeLog2) + ")");
    if (m_tree.values.size() + count > MaxTensorTreeValues)
      fail(open, "the tensor tree has more than " + std::to_string(MaxTensorTreeValues) + " values");
    if (depth + k > m_tree.max_log2) m_tree.max_log2 = depth + k;
    m_tree.nodes[index].first = static_cast<std::int32_t>(m_tree.values.size());
    m_tree.nodes[index].log2_grid = static_cast<std::int8_t>(k);
    for (std::size_t n = 0; n < count; ++n) {
      skip_space_and_commas();
      std::size_t j = m_pos;
      while (j < m_text.size() && !separator(m_text[j]) && m_text[j] != '}') ++j;
      const std::string token(m_text.substr(m_pos, j - m_pos));
      char* end = nullptr;
      errno = 0;
      const double v = std::strtod(token.c_str(), &end);
      if (token.empty() || *end != '\0') fail(m_pos, "tensor-tree value '" + token.substr(0, 40) + "' is not a number");
      if (!std::isfinite(v) || errno == ERANGE || v > 3.4e38)
        fail(m_pos, "tensor-tree value '" + token.substr(0, 40) + "' is not finite");
      if (v < 0) fail(m_pos, "tensor-tree value " + token.substr(0, 40) + " is negative (a BSDF is >= 0)");
      m_tree.values.push_back(static_cast<float>(v));
      m_pos = j;
    }
    skip_space_and_commas();
    ++m_pos;  // '}'
  }

  std::string_view m_text;
  int m_ndim;
  TensorTree& m_tree;
  std::size_t m_pos = 0;
};

// Visit the slice's cells under node `index`, whose cube has corner `corner` and side `size`.
void visit(const TensorTree& t, std::size_t index, const double* incident, const double* corner, double size,
           const std::function<void(double, double, double, float)>* f, std::size_t& count) {
  const TensorTree::Node& n = t.nodes[index];
  const int nd = t.ndim, ni = nd - 2;
  if (n.log2_grid < 0) {
    const double half = size * 0.5;
    for (int c = 0; c < (1 << nd); ++c) {
      double sub[4];
      bool inside = true;
      for (int i = 0; i < nd; ++i) {
        sub[i] = corner[i] + ((c >> i) & 1 ? half : 0.0);
        if (i < ni && !(incident[i] >= sub[i] && incident[i] < sub[i] + half)) inside = false;
      }
      if (inside) visit(t, static_cast<std::size_t>(n.first) + static_cast<std::size_t>(c), incident, sub, half, f, count);
    }
    return;
  }
  const int k = n.log2_grid;
  const std::size_t cells = std::size_t{1} << k;
  const double cell = size / static_cast<double>(cells);
  std::size_t base = 0;  // the incident dimensions' part of the index
  for (int i = 0; i < ni; ++i) {
    std::size_t c = static_cast<std::size_t>((incident[i] - corner[i]) / cell);
    if (c >= cells) c = cells - 1;
    base = (base << k) + c;
  }
  if (!f) {
    count += cells * cells;
    return;
  }
  for (std::size_t a = 0; a < cells; ++a)
    for (std::size_t b = 0; b < cells; ++b) {
      const std::size_t at = (((base << k) + a) << k) + b;
      (*f)(corner[ni] + cell * static_cast<double>(a), corner[ni + 1] + cell * static_cast<double>(b), cell,
           t.values[static_cast<std::size_t>(n.first) + at]);
    }
  count += cells * cells;
}

}  // namespace

float TensorTree::lookup(const double* pos) const {
  double p[4];
  for (int i = 0; i < ndim; ++i) p[i] = std::min(std::max(pos[i], 0.0), 1.0 - 1e-12);
  std::size_t index = 0;
  while (nodes[index].log2_grid < 0) {
    int c = 0;
    for (int i = 0; i < ndim; ++i) {
      p[i] *= 2.0;
      if (p[i] >= 1.0) {
        c |= 1 << i;
        p[i] -= 1.0;
      }
    }
    index = static_cast<std::size_t>(nodes[index].first) + static_cast<std::size_t>(c);
  }
  const int k = nodes[index].log2_grid;
  const std::size_t cells = std::size_t{1} << k;
  std::size_t at = 0;
  for (int i = 0; i < ndim; ++i) {
    std::size_t c = static_cast<std::size_t>(p[i] * static_cast<double>(cells));
    if (c >= cells) c = cells - 1;
    at = (at << k) + c;
  }
  return values[static_cast<std::size_t>(nodes[index].first) + at];
}

void TensorTree::for_each_slice_cell(const double* incident,
                                     const std::function<void(double, double, double, float)>& f) const {
  const double corner[4] = {0, 0, 0, 0};
  std::size_t count = 0;
  visit(*this, 0, incident, corner, 1.0, &f, count);
}

std::size_t TensorTree::slice_cell_count(const double* incident) const {
  const double corner[4] = {0, 0, 0, 0};
  std::size_t count = 0;
  visit(*this, 0, incident, corner, 1.0, nullptr, count);
  return count;
}

TensorTree parse_tensor_tree(std::string_view text, int ndim) {
  TensorTree tree;
  tree.ndim = ndim;
  Parser(text, ndim, tree).parse();
  return tree;
}

}  // namespace dayphoton
