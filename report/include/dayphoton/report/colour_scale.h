// ColourScale: how a value becomes a colour in the false-colour plans, PNGs and the temporal
// map of the report (issue 7: "colour scales with legends and units").
//
// Colours follow viridis (van der Walt & Smith, matplotlib 1.5, 2015: perceptually uniform,
// readable by the common colour-vision deficiencies and in greyscale print), sampled at nine
// published stops and interpolated linearly in sRGB; the 1/8 spacing keeps the difference
// from the 256-entry table below one 8-bit step. Values are clamped to [min, max] (the legend
// says so with "<=" / ">=" labels); a logarithmic scale maps log10(value).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace dayphoton::report {

struct ColourScale {
  double min = 0, max = 1;
  bool logarithmic = false;  ///< map log10(value); min > 0 then
  std::string quantity;      ///< e.g. "daylight factor"
  std::string unit;          ///< e.g. "%", "lx"

  /// Position of `value` on the scale in [0, 1] (clamped; NaN -> 0).
  double position(double value) const;
  /// sRGB colour of `value`.
  std::array<std::uint8_t, 3> colour(double value) const;
  /// Legend tick values: about `count` round numbers between min and max (decades for a
  /// logarithmic scale), always including both ends.
  std::vector<double> ticks(int count = 6) const;
};

/// Viridis at t in [0, 1] (clamped).
std::array<std::uint8_t, 3> viridis(double t);

/// "#rrggbb".
std::string hex_colour(const std::array<std::uint8_t, 3>& rgb);

/// Scales used by the report and the images (ranges chosen for side-lit rooms: DF 0-10 %,
/// time percentages 0-100 %, illuminance 10-10 000 lx logarithmic).
ColourScale daylight_factor_scale();
ColourScale percent_scale(const std::string& quantity);
ColourScale illuminance_scale();

}  // namespace dayphoton::report
