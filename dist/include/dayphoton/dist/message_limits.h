#pragma once
// Size policy of every message dist/ sends (declared once, used by every communicator).
#include <cstdint>

namespace dayphoton::dist {

/// A buffer larger than this travels as several messages of at most this many bytes.
/// MPI counts elements in an `int`, so one message must stay below 2^31 bytes; 64 MiB keeps
/// each message small enough for the eager/rendezvous protocols of every interconnect and
/// for a receiver to allocate as it goes.
constexpr std::uint64_t MaxChunkBytes = std::uint64_t{64} << 20;

/// No single buffer may exceed this (refused on send and on receive, before any allocation).
/// The largest artefact of a run (a photon map of one source, or a block of coefficients) is
/// well under a GiB; 16 GiB means a corrupt size field or a bug, not data.
constexpr std::uint64_t MaxBufferBytes = std::uint64_t{16} << 30;

}  // namespace dayphoton::dist
