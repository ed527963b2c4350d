// Tone mapping for viewing; see tone_map.h.
#include "dayphoton/study/tone_map.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "dayphoton/core/units.h"

namespace dayphoton::study {

namespace {

/// sRGB transfer function (IEC 61966-2-1) of a linear value in [0, 1], as an 8-bit code.
std::uint8_t srgb_byte(double linear) {
  const double v = std::clamp(linear, 0.0, 1.0);
  const double e = v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
  return static_cast<std::uint8_t>(std::lround(255.0 * e));
}

}  // namespace

RgbaImage tone_map(const FloatImage& rgb) {
  const int r = rgb.channel("R"), g = rgb.channel("G"), b = rgb.channel("B"), alpha = rgb.channel("A");
  if (r < 0 || g < 0 || b < 0) throw std::invalid_argument("tone_map: the image needs R, G and B channels");
  auto pixel = [&](int x, int y) {
    return Vec3{rgb.at(static_cast<std::size_t>(r), x, y), rgb.at(static_cast<std::size_t>(g), x, y),
                rgb.at(static_cast<std::size_t>(b), x, y)};
  };
  auto valid = [&](int x, int y, double& luminance) {
    if (alpha >= 0 && !(rgb.at(static_cast<std::size_t>(alpha), x, y) > 0)) return false;
    const Vec3 p = pixel(x, y);
    if (!is_finite(p) || p.x < 0 || p.y < 0 || p.z < 0) return false;
    luminance = rgb_to_photometric(p);
    return true;
  };
  // Log-average luminance (Reinhard eq. 1) with delta = 1e-4 cd/m2 against log(0).
  double log_sum = 0;
  std::size_t count = 0;
  std::vector<double> luminances;
  for (int y = 0; y < rgb.height; ++y)
    for (int x = 0; x < rgb.width; ++x) {
      double l = 0;
      if (!valid(x, y, l)) continue;
      log_sum += std::log(1e-4 + l);
      luminances.push_back(l);
      ++count;
    }
  RgbaImage out(rgb.width, rgb.height, {0, 0, 0, 255});
  if (count == 0) return out;
  const double log_average = std::exp(log_sum / static_cast<double>(count));
  const double key = 0.18 / log_average;
  std::sort(luminances.begin(), luminances.end());
  // The brightest 0.1 % are let burn out (none in images of fewer than 1000 pixels).
  const std::size_t white_index = luminances.size() - 1 - luminances.size() / 1000;
  const double white = std::max(1e-12, key * luminances[white_index]);
  for (int y = 0; y < rgb.height; ++y)
    for (int x = 0; x < rgb.width; ++x) {
      double l = 0;
      if (!valid(x, y, l)) {
        if (alpha >= 0 && !(rgb.at(static_cast<std::size_t>(alpha), x, y) > 0)) out.at(x, y) = {0, 0, 0, 0};
        continue;
      }
      if (l <= 0) continue;
      const double ls = key * l;
      const double ld = ls * (1 + ls / (white * white)) / (1 + ls);
      // Display RGB whose luminance weights give Ld: radiance x 179 x Ld / L.
      const Vec3 d = pixel(x, y) * (RadianceWhiteEfficacy_lm_per_W * ld / l);
      out.at(x, y) = {srgb_byte(d.x), srgb_byte(d.y), srgb_byte(d.z), 255};
    }
  return out;
}

}  // namespace dayphoton::study
