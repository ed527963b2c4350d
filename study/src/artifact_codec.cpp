// Binary encodings of photons, daylight coefficients and RADIANCE matrices for the cache
// (artifact_codec.h gives the layouts). The writer sizes its buffer exactly up front and
// stores bytes by shifts, so the output is little-endian on any host; the reader checks
// every length before it reads or allocates.
#include "dayphoton/study/artifact_codec.h"

#include <cstring>
#include <stdexcept>
#include <utility>
#include <vector>

namespace dayphoton::study {

namespace {

using engine::Photon;
using engine::SourceTally;

constexpr std::size_t PhotonBytes = 32;
constexpr std::size_t TallyBytes = 6 * 8 + 5 * 8 + 8 + 8;
constexpr std::size_t Vec3Bytes = 24;
/// Per (sensor, source): direct, caustic, global (Vec3) and the two variances (f64).
constexpr std::size_t CoefficientPairBytes = 3 * Vec3Bytes + 2 * 8;
/// Per (sensor, continuous sky): the direct irradiance (Vec3) and its variance (f64).
constexpr std::size_t SkyDirectBytes = Vec3Bytes + 8;
constexpr std::size_t PreambleBytes = 8;  // tag + version
/// A coefficient artefact's counts: sensors, sources, skies, photon part on the sky (0 or 1),
/// its basis rows and the sub-patch shares (0 or 1), u64 each.
constexpr std::size_t CoefficientHeaderBytes = 6 * 8;
/// Per (sensor, source) with the sub-patch shares: engine::StoredQuadrants f32.
constexpr std::size_t QuadrantPairBytes = engine::StoredQuadrants * 4;

class Writer {
 public:
  explicit Writer(std::size_t size) : m_out(size, '\0') {}

  void tag(const char (&t)[5], std::uint32_t version) {
    std::memcpy(&m_out[m_at], t, 4);
    m_at += 4;
    u32(version);
  }
  void u8(std::uint8_t v) { m_out[m_at++] = static_cast<char>(v); }
  void u32(std::uint32_t v) { le(v, 4); }
  void u64(std::uint64_t v) { le(v, 8); }
  void f32(float v) {
    std::uint32_t bits;
    std::memcpy(&bits, &v, 4);
    u32(bits);
  }
  void f64(double v) {
    std::uint64_t bits;
    std::memcpy(&bits, &v, 8);
    u64(bits);
  }
  void text(const std::string& s) {
    u64(s.size());
    std::memcpy(&m_out[m_at], s.data(), s.size());
    m_at += s.size();
  }
  void vec3(const Vec3& v) {
    f64(v.x);
    f64(v.y);
    f64(v.z);
  }
  void photon(const Photon& p) {
    for (const float x : p.position) f32(x);
    for (const float x : p.flux) f32(x);
    u32(p.source_word());
    for (const std::int8_t x : p.normal) u8(static_cast<std::uint8_t>(x));
    u8(p.class_byte());
  }

  std::string finish() {
    if (m_at != m_out.size()) throw std::logic_error("artifact codec: encoded size mismatch");
    return std::move(m_out);
  }

 private:
  void le(std::uint64_t v, int n) {
    for (int i = 0; i < n; ++i) m_out[m_at++] = static_cast<char>((v >> (8 * i)) & 0xff);
  }
  std::string m_out;
  std::size_t m_at = 0;
};

class Reader {
 public:
  Reader(const std::string& bytes, const char* what)
      : m_p(reinterpret_cast<const unsigned char*>(bytes.data())), m_n(bytes.size()), m_what(what) {}

  void tag(const char (&t)[5], std::uint32_t version) {
    need(4, "tag");
    if (std::memcmp(m_p, t, 4) != 0) fail(std::string("not a ") + m_what + " (tag is not '" + t + "')");
    m_at = 4;
    const std::uint32_t found = u32("layout version");
    if (found != version)
      fail(std::string(m_what) + " layout version " + std::to_string(found) + ", this build reads " +
           std::to_string(version));
  }
  std::uint8_t u8(const char* field) {
    need(1, field);
    return m_p[m_at++];
  }
  std::uint32_t u32(const char* field) { return static_cast<std::uint32_t>(le(4, field)); }
  std::uint64_t u64(const char* field) { return le(8, field); }
  float f32(const char* field) {
    const std::uint32_t bits = u32(field);
    float v;
    std::memcpy(&v, &bits, 4);
    return v;
  }
  double f64(const char* field) {
    const std::uint64_t bits = u64(field);
    double v;
    std::memcpy(&v, &bits, 8);
    return v;
  }
  /// A count of elements of at least `element_bytes` each, checked against what remains.
  std::size_t count(std::size_t element_bytes, const char* field) {
    const std::uint64_t n = u64(field);
    if (n > (m_n - m_at) / element_bytes)
      fail(std::string("truncated: ") + field + " says " + std::to_string(n) + " x " +
           std::to_string(element_bytes) + " bytes, " + std::to_string(m_n - m_at) + " remain");
    return static_cast<std::size_t>(n);
  }
  std::string text(const char* field) {
    const std::size_t n = count(1, field);
    std::string s(reinterpret_cast<const char*>(m_p + m_at), n);
    m_at += n;
    return s;
  }
  Vec3 vec3(const char* field) {
    const double x = f64(field), y = f64(field), z = f64(field);
    return {x, y, z};
  }
  Photon photon() {
    Photon p;
    for (float& x : p.position) x = f32("photon position");
    for (float& x : p.flux) x = f32("photon flux");
    p.set_source_word(u32("photon source"));
    for (std::int8_t& x : p.normal) x = static_cast<std::int8_t>(u8("photon normal"));
    // The path class and the sky quadrant (engine::Photon::class_byte).
    const std::uint8_t b = u8("photon path class");
    const std::uint8_t c = b & 3u;
    if (c > static_cast<std::uint8_t>(engine::PathClass::Global) || (b >> 4) != 0)
      fail("photon path class " + std::to_string(b) + " is not a path class and a sky quadrant");
    p.path_class = static_cast<engine::PathClass>(c);
    p.sky_quadrant = (b >> 2) & 3u;
    return p;
  }
  std::vector<Photon> photons(const char* field) {
    std::vector<Photon> out(count(PhotonBytes, field));
    for (Photon& p : out) p = photon();
    return out;
  }
  void done() const {
    if (m_at != m_n) fail(std::to_string(m_n - m_at) + " bytes left over after the " + m_what);
  }

  [[noreturn]] void fail(const std::string& why) const {
    throw std::runtime_error(std::string("cannot decode ") + m_what + ": " + why);
  }

 private:
  void need(std::size_t bytes, const char* field) const {
    if (m_n - m_at < bytes)
      fail(std::string("truncated at byte ") + std::to_string(m_at) + " (" + field + ")");
  }
  std::uint64_t le(int n, const char* field) {
    need(static_cast<std::size_t>(n), field);
    std::uint64_t v = 0;
    for (int i = 0; i < n; ++i) v |= std::uint64_t(m_p[m_at + i]) << (8 * i);
    m_at += static_cast<std::size_t>(n);
    return v;
  }
  const unsigned char* m_p;
  std::size_t m_n, m_at = 0;
  const char* m_what;
};

}  // namespace

// ---- photons ------------------------------------------------------------------------------

std::string encode_photons(const engine::TracedPhotons& photons) {
  std::size_t size = PreambleBytes + 8 + photons.surface.size() * PhotonBytes + 8;
  for (const auto& plane : photons.planes) size += 8 + plane.size() * PhotonBytes;
  size += 8 + photons.tallies.size() * TallyBytes;

  Writer w(size);
  w.tag("PHOT", PhotonLayoutVersion);
  w.u64(photons.surface.size());
  for (const Photon& p : photons.surface) w.photon(p);
  w.u64(photons.planes.size());
  for (const auto& plane : photons.planes) {
    w.u64(plane.size());
    for (const Photon& p : plane) w.photon(p);
  }
  w.u64(photons.tallies.size());
  for (const SourceTally& t : photons.tallies) {
    w.u64(t.prepass_attempts);
    w.u64(t.mainpass_attempts);
    w.u64(t.entered);
    w.u64(t.stored_global);
    w.u64(t.stored_caustic);
    w.u64(t.stored_direct);
    w.f64(t.bound_flux);
    w.f64(t.flux_per_attempt);
    w.f64(t.storage_probability_global);
    w.f64(t.storage_probability_caustic);
    w.f64(t.storage_probability_direct);
    w.u64(t.capped ? 1 : 0);
    w.u64(t.nothing_stores ? 1 : 0);
  }
  return w.finish();
}

engine::TracedPhotons decode_photons(const std::string& bytes) {
  Reader r(bytes, "photon artefact");
  r.tag("PHOT", PhotonLayoutVersion);
  engine::TracedPhotons out;
  out.surface = r.photons("surface photon count");
  // Each plane takes at least its 8-byte count.
  out.planes.resize(r.count(8, "plane count"));
  for (auto& plane : out.planes) plane = r.photons("plane photon count");
  out.tallies.resize(r.count(TallyBytes, "source count"));
  for (SourceTally& t : out.tallies) {
    t.prepass_attempts = r.u64("prepass_attempts");
    t.mainpass_attempts = r.u64("mainpass_attempts");
    t.entered = r.u64("entered");
    t.stored_global = r.u64("stored_global");
    t.stored_caustic = r.u64("stored_caustic");
    t.stored_direct = r.u64("stored_direct");
    t.bound_flux = r.f64("bound_flux");
    t.flux_per_attempt = r.f64("flux_per_attempt");
    t.storage_probability_global = r.f64("storage_probability_global");
    t.storage_probability_caustic = r.f64("storage_probability_caustic");
    t.storage_probability_direct = r.f64("storage_probability_direct");
    const std::uint64_t capped = r.u64("capped");
    if (capped > 1) r.fail("capped flag " + std::to_string(capped) + " is not 0 or 1");
    t.capped = capped == 1;
    const std::uint64_t nothing = r.u64("nothing_stores");
    if (nothing > 1) r.fail("nothing_stores flag " + std::to_string(nothing) + " is not 0 or 1");
    t.nothing_stores = nothing == 1;
  }
  r.done();
  return out;
}

// ---- daylight coefficients ------------------------------------------------------------------

std::string encode_coefficients(const engine::DaylightCoefficients& c) {
  const std::size_t n = c.sensors * c.sources;
  if ((c.sources != 0 && n / c.sources != c.sensors) || c.direct.size() != n ||
      c.caustic.size() != n || c.global.size() != n || !c.has_variance())
    throw std::invalid_argument("daylight coefficients: direct/caustic/global and both variances must hold " +
                                std::to_string(c.sensors) + " x " + std::to_string(c.sources) +
                                " values (have " + std::to_string(c.direct.size()) + ", " +
                                std::to_string(c.caustic.size()) + ", " +
                                std::to_string(c.global.size()) + ", " + std::to_string(c.direct_variance.size()) +
                                ", " + std::to_string(c.photon_variance.size()) + ")");
  const engine::DirectOnSkies& skies = c.direct_on_skies;
  const std::size_t m = c.sensors * skies.skies;
  if ((skies.skies != 0 && m / skies.skies != c.sensors) || skies.irradiance.size() != m || skies.variance.size() != m)
    throw std::invalid_argument("daylight coefficients: the direct part on " + std::to_string(skies.skies) +
                                " skies must hold " + std::to_string(c.sensors) + " x " +
                                std::to_string(skies.skies) + " values");
  const engine::PhotonOnSky& photon_sky = c.photon_on_sky;
  const std::size_t photon_rows = photon_sky.empty() ? 0 : c.sensors;
  if (!photon_sky.empty() && (photon_sky.irradiance.size() != c.sensors || photon_sky.variance.size() != c.sensors ||
                              photon_sky.basis_rows > c.sensors))
    throw std::invalid_argument("daylight coefficients: the photon part on the sky must hold " +
                                std::to_string(c.sensors) + " values");
  // The sub-patch shares: a bit each for the direct part's (1) and the photon part's (2).
  const bool quadrants = !c.direct_quadrants.empty(), photon_quadrants = !c.photon_quadrants.empty();
  for (const auto* shares : {&c.direct_quadrants, &c.photon_quadrants})
    if (!shares->empty() && shares->size() != n * engine::StoredQuadrants)
      throw std::invalid_argument("daylight coefficients: the sub-patch shares must hold " +
                                  std::to_string(c.sensors) + " x " + std::to_string(c.sources) + " x " +
                                  std::to_string(engine::StoredQuadrants) + " values");
  const std::size_t share_sets = std::size_t(quadrants) + std::size_t(photon_quadrants);
  Writer w(PreambleBytes + CoefficientHeaderBytes + n * CoefficientPairBytes + m * SkyDirectBytes +
           photon_rows * SkyDirectBytes + share_sets * n * QuadrantPairBytes);
  w.tag("DCOF", CoefficientLayoutVersion);
  w.u64(c.sensors);
  w.u64(c.sources);
  w.u64(skies.skies);
  w.u64(photon_rows > 0 ? 1 : 0);
  w.u64(photon_sky.basis_rows);
  w.u64((quadrants ? 1 : 0) | (photon_quadrants ? 2 : 0));
  for (const auto* part : {&c.direct, &c.caustic, &c.global})
    for (const Vec3& v : *part) w.vec3(v);
  for (const auto* part : {&c.direct_variance, &c.photon_variance})
    for (const double v : *part) w.f64(v);
  for (const Vec3& v : skies.irradiance) w.vec3(v);
  for (const double v : skies.variance) w.f64(v);
  for (const Vec3& v : photon_sky.irradiance) w.vec3(v);
  for (const double v : photon_sky.variance) w.f64(v);
  for (const float v : c.direct_quadrants) w.f32(v);
  for (const float v : c.photon_quadrants) w.f32(v);
  return w.finish();
}

engine::DaylightCoefficients decode_coefficients(const std::string& bytes) {
  Reader r(bytes, "daylight coefficient artefact");
  r.tag("DCOF", CoefficientLayoutVersion);
  engine::DaylightCoefficients c;
  const std::uint64_t sensors = r.u64("sensor count");
  const std::uint64_t sources = r.u64("source count");
  const std::uint64_t skies = r.u64("sky count");
  const std::uint64_t photon_sky = r.u64("photon part on the sky");
  const std::uint64_t basis_rows = r.u64("photon part's basis rows");
  const std::uint64_t quadrants = r.u64("sub-patch shares");
  if (quadrants > 3) r.fail("sub-patch shares flags " + std::to_string(quadrants) + " are not within 0-3");
  if (photon_sky > 1) r.fail("photon part on the sky: " + std::to_string(photon_sky) + " skies, at most 1");
  if (basis_rows > sensors) r.fail("photon part on the sky: " + std::to_string(basis_rows) + " basis rows");
  // The five arrays need CoefficientPairBytes per (sensor, source) pair and the two of the
  // skies (and of the photon part on the sky) SkyDirectBytes per (sensor, sky): check without
  // overflow.
  const std::size_t remaining = bytes.size() - (PreambleBytes + CoefficientHeaderBytes);
  const std::size_t pair_bytes =
      CoefficientPairBytes + ((quadrants & 1) + ((quadrants >> 1) & 1)) * QuadrantPairBytes;
  const std::uint64_t max_pairs = remaining / pair_bytes;
  const std::uint64_t sky_rows = skies + photon_sky;
  const bool fits = (sensors == 0 || (sources <= max_pairs / sensors && skies <= remaining / SkyDirectBytes / sensors &&
                                      sky_rows <= remaining / SkyDirectBytes / sensors));
  if (!fits || sensors * sources * pair_bytes + sensors * sky_rows * SkyDirectBytes != remaining)
    r.fail("size mismatch: " + std::to_string(sensors) + " sensors x " + std::to_string(sources) +
           " sources need " + std::to_string(pair_bytes) + " bytes each and x " + std::to_string(sky_rows) +
           " skies " + std::to_string(SkyDirectBytes) + " bytes each, " + std::to_string(remaining) +
           " bytes remain");
  c.sensors = static_cast<std::size_t>(sensors);
  c.sources = static_cast<std::size_t>(sources);
  const std::size_t n = c.sensors * c.sources;
  for (auto* part : {&c.direct, &c.caustic, &c.global}) {
    part->resize(n);
    for (Vec3& v : *part) v = r.vec3("coefficient");
  }
  for (auto* part : {&c.direct_variance, &c.photon_variance}) {
    part->resize(n);
    for (double& v : *part) v = r.f64("variance");
  }
  engine::DirectOnSkies& on_skies = c.direct_on_skies;
  on_skies.skies = static_cast<std::size_t>(skies);
  on_skies.irradiance.resize(c.sensors * on_skies.skies);
  for (Vec3& v : on_skies.irradiance) v = r.vec3("direct irradiance on a sky");
  on_skies.variance.resize(c.sensors * on_skies.skies);
  for (double& v : on_skies.variance) v = r.f64("variance on a sky");
  if (photon_sky == 1) {
    engine::PhotonOnSky& p = c.photon_on_sky;
    p.basis_rows = static_cast<std::size_t>(basis_rows);
    p.irradiance.resize(c.sensors);
    for (Vec3& v : p.irradiance) v = r.vec3("photon part on the sky");
    p.variance.resize(c.sensors);
    for (double& v : p.variance) v = r.f64("variance of the photon part on the sky");
  }
  if (quadrants & 1) {
    c.direct_quadrants.resize(n * engine::StoredQuadrants);
    for (float& v : c.direct_quadrants) v = r.f32("sub-patch share");
  }
  if (quadrants & 2) {
    c.photon_quadrants.resize(n * engine::StoredQuadrants);
    for (float& v : c.photon_quadrants) v = r.f32("photon sub-patch share");
  }
  r.done();
  return c;
}

// ---- RADIANCE matrices --------------------------------------------------------------------

std::string encode_matrix(const RadianceMatrix& m) {
  if (m.components() < 1) throw std::invalid_argument("matrix with fewer than 1 component");
  std::size_t size = PreambleBytes + 8 + 8 + 4 + 8 + m.data().size() * 4;
  for (const std::string& line : m.header_lines()) size += 8 + line.size();
  Writer w(size);
  w.tag("RMTX", MatrixLayoutVersion);
  w.u64(m.rows());
  w.u64(m.columns());
  w.u32(static_cast<std::uint32_t>(m.components()));
  w.u64(m.header_lines().size());
  for (const std::string& line : m.header_lines()) w.text(line);
  for (const float v : m.data()) w.f32(v);
  return w.finish();
}

RadianceMatrix decode_matrix(const std::string& bytes) {
  Reader r(bytes, "matrix artefact");
  r.tag("RMTX", MatrixLayoutVersion);
  const std::uint64_t rows = r.u64("row count");
  const std::uint64_t columns = r.u64("column count");
  const std::uint32_t components = r.u32("component count");
  if (components < 1 || components > 0x7fffffffu)
    r.fail("component count " + std::to_string(components) + " out of range");
  std::vector<std::string> header(r.count(8, "header line count"));
  for (std::string& line : header) line = r.text("header line length");
  // The data fills exactly what is left, 4 bytes per value: check without overflow.
  const std::size_t remaining = bytes.size() - (PreambleBytes + 8 + 8 + 4 + 8);
  std::size_t header_bytes = 0;
  for (const std::string& line : header) header_bytes += 8 + line.size();
  const std::uint64_t values = (remaining - header_bytes) / 4;
  const bool fits = (remaining - header_bytes) % 4 == 0 &&
                    (rows == 0 || columns <= values / rows) &&
                    (rows * columns == 0 || components <= values / (rows * columns)) &&
                    rows * columns * components == values;
  if (!fits)
    r.fail("size mismatch: " + std::to_string(rows) + " x " + std::to_string(columns) + " x " +
           std::to_string(components) + " values, " + std::to_string(remaining - header_bytes) +
           " bytes remain");
  RadianceMatrix m(static_cast<std::size_t>(rows), static_cast<std::size_t>(columns),
                   static_cast<int>(components));
  m.header_lines() = std::move(header);
  for (float& v : m.data()) v = r.f32("matrix value");
  r.done();
  return m;
}

}  // namespace dayphoton::study
