// Image files of the results (issue 7, DESIGN.md section 6: ".exr for linear data, .png for
// viewing"): OpenEXR for values (float channels, with header attributes naming the quantity
// and its unit), PNG for pictures (8-bit sRGB, with alpha).
//
// EXR: scan-line file, ZIP compression (lossless), 32-bit float channels, written through
// OpenEXR's Imf::OutputFile (Debian libopenexr-dev). Every file carries the attributes
//   "quantity" (string), "unit" (string), "software" ("dayphoton <version>")
// plus whatever the caller adds (strings, floats, 3-vectors). Pixel (0, 0) is the top left.
// PNG: libpng (Debian libpng-dev), 8-bit RGBA, no interlacing, an sRGB chunk.
// Both are written atomically (temporary file in the same folder, then rename).
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "dayphoton/core/vec3.h"

namespace dayphoton::study {

/// A float image with named channels, row-major, row 0 at the top.
struct FloatImage {
  int width = 0, height = 0;
  std::vector<std::string> channel_names;      ///< e.g. {"R", "G", "B"} or {"Y", "A"}
  std::vector<std::vector<float>> channels;    ///< one plane of width x height per name
  std::map<std::string, std::string> string_attributes;
  std::map<std::string, float> float_attributes;
  std::map<std::string, Vec3> vector_attributes;  ///< stored as v3f

  FloatImage() = default;
  FloatImage(int w, int h, std::vector<std::string> names);
  float& at(std::size_t channel, int x, int y) {
    return channels[channel][static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                             static_cast<std::size_t>(x)];
  }
  float at(std::size_t channel, int x, int y) const {
    return channels[channel][static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                             static_cast<std::size_t>(x)];
  }
  /// Index of a channel by name; -1 if absent.
  int channel(const std::string& name) const;
};

/// Write `image` (at least one channel, sizes consistent, otherwise std::invalid_argument)
/// with the attributes "quantity", "unit" and "software" added. Throws std::runtime_error
/// naming the path on I/O failure.
void write_exr(const FloatImage& image, const std::string& quantity, const std::string& unit,
               const std::string& path);

/// Read every channel of a scan-line or tiled EXR as float, and its string, float and v3f
/// attributes. Throws std::runtime_error naming the path.
FloatImage read_exr(const std::string& path);

/// An 8-bit RGBA picture, row-major, row 0 at the top, sRGB-encoded values.
struct RgbaImage {
  int width = 0, height = 0;
  std::vector<std::array<std::uint8_t, 4>> pixels;
  RgbaImage() = default;
  RgbaImage(int w, int h, std::array<std::uint8_t, 4> fill = {0, 0, 0, 0});
  std::array<std::uint8_t, 4>& at(int x, int y) {
    return pixels[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)];
  }
  const std::array<std::uint8_t, 4>& at(int x, int y) const {
    return pixels[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)];
  }
};

/// The PNG file's bytes (for embedding as a data URI) and writing it atomically. Throws
/// std::invalid_argument for an empty image, std::runtime_error on encoder or I/O failure.
std::string encode_png(const RgbaImage& image);
void write_png(const RgbaImage& image, const std::string& path);

/// RFC 4648 base64 (for data: URIs in the self-contained report).
std::string base64(const std::string& bytes);

}  // namespace dayphoton::study
