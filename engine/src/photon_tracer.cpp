// Photon tracer: see photon_tracer.h for the method, its sources and the storage rules.
#include "dayphoton/engine/photon_tracer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <tbb/parallel_for.h>


namespace dayphoton::engine {
namespace {

constexpr std::uint64_t AttemptsPerBlock = 1024;
/// Entries without a stored photon after which a pre-pass stops (see trace_source).
constexpr std::uint64_t NothingStoredEntries = 65536;

double channel_mean(const Vec3& v) { return (v.x + v.y + v.z) / 3.0; }

bool inside(const Bounds3& b, const Vec3& p) {
  return p.x >= b.lower.x && p.x <= b.upper.x && p.y >= b.lower.y && p.y <= b.upper.y &&
         p.z >= b.lower.z && p.z <= b.upper.z;
}

Photon make_photon(const Vec3& position, const Vec3& flux, const Vec3& normal,
                   std::uint32_t source, PathClass path_class) {
  Photon ph;
  ph.position = {float(position.x), float(position.y), float(position.z)};
  ph.flux = {float(flux.x), float(flux.y), float(flux.z)};
  ph.source = source;
  ph.set_normal(normal);
  ph.path_class = path_class;
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

/// Main-pass storage probability of each class (1 in the pre-pass).
struct StorageProbabilities {
  double global = 1, caustic = 1, direct = 1;
};

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
  void set_attempt(std::uint64_t seed, std::uint32_t source, std::uint64_t index) {
    m_seed = seed;
    m_source = source;
    m_index = index;
    m_storage.reset();
  }

  void record(int plane, const Photon& photon) override {
    if (m_options.region_of_interest && !inside(*m_options.region_of_interest, photon.position_m()))
      return;
    Photon stored = photon;
    const double d = photon.path_class == PathClass::Global    ? m_d.global
                     : photon.path_class == PathClass::Caustic ? m_d.caustic
                                                               : m_d.direct;
    // Stored or not; the flux is set per class after the passes (stored_photon_flux).
    if (d < 1) {
      if (!m_storage) m_storage.emplace(m_seed, m_source, m_index, RandomStream::Storage);
      if (!(m_storage->uniform() < d)) return;
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

 private:
  BlockResult& m_out;
  const TracingOptions& m_options;
  StorageProbabilities m_d;
  std::optional<Rng> m_storage;
  std::uint64_t m_seed = 0, m_index = 0;
  std::uint32_t m_source = 0;
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

// The port's own scattering event (seeds/000 section 4.1.3: photons leave the port "as if
// they had passed through it"). Returns the path start, or nothing if the photon is
// reflected back out or absorbed.
std::optional<PathStart> pass_port(const Scene& scene, const std::vector<Material>& materials,
                                   const PortEntry& entry, std::uint32_t source, Rng& scattering,
                                   Rng& roulette_rng) {
  const Port& port = scene.ports()[static_cast<std::size_t>(entry.port)];
  const Material& material =
      materials[static_cast<std::size_t>(scene.description().surfaces[port.surface].material)];
  const MaterialType type = material.type();
  if (type == MaterialType::Glass || type == MaterialType::Glazing || type == MaterialType::Opening) {
    // These transmit only straight through; what they reflect goes back out of the room and is
    // not followed. So the photon passes with the transmittance as its weight instead of a
    // sampled event and roulette: the same expected flux, and no entering photon lost at the
    // pane (docs/photon-tracing.md, "The first scattering event").
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

// A photon that lands on an outdoor scatterer straight from its source: its Direct record
// there (the scatterer's irradiance, which a final gather looking at the scatterer needs),
// then the scatterer's own scattering event, outdoors. Returns the path start, or nothing if
// the photon is absorbed.
std::optional<PathStart> land_on_scatterer(const Scene& scene, const std::vector<Material>& materials,
                                           const PortEntry& entry, std::uint32_t source,
                                           const TracingOptions& options, Rng& scattering,
                                           Rng& roulette_rng, PhotonSink& sink) {
  const Port& scatterer = scene.outdoor_scatterers()[static_cast<std::size_t>(entry.scatterer)];
  const Material& material =
      materials[static_cast<std::size_t>(scene.description().surfaces[scatterer.surface].material)];
  const Vec3 lit_side = dot(entry.direction, scatterer.normal) < 0 ? scatterer.normal : scatterer.normal * -1.0;
  if ((options.store_direct || options.store_direct_on_surfaces) && material.stores_photons())
    sink.record(-1, make_photon(entry.position, {1, 1, 1}, lit_side, source, PathClass::Direct));
  std::optional<PathStart> start = first_event(scene, material, entry.position, scatterer.normal, entry.direction,
                                               source, scattering, roulette_rng);
  if (start) start->outdoors = true;
  return start;
}

}  // namespace

bool trace_path(const Scene& scene, const std::vector<Material>& materials,
                const std::vector<ReceiverPlane>& planes, const PathStart& start,
                const TracingOptions& options, Rng& scattering, Rng& roulette_rng,
                PhotonSink& sink, std::uint64_t* rays) {
  Vec3 flux = start.flux;
  bool scattered = start.scattered;
  bool diffuse = start.diffuse_scattered;
  bool outdoors = start.outdoors;
  bool was_indoors = !outdoors;
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
        if (!(t >= ray.tmin && t < t_end)) continue;
        const Vec3 p = ray.origin + ray.direction * t;
        if (!planes[g].contains(p.x, p.y)) continue;
        sink.record(static_cast<int>(g),
                    make_photon({p.x, p.y, planes[g].height_m()}, flux, planes[g].normal(),
                                start.source, path_class));
      }
    }
    if (!hit) return was_indoors;
    const Material& material = materials[static_cast<std::size_t>(hit->material)];
    if (!hit->front_face && material.absorbs_inside()) {
      // The segment ran inside the dielectric: Beer-Lambert attenuation per metre.
      const Vec3 tpm = material.interior_transmittance_per_m();
      flux = mul(flux, {std::pow(tpm.x, hit->t), std::pow(tpm.y, hit->t), std::pow(tpm.z, hit->t)});
    }
    if ((store || options.store_direct_on_surfaces) && material.stores_photons() &&
        (!outdoors || hit->scatterer >= 0)) {
      const Vec3 side = hit->front_face ? hit->normal : hit->normal * -1.0;
      sink.record(-1, make_photon(hit->position, flux, side, start.source, path_class));
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
    ray = Ray{scene.offset_ray_origin(hit->position, hit->normal, s->direction), s->direction,
              0.0, std::numeric_limits<double>::infinity()};
  }
  return was_indoors;
}

namespace {

struct SourceResult {
  std::vector<Photon> surface;
  std::vector<std::vector<Photon>> planes;
  SourceTally tally;
  std::uint64_t scattered_indoors = 0;  ///< BlockResult::scattered_indoors, summed
};

// Trace attempts [first, last) of `source`, in parallel blocks, appending to `result`.
// Throws if a block did not run: when this pass runs inside an enclosing parallel loop (one
// task per source) and another iteration of that loop throws, TBB cancels the whole task
// group, so this nested loop returns early without having run every block (oneTBB developer
// guide, "Cancellation and Nested Parallelism"). The enclosing loop then rethrows the first
// exception; this one only stops a partial pass from being merged.
void trace_attempts(const Scene& scene, const std::vector<Material>& materials,
                    const std::vector<ReceiverPlane>& planes, const PortEmitter& emitter,
                    std::uint32_t source, std::uint64_t first, std::uint64_t last,
                    const StorageProbabilities& d, const TracingOptions& options,
                    SourceResult& result) {
  if (last <= first) return;
  const std::uint64_t blocks = (last - first + AttemptsPerBlock - 1) / AttemptsPerBlock;
  std::vector<BlockResult> block_results(blocks);
  tbb::parallel_for(std::uint64_t(0), blocks, [&](std::uint64_t b) {
    BlockResult& out = block_results[b];
    out.planes.resize(planes.size());
    BlockSink sink(out, options, d);
    const std::uint64_t begin = first + b * AttemptsPerBlock;
    const std::uint64_t end = std::min(last, begin + AttemptsPerBlock);
    for (std::uint64_t i = begin; i < end; ++i) {
      Rng emission(options.seed, source, i, RandomStream::Emission);
      const std::optional<PortEntry> entry = emitter.attempt(source, emission, &out.rays);
      if (!entry) continue;
      ++out.entered;
      Rng scattering(options.seed, source, i, RandomStream::Scattering);
      Rng roulette_rng(options.seed, source, i, RandomStream::Roulette);
      sink.set_attempt(options.seed, source, i);
      const std::optional<PathStart> start =
          entry->port >= 0
              ? pass_port(scene, materials, *entry, source, scattering, roulette_rng)
              : land_on_scatterer(scene, materials, *entry, source, options, scattering, roulette_rng, sink);
      if (!start) continue;
      const bool indoors = trace_path(scene, materials, planes, *start, options, scattering, roulette_rng,
                                      sink, &out.rays);
      if (entry->scatterer >= 0 && indoors) ++out.scattered_indoors;
    }
    out.complete = true;
  });
  for (const BlockResult& b : block_results)
    if (!b.complete)
      throw std::runtime_error("photon tracing was cancelled before every block of source " +
                               std::to_string(source) + " ran");
  result.planes.resize(planes.size());
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
    result.tally.entered += b.entered;
    result.tally.stored_global += b.global;
    result.tally.stored_caustic += b.caustic;
    result.tally.stored_direct += b.direct;
    result.tally.rays += b.rays;
    result.scattered_indoors += b.scattered_indoors;
  }
}

SourceResult trace_source(const Scene& scene, const std::vector<Material>& materials,
                          const std::vector<ReceiverPlane>& planes, const PortEmitter& emitter,
                          std::uint32_t source, const TracingOptions& options) {
  SourceResult result;
  result.planes.resize(planes.size());
  SourceTally& tally = result.tally;
  tally.bound_flux = emitter.bound_flux(source);
  if (!can_store_photons(scene, materials, planes)) {
    tally.nothing_stores = true;  // no photon of any source could ever be stored
    return result;
  }
  if (tally.bound_flux <= 0) return result;

  const double factor =
      source < options.source_photon_factor.size() ? options.source_photon_factor[source] : 1.0;
  auto scaled = [factor](std::size_t n) {
    return static_cast<std::size_t>(std::llround(double(n) * std::max(0.0, factor)));
  };
  const std::size_t target_g = scaled(options.photons_per_source);
  const std::size_t target_c = scaled(options.caustic_photons_per_source);
  // Direct photons on surfaces (for a final gather) get the global photons' target, so that
  // their count stays bounded however few global photons a dark room stores.
  const std::size_t target_d = options.store_direct_on_surfaces ? target_g : 0;
  std::size_t smallest = target_g;
  if (target_c > 0) smallest = std::min(smallest, target_c);
  const std::size_t largest = std::max(target_g, target_c);
  if (largest == 0) return result;

  // Pre-pass (Alg. 4.1), every photon stored. The thesis doubles it while a map is empty;
  // here it doubles until every targeted class has enough photons for its yield to be
  // known to ~10 % (min(100, k * target) stored), or, if a class stays empty while another
  // has enough after 64 doublings' worth of attempts, that class is taken as absent (e.g.
  // caustics in an all-diffuse room), or the attempts reach the give-up limit (a source the
  // ports see but whose light is blocked).
  const std::uint64_t initial = std::max<std::uint64_t>(
      1, static_cast<std::uint64_t>(std::ceil(options.prepass_fraction * double(smallest))));
  std::uint64_t prepass = initial;
  std::uint64_t done = 0;
  // Attempt limits in port-equivalent attempts (photon_tracer.h, "Outdoor scatterers"): an
  // attempt on a port counts fully; of the attempts on outdoor scatterers only those whose
  // light enters a room count (an upper 95 % bound on their share, from the attempts so far).
  const double port_share = tally.bound_flux > 0 ? emitter.port_bound_flux(source) / tally.bound_flux : 1.0;
  auto useful_share = [&](std::uint64_t attempts) {
    if (port_share >= 1.0 || attempts == 0) return 1.0;
    return std::min(1.0, port_share + (double(result.scattered_indoors) + 3.0) / double(attempts));
  };
  auto scaled_limit = [&](std::size_t per_target, std::uint64_t attempts) {
    return std::max<std::uint64_t>(1, static_cast<std::uint64_t>(std::ceil(
                                          double(per_target) * double(largest) * useful_share(attempts))));
  };

  auto enough = [&](std::size_t target, std::uint64_t stored) {
    return target == 0 ||
           double(stored) >= std::min(100.0, std::ceil(options.prepass_fraction * double(target)));
  };
  for (;;) {
    trace_attempts(scene, materials, planes, emitter, source, done, prepass, StorageProbabilities{}, options,
                   result);
    done = prepass;
    const bool g_ok = enough(target_g, tally.stored_global);
    const bool c_ok = enough(target_c, tally.stored_caustic);
    const bool d_ok = enough(target_d, tally.stored_direct);
    const bool g_found = target_g > 0 && tally.stored_global > 0 && g_ok;
    const bool c_found = target_c > 0 && tally.stored_caustic > 0 && c_ok;
    const bool d_found = target_d > 0 && tally.stored_direct > 0 && d_ok;
    if (g_ok && c_ok && d_ok) break;
    if ((g_found || c_found || d_found) && prepass >= 64 * initial) break;
    if (prepass >= std::max(initial, scaled_limit(options.max_prepass_attempts_per_target, prepass))) break;
    // Light enters but nothing is stored (every surface it reaches absorbs it before it
    // scatters onto anything that stores, e.g. a black room): after 2^16 entries the stored
    // fraction of the entering flux is below 5e-5 (95 % confidence: 3 / 65536); stop.
    if (tally.entered >= NothingStoredEntries && tally.stored_global + tally.stored_caustic + tally.stored_direct == 0)
      break;
    // Nothing entered at all: the ports do not see this source (a sun disc's emission bound
    // is a little above zero just behind a port's plane; a sky bin's is exact, see
    // port_emission.h) or it is blocked. After 2^16 attempts its flux is below 5e-5 of the bound (95 %
    // confidence: 3 / 65536) and is dropped.
    if (tally.entered == 0 && prepass >= 65536) break;
    prepass *= 2;
  }
  tally.prepass_attempts = prepass;

  // Main pass (Alg. 4.2, eqs. 4.8-4.10): r_j = n_j / N_j - 1 from the pre-pass yields.
  auto shortfall = [](std::size_t target, std::uint64_t stored) {
    if (target == 0 || stored == 0) return 0.0;
    return std::max(double(target) / double(stored), 1.0) - 1.0;
  };
  const double r_g = shortfall(target_g, tally.stored_global);
  const double r_c = shortfall(target_c, tally.stored_caustic);
  const double r_d = shortfall(target_d, tally.stored_direct);
  const double r_max = std::max({r_g, r_c, r_d});
  if (r_max > 0) {
    tally.storage_probability_global = r_g / r_max;
    tally.storage_probability_caustic = target_c > 0 ? r_c / r_max : r_g / r_max;
    if (target_d > 0) tally.storage_probability_direct = r_d / r_max;
    const StorageProbabilities d{tally.storage_probability_global, tally.storage_probability_caustic,
                                 tally.storage_probability_direct};
    // The low-yield cap (photon_tracer.h): fixed before any of these attempts is traced.
    const std::uint64_t cap = options.max_mainpass_attempts_per_target == 0
                                  ? std::numeric_limits<std::uint64_t>::max()
                                  : scaled_limit(options.max_mainpass_attempts_per_target, prepass);
    const double planned = std::ceil(double(prepass) * r_max);
    tally.capped = planned > double(cap);
    const std::uint64_t main = tally.capped ? cap : static_cast<std::uint64_t>(planned);
    const std::uint64_t g0 = tally.stored_global, c0 = tally.stored_caustic, d0 = tally.stored_direct;
    trace_attempts(scene, materials, planes, emitter, source, prepass, prepass + main, d, options,
                   result);
    tally.mainpass_attempts = main;
    // Top-up (not in the thesis): the pre-pass yield has the noise of a few hundred photons,
    // so the main pass can fall short by several per cent; its own yield (thousands of
    // photons) sizes one more run of attempts with the same storage probabilities. Every
    // attempt still carries bound_flux / attempts, so the flux stays unbiased.
    double extra = 0;
    auto need = [&](std::size_t target, std::uint64_t stored, std::uint64_t before) {
      const double yield = double(stored - before) / double(main);
      if (target == 0 || stored >= target || yield <= 0) return 0.0;
      return double(target - stored) / yield;
    };
    extra = std::max({need(target_g, tally.stored_global, g0), need(target_c, tally.stored_caustic, c0),
                      need(target_d, tally.stored_direct, d0)});
    std::uint64_t topup = std::min<std::uint64_t>(main, static_cast<std::uint64_t>(std::ceil(extra)));
    if (topup > cap - main) {
      topup = cap - main;
      tally.capped = true;
    }
    if (topup > 0) {
      trace_attempts(scene, materials, planes, emitter, source, prepass + main,
                     prepass + main + topup, d, options, result);
      tally.mainpass_attempts += topup;
    }
  }

  // Normalise (eqs. 4.11-4.12, per class: see the header comment).
  tally.flux_per_attempt =
      tally.bound_flux / double(tally.prepass_attempts + tally.mainpass_attempts);
  float scale[3];  // indexed by PathClass
  for (PathClass c : {PathClass::Direct, PathClass::Caustic, PathClass::Global})
    scale[static_cast<int>(c)] = static_cast<float>(tally.stored_photon_flux(c));
  auto rescale = [&scale](std::vector<Photon>& photons) {
    for (Photon& p : photons)
      for (float& f : p.flux) f *= scale[static_cast<int>(p.path_class)];
  };
  rescale(result.surface);
  for (auto& plane : result.planes) rescale(plane);
  return result;
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

TracedPhotons trace_source_photons(const Scene& scene, const std::vector<Material>& materials,
                                   const PortEmitter& emitter,
                                   const std::vector<ReceiverPlane>& planes,
                                   const TracingOptions& options, std::size_t source) {
  SourceResult r = trace_source(scene, materials, planes, emitter,
                                static_cast<std::uint32_t>(source), options);
  TracedPhotons out;
  out.surface = std::move(r.surface);
  out.planes = std::move(r.planes);
  out.planes.resize(planes.size());
  out.tallies.push_back(r.tally);
  return out;
}

TracedPhotons trace_source_attempts(const Scene& scene, const std::vector<Material>& materials,
                                    const PortEmitter& emitter, const std::vector<ReceiverPlane>& planes,
                                    const TracingOptions& options, std::size_t source, std::uint64_t first,
                                    std::uint64_t last) {
  SourceResult r;
  r.planes.resize(planes.size());
  r.tally.bound_flux = emitter.bound_flux(static_cast<std::uint32_t>(source));
  if (!can_store_photons(scene, materials, planes)) {
    r.tally.nothing_stores = true;
  } else if (r.tally.bound_flux > 0 && last > first) {
    trace_attempts(scene, materials, planes, emitter, static_cast<std::uint32_t>(source), first, last,
                   StorageProbabilities{}, options, r);
    r.tally.prepass_attempts = last - first;
  }
  TracedPhotons out;
  out.surface = std::move(r.surface);
  out.planes = std::move(r.planes);
  out.planes.resize(planes.size());
  out.tallies.push_back(r.tally);
  return out;
}

TracedPhotons merge_traced_photons(std::vector<TracedPhotons>&& per_source) {
  TracedPhotons out;
  std::size_t plane_count = 0;
  for (const TracedPhotons& r : per_source) plane_count = std::max(plane_count, r.planes.size());
  out.planes.resize(plane_count);
  std::size_t surface_total = 0, tally_total = 0;
  std::vector<std::size_t> plane_total(plane_count, 0);
  for (const TracedPhotons& r : per_source) {
    surface_total += r.surface.size();
    tally_total += r.tallies.size();
    for (std::size_t g = 0; g < r.planes.size(); ++g) plane_total[g] += r.planes[g].size();
  }
  out.surface.reserve(surface_total);
  out.tallies.reserve(tally_total);
  for (std::size_t g = 0; g < plane_count; ++g) out.planes[g].reserve(plane_total[g]);
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
