// direct_sun.bin.gz: the exact direct sun of a grid, exported by `run`, read by `annual`.
// Layout and meaning in direct_sun_file.h and docs/outputs.md. Compression: zlib's deflate
// with a gzip wrapper (J.-l. Gailly and M. Adler, zlib 1.2 manual, deflateInit2 with
// windowBits 15 + 16), so `zcat` shows the header; reading goes through GzipInput and its
// decompressed-size limit.
#include "dayphoton/study/direct_sun_file.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>

#include <zlib.h>

#include "dayphoton/core/atomic_file.h"
#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/gzip_input.h"
#include "dayphoton/core/units.h"
#include "dayphoton/study/annual_sun.h"

namespace dayphoton::study {
namespace {

constexpr const char* FirstLine = "dayphoton direct sun";
constexpr int Version = 1;
/// Header lines longer than this are not ours (a binary file read as text).
constexpr std::size_t MaxHeaderLine = 4096;
constexpr std::size_t MaxHeaderLines = 64;

void put_u32(std::string& out, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<char>((v >> (8 * i)) & 0xFF));
}
void put_f32(std::string& out, float f) {
  std::uint32_t v;
  std::memcpy(&v, &f, 4);
  put_u32(out, v);
}
void put_f64(std::string& out, double d) {
  std::uint64_t v;
  std::memcpy(&v, &d, 8);
  for (int i = 0; i < 8; ++i) out.push_back(static_cast<char>((v >> (8 * i)) & 0xFF));
}

/// A header value on one line (a file name may hold a line break).
std::string one_line(std::string text) {
  for (char& c : text)
    if (c == '\n' || c == '\r') c = ' ';
  return text;
}

std::string gzip(const std::string& data) {
  z_stream z{};
  if (deflateInit2(&z, 6, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY) != Z_OK)
    throw std::runtime_error("direct sun file: zlib deflateInit2 failed");
  std::string out;
  out.resize(deflateBound(&z, static_cast<uLong>(data.size())) + 64);
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data.data()));
  z.avail_in = static_cast<uInt>(data.size());
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = static_cast<uInt>(out.size());
  const int rc = deflate(&z, Z_FINISH);
  const std::size_t written = out.size() - z.avail_out;
  deflateEnd(&z);
  if (rc != Z_STREAM_END) throw std::runtime_error("direct sun file: zlib deflate failed");
  out.resize(written);
  return out;
}

/// Bytes from a stream, or a located error naming what was being read.
class Reader {
 public:
  Reader(std::istream& in, std::string path) : m_in(in), m_path(std::move(path)) {}
  void bytes(void* to, std::size_t n, const std::string& what) {
    m_in.read(static_cast<char*>(to), static_cast<std::streamsize>(n));
    if (static_cast<std::size_t>(m_in.gcount()) != n) fail("ends inside " + what);
    m_offset += n;
  }
  std::uint32_t u32(const std::string& what) {
    unsigned char b[4];
    bytes(b, 4, what);
    return std::uint32_t(b[0]) | std::uint32_t(b[1]) << 8 | std::uint32_t(b[2]) << 16 | std::uint32_t(b[3]) << 24;
  }
  float f32(const std::string& what) {
    const std::uint32_t v = u32(what);
    float f;
    std::memcpy(&f, &v, 4);
    return f;
  }
  double f64(const std::string& what) {
    unsigned char b[8];
    bytes(b, 8, what);
    std::uint64_t v = 0;
    for (int i = 7; i >= 0; --i) v = v << 8 | b[i];
    double d;
    std::memcpy(&d, &v, 8);
    return d;
  }
  [[noreturn]] void fail(const std::string& message) const {
    throw InputError(SourceLocation{m_path, 0, 0},
                     "decompressed byte " + std::to_string(m_offset) + ": " + message);
  }
  void count(std::size_t n) { m_offset += n; }

 private:
  std::istream& m_in;
  std::string m_path;
  std::size_t m_offset = 0;
};

std::size_t header_count(const std::map<std::string, std::string>& keys, const std::string& key,
                         std::size_t limit, const std::string& path) {
  const auto it = keys.find(key);
  if (it == keys.end()) throw InputError(SourceLocation{path, 0, 0}, "the header has no " + key + "=");
  std::size_t v = 0;
  std::size_t used = 0;
  try {
    v = std::stoull(it->second, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != it->second.size() || v > limit)
    throw InputError(SourceLocation{path, 0, 0},
                     key + "=" + it->second + " is not a count from 0 to " + std::to_string(limit));
  return v;
}

}  // namespace

DirectSunExport make_direct_sun_export(const std::vector<DirectSunPart>& parts) {
  struct Column {
    const sky::SunRecord* sun;
    const RadianceMatrix* direct;
    std::size_t column;
  };
  std::vector<Column> columns;
  int components = 3;  // of every part: RGB, or one luminance value
  DirectSunExport e;
  bool first = true;
  for (const DirectSunPart& p : parts) {
    if (p.direct->columns() != p.suns->size() || (p.direct->components() != 3 && p.direct->components() != 1) ||
        (!first && p.direct->components() != components))
      throw std::invalid_argument("direct sun export: " + std::to_string(p.direct->columns()) + " columns x " +
                                  std::to_string(p.direct->components()) + " components for " +
                                  std::to_string(p.suns->size()) + " suns (RGB or luminance, alike, expected)");
    if (!first && p.direct->rows() != e.sensors)
      throw std::invalid_argument("direct sun export: parts with different sensor counts");
    e.sensors = p.direct->rows();
    components = p.direct->components();
    first = false;
    for (std::size_t k = 0; k < p.suns->size(); ++k) columns.push_back({&(*p.suns)[k], p.direct, k});
  }
  std::sort(columns.begin(), columns.end(), [](const Column& a, const Column& b) { return a.sun->step < b.sun->step; });
  for (std::size_t k = 1; k < columns.size(); ++k)
    if (columns[k].sun->step == columns[k - 1].sun->step)
      throw std::invalid_argument("direct sun export: step " + std::to_string(columns[k].sun->step) + " given twice");
  for (const Column& c : columns) {
    if (c.sun->step > std::numeric_limits<std::uint32_t>::max())
      throw std::invalid_argument("direct sun export: a step beyond 32 bits");
    e.steps.push_back(static_cast<std::uint32_t>(c.sun->step));
    e.directions.push_back(c.sun->direction);
  }
  // As direct_sun_table (annual_sun.cpp) sums them: 179 w_c C_c in double, c = 0, 1, 2; a
  // luminance matrix (one component): 179 C_0.
  const Vec3 w = components == 3 ? RgbLuminanceWeights * RadianceWhiteEfficacy_lm_per_W
                                 : Vec3{RadianceWhiteEfficacy_lm_per_W, 0, 0};
  e.row_start.assign(e.sensors + 1, 0);
  for (std::size_t s = 0; s < e.sensors; ++s) {
    for (std::size_t k = 0; k < columns.size(); ++k) {
      double v = 0;
      for (int c = 0; c < components; ++c) v += w[c] * double(columns[k].direct->at(s, columns[k].column, c));
      if (v > 0) {
        e.sun.push_back(static_cast<std::uint32_t>(k));
        e.lux.push_back(v);
      }
    }
    e.row_start[s + 1] = e.lux.size();
  }
  return e;
}

std::vector<sky::SunRecord> daytime_suns_without_direct(const weather::HourlyWeather& weather,
                                                        const sky::SolarSite& site,
                                                        const sky::SkyMatrixOptions& options,
                                                        const std::vector<sky::SunRecord>& lit) {
  std::vector<char> has(weather.records.size(), 0);
  for (const sky::SunRecord& s : lit)
    if (s.step < has.size()) has[s.step] = 1;
  std::vector<sky::SunRecord> other;
  for (const sky::SunRecord& s : sky::daytime_sun_positions(weather, site, options))
    if (!has[s.step] && static_cast<float>(s.direction.z) > 0) other.push_back(s);
  return suns_from_matrix(suns_to_matrix(other));
}

void write_direct_sun_file(const DirectSunExport& e, const std::string& path) {
  const std::size_t n = e.sun_count();
  std::ostringstream header;
  header << FirstLine << "\nversion=" << Version << "\nsensors=" << e.sensors << "\nsuns=" << n
         << "\nsun_bins_mf=" << e.sun_bins_mf << "\nseed=" << e.seed << "\nsamples=" << e.samples
         << "\nquantity=direct-sun illuminance per unit disc radiance, lx per W/(sr m2): 179 (0.265, 0.670, 0.065) . "
            "RGB irradiance of a 0.533 deg sun disc through the glazing, zero bounces"
         << "\nsuns_basis=every record of the run's weather file whose sun centre is above the horizon at the site"
         << "\nlayout=K x (uint32 step, float32 x y z); per sensor ceil(K/8) bytes bit mask (bit k%8 of byte k/8: "
            "sun k reaches the sensor) then float64 per set bit; little-endian"
         << "\nsite=" << one_line(e.site) << "\nweather=" << one_line(e.weather) << "\n\n";
  std::string data = header.str();
  const std::size_t mask_bytes = (n + 7) / 8;
  data.reserve(data.size() + 16 * n + e.sensors * mask_bytes + 8 * e.lux.size());
  for (std::size_t k = 0; k < n; ++k) {
    put_u32(data, e.steps[k]);
    for (int c = 0; c < 3; ++c) put_f32(data, static_cast<float>(e.directions[k][c]));
  }
  std::string mask(mask_bytes, '\0');
  for (std::size_t s = 0; s < e.sensors; ++s) {
    std::fill(mask.begin(), mask.end(), '\0');
    for (std::size_t i = e.row_start[s]; i < e.row_start[s + 1]; ++i)
      mask[e.sun[i] / 8] = static_cast<char>(static_cast<unsigned char>(mask[e.sun[i] / 8]) | (1u << (e.sun[i] % 8)));
    data += mask;
    for (std::size_t i = e.row_start[s]; i < e.row_start[s + 1]; ++i) put_f64(data, e.lux[i]);
  }
  const std::string compressed = gzip(data);
  write_file_atomically(path, [&](std::ostream& out) { out.write(compressed.data(), std::streamsize(compressed.size())); },
                        true);
}

DirectSunExport read_direct_sun_file(const std::string& path, std::uint64_t max_decompressed_bytes) {
  GzipInput in(path, max_decompressed_bytes, "direct-sun file", "--max-decompressed-bytes");
  Reader r(in, path);
  std::map<std::string, std::string> keys;
  for (std::size_t line_no = 1;; ++line_no) {
    std::string line;
    char ch;
    while (in.get(ch) && ch != '\n') {
      line.push_back(ch);
      if (line.size() > MaxHeaderLine)
        throw InputError(SourceLocation{path, int(line_no), 0}, "header line longer than " +
                                                                   std::to_string(MaxHeaderLine) + " characters");
    }
    if (!in) throw InputError(SourceLocation{path, int(line_no), 0}, "the header does not end (no empty line)");
    r.count(line.size() + 1);
    if (line_no == 1) {
      if (line != FirstLine)
        throw InputError(SourceLocation{path, 1, 1}, "not a dayphoton direct-sun file (first line '" +
                                                         line.substr(0, 40) + "')");
      continue;
    }
    if (line.empty()) break;
    if (line_no > MaxHeaderLines) throw InputError(SourceLocation{path, int(line_no), 0}, "header too long");
    const std::size_t eq = line.find('=');
    if (eq == std::string::npos) throw InputError(SourceLocation{path, int(line_no), 1}, "expected key=value");
    keys[line.substr(0, eq)] = line.substr(eq + 1);
  }
  if (header_count(keys, "version", 1000, path) != std::size_t(Version))
    throw InputError(SourceLocation{path, 0, 0}, "version " + keys["version"] + ", this dayphoton reads " +
                                                     std::to_string(Version));
  DirectSunExport e;
  // A year of hourly records has at most 8784 suns; sub-hourly files up to 60 a hour.
  e.sensors = header_count(keys, "sensors", std::size_t(1) << 31, path);
  const std::size_t n = header_count(keys, "suns", 60 * 8784, path);
  e.sun_bins_mf = static_cast<int>(header_count(keys, "sun_bins_mf", 64, path));
  e.seed = header_count(keys, "seed", std::numeric_limits<std::size_t>::max(), path);
  e.samples = static_cast<int>(header_count(keys, "samples", 1 << 20, path));
  e.site = keys["site"];
  e.weather = keys["weather"];
  for (std::size_t k = 0; k < n; ++k) {
    e.steps.push_back(r.u32("the sun records"));
    Vec3 d;
    for (int c = 0; c < 3; ++c) d[c] = r.f32("the sun records");
    if (!is_finite(d) || !(d.z > 0) || !(length(d) > 0.99 && length(d) < 1.01))
      r.fail("sun " + std::to_string(k) + " is not a unit direction above the horizon");
    if (k > 0 && e.steps[k] <= e.steps[k - 1]) r.fail("sun " + std::to_string(k) + ": steps must increase");
    e.directions.push_back(normalize(d));
  }
  const std::size_t mask_bytes = (n + 7) / 8;
  std::vector<unsigned char> mask(mask_bytes);
  // Grown as the data arrive: a header claiming many sensors allocates nothing in advance.
  e.row_start.assign(1, 0);
  for (std::size_t s = 0; s < e.sensors; ++s) {
    const std::string what = "sensor " + std::to_string(s);
    r.bytes(mask.data(), mask_bytes, what);
    for (std::size_t k = 0; k < n; ++k)
      if (mask[k / 8] >> (k % 8) & 1u) {
        const double v = r.f64(what);
        if (!std::isfinite(v) || !(v > 0)) r.fail(what + ", sun " + std::to_string(k) + ": not a positive number");
        e.sun.push_back(static_cast<std::uint32_t>(k));
        e.lux.push_back(v);
      }
    if (n % 8 && mask[mask_bytes - 1] >> (n % 8)) r.fail(what + ": bits set beyond the last sun");
    e.row_start.push_back(e.lux.size());
  }
  char extra;
  if (in.get(extra)) r.fail("data after the last sensor");
  return e;
}

}  // namespace dayphoton::study
