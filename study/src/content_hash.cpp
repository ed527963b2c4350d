// ContentHash: FNV-1a 64 and a multiply-xorshift stream over canonical encodings
// (content_hash.h explains the encodings; docs/cache.md how keys use them).
#include "dayphoton/study/content_hash.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <vector>

#include "dayphoton/core/error_text.h"

namespace dayphoton::study {

namespace {

// Type tags: arbitrary but fixed forever (changing one changes every key).
constexpr std::uint8_t TagText = 1, TagNumber = 2, TagInteger = 3, TagVec3 = 4, TagFile = 5,
                       TagHash = 6;

constexpr std::uint64_t FnvPrime = 0x100000001b3ull;
// Stream B's multiplier: an odd constant unrelated to the FNV prime (Knuth's MMIX LCG
// multiplier), so the two streams do not collide together.
constexpr std::uint64_t StreamBMultiplier = 0x5851f42d4c957f2dull;

// murmur3's 64-bit finaliser: every input bit affects every output bit.
std::uint64_t avalanche(std::uint64_t h) {
  h ^= h >> 33;
  h *= 0xff51afd7ed558ccdull;
  h ^= h >> 33;
  h *= 0xc4ceb9fe1a85ec53ull;
  h ^= h >> 33;
  return h;
}

}  // namespace

ContentHash& ContentHash::bytes(const void* data, std::size_t size) {
  const auto* p = static_cast<const unsigned char*>(data);
  std::uint64_t a = m_a, b = m_b;
  for (std::size_t i = 0; i < size; ++i) {
    a = (a ^ p[i]) * FnvPrime;
    b = (b ^ p[i]) * StreamBMultiplier;
    b ^= b >> 29;
  }
  m_a = a;
  m_b = b;
  return *this;
}

void ContentHash::tag(std::uint8_t t) { bytes(&t, 1); }

void ContentHash::u64(std::uint64_t v) {
  unsigned char le[8];
  for (int i = 0; i < 8; ++i) le[i] = static_cast<unsigned char>(v >> (8 * i));
  bytes(le, 8);
}

ContentHash& ContentHash::text(const std::string& s) {
  tag(TagText);
  u64(s.size());
  return bytes(s.data(), s.size());
}

ContentHash& ContentHash::number(double v) {
  tag(TagNumber);
  if (v == 0.0) v = 0.0;  // -0.0 == 0.0: one key for both
  if (std::isnan(v)) v = std::numeric_limits<double>::quiet_NaN();
  std::uint64_t bits;
  std::memcpy(&bits, &v, sizeof bits);
  u64(bits);
  return *this;
}

ContentHash& ContentHash::integer(std::int64_t v) {
  tag(TagInteger);
  u64(static_cast<std::uint64_t>(v));
  return *this;
}

ContentHash& ContentHash::vec3(const Vec3& v) {
  tag(TagVec3);
  number(v.x);
  number(v.y);
  return number(v.z);
}

ContentHash& ContentHash::file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path + ": " + error_text(errno));
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  in.seekg(0, std::ios::beg);
  if (size < 0 || !in) throw std::runtime_error("cannot read " + path + ": cannot find its size");
  tag(TagFile);
  u64(static_cast<std::uint64_t>(size));
  std::vector<char> buffer(1 << 16);
  std::uint64_t remaining = static_cast<std::uint64_t>(size);
  while (remaining > 0) {
    const std::size_t n = static_cast<std::size_t>(std::min<std::uint64_t>(remaining, buffer.size()));
    in.read(buffer.data(), static_cast<std::streamsize>(n));
    if (static_cast<std::size_t>(in.gcount()) != n)
      throw std::runtime_error("cannot read " + path + ": it changed while being read");
    bytes(buffer.data(), n);
    remaining -= n;
  }
  return *this;
}

ContentHash& ContentHash::hash(const ContentHash& other) {
  tag(TagHash);
  u64(other.m_a);
  u64(avalanche(other.m_b));
  return *this;
}

std::string ContentHash::hex() const {
  static const char digits[] = "0123456789abcdef";
  std::string out(32, '0');
  const std::uint64_t words[2] = {m_a, avalanche(m_b)};
  for (int w = 0; w < 2; ++w)
    for (int i = 0; i < 16; ++i) out[w * 16 + i] = digits[(words[w] >> (60 - 4 * i)) & 0xf];
  return out;
}

}  // namespace dayphoton::study
