// An attempt range (engine::AttemptRange: photons and counts of attempts [a, b) of one source)
// as a message between the ranks of an MPI run: its counts, then per photon list (the
// surface's, then each plane's) the count and the 32-byte records as this build lays them out
// (every rank runs the same build, as for the rest of the run's messages). Used where a
// source's attempts are traced in ranges over the ranks: split_photon_steps.cpp (a big
// source's passes) and distributed_round_work.cpp (the accuracy rounds).
#pragma once

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <type_traits>
#include <vector>

#include "dayphoton/dist/byte_buffer.h"
#include "dayphoton/engine/photon_tracer.h"

namespace dayphoton::study {
namespace range_wire {

static_assert(std::is_trivially_copyable_v<engine::Photon>, "photon records travel as bytes");

inline void put_bytes(dist::ByteBuffer& out, const void* data, std::size_t n) {
  const std::size_t at = out.size();
  out.resize(at + n);
  if (n > 0) std::memcpy(out.data() + at, data, n);
}

inline void put_u64(dist::ByteBuffer& out, std::uint64_t v) { put_bytes(out, &v, sizeof v); }

inline std::uint64_t get_u64(const dist::ByteBuffer& in, std::size_t& at) {
  std::uint64_t v = 0;
  if (in.size() - at < sizeof v) throw std::runtime_error("photon range: truncated message");
  std::memcpy(&v, in.data() + at, sizeof v);
  at += sizeof v;
  return v;
}

inline void put_photons(dist::ByteBuffer& out, const std::vector<engine::Photon>& photons) {
  put_u64(out, photons.size());
  put_bytes(out, photons.data(), photons.size() * sizeof(engine::Photon));
}

inline std::vector<engine::Photon> get_photons(const dist::ByteBuffer& in, std::size_t& at) {
  const std::uint64_t n = get_u64(in, at);
  if (n > (in.size() - at) / sizeof(engine::Photon)) throw std::runtime_error("photon range: truncated message");
  std::vector<engine::Photon> photons(n);
  if (n > 0) std::memcpy(photons.data(), in.data() + at, n * sizeof(engine::Photon));
  at += n * sizeof(engine::Photon);
  return photons;
}

}  // namespace range_wire

inline dist::ByteBuffer encode_attempt_range(const engine::AttemptRange& r) {
  using namespace range_wire;
  dist::ByteBuffer out;
  const engine::AttemptCounts& c = r.counts;
  for (std::uint64_t v : {c.entered, c.stored_global, c.stored_caustic, c.stored_direct, c.rays, c.scattered_indoors})
    put_u64(out, v);
  put_photons(out, r.surface);
  put_u64(out, r.planes.size());
  for (const std::vector<engine::Photon>& plane : r.planes) put_photons(out, plane);
  return out;
}

/// Throws std::runtime_error for a truncated or malformed message.
inline engine::AttemptRange decode_attempt_range(const dist::ByteBuffer& in) {
  using namespace range_wire;
  engine::AttemptRange r;
  std::size_t at = 0;
  engine::AttemptCounts& c = r.counts;
  for (std::uint64_t* v : {&c.entered, &c.stored_global, &c.stored_caustic, &c.stored_direct, &c.rays,
                           &c.scattered_indoors})
    *v = get_u64(in, at);
  r.surface = get_photons(in, at);
  const std::uint64_t planes = get_u64(in, at);
  if (planes > in.size()) throw std::runtime_error("photon range: malformed message");
  r.planes.resize(planes);
  for (std::vector<engine::Photon>& plane : r.planes) plane = get_photons(in, at);
  if (at != in.size()) throw std::runtime_error("photon range: malformed message");
  return r;
}

}  // namespace dayphoton::study
