// Gauss-Legendre quadrature nodes for the deterministic albedo integrals of the scattering
// models (ward_lobe.cpp). Nodes are the roots of the Legendre polynomial P_n found by Newton's
// method from Tricomi's initial guesses; weights 2 / ((1 - x^2) P_n'(x)^2)
// (Abramowitz & Stegun 25.4.29). Computed once per order and cached.
#pragma once

#include <vector>

namespace dayphoton::engine {

struct QuadratureNode {
  double x;       ///< abscissa in (-1, 1)
  double weight;  ///< weights sum to 2
};

/// The n-point Gauss-Legendre rule on [-1, 1] (n >= 1), exact for polynomials of degree 2n-1.
const std::vector<QuadratureNode>& gauss_legendre(int n);

}  // namespace dayphoton::engine
