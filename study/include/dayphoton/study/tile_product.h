// The inner product of the annual illuminance (annual_illuminance.cpp): a few sensors' weighted
// coefficient rows times one tile of gathered sky columns, every sum in the order of the plain
// loop, so the values do not depend on which variant runs.
#pragma once

#include <cstddef>

namespace dayphoton::study::detail {

/// Sky columns per tile: the steps one row of weights is multiplied into at once.
constexpr std::size_t TileSteps = 16;

/// For each of the `sensors` rows (1 or 2) of `rows` (row r at rows + r * k) and each step j of
/// the tile: out[r * TileSteps + j] = sum over i = 0 .. k - 1, in that order, of
/// rows[r * k + i] * columns[i * TileSteps + j], each product rounded to double and added to
/// the running sum starting at 0 (no fused multiply-add, no reassociation). On x86-64
/// processors with AVX (CPUID, checked once) the four-wide instructions do it, elsewhere the
/// compiler's two-wide loop: the same roundings in the same order, so the same values.
void tile_product(const double* rows, std::size_t sensors, std::size_t k, const double* columns, double* out);

/// Whether tile_product uses the AVX variant on this processor.
bool tile_product_uses_avx();

/// tile_product's portable variant, for the tests that compare the two.
void tile_product_portable(const double* rows, std::size_t sensors, std::size_t k, const double* columns,
                           double* out);

}  // namespace dayphoton::study::detail
