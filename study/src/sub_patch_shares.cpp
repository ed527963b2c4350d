// The annual product's sub-patch shares: see sub_patch_shares.h.
#include "dayphoton/study/sub_patch_shares.h"

#include <stdexcept>
#include <string>

#include "dayphoton/core/units.h"
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

SubPatchShares sub_patch_shares(const engine::DaylightCoefficients& c, SharesOf of) {
  SubPatchShares out;
  out.sensors = c.sensors;
  out.bins = c.sources;
  const bool direct = of == SharesOf::Coefficient;
  if (direct ? c.direct_quadrants.empty() : c.photon_quadrants.empty()) return out;
  const std::size_t n = c.sensors * c.sources;
  if (direct && (c.direct_quadrants.size() != n * engine::StoredQuadrants || c.direct.size() != n))
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
    const Vec3 whole = !photon ? c.direct[i] : direct ? c.direct[i] + c.caustic[i] + c.global[i] : c.caustic[i] + c.global[i];
    v[0] = static_cast<float>(engine::luminance_of(whole));
    for (std::size_t q = 0; q < engine::StoredQuadrants; ++q) {
      const std::size_t k = i * engine::StoredQuadrants + q;
      v[1 + q] = (direct ? c.direct_quadrants[k] : 0.0f) + (photon ? c.photon_quadrants[k] : 0.0f);
    }
  }
  return out;
}

std::vector<double> sub_patch_correction_lux(const SubPatchShares& shares, const RadianceMatrix& quadrant_deltas,
                                             std::size_t column) {
  std::vector<double> out(shares.sensors, 0.0);
  if (shares.empty()) return out;
  if (quadrant_deltas.rows() != 4 * shares.bins || column >= quadrant_deltas.columns() ||
      quadrant_deltas.components() != 1 || shares.values.size() != shares.sensors * shares.bins * SubPatchShares::ValuesPerBin)
    throw std::invalid_argument("sub-patch correction: shares of " + std::to_string(shares.bins) +
                                " bins against quadrant deltas of " + std::to_string(quadrant_deltas.rows()) +
                                " rows, column " + std::to_string(column) + " of " +
                                std::to_string(quadrant_deltas.columns()));
  for (std::size_t s = 0; s < shares.sensors; ++s) {
    double sum = 0;
    for (std::size_t p = 0; p < shares.bins; ++p) {
      const float* v = shares.values.data() + (s * shares.bins + p) * SubPatchShares::ValuesPerBin;
      const double q3 = double(v[0]) - double(v[1]) - double(v[2]) - double(v[3]);
      for (std::size_t q = 0; q < 3; ++q) sum += double(v[1 + q]) * double(quadrant_deltas.at(4 * p + q, column, 0));
      sum += q3 * double(quadrant_deltas.at(4 * p + 3, column, 0));
    }
    out[s] = RadianceWhiteEfficacy_lm_per_W * sum;
  }
  return out;
}

}  // namespace dayphoton::study
