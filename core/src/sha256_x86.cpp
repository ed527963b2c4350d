// SHA-256 rounds on the x86 SHA extensions after Gulley, Gopal, Yap, Feghali, Guilford, Wolrich,
// "Intel SHA Extensions: New Instructions Supporting the Secure Hash Algorithm on Intel
// Architecture Processors" (Intel, July 2013), section "SHA-256" and its round structure:
// the state kept as ABEF and CDGH, two rounds per SHA256RNDS2, the message schedule of
// FIPS 180-4 section 6.2.2 step 1 by SHA256MSG1 (W[t-16] + sigma0(W[t-15])) and SHA256MSG2
// (+ sigma1(W[t-2]), after W[t-7] is added with PALIGNR). Compiled for those instructions
// alone (function attributes), called only after CPUID reports them.
#include "sha256_x86.h"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <cpuid.h>
#include <immintrin.h>
#define DAYPHOTON_SHA256_X86 1
#endif

namespace dayphoton::detail {

#ifdef DAYPHOTON_SHA256_X86

namespace {

bool cpu_has_sha_extensions() {
  unsigned a = 0, b = 0, c = 0, d = 0;
  if (!__get_cpuid(1, &a, &b, &c, &d)) return false;
  const bool ssse3 = (c & (1u << 9)) != 0, sse41 = (c & (1u << 19)) != 0;
  if (!__get_cpuid_count(7, 0, &a, &b, &c, &d)) return false;
  const bool sha = (b & (1u << 29)) != 0;
  return ssse3 && sse41 && sha;
}

}  // namespace

bool sha256_x86_available() {
  static const bool available = cpu_has_sha_extensions();
  return available;
}

__attribute__((target("sha,sse4.1,ssse3"))) void sha256_x86_blocks(std::uint32_t state[8], const std::uint8_t* data,
                                                                    std::size_t blocks) {
  // Big-endian message words (FIPS 180-4 section 3.1) from the little-endian loads.
  const __m128i byte_swap = _mm_set_epi64x(0x0c0d0e0f08090a0bLL, 0x0405060700010203LL);
  // H0..H7 rearranged into ABEF and CDGH, the operand order of SHA256RNDS2.
  __m128i tmp = _mm_shuffle_epi32(_mm_loadu_si128(reinterpret_cast<const __m128i*>(state)), 0xB1);  // CDAB
  __m128i cdgh = _mm_shuffle_epi32(_mm_loadu_si128(reinterpret_cast<const __m128i*>(state + 4)), 0x1B);  // EFGH
  __m128i abef = _mm_alignr_epi8(tmp, cdgh, 8);
  cdgh = _mm_blend_epi16(cdgh, tmp, 0xF0);
  for (std::size_t n = 0; n < blocks; ++n, data += 64) {
    const __m128i abef_saved = abef, cdgh_saved = cdgh;
    __m128i w[4];  // w[g % 4]: W[4g .. 4g+3] of the rounds 4g .. 4g+3
    for (int i = 0; i < 4; ++i)
      w[i] = _mm_shuffle_epi8(_mm_loadu_si128(reinterpret_cast<const __m128i*>(data + 16 * i)), byte_swap);
    for (int g = 0; g < 16; ++g) {
      __m128i wk = _mm_add_epi32(w[g % 4], _mm_load_si128(reinterpret_cast<const __m128i*>(K + 4 * g)));
      cdgh = _mm_sha256rnds2_epu32(cdgh, abef, wk);  // rounds 4g, 4g+1
      if (g >= 3 && g <= 14) {  // W[4g+4 .. 4g+7] completed: + W[t-7], then sigma1(W[t-2])
        __m128i& next = w[(g + 1) % 4];
        next = _mm_add_epi32(next, _mm_alignr_epi8(w[g % 4], w[(g + 3) % 4], 4));
        next = _mm_sha256msg2_epu32(next, w[g % 4]);
      }
      wk = _mm_shuffle_epi32(wk, 0x0E);
      abef = _mm_sha256rnds2_epu32(abef, cdgh, wk);  // rounds 4g+2, 4g+3
      if (g >= 1 && g <= 12)  // W[t-16] + sigma0(W[t-15]) for the words 4g+12 .. 4g+15
        w[(g + 3) % 4] = _mm_sha256msg1_epu32(w[(g + 3) % 4], w[g % 4]);
    }
    abef = _mm_add_epi32(abef, abef_saved);
    cdgh = _mm_add_epi32(cdgh, cdgh_saved);
  }
  // Back to H0..H7.
  tmp = _mm_shuffle_epi32(abef, 0x1B);   // FEBA
  cdgh = _mm_shuffle_epi32(cdgh, 0xB1);  // DCHG
  _mm_storeu_si128(reinterpret_cast<__m128i*>(state), _mm_blend_epi16(tmp, cdgh, 0xF0));      // DCBA
  _mm_storeu_si128(reinterpret_cast<__m128i*>(state + 4), _mm_alignr_epi8(cdgh, tmp, 8));  // HGFE
}

#else

bool sha256_x86_available() { return false; }

void sha256_x86_blocks(std::uint32_t*, const std::uint8_t*, std::size_t) {}

#endif

}  // namespace dayphoton::detail
