// ContentHash: a 128-bit digest of everything an artefact depends on, used as its cache key
// (DESIGN.md sections 2 and 6; issue 5: "caches every artefact keyed by a hash of its inputs").
// docs/cache.md describes how keys are built and what invalidates what.
//
// Not cryptographic: two independent 64-bit streams make accidental collisions negligible
// for a cache (a cache folder holds thousands of artefacts, not 2^64):
//   - stream A is FNV-1a 64 (Fowler, Noll, Vo; offset basis 0xcbf29ce484222325, prime
//     0x100000001b3), so bytes() alone reproduces the published FNV-1a test vectors;
//   - stream B is a multiply-xorshift accumulator with a different multiplier, passed
//     through a final avalanche (the murmur3 fmix64 constants) when the digest is read.
// Values are added in a canonical binary form so the key depends neither on formatting,
// locale nor host byte order:
//   - every typed value (text, number, integer, vec3, file, hash) starts with a one-byte
//     type tag, so the same bytes added as different types give different keys;
//   - integers and doubles are 8 bytes little-endian (doubles by bit pattern, -0.0 folded
//     into +0.0 and every NaN into one quiet NaN, since those compare or behave alike);
//   - strings and files are prefixed with their length, so text("ab") + text("c") differs
//     from text("a") + text("bc");
//   - bytes() adds raw bytes with no tag and no length: the caller's own framing.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "dayphoton/core/vec3.h"

namespace dayphoton::study {

class ContentHash {
 public:
  /// Raw bytes, no type tag, no length (bytes("ab") + bytes("c") == bytes("abc")).
  ContentHash& bytes(const void* data, std::size_t size);
  ContentHash& text(const std::string& s);     ///< length-prefixed
  ContentHash& number(double v);               ///< bit pattern (+0 and -0 unified)
  ContentHash& integer(std::int64_t v);
  ContentHash& vec3(const Vec3& v);
  /// A file's whole content, length-prefixed; the path itself is not part of the key, so
  /// moving a project folder keeps its cache valid. Throws std::runtime_error naming the
  /// file if it cannot be read.
  ContentHash& file(const std::string& path);
  /// Another digest (for keys built from other keys).
  ContentHash& hash(const ContentHash& other);

  /// 32 lowercase hex digits: stream A, then stream B after its final avalanche.
  std::string hex() const;

 private:
  void tag(std::uint8_t t);
  void u64(std::uint64_t v);
  std::uint64_t m_a = 0xcbf29ce484222325ull;  ///< FNV-1a 64 offset basis
  std::uint64_t m_b = 0x9E3779B97F4A7C15ull;  ///< 2^64 / golden ratio
};

}  // namespace dayphoton::study
