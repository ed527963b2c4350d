// ContentHash: a 128-bit digest of everything an artefact depends on, used as its cache key
// (DESIGN.md section 6; issue 5: "caches every artefact keyed by a hash of its inputs").
// Not cryptographic: two independent 64-bit streams (FNV-1a and a multiply-xorshift
// accumulator) make accidental collisions negligible for a cache. Values are added in a
// canonical binary form (doubles by bit pattern, strings with their length) so the key does
// not depend on formatting or locale.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "dayphoton/core/vec3.h"

namespace dayphoton::study {

class ContentHash {
 public:
  ContentHash& bytes(const void* data, std::size_t size);
  ContentHash& text(const std::string& s);     ///< length-prefixed
  ContentHash& number(double v);               ///< bit pattern (+0 and -0 unified)
  ContentHash& integer(std::int64_t v);
  ContentHash& vec3(const Vec3& v);
  /// A file's whole content (throws std::runtime_error naming the file if unreadable).
  ContentHash& file(const std::string& path);
  /// Another digest (for keys built from other keys).
  ContentHash& hash(const ContentHash& other);

  /// 32 lowercase hex digits.
  std::string hex() const;

 private:
  std::uint64_t m_a = 0xcbf29ce484222325ull;  ///< FNV-1a 64 offset basis
  std::uint64_t m_b = 0x9E3779B97F4A7C15ull;
};

}  // namespace dayphoton::study
