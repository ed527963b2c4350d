// Counter-based random numbers: every number is a pure function of (seed, source, photon
// index, stream, draw), so a photon's path does not depend on which thread traces it, in
// which order, or on how many processes share the work (DESIGN.md sections 5 and 7).
//
// Why separate streams: Schregle's thesis (seeds/000 section 6.2, digest section 5.1) found
// its sphere furnace most consistent with independent generator states for emission,
// scattering and Russian roulette; here each (photon, stream) pair is its own generator.
//
// Generator: SplitMix64 (Steele, Lea & Flood, "Fast splittable pseudorandom number
// generators", OOPSLA 2014), which passes BigCrush. The key (seed, source, index, stream)
// is hashed into the starting state with the same finaliser, one word at a time, so
// neighbouring keys give unrelated sequences.
#pragma once

#include <cstdint>

namespace dayphoton::engine {

/// The independent streams of one photon (or one sensor, for estimates).
enum class RandomStream : std::uint32_t {
  Emission = 1,     ///< port, position and direction of a new photon
  Scattering = 2,   ///< BSDF component and direction
  Roulette = 3,     ///< Russian roulette and storage decisions
  Direct = 4,       ///< stratified direct-component sampling at a sensor
  Estimate = 5,     ///< randomised estimators (bias compensation)
  Storage = 6,      ///< main-pass storage decisions (photon-count control)
  Gather = 7,       ///< final-gather rays from a sensor
  DirectPort = 8,   ///< port points of the direct component's port sampling
  Placement = 9,    ///< the placement test's walks from a sensor (sensor_placement.h)
};

/// The part of a key shared by every photon of one source, hashed once: mix(mix(seed) ^ source).
struct RngSourceKey {
  std::uint64_t hashed;
};

class Rng {
 public:
  Rng(std::uint64_t seed, std::uint64_t source, std::uint64_t index, RandomStream stream)
      : Rng(source_key(seed, source), index, stream) {}
  /// The same generator as Rng(seed, source, index, stream) for key = source_key(seed, source),
  /// with the source's half of the hashing done once (a tracer makes three generators per
  /// photon).
  Rng(RngSourceKey key, std::uint64_t index, RandomStream stream)
      : m_state(mix(mix(key.hashed ^ index) ^ static_cast<std::uint64_t>(stream))) {}
  static RngSourceKey source_key(std::uint64_t seed, std::uint64_t source) { return {mix(mix(seed) ^ source)}; }

  /// Next 64 random bits.
  std::uint64_t next_u64() {
    m_state += 0x9E3779B97F4A7C15ull;
    return mix(m_state);
  }
  /// Uniform in [0, 1) with 53 random bits (never 1.0).
  double uniform() { return static_cast<double>(next_u64() >> 11) * 0x1.0p-53; }

  /// SplitMix64's finaliser (a bijection on 64-bit words).
  static std::uint64_t mix(std::uint64_t z) {
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }

 private:
  std::uint64_t m_state;
};

}  // namespace dayphoton::engine
