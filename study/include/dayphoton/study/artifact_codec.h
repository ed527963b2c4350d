// Binary encodings of the pipeline's artefacts for the ArtifactStore: the photons of one
// source (resumable photon pass), daylight coefficients, and RADIANCE matrices (sky matrices).
// Little-endian, fixed-width fields, a leading layout version; decoding checks sizes and
// throws std::runtime_error on any mismatch (the store then treats the artefact as absent).
#pragma once

#include <string>

#include "dayphoton/core/radiance_matrix.h"
#include "dayphoton/engine/daylight_coefficients.h"
#include "dayphoton/engine/photon_tracer.h"

namespace dayphoton::study {

std::string encode_photons(const engine::TracedPhotons& photons);
engine::TracedPhotons decode_photons(const std::string& bytes);

std::string encode_coefficients(const engine::DaylightCoefficients& c);
engine::DaylightCoefficients decode_coefficients(const std::string& bytes);

std::string encode_matrix(const RadianceMatrix& m);
RadianceMatrix decode_matrix(const std::string& bytes);

}  // namespace dayphoton::study
