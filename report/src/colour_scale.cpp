// Colour scales of the report and images; see colour_scale.h.
#include "dayphoton/report/colour_scale.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace dayphoton::report {

namespace {

// Viridis at t = 0, 1/8, ..., 1 (matplotlib's published table, entries 0, 32, ..., 224, 255).
constexpr std::array<std::array<double, 3>, 9> ViridisStops{{{68, 1, 84},
                                                             {71, 45, 123},
                                                             {59, 82, 139},
                                                             {44, 114, 142},
                                                             {33, 145, 140},
                                                             {40, 174, 128},
                                                             {94, 201, 98},
                                                             {173, 220, 48},
                                                             {253, 231, 37}}};

/// A "nice" step (1, 2 or 5 x 10^k) close to span / count.
double nice_step(double span, int count) {
  const double raw = span / std::max(1, count);
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  const double r = raw / magnitude;
  const double m = r < 1.5 ? 1 : (r < 3.5 ? 2 : (r < 7.5 ? 5 : 10));
  return m * magnitude;
}

}  // namespace

std::array<std::uint8_t, 3> viridis(double t) {
  if (!(t > 0)) t = 0;
  if (t > 1) t = 1;
  const double x = t * 8.0;
  const int i = std::min(7, static_cast<int>(x));
  const double f = x - i;
  std::array<std::uint8_t, 3> out{};
  for (int c = 0; c < 3; ++c) {
    const double v = ViridisStops[i][c] + f * (ViridisStops[i + 1][c] - ViridisStops[i][c]);
    out[c] = static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0, 255.0)));
  }
  return out;
}

std::string hex_colour(const std::array<std::uint8_t, 3>& rgb) {
  char buffer[8];
  std::snprintf(buffer, sizeof buffer, "#%02x%02x%02x", rgb[0], rgb[1], rgb[2]);
  return buffer;
}

double ColourScale::position(double value) const {
  if (std::isnan(value)) return 0;
  double a = min, b = max, v = value;
  if (logarithmic) {
    a = std::log10(min);
    b = std::log10(max);
    v = value > 0 ? std::log10(value) : a;
  }
  if (!(b > a)) return 0;
  return std::clamp((v - a) / (b - a), 0.0, 1.0);
}

std::array<std::uint8_t, 3> ColourScale::colour(double value) const { return viridis(position(value)); }

std::vector<double> ColourScale::ticks(int count) const {
  std::vector<double> out;
  if (logarithmic) {
    for (double d = std::pow(10.0, std::ceil(std::log10(min) - 1e-9)); d <= max * (1 + 1e-9); d *= 10)
      out.push_back(d);
    if (out.empty() || out.front() > min * (1 + 1e-9)) out.insert(out.begin(), min);
    if (out.back() < max * (1 - 1e-9)) out.push_back(max);
    return out;
  }
  const double step = nice_step(max - min, count);
  out.push_back(min);
  for (double v = std::ceil(min / step + 1e-9) * step; v < max - 1e-9 * step; v += step)
    if (v > min + 1e-9 * step) out.push_back(v);
  out.push_back(max);
  return out;
}

ColourScale daylight_factor_scale() { return {0, 10, false, "daylight factor", "%"}; }
ColourScale percent_scale(const std::string& quantity) { return {0, 100, false, quantity, "%"}; }
ColourScale illuminance_scale() { return {10, 10000, true, "illuminance", "lx"}; }

}  // namespace dayphoton::report
