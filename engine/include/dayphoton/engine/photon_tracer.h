// Photon tracer: the forward pass of the contribution photon map (DESIGN.md section 5;
// seeds/000 sections 3.1.1 and 4.1; seeds/001 sections 2-4).
//
// Every source (sky bin, sun disc) emits its own photons through the ports (PortEmitter).
// Transport is analogue (seeds/000 section 3.1.1.2): the material's sample() picks the
// event and direction, the RGB flux is multiplied by the sample weight and Russian roulette
// with the FLUX-WEIGHTED survival probability P = mean(flux * weight) / mean(flux) keeps the
// photon flux constant without biasing coloured light (digest section 2.1.4). One exception:
// the first scattering event of a path (its first event other than a straight
// transmission, usually its first hit in the room) multiplies the flux by the weight and
// plays no roulette, so a photon that reached a dark floor is not lost with all the rays it cost; its
// photons then carry that event's reflectance (docs/photon-tracing.md, "The first
// scattering event": on the office a third of the rays per stored photon, about the same
// noise per photon).
//
// Path classes and storage (digest section 2.1.5):
//   - a photon that has not scattered since the port (StraightTransmission through glazing
//     or openings does not count as scattering) is DIRECT: its hits and plane crossings are
//     not stored, because the direct component comes from shadow rays
//     (direct_component.h) that pass exactly the same straight transmissions;
//   - after only specular events (delta or glossy reflection/refraction) it is CAUSTIC;
//   - after at least one diffuse event it is GLOBAL.
//   Photons are stored at every hit on a surface with a diffuse component and at every
//   crossing of a receiver plane from its front side inside its outline. With
//   store_direct, direct photons are stored too (flagged Direct), for diagnostics only.
//
// Photon counts (seeds/000 section 4.1.4, Alg. 4.1/4.2; seeds/001 section 4.2.1: an equal
// number of stored photons per source): a pre-pass of k * target attempts (doubled until
// every targeted class has enough photons to measure its yield, or is found absent;
// attempts accumulate, nothing is discarded), then a main pass sized so that each class
// reaches its target, storing class j with probability d_j, then one top-up run sized from
// the main pass's own yield. Every attempt carries bound_flux / (all attempts)
// (port_emission.h); a class stored in the P pre-pass attempts and with probability d_j in
// the M main-pass ones has sampled P + M d_j attempts' worth of its light, so each of its
// photons carries bound_flux / (P + M d_j) (SourceTally::stored_photon_flux). The thesis'
// per-photon 1/d_j instead loses a class with d_j = 0 (already at its target after the
// pre-pass: its main-pass light went missing, -88 % on a caustic-target test room).
//
// Low-yield cap (not in the thesis): the main pass and top-up together make at most
// max_mainpass_attempts_per_target x (largest target) attempts. A source that stores fewer
// than ~1 photon per that many attempts (a sky patch seen by a port through a sliver, or
// passing straight through a port enclosure) then keeps fewer photons instead of running for
// minutes. Each pass's attempt count is fixed before it is traced, so its attempts are
// i.i.d. and bound_flux / attempts keeps their flux unbiased whatever the count. Where the
// capped sources bring little light only the variance grows (docs/photon-tracing.md,
// "Low-yield cap": a capped source's absolute noise is at most that of a source whose yield
// is exactly at the cap). Where a large outdoor scatterer takes nearly every attempt, every
// source is capped far below its target, and the density estimates of sources with a handful
// of photons spread their light over the room: a bias the stated error does not contain.
// The study then traces those sources again with the cap in raw attempts (raw_attempt_cap
// below), and names in run.log what stays starved (docs/photon-tracing.md, "Low-yield cap").
//
// Outdoor scatterers (port_emission.h): a photon that lands on one is stored there as
// Direct (with store_direct or store_direct_on_surfaces: a final gather looking out of a
// window at the scatterer reads it; with scatterer_direct_sides only on the sides a gather
// can read, gathered_scatterer_sides.h) and scattered by its material, outdoors (trace_path).
// Many of these photons never enter a room (a mirror shelf under a high north sky reflects
// everything back up), so the low-yield cap and the pre-pass give-up limit count attempts
// in port-equivalents: every attempt on a port counts, and of the attempts on scatterers
// only the share whose path entered a room (its upper 95 % bound, (n + 3) / attempts). A
// scene without scatterers is capped exactly as before.
//
// Determinism: attempt i of source p uses Rng(seed, p, i, stream) for the emission,
// scattering and roulette streams; attempts are traced in blocks in parallel (oneTBB) and
// the stored photons concatenated in (source, attempt) order, so the result is identical
// for any number of threads.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "dayphoton/core/vec3.h"
#include "dayphoton/engine/distant_source.h"
#include "dayphoton/engine/material.h"
#include "dayphoton/engine/photon.h"
#include "dayphoton/engine/port_emission.h"
#include "dayphoton/engine/random.h"
#include "dayphoton/engine/receiver_plane.h"
#include "dayphoton/engine/scene.h"
#include "dayphoton/engine/sky_ratios.h"

namespace dayphoton::engine {

struct TracingOptions {
  /// Target number of stored GLOBAL photons per source (surfaces and planes together).
  std::size_t photons_per_source = 20000;
  /// Target number of stored CAUSTIC photons per source; 0 = no target of its own (caustic
  /// photons are then stored with the global photons' probability).
  std::size_t caustic_photons_per_source = 0;
  /// Per-source multipliers of both targets (empty = 1 for all). Equal counts per bin
  /// suit bins of similar solid angle and flux (seeds/001 section 4.2.1), but the ground
  /// bin 0 is a whole hemisphere: under a CIE overcast sky with ground reflectance 0.2 it
  /// brings ~20 % of the light through a vertical window while a Tregenza sky bin brings
  /// ~1 %, so with equal counts its noise dominates the indirect light deep in a room.
  /// Giving a source photons in proportion to its share of the light (Neyman allocation)
  /// minimises the variance of the sum; see ground_photon_factor() in the pipeline.
  std::vector<double> source_photon_factor;
  std::uint64_t seed = 1;
  double prepass_fraction = 0.25;        ///< k of Alg. 4.1
  /// The pre-pass stops at this many attempts per targeted photon even if it has not stored
  /// enough to measure the yield (the main pass is then sized from what it stored, and
  /// capped; with nothing stored there is no main pass), or at 65536 attempts of which none
  /// entered (e.g. a sun behind the building, a bin just behind the port's plane).
  std::size_t max_prepass_attempts_per_target = 256;
  /// The main pass and its top-up make at most this many attempts per targeted photon
  /// (times the largest scaled target); 0 = no cap. Only sources storing fewer than about
  /// one photon per this many attempts are affected: they keep fewer photons, their flux
  /// stays unbiased (see above), and SourceTally::capped is set.
  std::size_t max_mainpass_attempts_per_target = 256;
  /// Per source (missing entries: 0): 1 makes this source's main-pass cap count raw
  /// attempts, max_mainpass_attempts_per_target x target, without the scaling by the useful
  /// share that outdoor scatterers bring ("Outdoor scatterers" above). The pipeline sets it
  /// for the sources it traces again because the scaled cap starved the sources that carry
  /// the light (study/src/photon_pass_notes.h, lifted_cap_sources).
  std::vector<char> raw_attempt_cap;
  bool store_direct = false;             ///< also store Direct photons (diagnostics)
  /// Store Direct photons on surfaces (not on planes), with the global photons' target, for
  /// a final gather (final_gather.h). Their main-pass storage probability follows the
  /// photon-count control like the other classes' (SourceTally::storage_probability_direct).
  bool store_direct_on_surfaces = false;
  /// With store_direct_on_surfaces: per outdoor scatterer (Scene::outdoor_scatterers order),
  /// the sides whose Direct photons are stored (gathered_scatterer_sides.h: the sides a gather
  /// can read; ScattererNormalSide / ScattererOppositeSide bits). Empty: every side, as
  /// without the rule. Direct photons on the other sides are neither stored nor counted.
  /// store_direct (diagnostics) stores them all.
  std::vector<std::uint8_t> scatterer_direct_sides;
  /// Keep the photons stored on surfaces. When every sensor grid is a receiver plane they
  /// are not used: they are then still counted (the counts control is unchanged, so the
  /// same settings give the same plane photons) but not kept, which saves ~70 % of memory.
  bool keep_surface_photons = true;
  std::optional<Bounds3> region_of_interest;  ///< store only photons inside this box
  int max_events = 512;                  ///< safety cap on scattering events per path
  /// Each sky-bin photon's sky ratio (photon.h, sky_ratios.h) from the direction it was
  /// emitted toward; null: every ratio 1. The bins of a SourceSet::sky_bins set only (a sun
  /// disc's photons keep 1). It changes no flux, no count and no random number: only the
  /// records' ratio codes.
  std::shared_ptr<const SkyRatios> sky_ratios;
};

/// What happened to one source's photons.
struct SourceTally {
  std::uint64_t prepass_attempts = 0;
  std::uint64_t mainpass_attempts = 0;   ///< main pass and its top-up
  std::uint64_t entered = 0;             ///< accepted, unoccluded emissions
  std::uint64_t stored_global = 0, stored_caustic = 0, stored_direct = 0;
  std::uint64_t rays = 0;                ///< rays cast: emission occlusion tests + path segments
  double bound_flux = 0;                 ///< PortEmitter::bound_flux
  double flux_per_attempt = 0;           ///< bound_flux / all attempts
  double storage_probability_global = 1, storage_probability_caustic = 1;
  double storage_probability_direct = 1;  ///< < 1 only with store_direct_on_surfaces
  /// Nothing in the scene can store a photon (no surface with a diffuse component, and no
  /// receiver plane or nothing that scatters): the source was not traced.
  bool nothing_stores = false;
  /// The main pass (with its top-up) was cut to max_mainpass_attempts_per_target x target
  /// attempts: the source stores fewer photons than its target.
  bool capped = false;

  /// Flux every stored photon of `path_class` carries (per unit source radiance):
  /// bound_flux / (prepass + mainpass x d), d the class's main-pass storage probability.
  /// Stored photons of a class sample P + M d attempts' worth of its light.
  double stored_photon_flux(PathClass path_class) const {
    const double d = path_class == PathClass::Global    ? storage_probability_global
                     : path_class == PathClass::Caustic ? storage_probability_caustic
                                                        : storage_probability_direct;
    return bound_flux / (double(prepass_attempts) + double(mainpass_attempts) * d);
  }
};

struct TracedPhotons {
  std::vector<Photon> surface;              ///< stored on surfaces with a diffuse component
  std::vector<std::vector<Photon>> planes;  ///< per receiver plane (argument order)
  std::vector<SourceTally> tallies;         ///< per source
};

/// False if no photon could ever be stored: no surface material stores photons, and either
/// there is no receiver plane or no material scatters light other than straight through (a
/// black room with open or glazed ports). trace_source_photons then traces nothing and sets
/// SourceTally::nothing_stores.
bool can_store_photons(const Scene& scene, const std::vector<Material>& materials,
                       const std::vector<ReceiverPlane>& planes);

/// The forward pass for every source of `sources`. `materials[m]` models scene material m.
TracedPhotons trace_photons(const Scene& scene, const std::vector<Material>& materials,
                            const SourceSet& sources, const std::vector<ReceiverPlane>& planes,
                            const TracingOptions& options);

/// The forward pass of one source (trace_photons runs it for every source in parallel):
/// `tallies` has one entry. A pure function of (scene, source, options), so it can be cached
/// per source and a run resumed source by source.
TracedPhotons trace_source_photons(const Scene& scene, const std::vector<Material>& materials,
                                   const PortEmitter& emitter,
                                   const std::vector<ReceiverPlane>& planes,
                                   const TracingOptions& options, std::size_t source);

/// Attempts [first, last) of one source with every class stored (no storage probabilities)
/// and each photon's flux as traced, relative to its attempt's flux (not yet multiplied by
/// bound_flux / attempts): the building block of the accuracy rounds (photon_rounds.h), which
/// extend a source's attempts round by round. Attempt i is a pure function of (seed, source,
/// i), so tracing [0, a) and then [a, b) gives the photons of [0, b) in the same order.
/// `tallies` has one entry: entered, stored counts, rays and bound_flux of these attempts,
/// and their number in prepass_attempts; nothing_stores as trace_source_photons.
TracedPhotons trace_source_attempts(const Scene& scene, const std::vector<Material>& materials,
                                    const PortEmitter& emitter, const std::vector<ReceiverPlane>& planes,
                                    const TracingOptions& options, std::size_t source, std::uint64_t first,
                                    std::uint64_t last);

// ---- ranges of attempts (the building block of the pass control, source_passes.h) --------

/// Main-pass storage probability of each class (1 in the pre-pass): a record of class j is
/// kept with probability d_j, drawn from its attempt's own storage stream.
struct StorageProbabilities {
  double global = 1, caustic = 1, direct = 1;
};

/// What the photon-count control reads of a run of attempts. Every field is a sum over the
/// attempts, so the counts of [a, c) are those of [a, b) plus those of [b, c): a pass traced
/// in ranges (on several ranks) has exactly the counts of the pass traced at once.
struct AttemptCounts {
  std::uint64_t entered = 0;  ///< accepted, unoccluded emissions
  std::uint64_t stored_global = 0, stored_caustic = 0, stored_direct = 0;  ///< kept or only counted
  std::uint64_t rays = 0;
  /// Attempts that landed on an outdoor scatterer and whose path then entered a room.
  std::uint64_t scattered_indoors = 0;

  AttemptCounts& operator+=(const AttemptCounts& more);
};
bool operator==(const AttemptCounts& a, const AttemptCounts& b);

/// Attempts [first, last) of one source: the stored photons in attempt order, each with its
/// flux relative to its attempt's (not yet scaled: the scale depends on every pass, see
/// SourceTally::stored_photon_flux), and their counts.
struct AttemptRange {
  std::vector<Photon> surface;              ///< kept only with options.keep_surface_photons
  std::vector<std::vector<Photon>> planes;  ///< per receiver plane
  AttemptCounts counts;
};

/// Traces attempts [first, last) of `source` with the storage probabilities `storage`, in
/// parallel blocks. Attempt i is a pure function of (options.seed, source, i), so the ranges
/// of any split of [a, b), appended in order (append_attempt_range), give the range [a, b)
/// byte for byte. Traces whatever it is asked: the pass control (source_passes.h) decides
/// whether a source is traced at all.
AttemptRange trace_attempt_range(const Scene& scene, const std::vector<Material>& materials,
                                 const PortEmitter& emitter, const std::vector<ReceiverPlane>& planes,
                                 const TracingOptions& options, std::size_t source, std::uint64_t first,
                                 std::uint64_t last, const StorageProbabilities& storage);

/// Appends `more`, the attempts right after those of `to`, to `to`: photons concatenated,
/// counts summed.
void append_attempt_range(AttemptRange& to, AttemptRange&& more);

/// Concatenate per-source results in order (the layout trace_photons returns).
TracedPhotons merge_traced_photons(std::vector<TracedPhotons>&& per_source);

// ---- one path (exposed for tests with local sources, e.g. the furnace) -----------------

/// Where a path's records go. Flux is relative (the caller scales it); `plane` is the
/// receiver plane index for plane crossings, -1 for surface hits.
class PhotonSink {
 public:
  virtual ~PhotonSink() = default;
  virtual void record(int plane, const Photon& photon) = 0;
  /// A record on a diffusing port (translucent, transmitted_specular < 1), either side:
  /// stored whatever the region of interest, since a final gather that reaches the port from
  /// the room reads both (the sky side through its diffuse transmittance).
  virtual void record_on_diffusing_port(const Photon& photon) { record(-1, photon); }
};

struct PathStart {
  Vec3 origin;           ///< metres, already off any surface
  Vec3 direction;        ///< propagation direction, unit
  Vec3 flux{1, 1, 1};    ///< RGB, relative
  std::uint32_t source = 0;
  std::uint32_t sky_ratio_code = SkyRatioOne;  ///< of the path's photons (photon.h)
  std::uint8_t sky_quadrant = 0;               ///< of the path's photons (photon.h)
  bool scattered = false;         ///< false: the path starts as Direct
  bool diffuse_scattered = false; ///< true: the path is already Global
  /// The path starts outdoors (on an outdoor scatterer), not in a room behind a port.
  bool outdoors = false;
};

/// Trace one photon path, reporting stored records to `sink` (Direct records only if
/// options.store_direct). `scattering` and `roulette` are the path's two streams; `rays`, if
/// given, counts the rays cast.
///
/// Indoors and outdoors: a path is outdoors from an outdoor scatterer until it passes a port
/// inward (along the port's normal), and again after passing one outward. Outdoors it is
/// stored only on outdoor scatterers (what a final gather looking at them needs), never on
/// the outer faces of rooms or on receiver planes. Returns true if the path was indoors at
/// any point.
bool trace_path(const Scene& scene, const std::vector<Material>& materials,
                const std::vector<ReceiverPlane>& planes, const PathStart& start,
                const TracingOptions& options, Rng& scattering, Rng& roulette, PhotonSink& sink,
                std::uint64_t* rays = nullptr);

}  // namespace dayphoton::engine
