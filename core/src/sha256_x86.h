// SHA-256's compression function (NIST FIPS 180-4 section 6.2.2) on the x86 SHA extensions,
// for Sha256 (sha256.h), which calls it where the processor has them.
#pragma once

#include <cstddef>
#include <cstdint>

namespace dayphoton::detail {

/// Whether this processor has the SHA extensions and SSSE3 / SSE4.1 (CPUID), checked once.
/// Always false on other architectures.
bool sha256_x86_available();

/// Compresses `blocks` 64-byte blocks of `data` into `state` (H0..H7, FIPS 180-4 section
/// 6.2.2), the same values as the portable rounds. Only where sha256_x86_available().
void sha256_x86_blocks(std::uint32_t state[8], const std::uint8_t* data, std::size_t blocks);

}  // namespace dayphoton::detail
