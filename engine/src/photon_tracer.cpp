// Photon tracer: see photon_tracer.h for the method, its sources and the storage rules.
#include "dayphoton/engine/photon_tracer.h"

#include "dayphoton/engine/gathered_scatterer_sides.h"
#include "dayphoton/engine/source_passes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <tbb/parallel_for.h>


namespace dayphoton::engine {
namespace {

constexpr std::uint64_t AttemptsPerBlock = 1024;

double channel_mean(const Vec3& v) { return (v.x + v.y + v.z) / 3.0; }

bool inside(const Bounds3& b, const Vec3& p) {
  return p.x >= b.lower.x && p.x <= b.upper.x && p.y >= b.lower.y && p.y <= b.upper.y &&
         p.z >= b.lower.z && p.z <= b.upper.z;
}

Photon make_photon(const Vec3& position, const Vec3& flux, const Vec3& normal,
                   std::uint32_t source, std::uint32_t sky_ratio_code, std::uint8_t sky_quadrant,
                   PathClass path_class) {
  Photon ph;
  ph.position = {float(position.x), float(position.y), float(position.z)};
  ph.flux = {float(flux.x), float(flux.y), float(flux.z)};
  ph.source = source;  // < MaxPhotonSources (PortEmitter)
  ph.sky_ratio_code = sky_ratio_code;
  ph.set_normal(normal);
  ph.path_class = path_class;
  ph.sky_quadrant = sky_quadrant & 3u;
  return ph;
}

// Flux-weighted Russian roulette after multiplying by `weight` (digest section 2.1.4).
// Returns false if the photon is absorbed; otherwise `flux` holds the survivor's flux.
bool roulette(Vec3& flux, const Vec3& weight, Rng& rng) {
  const double before = channel_mean(flux);
  const Vec3 after = mul(flux, weight);
  const double survive = before > 0 ? channel_mean(after) / before : 0.0;
  const double u = rng.uniform();
  if (!(survive > 0)) return false;
  if (survive < 1) {
    if (u >= survive) return false;
    flux = after * (1.0 / survive);
  } else {
    flux = after;  // weight > 1 on average (possible for glossy lobes): no roulette needed
  }
  return true;
}

// Collects one block's records, applying the main pass's storage probabilities.
struct BlockResult {
  std::vector<Photon> surface;
  std::vector<std::vector<Photon>> planes;
  std::uint64_t entered = 0, global = 0, caustic = 0, direct = 0, rays = 0;
  /// Attempts that landed on an outdoor scatterer and whose path then entered a room.
  std::uint64_t scattered_indoors = 0;
  bool complete = false;  ///< every attempt of the block was traced
};

class BlockSink final : public PhotonSink {
 public:
  BlockSink(BlockResult& out, const TracingOptions& options, const StorageProbabilities& d)
      : m_out(out), m_options(options), m_d(d) {}
  /// The attempt whose photons follow: their storage stream, made on first use (only the
  /// main pass's storage probabilities below 1 draw from it).
  void set_attempt(RngSourceKey key, std::uint64_t index) {
    m_key = key;
    m_index = index;
    m_storage_ready = false;
  }

  void record(int plane, const Photon& photon) override {
    if (m_options.region_of_interest && !inside(*m_options.region_of_interest, photon.position_m()))
      return;
    store(plane, photon);
  }
  // The region of interest does not apply: the port is where the gather behind it reads,
  // wherever the box ends.
  void record_on_diffusing_port(const Photon& photon) override { store(-1, photon); }

 private:
  void store(int plane, const Photon& photon) {
    Photon stored = photon;
    const double d = photon.path_class == PathClass::Global    ? m_d.global
                     : photon.path_class == PathClass::Caustic ? m_d.caustic
                                                               : m_d.direct;
    // Stored or not; the flux is set per class after the passes (stored_photon_flux).
    if (d < 1) {
      if (!m_storage_ready) {
        m_storage = Rng(m_key, m_index, RandomStream::Storage);
        m_storage_ready = true;
      }
      if (!(m_storage.uniform() < d)) return;
    }
    (photon.path_class == PathClass::Global    ? m_out.global
     : photon.path_class == PathClass::Caustic ? m_out.caustic
                                               : m_out.direct)++;
    if (plane < 0) {
      if (m_options.keep_surface_photons) m_out.surface.push_back(stored);
    } else {
      m_out.planes[static_cast<std::size_t>(plane)].push_back(stored);
    }
  }

  BlockResult& m_out;
  const TracingOptions& m_options;
  StorageProbabilities m_d;
  // The attempt's storage stream, made on its first stored photon (a plain Rng and a flag, as
  // GCC 12 misreads a std::optional<Rng> as maybe uninitialized).
  Rng m_storage{RngSourceKey{0}, 0, RandomStream::Storage};
  bool m_storage_ready = false;
  RngSourceKey m_key{0};
  std::uint64_t m_index = 0;
};

// The first scattering event of a path, at `position` on a surface of `material` (geometric
// normal `normal`) that a photon of unit flux reaches along `direction`: the sampled event,
// then flux-weighted roulette. Returns the path start, or nothing if the photon is absorbed.
std::optional<PathStart> first_event(const Scene& scene, const Material& material, const Vec3& position,
                                     const Vec3& normal, const Vec3& direction, std::uint32_t source,
                                     Rng& scattering, Rng& roulette_rng) {
  const double u0 = scattering.uniform(), u1 = scattering.uniform(), u2 = scattering.uniform();
  const std::optional<ScatterSample> s = material.sample(direction, normal, u0, u1, u2);
  if (!s) return std::nullopt;
  PathStart start;
  start.flux = {1, 1, 1};
  if (!roulette(start.flux, s->weight, roulette_rng)) return std::nullopt;
  start.direction = s->direction;
  start.origin = scene.offset_ray_origin(position, normal, s->direction);
  start.source = source;
  start.scattered = s->type != ScatterType::StraightTransmission;
  start.diffuse_scattered = is_diffuse(s->type);
  return start;
}

// Whether `material` transmits a diffuse part (translucent, transmitted_specular < 1): at a
// port, a final gather reaching it from the room reads the photons on its sky side.
bool transmits_diffusely(const Material& material) { return channel_mean(material.diffuse_transmittance()) > 0; }

// What pass_port needs of a port: looked up once per pass, not once per photon.
struct PortPane {
  const Port* port = nullptr;
  const Material* material = nullptr;
  bool straight_only = false;  ///< glass, glazing or opening: transmits only straight through
  /// Transmits diffusely (translucent, transmitted_specular < 1): a final gather reaching it
  /// from the room looks up the photons on its sky side, so they are stored there.
  bool diffusing = false;
};

std::vector<PortPane> port_panes(const Scene& scene, const std::vector<Material>& materials) {
  std::vector<PortPane> panes;
  for (const Port& port : scene.ports().ports()) {
    const Material& material =
        materials[static_cast<std::size_t>(scene.description().surfaces[static_cast<std::size_t>(port.surface)].material)];
    const MaterialType type = material.type();
    const bool straight_only = type == MaterialType::Glass || type == MaterialType::Glazing || type == MaterialType::Opening;
    panes.push_back(PortPane{&port, &material, straight_only,
                             !straight_only && material.stores_photons() && transmits_diffusely(material)});
  }
  return panes;
}

// The port's own scattering event (seeds/000 section 4.1.3: photons leave the port "as if
// they had passed through it"). Returns the path start, or nothing if the photon is
// reflected back out or absorbed.
std::optional<PathStart> pass_port(const Scene& scene, const PortPane& pane, const PortEntry& entry,
                                   std::uint32_t source, Rng& scattering, Rng& roulette_rng) {
  const Port& port = *pane.port;
  const Material& material = *pane.material;
  if (pane.straight_only) {
    // These transmit only straight through, and what they reflect goes back out of the room
    // (followed outdoors by reflect_off_pane where outdoor scatterers can send it back). So the
    // photon passes with the transmittance as its weight instead of a sampled event and
    // roulette: the same expected flux, and no entering photon lost at the pane
    // (docs/photon-tracing.md, "The first scattering event").
    const Vec3 t = material.straight_transmittance(entry.direction, port.normal);
    if (!(channel_mean(t) > 0)) return std::nullopt;
    PathStart start;
    start.flux = t;
    start.direction = entry.direction;
    start.origin = scene.offset_ray_origin(entry.position, port.normal, entry.direction);
    start.source = source;
    return start;
  }
  std::optional<PathStart> start =
      first_event(scene, material, entry.position, port.normal, entry.direction, source, scattering, roulette_rng);
  if (start && dot(start->direction, port.normal) <= 0) return std::nullopt;  // back out of the room
  return start;
}

// What a glass, glazing or opening port reflects of a photon entering it from the sky: the
// pane's specular reflection (albedo less straight transmittance: these have no diffuse
// part), followed outdoors where outdoor scatterers can send it back through a port (a
// north-light roof facing the next tooth's glazing, a reveal, an overhang, an exterior
// shelf). Under an open sky it leaves for good and is not started: the scene has no outdoor
// scatterer then. Nothing, where the pane reflects nothing (an opening).
std::optional<PathStart> reflect_off_pane(const Scene& scene, const PortPane& pane, const PortEntry& entry,
                                          std::uint32_t source) {
  if (!pane.straight_only || scene.outdoor_scatterers().empty()) return std::nullopt;
  const Port& port = *pane.port;
  const Vec3 r = pane.material->albedo(entry.direction, port.normal) -
                 pane.material->straight_transmittance(entry.direction, port.normal);
  if (!(channel_mean(r) > 1e-9)) return std::nullopt;
  PathStart start;
  start.flux = {std::max(0.0, r.x), std::max(0.0, r.y), std::max(0.0, r.z)};
  start.direction = normalize(entry.direction - port.normal * (2 * dot(entry.direction, port.normal)));
  start.origin = scene.offset_ray_origin(entry.position, port.normal, start.direction);
  start.source = source;
  start.scattered = true;  // a specular reflection: Caustic until a diffuse event
  start.outdoors = true;
  return start;
}

// Whether a Direct photon on side `side` of outdoor scatterer `scatterer` is stored:
// always with store_direct, else with store_direct_on_surfaces where a gather can read it
// (TracingOptions::scatterer_direct_sides).
bool stores_direct_on_scatterer(const Scene& scene, const TracingOptions& options, int scatterer, const Vec3& side) {
  if (options.store_direct) return true;
  if (!options.store_direct_on_surfaces) return false;
  if (options.scatterer_direct_sides.empty()) return true;
  const std::size_t s = static_cast<std::size_t>(scatterer);
  return (options.scatterer_direct_sides[s] & scatterer_side_bit(side, scene.outdoor_scatterers()[s].normal)) != 0;
}

// A photon that lands on an outdoor scatterer straight from its source: its Direct record
// there (the scatterer's irradiance, which a final gather looking at the scatterer needs),
// then the scatterer's own scattering event, outdoors. Returns the path start, or nothing if
// the photon is absorbed.
std::optional<PathStart> land_on_scatterer(const Scene& scene, const std::vector<Material>& materials,
                                           const PortEntry& entry, std::uint32_t source,
                                           std::uint32_t sky_ratio_code, std::uint8_t sky_quadrant,
                                           const TracingOptions& options,
                                           Rng& scattering, Rng& roulette_rng, PhotonSink& sink) {
  const Port& scatterer = scene.outdoor_scatterers()[static_cast<std::size_t>(entry.scatterer)];
  const Material& material =
      materials[static_cast<std::size_t>(scene.description().surfaces[scatterer.surface].material)];
  const Vec3 lit_side = dot(entry.direction, scatterer.normal) < 0 ? scatterer.normal : scatterer.normal * -1.0;
  if (material.stores_photons() && stores_direct_on_scatterer(scene, options, entry.scatterer, lit_side))
    sink.record(-1, make_photon(entry.position, {1, 1, 1}, lit_side, source, sky_ratio_code, sky_quadrant, PathClass::Direct));
  std::optional<PathStart> start = first_event(scene, material, entry.position, scatterer.normal, entry.direction,
                                               source, scattering, roulette_rng);
  if (start) start->outdoors = true;
  return start;
}

}  // namespace

namespace {

// trace_path for a sink of type Sink: the tracer's own (final) block sink gets direct calls.
template <class Sink>
bool trace_path_to(const Scene& scene, const std::vector<Material>& materials,
                   const std::vector<ReceiverPlane>& planes, const PathStart& start,
                   const TracingOptions& options, Rng& scattering, Rng& roulette_rng, Sink& sink,
                   std::uint64_t* rays) {
  Vec3 flux = start.flux;
  bool scattered = start.scattered;
  bool diffuse = start.diffuse_scattered;
  bool outdoors = start.outdoors;
  bool was_indoors = !outdoors;
  const double epsilon_m = scene.ray_epsilon_m();
  Ray ray{start.origin, start.direction, 0.0, std::numeric_limits<double>::infinity()};
  for (int event = 0; event <= options.max_events; ++event) {
    const PathClass path_class = !scattered ? PathClass::Direct
                                 : diffuse  ? PathClass::Global
                                            : PathClass::Caustic;
    const bool store = scattered || options.store_direct;
    const std::optional<Hit> hit = scene.intersect(ray);
    if (rays) ++*rays;
    const double t_end = hit ? hit->t : std::numeric_limits<double>::infinity();
    if (store && !outdoors) {
      for (std::size_t g = 0; g < planes.size(); ++g) {
        const double t = planes[g].front_crossing(ray.origin, ray.direction);
        if (!(t >= ray.tmin)) continue;
        // A plane on a surface (a grid on the floor, on a desk top, on the ceiling facing
        // down): the photon lands on the surface where it reaches the plane, and the hit's t
        // and the crossing's agree only to rounding, so a strict t < t_end lost them all
        // (a floor grid read 8-68 % low, a ceiling grid 25-85 %). A hit within the ray offset
        // of the plane counts as a crossing where it lands.
        const bool lands_on_plane =
            hit && !(t < t_end) && std::fabs(hit->position.z - planes[g].height_m()) <= epsilon_m;
        if (!(t < t_end) && !lands_on_plane) continue;
        const Vec3 p = lands_on_plane ? hit->position : ray.origin + ray.direction * t;
        if (!planes[g].contains(p.x, p.y)) continue;
        sink.record(static_cast<int>(g),
                    make_photon({p.x, p.y, planes[g].height_m()}, flux, planes[g].normal(),
                                start.source, start.sky_ratio_code, start.sky_quadrant, path_class));
      }
    }
    if (!hit) return was_indoors;
    const Material& material = materials[static_cast<std::size_t>(hit->material)];
    if (!hit->front_face && material.absorbs_inside()) {
      // The segment ran inside the dielectric: Beer-Lambert attenuation per metre.
      const Vec3 tpm = material.interior_transmittance_per_m();
      flux = mul(flux, {std::pow(tpm.x, hit->t), std::pow(tpm.y, hit->t), std::pow(tpm.z, hit->t)});
    }
    // Outdoors, photons are stored on scatterers and on the sky side of a diffusing port (what
    // it transmits into the room: light scattered outdoors onto it, e.g. by the ground).
    if ((store || options.store_direct_on_surfaces) && material.stores_photons() &&
        (!outdoors || hit->scatterer >= 0 ||
         (hit->port >= 0 && transmits_diffusely(material)))) {
      const Vec3 side = hit->front_face ? hit->normal : hit->normal * -1.0;
      // A Direct photon outdoors (on a scatterer, after straight passes only): where a
      // gather can read it.
      const Photon photon =
          make_photon(hit->position, flux, side, start.source, start.sky_ratio_code, start.sky_quadrant, path_class);
      if (hit->port >= 0 && transmits_diffusely(material))
        sink.record_on_diffusing_port(photon);
      else if (store || !outdoors || stores_direct_on_scatterer(scene, options, hit->scatterer, side))
        sink.record(-1, photon);
    }
    const double u0 = scattering.uniform(), u1 = scattering.uniform(), u2 = scattering.uniform();
    const std::optional<ScatterSample> s = material.sample(ray.direction, hit->normal, u0, u1, u2);
    if (!s) return was_indoors;
    if (!scattered && s->type != ScatterType::StraightTransmission) {
      // The path's first scattering event in the room: its weight is carried instead of
      // played by roulette (docs/photon-tracing.md, "The first scattering event").
      flux = mul(flux, s->weight);
      if (!(channel_mean(flux) > 0)) return was_indoors;
    } else if (!roulette(flux, s->weight, roulette_rng)) {
      return was_indoors;
    }
    if (hit->port >= 0) {
      // Passing a port (not reflected by it): indoors along its normal, outdoors against it.
      const Vec3& n = scene.ports()[static_cast<std::size_t>(hit->port)].normal;
      const double before = dot(ray.direction, n), after = dot(s->direction, n);
      if (before > 0 && after > 0) outdoors = false;
      if (before < 0 && after < 0) outdoors = true;
      was_indoors = was_indoors || !outdoors;
    }
    if (s->type != ScatterType::StraightTransmission) {
      scattered = true;
      diffuse = diffuse || is_diffuse(s->type);
    }
    ray = Ray{offset_ray_origin(hit->position, hit->normal, s->direction, epsilon_m), s->direction,
              0.0, std::numeric_limits<double>::infinity()};
  }
  return was_indoors;
}

}  // namespace

bool trace_path(const Scene& scene, const std::vector<Material>& materials,
                const std::vector<ReceiverPlane>& planes, const PathStart& start,
                const TracingOptions& options, Rng& scattering, Rng& roulette_rng,
                PhotonSink& sink, std::uint64_t* rays) {
  return trace_path_to(scene, materials, planes, start, options, scattering, roulette_rng, sink, rays);
}

namespace {

// Trace attempts [first, last) of `source`, in parallel blocks, appending to `result` (its
// counts included). Returns the counts of these attempts.
// Throws if a block did not run: when this pass runs inside an enclosing parallel loop (one
// task per source) and another iteration of that loop throws, TBB cancels the whole task
// group, so this nested loop returns early without having run every block (oneTBB developer
// guide, "Cancellation and Nested Parallelism"). The enclosing loop then rethrows the first
// exception; this one only stops a partial pass from being merged.
AttemptCounts trace_attempts(const Scene& scene, const std::vector<Material>& materials,
                             const std::vector<ReceiverPlane>& planes, const PortEmitter& emitter,
                             std::uint32_t source, std::uint64_t first, std::uint64_t last,
                             const StorageProbabilities& d, const TracingOptions& options, AttemptRange& result) {
  if (!options.scatterer_direct_sides.empty() &&
      options.scatterer_direct_sides.size() != scene.outdoor_scatterers().size())
    throw std::invalid_argument("photon tracing: scatterer_direct_sides has " +
                                std::to_string(options.scatterer_direct_sides.size()) + " entries but the scene " +
                                std::to_string(scene.outdoor_scatterers().size()) + " outdoor scatterers");
  result.planes.resize(planes.size());
  AttemptCounts c;
  if (last <= first) return c;
  const std::uint64_t blocks = (last - first + AttemptsPerBlock - 1) / AttemptsPerBlock;
  std::vector<BlockResult> block_results(blocks);
  const RngSourceKey key = Rng::source_key(options.seed, source);
  const std::vector<PortPane> panes = port_panes(scene, materials);
  // The sky ratio's bin: the bins of a sky basis only (a sun disc's photons keep ratio 1).
  const DistantSource& emitted = emitter.sources()[source];
  const bool sky_bin = options.sky_ratios && emitted.kind == SourceKind::SkyBin;
  const std::size_t sky_bin_index = static_cast<std::size_t>(std::max(0, emitted.bin));
  if (sky_bin && sky_bin_index >= options.sky_ratios->bins())
    throw std::invalid_argument("photon tracing: sky ratios of " + std::to_string(options.sky_ratios->bins()) +
                                " bins for sky bin " + std::to_string(sky_bin_index));
  // The bin whose quadrants the photons record: a sky bin of a basis (not the ground's).
  const int quadrant_bin =
      emitter.sources().has_basis() && emitted.kind == SourceKind::SkyBin ? std::max(0, emitted.bin) : 0;
  tbb::parallel_for(std::uint64_t(0), blocks, [&](std::uint64_t b) {
    BlockResult& out = block_results[b];
    out.planes.resize(planes.size());
    BlockSink sink(out, options, d);
    const std::uint64_t begin = first + b * AttemptsPerBlock;
    const std::uint64_t end = std::min(last, begin + AttemptsPerBlock);
    for (std::uint64_t i = begin; i < end; ++i) {
      Rng emission(key, i, RandomStream::Emission);
      const std::optional<PortEntry> entry = emitter.attempt(source, emission, &out.rays);
      if (!entry) continue;
      ++out.entered;
      Rng scattering(key, i, RandomStream::Scattering);
      Rng roulette_rng(key, i, RandomStream::Roulette);
      sink.set_attempt(key, i);
      const std::uint32_t ratio_code =
          sky_bin ? Photon::sky_ratio_code_of(options.sky_ratios->ratio(sky_bin_index, entry->direction * -1.0))
                  : SkyRatioOne;
      // The quadrant of its sky bin the photon was emitted into (photon.h; 0 for the ground and
      // sun discs).
      const std::uint8_t quadrant =
          quadrant_bin > 0 ? static_cast<std::uint8_t>(emitter.sources().basis().quadrant(quadrant_bin, entry->direction * -1.0))
                           : std::uint8_t(0);
      std::optional<PathStart> start =
          entry->port >= 0
              ? pass_port(scene, panes[static_cast<std::size_t>(entry->port)], *entry, source, scattering, roulette_rng)
              : land_on_scatterer(scene, materials, *entry, source, ratio_code, quadrant, options, scattering,
                                  roulette_rng,
                                  sink);
      if (entry->port >= 0) {
        // A diffusing port's sky-side irradiance: the Direct record of the photon that lands on
        // it, which a final gather reaching the port from the room reads through the port's
        // diffuse transmittance (the direct component takes only its straight transmission).
        const PortPane& pane = panes[static_cast<std::size_t>(entry->port)];
        if (pane.diffusing && (options.store_direct || options.store_direct_on_surfaces))
          sink.record_on_diffusing_port(make_photon(entry->position, {1, 1, 1}, pane.port->normal * -1.0, source,
                                                  ratio_code, quadrant, PathClass::Direct));
      }
      if (start) {
        start->sky_ratio_code = ratio_code;
        start->sky_quadrant = quadrant;
        const bool indoors = trace_path_to(scene, materials, planes, *start, options, scattering, roulette_rng,
                                           sink, &out.rays);
        if (entry->scatterer >= 0 && indoors) ++out.scattered_indoors;
      }
      // The pane's outward reflection, after the transmitted path (from the same streams).
      if (entry->port >= 0)
        if (std::optional<PathStart> back =
                reflect_off_pane(scene, panes[static_cast<std::size_t>(entry->port)], *entry, source)) {
          back->sky_ratio_code = ratio_code;
          back->sky_quadrant = quadrant;
          trace_path_to(scene, materials, planes, *back, options, scattering, roulette_rng, sink, &out.rays);
        }
    }
    out.complete = true;
  });
  for (const BlockResult& b : block_results)
    if (!b.complete)
      throw std::runtime_error("photon tracing was cancelled before every block of source " +
                               std::to_string(source) + " ran");
  // One allocation per vector (growing by insertion reallocates and copies every photon
  // several times, and each fresh page costs a page fault).
  std::size_t surface_total = result.surface.size();
  std::vector<std::size_t> plane_total(planes.size());
  for (std::size_t g = 0; g < planes.size(); ++g) plane_total[g] = result.planes[g].size();
  for (const BlockResult& b : block_results) {
    surface_total += b.surface.size();
    for (std::size_t g = 0; g < planes.size(); ++g) plane_total[g] += b.planes[g].size();
  }
  result.surface.reserve(surface_total);
  for (std::size_t g = 0; g < planes.size(); ++g) result.planes[g].reserve(plane_total[g]);
  for (BlockResult& b : block_results) {
    result.surface.insert(result.surface.end(), b.surface.begin(), b.surface.end());
    for (std::size_t g = 0; g < planes.size(); ++g)
      result.planes[g].insert(result.planes[g].end(), b.planes[g].begin(), b.planes[g].end());
    c.entered += b.entered;
    c.stored_global += b.global;
    c.stored_caustic += b.caustic;
    c.stored_direct += b.direct;
    c.rays += b.rays;
    c.scattered_indoors += b.scattered_indoors;
  }
  result.counts += c;
  return c;
}

}  // namespace

bool can_store_photons(const Scene& scene, const std::vector<Material>& materials,
                       const std::vector<ReceiverPlane>& planes) {
  const std::vector<Surface>& surfaces = scene.description().surfaces;
  bool scatters = false;
  for (const Surface& surface : surfaces) {
    const Material& m = materials[static_cast<std::size_t>(surface.material)];
    if (m.stores_photons()) return true;
    if (!scatters && !planes.empty()) {
      // Anything but a straight pass-through, at normal and at grazing incidence.
      for (const Vec3& incoming : {Vec3{0, 0, -1}, normalize(Vec3{1, 0, -0.2})}) {
        const Vec3 n{0, 0, 1};
        const Vec3 rest = m.albedo(incoming, n) - m.straight_transmittance(incoming, n);
        if (rest.x > 1e-12 || rest.y > 1e-12 || rest.z > 1e-12) scatters = true;
      }
    }
  }
  return scatters;
}

AttemptCounts& AttemptCounts::operator+=(const AttemptCounts& more) {
  entered += more.entered;
  stored_global += more.stored_global;
  stored_caustic += more.stored_caustic;
  stored_direct += more.stored_direct;
  rays += more.rays;
  scattered_indoors += more.scattered_indoors;
  return *this;
}

bool operator==(const AttemptCounts& a, const AttemptCounts& b) {
  return a.entered == b.entered && a.stored_global == b.stored_global && a.stored_caustic == b.stored_caustic &&
         a.stored_direct == b.stored_direct && a.rays == b.rays && a.scattered_indoors == b.scattered_indoors;
}

AttemptRange trace_attempt_range(const Scene& scene, const std::vector<Material>& materials,
                                 const PortEmitter& emitter, const std::vector<ReceiverPlane>& planes,
                                 const TracingOptions& options, std::size_t source, std::uint64_t first,
                                 std::uint64_t last, const StorageProbabilities& storage) {
  AttemptRange r;
  trace_attempts(scene, materials, planes, emitter, static_cast<std::uint32_t>(source), first, last, storage,
                 options, r);
  return r;
}

void append_attempt_range(AttemptRange& to, AttemptRange&& more) {
  if (to.surface.empty()) {
    to.surface = std::move(more.surface);
  } else {
    to.surface.insert(to.surface.end(), more.surface.begin(), more.surface.end());
  }
  to.planes.resize(std::max(to.planes.size(), more.planes.size()));
  for (std::size_t g = 0; g < more.planes.size(); ++g) {
    if (to.planes[g].empty()) {
      to.planes[g] = std::move(more.planes[g]);
    } else {
      to.planes[g].insert(to.planes[g].end(), more.planes[g].begin(), more.planes[g].end());
    }
  }
  to.counts += more.counts;
  more = AttemptRange{};
}

TracedPhotons trace_source_photons(const Scene& scene, const std::vector<Material>& materials,
                                   const PortEmitter& emitter,
                                   const std::vector<ReceiverPlane>& planes,
                                   const TracingOptions& options, std::size_t source) {
  // The pass control (source_passes.h) with every pass traced here, into one range.
  SourcePasses passes(scene, materials, emitter, planes, options, source);
  AttemptRange photons;
  photons.planes.resize(planes.size());
  while (const std::optional<AttemptPass> pass = passes.next())
    passes.record(trace_attempts(scene, materials, planes, emitter, static_cast<std::uint32_t>(source), pass->first,
                                 pass->last, pass->storage, options, photons));
  return passes.finish(std::move(photons));
}

TracedPhotons trace_source_attempts(const Scene& scene, const std::vector<Material>& materials,
                                    const PortEmitter& emitter, const std::vector<ReceiverPlane>& planes,
                                    const TracingOptions& options, std::size_t source, std::uint64_t first,
                                    std::uint64_t last) {
  AttemptRange r;
  r.planes.resize(planes.size());
  SourceTally tally;
  tally.bound_flux = emitter.bound_flux(static_cast<std::uint32_t>(source));
  if (!can_store_photons(scene, materials, planes)) {
    tally.nothing_stores = true;
  } else if (tally.bound_flux > 0 && last > first) {
    trace_attempts(scene, materials, planes, emitter, static_cast<std::uint32_t>(source), first, last,
                   StorageProbabilities{}, options, r);
    tally.prepass_attempts = last - first;
    tally.entered = r.counts.entered;
    tally.stored_global = r.counts.stored_global;
    tally.stored_caustic = r.counts.stored_caustic;
    tally.stored_direct = r.counts.stored_direct;
    tally.rays = r.counts.rays;
  }
  TracedPhotons out;
  out.surface = std::move(r.surface);
  out.planes = std::move(r.planes);
  out.planes.resize(planes.size());
  out.tallies.push_back(tally);
  return out;
}

TracedPhotons merge_traced_photons(std::vector<TracedPhotons>&& per_source) {
  TracedPhotons out;
  std::size_t plane_count = 0;
  for (const TracedPhotons& r : per_source) plane_count = std::max(plane_count, r.planes.size());
  out.planes.resize(plane_count);
  // Reserved at their final sizes: no vector grows to twice what it holds while merging.
  std::size_t surface_count = 0, tally_count = 0;
  std::vector<std::size_t> plane_sizes(plane_count, 0);
  for (const TracedPhotons& r : per_source) {
    surface_count += r.surface.size();
    tally_count += r.tallies.size();
    for (std::size_t g = 0; g < r.planes.size(); ++g) plane_sizes[g] += r.planes[g].size();
  }
  out.surface.reserve(surface_count);
  out.tallies.reserve(tally_count);
  for (std::size_t g = 0; g < plane_count; ++g) out.planes[g].reserve(plane_sizes[g]);
  for (TracedPhotons& r : per_source) {
    out.surface.insert(out.surface.end(), r.surface.begin(), r.surface.end());
    for (std::size_t g = 0; g < r.planes.size(); ++g)
      out.planes[g].insert(out.planes[g].end(), r.planes[g].begin(), r.planes[g].end());
    out.tallies.insert(out.tallies.end(), r.tallies.begin(), r.tallies.end());
    r = TracedPhotons{};  // release as we go: the merged copy is the only one kept
  }
  return out;
}

TracedPhotons trace_photons(const Scene& scene, const std::vector<Material>& materials,
                            const SourceSet& sources, const std::vector<ReceiverPlane>& planes,
                            const TracingOptions& options) {
  const PortEmitter emitter(scene, sources);
  std::vector<TracedPhotons> results(sources.size());
  tbb::parallel_for(std::size_t(0), sources.size(), [&](std::size_t p) {
    results[p] = trace_source_photons(scene, materials, emitter, planes, options, p);
  });
  return merge_traced_photons(std::move(results));
}

}  // namespace dayphoton::engine
