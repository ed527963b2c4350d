// SHA-256 after NIST FIPS 180-4, "Secure Hash Standard" (2015): constants section 4.2.2,
// initial hash value section 5.3.3, padding section 5.1.1, computation section 6.2.2.
#include "dayphoton/core/sha256.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <vector>

#include "dayphoton/core/error_text.h"

#include "sha256_x86.h"

namespace dayphoton {

namespace {

using detail::K;

constexpr std::uint32_t rotr(std::uint32_t x, int n) { return (x >> n) | (x << (32 - n)); }

}  // namespace

Sha256::Sha256(Rounds rounds)
    : m_hardware(rounds == Rounds::Fastest && detail::sha256_x86_available()),
      m_state{0x6a09e667, 0xbb67ae85, 0x3c6ef372, 0xa54ff53a, 0x510e527f, 0x9b05688c, 0x1f83d9ab, 0x5be0cd19} {}

void Sha256::block(const std::uint8_t* p) {
  std::uint32_t w[64];
  for (int t = 0; t < 16; ++t)
    w[t] = (std::uint32_t(p[4 * t]) << 24) | (std::uint32_t(p[4 * t + 1]) << 16) |
           (std::uint32_t(p[4 * t + 2]) << 8) | std::uint32_t(p[4 * t + 3]);
  for (int t = 16; t < 64; ++t) {
    const std::uint32_t s0 = rotr(w[t - 15], 7) ^ rotr(w[t - 15], 18) ^ (w[t - 15] >> 3);
    const std::uint32_t s1 = rotr(w[t - 2], 17) ^ rotr(w[t - 2], 19) ^ (w[t - 2] >> 10);
    w[t] = w[t - 16] + s0 + w[t - 7] + s1;
  }
  std::uint32_t a = m_state[0], b = m_state[1], c = m_state[2], d = m_state[3];
  std::uint32_t e = m_state[4], f = m_state[5], g = m_state[6], h = m_state[7];
  for (int t = 0; t < 64; ++t) {
    const std::uint32_t t1 = h + (rotr(e, 6) ^ rotr(e, 11) ^ rotr(e, 25)) + ((e & f) ^ (~e & g)) + K[t] + w[t];
    const std::uint32_t t2 = (rotr(a, 2) ^ rotr(a, 13) ^ rotr(a, 22)) + ((a & b) ^ (a & c) ^ (b & c));
    h = g;
    g = f;
    f = e;
    e = d + t1;
    d = c;
    c = b;
    b = a;
    a = t1 + t2;
  }
  m_state[0] += a;
  m_state[1] += b;
  m_state[2] += c;
  m_state[3] += d;
  m_state[4] += e;
  m_state[5] += f;
  m_state[6] += g;
  m_state[7] += h;
}

bool Sha256::hardware_rounds() { return detail::sha256_x86_available(); }

void Sha256::blocks(const std::uint8_t* p, std::size_t count) {
  if (m_hardware) {
    detail::sha256_x86_blocks(m_state.data(), p, count);
    return;
  }
  for (std::size_t i = 0; i < count; ++i) block(p + 64 * i);
}

void Sha256::update(const void* data, std::size_t size) {
  const auto* p = static_cast<const std::uint8_t*>(data);
  m_bytes += size;
  while (size > 0) {
    if (m_buffered == 0 && size >= 64) {
      const std::size_t count = size / 64;
      blocks(p, count);
      p += 64 * count;
      size -= 64 * count;
      continue;
    }
    const std::size_t n = std::min(size, 64 - m_buffered);
    std::memcpy(m_buffer.data() + m_buffered, p, n);
    m_buffered += n;
    p += n;
    size -= n;
    if (m_buffered == 64) {
      blocks(m_buffer.data(), 1);
      m_buffered = 0;
    }
  }
}

std::string Sha256::hex() {
  // Padding (section 5.1.1): a 1 bit, zeros to 56 mod 64 bytes, the length in bits (big endian).
  const std::uint64_t bits = m_bytes * 8;
  const std::uint8_t one = 0x80, zero = 0;
  update(&one, 1);
  while (m_buffered != 56) update(&zero, 1);
  std::uint8_t length[8];
  for (int i = 0; i < 8; ++i) length[i] = static_cast<std::uint8_t>(bits >> (56 - 8 * i));
  update(length, 8);
  static const char* digits = "0123456789abcdef";
  std::string out;
  for (std::uint32_t word : m_state)
    for (int shift = 28; shift >= 0; shift -= 4) out += digits[(word >> shift) & 0xf];
  return out;
}

std::string sha256_hex(const std::string& bytes) {
  Sha256 h;
  h.update(bytes.data(), bytes.size());
  return h.hex();
}

std::string sha256_file_hex(const std::string& path, std::uint64_t* size_bytes) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path + ": " + error_text(errno));
  Sha256 h;
  std::vector<char> buffer(1 << 16);
  std::uint64_t total = 0;
  while (in) {
    in.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
    const std::streamsize n = in.gcount();
    if (n > 0) {
      h.update(buffer.data(), static_cast<std::size_t>(n));
      total += static_cast<std::uint64_t>(n);
    }
  }
  if (in.bad()) throw std::runtime_error("cannot read " + path);
  if (size_bytes) *size_bytes = total;
  return h.hex();
}

}  // namespace dayphoton
