// A list of byte strings in one dist::ByteBuffer, for the messages of the distributed
// executor (distributed_executor.cpp, distributed_blocks.cpp): the count, then per string its
// length and bytes (64-bit lengths as this machine writes them; every rank runs the same
// build). Readers throw std::runtime_error on a truncated or malformed buffer.
#pragma once

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "dayphoton/dist/byte_buffer.h"

namespace dayphoton::study {

inline void put_u64(dist::ByteBuffer& out, std::uint64_t v) {
  const std::size_t at = out.size();
  out.resize(at + sizeof v);
  std::memcpy(out.data() + at, &v, sizeof v);
}

inline std::uint64_t get_u64(const dist::ByteBuffer& in, std::size_t& at) {
  std::uint64_t v = 0;
  if (in.size() - at < sizeof v) throw std::runtime_error("distributed executor: truncated message");
  std::memcpy(&v, in.data() + at, sizeof v);
  at += sizeof v;
  return v;
}

inline void put_strings(dist::ByteBuffer& out, const std::vector<std::string>& strings) {
  put_u64(out, strings.size());
  for (const std::string& s : strings) {
    put_u64(out, s.size());
    const std::size_t at = out.size();
    out.resize(at + s.size());
    if (!s.empty()) std::memcpy(out.data() + at, s.data(), s.size());
  }
}

inline std::vector<std::string> get_strings(const dist::ByteBuffer& in, std::size_t& at) {
  const std::uint64_t n = get_u64(in, at);
  if (n > in.size()) throw std::runtime_error("distributed executor: malformed message");
  std::vector<std::string> strings(n);
  for (std::string& s : strings) {
    const std::uint64_t length = get_u64(in, at);
    if (length > in.size() - at) throw std::runtime_error("distributed executor: truncated message");
    s.assign(reinterpret_cast<const char*>(in.data() + at), length);
    at += length;
  }
  return strings;
}

}  // namespace dayphoton::study
