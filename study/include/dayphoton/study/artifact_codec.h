// Binary encodings of the pipeline's artefacts for the ArtifactStore: the photons of one
// source (resumable photon pass), daylight coefficients, and RADIANCE matrices (sky matrices).
// docs/cache.md describes where they are stored.
//
// Layout: a 4-byte tag naming the type ("PHOT", "DCOF", "RMTX"), a u32 layout version, then
// the fields in declaration order; every integer and float little-endian and fixed-width
// (sizes and counts u64, floats and doubles by bit pattern, so a round trip is bit-exact,
// NaNs included), whatever the host. Decoding checks the tag, the version, every count
// against the bytes that remain (before allocating anything) and that nothing is left over,
// and throws std::runtime_error on any mismatch; the pipeline then treats the artefact as
// absent and recomputes it.
//
//   photons:      u64 n, n photons; u64 planes, per plane u64 n + n photons; u64 sources,
//                 per source the SourceTally (6 x u64, 5 x f64, u64 capped 0/1, u64 nothing_stores 0/1). A photon is 32 bytes:
//                 3 x f32 position, 3 x f32 flux, u32 source word (the source in the low 20
//                 bits, the sky ratio code in the top 12: engine::Photon::source_word), 3 x i8
//                 normal, u8 path class (checked to be a PathClass).
//   coefficients: u64 sensors, u64 sources, u64 skies, u64 photon part on the sky (0 or 1),
//                 u64 its basis rows, u64 sub-patch shares (0 or 1), then direct, caustic, global, each sensors x sources Vec3
//                 as 3 x f64, then direct_variance and photon_variance, each sensors x sources
//                 f64, then the direct part on the skies (sensors x skies Vec3, then as many
//                 f64 variances), then the photon part on the sky (sensors Vec3, sensors f64)
//                 if it is there, then the direct part's sub-patch shares (sensors x sources x
//                 engine::StoredQuadrants f32) if they are there.
//   matrix:       u64 rows, u64 columns, u32 components (>= 1), u64 header lines, each
//                 u64 length + bytes, then rows x columns x components f32.
#pragma once

#include <cstdint>
#include <string>

#include "dayphoton/core/radiance_matrix.h"
#include "dayphoton/engine/daylight_coefficients.h"
#include "dayphoton/engine/photon_tracer.h"

namespace dayphoton::study {

/// Layout versions: bump one whenever its layout changes, so older artefacts are refused
/// (and recomputed) instead of misread.
inline constexpr std::uint32_t PhotonLayoutVersion = 5;  // 2: SourceTally::capped; 3: storage_probability_direct, nothing_stores; 4: the sky ratio in the source word's top 12 bits (engine/photon.h); 5: the sky quadrant in the path class's byte
inline constexpr std::uint32_t CoefficientLayoutVersion = 6;  // 2: the variances; 3: the direct part on skies; 4: the photon part on the sky; 5: the sub-patch shares; 6: the photon part's sub-patch shares
inline constexpr std::uint32_t MatrixLayoutVersion = 1;

std::string encode_photons(const engine::TracedPhotons& photons);
engine::TracedPhotons decode_photons(const std::string& bytes);

/// Throws std::invalid_argument if direct, caustic or global is not sensors x sources long.
std::string encode_coefficients(const engine::DaylightCoefficients& c);
engine::DaylightCoefficients decode_coefficients(const std::string& bytes);

std::string encode_matrix(const RadianceMatrix& m);
RadianceMatrix decode_matrix(const std::string& bytes);

}  // namespace dayphoton::study
