// The annual product's sub-patch shares: see sub_patch_shares.h.
#include "dayphoton/study/sub_patch_shares.h"

#include <stdexcept>
#include <string>

#include "dayphoton/engine/estimate_variance.h"

namespace dayphoton::study {

SubPatchShares SubPatchShares::rows(std::size_t begin, std::size_t end) const {
  if (begin > end || end > sensors) throw std::invalid_argument("sub-patch shares: rows out of range");
  SubPatchShares out;
  out.sensors = end - begin;
  out.bins = bins;
  if (empty()) return out;
  const std::size_t row = bins * ValuesPerBin;
  out.values.assign(values.begin() + std::ptrdiff_t(begin * row), values.begin() + std::ptrdiff_t(end * row));
  return out;
}

RadianceMatrix sub_patch_shares_matrix(const SubPatchShares& shares) {
  RadianceMatrix m(shares.sensors, shares.bins, static_cast<int>(SubPatchShares::ValuesPerBin));
  m.data() = shares.values;
  return m;
}

SubPatchShares sub_patch_shares_of(const RadianceMatrix& m, std::size_t sensors, std::size_t bins) {
  if (m.rows() != sensors || m.columns() != bins ||
      m.components() != static_cast<int>(SubPatchShares::ValuesPerBin))
    throw std::invalid_argument("has " + std::to_string(m.rows()) + " rows x " + std::to_string(m.columns()) +
                                " columns x " + std::to_string(m.components()) + " components, expected " +
                                std::to_string(sensors) + " sensors x " + std::to_string(bins) + " bins x " +
                                std::to_string(SubPatchShares::ValuesPerBin));
  SubPatchShares out;
  out.sensors = sensors;
  out.bins = bins;
  out.values = m.data();
  return out;
}

SubPatchShares sub_patch_shares(const engine::DaylightCoefficients& c) {
  SubPatchShares out;
  out.sensors = c.sensors;
  out.bins = c.sources;
  if (c.direct_quadrants.empty()) return out;
  const std::size_t n = c.sensors * c.sources;
  if (c.direct_quadrants.size() != n * engine::StoredQuadrants || c.direct.size() != n)
    throw std::invalid_argument("sub-patch shares: " + std::to_string(c.direct_quadrants.size()) + " shares and " +
                                std::to_string(c.direct.size()) + " direct coefficients for " +
                                std::to_string(c.sensors) + " sensors x " + std::to_string(c.sources) + " sources");
  // With the photon part's shares, the whole coefficient's: both parts' luminance and shares.
  const bool photon = !c.photon_quadrants.empty();
  if (photon && (c.photon_quadrants.size() != n * engine::StoredQuadrants || c.caustic.size() != n ||
                 c.global.size() != n))
    throw std::invalid_argument("sub-patch shares: " + std::to_string(c.photon_quadrants.size()) +
                                " photon shares and " + std::to_string(c.caustic.size()) +
                                " photon coefficients for " + std::to_string(c.sensors) + " sensors x " +
                                std::to_string(c.sources) + " sources");
  out.values.resize(n * SubPatchShares::ValuesPerBin);
  for (std::size_t i = 0; i < n; ++i) {
    float* v = out.values.data() + i * SubPatchShares::ValuesPerBin;
    v[0] = static_cast<float>(engine::luminance_of(photon ? c.direct[i] + c.caustic[i] + c.global[i] : c.direct[i]));
    for (std::size_t q = 0; q < engine::StoredQuadrants; ++q) {
      const std::size_t k = i * engine::StoredQuadrants + q;
      v[1 + q] = c.direct_quadrants[k] + (photon ? c.photon_quadrants[k] : 0.0f);
    }
  }
  return out;
}

}  // namespace dayphoton::study
