// Gauss-Legendre nodes by Newton iteration on P_n; see bsdf_quadrature.h.
#include "bsdf_quadrature.h"

#include <cmath>
#include <map>
#include <mutex>
#include <stdexcept>

#include "dayphoton/core/units.h"

namespace dayphoton::engine {
namespace {

std::vector<QuadratureNode> compute_rule(int n) {
  std::vector<QuadratureNode> nodes(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) {
    // Tricomi's approximation of the k-th root, then Newton on the three-term recurrence.
    double x = std::cos(Pi * (k + 0.75) / (n + 0.5));
    double derivative = 1;
    for (int iteration = 0; iteration < 100; ++iteration) {
      double p_prev = 1, p = x;  // P_0, P_1
      for (int j = 2; j <= n; ++j) {
        const double p_next = ((2.0 * j - 1.0) * x * p - (j - 1.0) * p_prev) / j;
        p_prev = p;
        p = p_next;
      }
      derivative = n * (x * p - p_prev) / (x * x - 1.0);
      const double step = p / derivative;
      x -= step;
      if (std::fabs(step) < 1e-15) break;
    }
    nodes[static_cast<std::size_t>(k)] = {x, 2.0 / ((1.0 - x * x) * derivative * derivative)};
  }
  return nodes;
}

}  // namespace

const std::vector<QuadratureNode>& gauss_legendre(int n) {
  if (n < 1) throw std::invalid_argument("Gauss-Legendre order must be at least 1");
  static std::mutex mutex;
  static std::map<int, std::vector<QuadratureNode>> cache;  // node addresses stay valid
  const std::lock_guard<std::mutex> lock(mutex);
  auto it = cache.find(n);
  if (it == cache.end()) it = cache.emplace(n, compute_rule(n)).first;
  return it->second;
}

}  // namespace dayphoton::engine
