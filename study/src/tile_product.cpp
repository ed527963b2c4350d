// The annual product's inner tile: see tile_product.h. The AVX variant is compiled for AVX alone
// (a function attribute, no FMA: a fused multiply-add rounds once where the plain loop rounds
// twice, which would change the values) and called only after CPUID reports AVX and the
// operating system's support for its registers (__builtin_cpu_supports).
#include "dayphoton/study/tile_product.h"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
#define DAYPHOTON_TILE_PRODUCT_AVX 1
#endif

namespace dayphoton::study::detail {

void tile_product_portable(const double* rows, std::size_t sensors, std::size_t k, const double* columns,
                           double* out) {
  for (std::size_t r = 0; r < sensors; ++r) {
    const double* row = rows + r * k;
    double acc[TileSteps] = {};
    for (std::size_t i = 0; i < k; ++i) {
      const double wi = row[i];
      const double* col = columns + i * TileSteps;
      for (std::size_t j = 0; j < TileSteps; ++j) acc[j] += wi * col[j];
    }
    for (std::size_t j = 0; j < TileSteps; ++j) out[r * TileSteps + j] = acc[j];
  }
}

#ifdef DAYPHOTON_TILE_PRODUCT_AVX

namespace {

static_assert(TileSteps == 16, "the AVX variant holds a tile in four registers per sensor");

/// Two sensors at once: each column vector is loaded once for both rows.
__attribute__((target("avx"))) void tile_product_avx2_rows(const double* row0, const double* row1, std::size_t k,
                                                           const double* columns, double* out) {
  __m256d a0 = _mm256_setzero_pd(), a1 = _mm256_setzero_pd(), a2 = _mm256_setzero_pd(), a3 = _mm256_setzero_pd();
  __m256d b0 = _mm256_setzero_pd(), b1 = _mm256_setzero_pd(), b2 = _mm256_setzero_pd(), b3 = _mm256_setzero_pd();
  for (std::size_t i = 0; i < k; ++i) {
    const double* col = columns + i * TileSteps;
    const __m256d c0 = _mm256_loadu_pd(col), c1 = _mm256_loadu_pd(col + 4);
    const __m256d c2 = _mm256_loadu_pd(col + 8), c3 = _mm256_loadu_pd(col + 12);
    const __m256d w0 = _mm256_broadcast_sd(row0 + i), w1 = _mm256_broadcast_sd(row1 + i);
    a0 = _mm256_add_pd(a0, _mm256_mul_pd(w0, c0));
    a1 = _mm256_add_pd(a1, _mm256_mul_pd(w0, c1));
    a2 = _mm256_add_pd(a2, _mm256_mul_pd(w0, c2));
    a3 = _mm256_add_pd(a3, _mm256_mul_pd(w0, c3));
    b0 = _mm256_add_pd(b0, _mm256_mul_pd(w1, c0));
    b1 = _mm256_add_pd(b1, _mm256_mul_pd(w1, c1));
    b2 = _mm256_add_pd(b2, _mm256_mul_pd(w1, c2));
    b3 = _mm256_add_pd(b3, _mm256_mul_pd(w1, c3));
  }
  _mm256_storeu_pd(out, a0);
  _mm256_storeu_pd(out + 4, a1);
  _mm256_storeu_pd(out + 8, a2);
  _mm256_storeu_pd(out + 12, a3);
  _mm256_storeu_pd(out + 16, b0);
  _mm256_storeu_pd(out + 20, b1);
  _mm256_storeu_pd(out + 24, b2);
  _mm256_storeu_pd(out + 28, b3);
}

__attribute__((target("avx"))) void tile_product_avx1_row(const double* row, std::size_t k, const double* columns,
                                                          double* out) {
  __m256d a0 = _mm256_setzero_pd(), a1 = _mm256_setzero_pd(), a2 = _mm256_setzero_pd(), a3 = _mm256_setzero_pd();
  for (std::size_t i = 0; i < k; ++i) {
    const double* col = columns + i * TileSteps;
    const __m256d w = _mm256_broadcast_sd(row + i);
    a0 = _mm256_add_pd(a0, _mm256_mul_pd(w, _mm256_loadu_pd(col)));
    a1 = _mm256_add_pd(a1, _mm256_mul_pd(w, _mm256_loadu_pd(col + 4)));
    a2 = _mm256_add_pd(a2, _mm256_mul_pd(w, _mm256_loadu_pd(col + 8)));
    a3 = _mm256_add_pd(a3, _mm256_mul_pd(w, _mm256_loadu_pd(col + 12)));
  }
  _mm256_storeu_pd(out, a0);
  _mm256_storeu_pd(out + 4, a1);
  _mm256_storeu_pd(out + 8, a2);
  _mm256_storeu_pd(out + 12, a3);
}

bool cpu_has_avx() {
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx");
}

}  // namespace

bool tile_product_uses_avx() {
  static const bool avx = cpu_has_avx();
  return avx;
}

void tile_product(const double* rows, std::size_t sensors, std::size_t k, const double* columns, double* out) {
  if (!tile_product_uses_avx()) {
    tile_product_portable(rows, sensors, k, columns, out);
    return;
  }
  std::size_t r = 0;
  for (; r + 2 <= sensors; r += 2)
    tile_product_avx2_rows(rows + r * k, rows + (r + 1) * k, k, columns, out + r * TileSteps);
  if (r < sensors) tile_product_avx1_row(rows + r * k, k, columns, out + r * TileSteps);
}

#else

bool tile_product_uses_avx() { return false; }

void tile_product(const double* rows, std::size_t sensors, std::size_t k, const double* columns, double* out) {
  tile_product_portable(rows, sensors, k, columns, out);
}

#endif

}  // namespace dayphoton::study::detail
