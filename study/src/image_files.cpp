// EXR (OpenEXR) and PNG (libpng) files of the results; see image_files.h.
//
// Why libraries and not our own encoders: both are Debian packages (libopenexr-dev is already
// a dependency, libpng-dev comes with it on any desktop install), both formats have corner
// cases (EXR's channel sorting and line orders, PNG's CRCs and zlib framing) that a reader
// in another tool will hold us to, and neither library is large. docs/architecture.md.
#include "dayphoton/study/image_files.h"

#include <filesystem>
#include <memory>
#include <stdexcept>
#include <unistd.h>

#include <ImfChannelList.h>
#include <ImfFloatAttribute.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfStringAttribute.h>
#include <ImfVecAttribute.h>
#include <csetjmp>
#include <png.h>

#include "dayphoton/core/atomic_file.h"

#ifndef DAYPHOTON_VERSION
#define DAYPHOTON_VERSION "unknown"
#endif

namespace dayphoton::study {

namespace fs = std::filesystem;

static_assert(sizeof(std::array<std::uint8_t, 4>) == 4, "RGBA rows are handed to libpng as bytes");

FloatImage::FloatImage(int w, int h, std::vector<std::string> names)
    : width(w), height(h), channel_names(std::move(names)) {
  if (w <= 0 || h <= 0) throw std::invalid_argument("image size must be positive");
  channels.assign(channel_names.size(),
                  std::vector<float>(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), 0.0f));
}

int FloatImage::channel(const std::string& name) const {
  for (std::size_t i = 0; i < channel_names.size(); ++i)
    if (channel_names[i] == name) return static_cast<int>(i);
  return -1;
}

void write_exr(const FloatImage& image, const std::string& quantity, const std::string& unit,
               const std::string& path) {
  const std::size_t pixels = static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height);
  if (image.width <= 0 || image.height <= 0 || image.channel_names.empty() ||
      image.channels.size() != image.channel_names.size())
    throw std::invalid_argument("write_exr: " + path + ": empty image or channel count mismatch");
  for (const auto& c : image.channels)
    if (c.size() != pixels) throw std::invalid_argument("write_exr: " + path + ": channel size mismatch");

  Imf::Header header(image.width, image.height);
  header.compression() = Imf::ZIP_COMPRESSION;
  for (const std::string& name : image.channel_names) header.channels().insert(name, Imf::Channel(Imf::FLOAT));
  header.insert("quantity", Imf::StringAttribute(quantity));
  header.insert("unit", Imf::StringAttribute(unit));
  header.insert("software", Imf::StringAttribute(std::string("dayphoton ") + DAYPHOTON_VERSION));
  for (const auto& [name, value] : image.string_attributes) header.insert(name, Imf::StringAttribute(value));
  for (const auto& [name, value] : image.float_attributes) header.insert(name, Imf::FloatAttribute(value));
  for (const auto& [name, v] : image.vector_attributes)
    header.insert(name, Imf::V3fAttribute(Imath::V3f(static_cast<float>(v.x), static_cast<float>(v.y),
                                                     static_cast<float>(v.z))));

  Imf::FrameBuffer frame;
  const std::size_t x_stride = sizeof(float);
  const std::size_t y_stride = sizeof(float) * static_cast<std::size_t>(image.width);
  for (std::size_t c = 0; c < image.channels.size(); ++c)
    frame.insert(image.channel_names[c],
                 Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(const_cast<float*>(image.channels[c].data())),
                            x_stride, y_stride));

  // Atomic: OpenEXR writes a temporary file beside the target, renamed when complete.
  const std::string temporary = path + ".tmp." + std::to_string(::getpid());
  try {
    Imf::OutputFile file(temporary.c_str(), header, 1);
    file.setFrameBuffer(frame);
    file.writePixels(image.height);
  } catch (const std::exception& e) {
    std::error_code ignored;
    fs::remove(temporary, ignored);
    throw std::runtime_error("cannot write " + path + ": " + e.what());
  }
  std::error_code ec;
  fs::rename(temporary, path, ec);
  if (ec) {
    fs::remove(temporary, ec);
    throw std::runtime_error("cannot write " + path + ": rename failed");
  }
}

FloatImage read_exr(const std::string& path) {
  try {
    Imf::InputFile file(path.c_str());
    const Imf::Header& header = file.header();
    const Imath::Box2i window = header.dataWindow();
    const int width = window.max.x - window.min.x + 1;
    const int height = window.max.y - window.min.y + 1;
    std::vector<std::string> names;
    for (auto it = header.channels().begin(); it != header.channels().end(); ++it) names.push_back(it.name());
    FloatImage image(width, height, names);
    Imf::FrameBuffer frame;
    const std::size_t x_stride = sizeof(float);
    const std::size_t y_stride = sizeof(float) * static_cast<std::size_t>(width);
    for (std::size_t c = 0; c < names.size(); ++c) {
      // The slice base is offset so that pixel (min.x, min.y) lands on element 0.
      char* base = reinterpret_cast<char*>(image.channels[c].data()) -
                   static_cast<std::ptrdiff_t>(window.min.x) * static_cast<std::ptrdiff_t>(x_stride) -
                   static_cast<std::ptrdiff_t>(window.min.y) * static_cast<std::ptrdiff_t>(y_stride);
      frame.insert(names[c], Imf::Slice(Imf::FLOAT, base, x_stride, y_stride));
    }
    file.setFrameBuffer(frame);
    file.readPixels(window.min.y, window.max.y);
    for (auto it = header.begin(); it != header.end(); ++it) {
      const Imf::Attribute& a = it.attribute();
      if (const auto* s = dynamic_cast<const Imf::StringAttribute*>(&a)) {
        image.string_attributes[it.name()] = s->value();
      } else if (const auto* f = dynamic_cast<const Imf::FloatAttribute*>(&a)) {
        image.float_attributes[it.name()] = f->value();
      } else if (const auto* v = dynamic_cast<const Imf::V3fAttribute*>(&a)) {
        image.vector_attributes[it.name()] = Vec3{v->value().x, v->value().y, v->value().z};
      }
    }
    return image;
  } catch (const std::invalid_argument&) {
    throw;
  } catch (const std::exception& e) {
    throw std::runtime_error("cannot read " + path + ": " + e.what());
  }
}

RgbaImage::RgbaImage(int w, int h, std::array<std::uint8_t, 4> fill) : width(w), height(h) {
  if (w <= 0 || h <= 0) throw std::invalid_argument("image size must be positive");
  pixels.assign(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), fill);
}

namespace {

extern "C" void png_append(png_structp png, png_bytep data, png_size_t length) {
  auto* out = static_cast<std::string*>(png_get_io_ptr(png));
  out->append(reinterpret_cast<const char*>(data), length);
}
extern "C" void png_flush_nothing(png_structp) {}

/// libpng reports errors by longjmp to png_jmpbuf (its documented C interface): this frame
/// holds only plain data after setjmp, so the jump skips no destructor. Returns false if
/// libpng failed (out of memory; the arguments are checked by the caller).
bool encode_rows(png_structp png, png_infop info, const RgbaImage& image) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_set_IHDR(png, info, static_cast<png_uint_32>(image.width), static_cast<png_uint_32>(image.height), 8,
               PNG_COLOR_TYPE_RGBA, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_sRGB(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
  png_write_info(png, info);
  for (int y = 0; y < image.height; ++y) {
    const std::size_t first = static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width);
    png_write_row(png, const_cast<png_bytep>(image.pixels[first].data()));
  }
  png_write_end(png, nullptr);
  return true;
}

}  // namespace

std::string encode_png(const RgbaImage& image) {
  if (image.width <= 0 || image.height <= 0 ||
      image.pixels.size() != static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height))
    throw std::invalid_argument("encode_png: empty image or size mismatch");
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  if (!png) throw std::runtime_error("PNG encoder: out of memory");
  png_infop info = png_create_info_struct(png);
  std::string bytes;
  bool ok = false;
  if (info) {
    png_set_write_fn(png, &bytes, png_append, png_flush_nothing);
    ok = encode_rows(png, info, image);
  }
  png_destroy_write_struct(&png, info ? &info : nullptr);
  if (!ok) throw std::runtime_error("PNG encoder failed");
  return bytes;
}

void write_png(const RgbaImage& image, const std::string& path) {
  write_file_atomically(path, encode_png(image));
}

std::string base64(const std::string& bytes) {
  static const char* const alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const unsigned v = (static_cast<unsigned char>(bytes[i]) << 16) |
                       (static_cast<unsigned char>(bytes[i + 1]) << 8) | static_cast<unsigned char>(bytes[i + 2]);
    out += alphabet[(v >> 18) & 63];
    out += alphabet[(v >> 12) & 63];
    out += alphabet[(v >> 6) & 63];
    out += alphabet[v & 63];
  }
  if (i + 1 == bytes.size()) {
    const unsigned v = static_cast<unsigned char>(bytes[i]) << 16;
    out += alphabet[(v >> 18) & 63];
    out += alphabet[(v >> 12) & 63];
    out += "==";
  } else if (i + 2 == bytes.size()) {
    const unsigned v = (static_cast<unsigned char>(bytes[i]) << 16) | (static_cast<unsigned char>(bytes[i + 1]) << 8);
    out += alphabet[(v >> 18) & 63];
    out += alphabet[(v >> 12) & 63];
    out += alphabet[(v >> 6) & 63];
    out += '=';
  }
  return out;
}

}  // namespace dayphoton::study
