#pragma once
// The little fixed layout of dist/'s own control messages (assignments, outcomes): unsigned
// 64-bit integers little-endian, strings as a length and their bytes. Internal to dist/.
#include <cstdint>
#include <stdexcept>
#include <string>

#include "dayphoton/dist/byte_buffer.h"

namespace dayphoton::dist::wire {

inline void put_u64(ByteBuffer& out, std::uint64_t v) {
  for (int i = 0; i < 8; ++i) out.push_back(static_cast<std::byte>((v >> (8 * i)) & 0xffu));
}

inline void put_string(ByteBuffer& out, const std::string& s) {
  put_u64(out, s.size());
  for (char c : s) out.push_back(static_cast<std::byte>(c));
}

/// Reads what put_* wrote; a short or inconsistent buffer is a std::runtime_error.
class Reader {
 public:
  explicit Reader(const ByteBuffer& in) : m_in(in) {}

  std::uint64_t u64() {
    need(8);
    std::uint64_t v = 0;
    for (int i = 0; i < 8; ++i) v |= std::uint64_t(std::to_integer<unsigned>(m_in[m_at + i])) << (8 * i);
    m_at += 8;
    return v;
  }

  std::string string() {
    const std::uint64_t n = u64();
    need(n);
    std::string s(n, '\0');
    for (std::uint64_t i = 0; i < n; ++i) s[i] = static_cast<char>(m_in[m_at + i]);
    m_at += n;
    return s;
  }

  bool at_end() const { return m_at == m_in.size(); }

 private:
  void need(std::uint64_t n) const {
    if (n > m_in.size() - m_at) throw std::runtime_error("dist: truncated control message");
  }
  const ByteBuffer& m_in;
  std::size_t m_at = 0;
};

}  // namespace dayphoton::dist::wire
