// Sensor blocks: see sensor_blocks.h.
#include "dayphoton/study/sensor_blocks.h"

#include <algorithm>
#include <stdexcept>

#include "dayphoton/study/artifact_codec.h"

namespace dayphoton::study {

std::vector<engine::SensorRange> sensor_blocks(std::size_t sensors, std::size_t block_size) {
  if (block_size == 0) throw std::invalid_argument("sensor blocks: the block size must be at least 1");
  std::vector<engine::SensorRange> blocks;
  blocks.reserve((sensors + block_size - 1) / block_size);
  for (std::size_t begin = 0; begin < sensors; begin += block_size)
    blocks.push_back({begin, begin + std::min(block_size, sensors - begin)});
  return blocks;
}

std::string join_coefficient_blocks(const std::vector<std::string>& blocks) {
  if (blocks.empty()) throw std::invalid_argument("sensor blocks: no coefficient block to join");
  engine::DaylightCoefficients whole = decode_coefficients(blocks.front());
  for (std::size_t b = 1; b < blocks.size(); ++b) {
    const engine::DaylightCoefficients part = decode_coefficients(blocks[b]);
    if (part.sources != whole.sources)
      throw std::invalid_argument("sensor blocks: a coefficient block of " + std::to_string(part.sources) +
                                  " sources joined to one of " + std::to_string(whole.sources));
    whole.sensors += part.sensors;
    auto append = [](auto& to, const auto& from) { to.insert(to.end(), from.begin(), from.end()); };
    append(whole.direct, part.direct);
    append(whole.caustic, part.caustic);
    append(whole.global, part.global);
    append(whole.direct_variance, part.direct_variance);
    append(whole.photon_variance, part.photon_variance);
    if (part.direct_on_skies.skies != whole.direct_on_skies.skies)
      throw std::invalid_argument("sensor blocks: a coefficient block on " + std::to_string(part.direct_on_skies.skies) +
                                  " skies joined to one on " + std::to_string(whole.direct_on_skies.skies));
    append(whole.direct_on_skies.irradiance, part.direct_on_skies.irradiance);
    append(whole.direct_on_skies.variance, part.direct_on_skies.variance);
    if (part.direct_quadrants.empty() != whole.direct_quadrants.empty())
      throw std::invalid_argument("sensor blocks: a coefficient block with and one without the sub-patch shares");
    append(whole.direct_quadrants, part.direct_quadrants);
    if (part.photon_quadrants.empty() != whole.photon_quadrants.empty())
      throw std::invalid_argument("sensor blocks: a coefficient block with and one without the photon sub-patch shares");
    append(whole.photon_quadrants, part.photon_quadrants);
    if (part.photon_on_sky.empty() != whole.photon_on_sky.empty())
      throw std::invalid_argument("sensor blocks: a coefficient block with and one without the photon part on the sky");
    append(whole.photon_on_sky.irradiance, part.photon_on_sky.irradiance);
    append(whole.photon_on_sky.variance, part.photon_on_sky.variance);
    whole.photon_on_sky.basis_rows += part.photon_on_sky.basis_rows;
  }
  return encode_coefficients(whole);
}

std::string join_matrix_blocks(const std::vector<std::string>& blocks) {
  if (blocks.empty()) throw std::invalid_argument("sensor blocks: no matrix block to join");
  std::vector<RadianceMatrix> parts;
  parts.reserve(blocks.size());
  std::size_t rows = 0;
  for (const std::string& bytes : blocks) {
    parts.push_back(decode_matrix(bytes));
    const RadianceMatrix& m = parts.back();
    const RadianceMatrix& first = parts.front();
    if (m.columns() != first.columns() || m.components() != first.components() ||
        m.header_lines() != first.header_lines())
      throw std::invalid_argument("sensor blocks: matrix blocks of different columns, components or headers");
    rows += m.rows();
  }
  RadianceMatrix whole(rows, parts.front().columns(), parts.front().components());
  whole.header_lines() = parts.front().header_lines();
  auto at = whole.data().begin();
  for (const RadianceMatrix& m : parts) at = std::copy(m.data().begin(), m.data().end(), at);
  return encode_matrix(whole);
}

std::vector<std::string> output_of_blocks(const std::vector<std::vector<std::string>>& blocks, std::size_t k) {
  std::vector<std::string> out;
  out.reserve(blocks.size());
  for (const std::vector<std::string>& b : blocks) {
    if (k >= b.size())
      throw std::invalid_argument("sensor blocks: a block has " + std::to_string(b.size()) + " outputs, not " +
                                  std::to_string(k + 1));
    out.push_back(b[k]);
  }
  return out;
}

SensorBlocks matrix_sensor_blocks(std::size_t sensors, std::function<RadianceMatrix(engine::SensorRange)> rows) {
  SensorBlocks b;
  b.sensors = sensors;
  b.compute_rows = [rows = std::move(rows)](std::size_t begin, std::size_t end) {
    return std::vector<std::string>{encode_matrix(rows(engine::SensorRange{begin, end}))};
  };
  b.join = [](const std::vector<std::vector<std::string>>& blocks) {
    return std::vector<std::string>{join_matrix_blocks(output_of_blocks(blocks, 0))};
  };
  return b;
}

}  // namespace dayphoton::study
