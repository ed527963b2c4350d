// perez_sky_component_bench: how far the annual illuminance's sky component (coefficients x the
// hourly Perez sky vector, patch-centre values as the annual study builds it) is from the sky
// component under the continuous Perez sky of the same hour, at the sensors of
// projects/wall_sensors (work plane, back wall, west wall) and of the same room black (every
// reflectance 0, the window an unglazed opening: its whole illuminance is the direct part).
//
// Both come from the very same shadow-ray samples (engine::DirectOptions::skies: each sample's
// value per unit radiance times the continuous sky's radiance at its own direction), so their
// difference is the basis's error alone (docs/direct-component.md, "Continuous skies"). The
// continuous sky is sky::make_perez_sky of the hour's record (the sky matrix's inputs: RADIANCE
// sun formulas, 11 C dew point), times gendaymtx's sky colour, the matrix's ground bin below
// the horizon. The patch-mean vector (sky::PatchValue::Mean) is reported beside it.
//
// The fix candidates are scored on the same samples (moment_skies): each patch's first
// moments about its centre with the sky's centre value and tangent gradient (a first-order
// Taylor model of the sky inside the patch), and 2 x 2 sub-patches with their mean radiance;
// beside them the study's own (engine::direct_coefficients' sub-patch shares with the sky
// matrix's quadrant deltas, study/sub_patch_shares.h).
//
// Two modes:
//   hours [N]  N hours per sky class (overcast: Perez clearness bin 1; intermediate: bins 2-5;
//              clear: bins 6-8) from each weather file (the project's Oakland TMY3 and
//              tests/data/weather/DEU_Mannheim.epw), evenly spread over the class's daytime
//              records with the sun above 2 degrees. A normal annual run of the project for
//              each weather file gives the hourly total; the error is given relative to the
//              direct part (sky + ground through the window) and to the total.
//   year [S]   every occupied daytime hour of each weather file, S shadow rays per bin (16 by
//              default, the project's: the very samples of the run's direct part): the run's
//              hourly totals (the study's: patch values plus the sub-patch correction) and the
//              patch-uniform ones (the correction taken out) against the reference (the direct
//              part replaced by the continuous sky's), and the annual metrics (DA300, UDI) of
//              each against the reference's.
// Usage: perez_sky_component_bench hours|year [N|S] [threads]. Writes runs under
// $TMPDIR/dayphoton_perez_sky_component_bench (or /tmp).
#include <tbb/global_control.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "dayphoton/core/units.h"
#include "dayphoton/engine/direct_component.h"
#include "dayphoton/engine/distant_source.h"
#include "dayphoton/engine/estimate_variance.h"
#include "dayphoton/engine/scene.h"
#include "dayphoton/metrics/annual_metrics.h"
#include "dayphoton/project/project.h"
#include "dayphoton/sky/patch_basis.h"
#include "dayphoton/sky/perez.h"
#include "dayphoton/sky/sky_matrix.h"
#include "dayphoton/study/annual_study.h"
#include "dayphoton/study/annual_sun.h"
#include "dayphoton/study/progress.h"
#include "dayphoton/study/project_metric_settings.h"
#include "dayphoton/study/results_model.h"
#include "dayphoton/study/study_runner.h"
#include "dayphoton/study/sun_site.h"
#include "dayphoton/weather/epw_reader.h"
#include "dayphoton/weather/site_clock.h"
#include "df_only_run.h"
#include "error_stats.h"
#include "perez_hour.h"

using namespace dayphoton;
namespace fs = std::filesystem;

namespace {

/// Sun altitude below which an hour is not picked (twilight skies: the Perez model clamps Z).
constexpr double MinimumSunAltitude_deg = 2.0;

/// One weather file with the project set to it, its sky matrices and suns.
struct Climate {
  std::string name;
  project::Project proj;
  weather::HourlyWeather epw;
  sky::SolarSite site;
  std::vector<weather::TimeStep> steps;
  sky::SkyMatrix centre, mean;          ///< as the annual study builds it (with its quadrant deltas); patch means
  std::vector<std::optional<Vec3>> sun;  ///< per record: the sun above the horizon
};

Climate make_climate(const std::string& name, project::Project proj, const std::string& epw_path) {
  Climate c;
  c.name = name;
  if (epw_path != proj.weather.path) {
    proj.weather.path = epw_path;
    proj.site.from_weather = true;  // the sun of the file's own site
  }
  c.proj = std::move(proj);
  c.epw = weather::read_hourly_weather(c.proj.weather.path);
  c.site = study::resolve_sun_site(c.proj.site, c.epw).solar;
  c.steps = weather::SiteClock::for_weather(c.epw).steps(c.epw.records);
  const sky::PatchBasis basis = sky::PatchBasis::tregenza();
  sky::SkyMatrixOptions options = study::sun_excluded_sky_options(c.proj.simulation.ground_reflectance);
  options.quadrant_deltas = true;
  c.centre = sky::build_sky_matrix(c.epw, c.site, basis, options);
  options.quadrant_deltas = false;
  sky::SkyMatrixOptions mean_options = options;
  mean_options.patch_value = sky::PatchValue::Mean;
  c.mean = sky::build_sky_matrix(c.epw, c.site, basis, mean_options);
  c.sun.assign(c.steps.size(), std::nullopt);
  for (const sky::SunRecord& s : sky::daytime_sun_positions(c.epw, c.site, options)) c.sun[s.step] = s.direction;
  return c;
}

sky::PerezInputs perez_inputs(const Climate& c, std::size_t t) { return bench::perez_inputs_of(c.epw, c.steps, c.sun, t); }

/// The continuous Perez sky of record t, as the matrix's column t would be without patches.
engine::ContinuousSky continuous_sky(const Climate& c, std::size_t t) {
  const Vec3 ground{c.centre.matrix.at(0, t, 0), c.centre.matrix.at(0, t, 1), c.centre.matrix.at(0, t, 2)};
  return bench::continuous_perez_sky(perez_inputs(c, t), ground, c.name + " record " + std::to_string(t));
}

/// Largest relative difference between column t of the study's matrix and the patch-centre
/// vector of the continuous sky (sky::sky_vector, same normalisation): the two are one sky.
double centre_vector_difference(const Climate& c, std::size_t t) {
  const sky::PerezSky perez = sky::make_perez_sky(perez_inputs(c, t));
  const Vec3 ground{c.centre.matrix.at(0, t, 0), c.centre.matrix.at(0, t, 1), c.centre.matrix.at(0, t, 2)};
  const RadianceMatrix v = sky::sky_vector(*perez.sky, sky::PatchBasis::tregenza(), ground, sky::PatchValue::Centre);
  const Vec3 colour = sky::SkyMatrixOptions::gendaymtx_compatible().sky_colour;
  double worst = 0;
  for (std::size_t p = 1; p < v.rows(); ++p) {
    const double matrix = c.centre.matrix.at(p, t, 1), vector = v.at(p, 0, 1) * colour.y;
    worst = std::max(worst, std::fabs(matrix - vector) / std::max(1e-12, std::fabs(vector)));
  }
  return worst;
}

/// Illuminance (lux) of coefficient row s under column t of `m`.
double basis_lux(const std::vector<Vec3>& coefficients, std::size_t sources, std::size_t s, const RadianceMatrix& m,
                 std::size_t t) {
  Vec3 e;
  for (std::size_t p = 0; p < sources; ++p)
    e += mul(coefficients[s * sources + p], Vec3{m.at(p, t, 0), m.at(p, t, 1), m.at(p, t, 2)});
  return RadianceWhiteEfficacy_lm_per_W * engine::luminance_of(e);
}

/// The scene of the project, or of the same room black (every reflectance 0, every glass an
/// opening).
struct Room {
  engine::Scene scene;
  std::vector<engine::Material> materials;
  std::vector<SensorGrid> grids;
};

Room make_room(const project::Project& proj, bool black) {
  SceneDescription d = project::build_scene_description(proj);
  if (black)
    for (MaterialSpec& m : d.materials) {
      m.reflectance = {0, 0, 0};
      if (m.type == MaterialType::Glass) m.type = MaterialType::Opening;
    }
  Room r{engine::Scene::build(d), {}, {}};
  for (const MaterialSpec& m : d.materials) r.materials.push_back(engine::Material::from_spec(m));
  for (const SensorGrid& g : d.grids)
    if (g.name != "workplane_points") r.grids.push_back(g);  // the same positions as `workplane`
  return r;
}

/// A normal annual run of the climate's project (no images, report, coefficients); the hourly
/// tables of its grids by name.
std::map<std::string, metrics::IlluminanceTable> annual_run(const Climate& c, const fs::path& folder) {
  project::Project p = c.proj;
  p.study = project::StudyKind::Annual;
  p.outputs.annual_illuminance = p.outputs.metrics = true;
  p.outputs.images = p.outputs.report = p.outputs.coefficients = false;
  std::ostringstream log;
  study::Progress progress(log, study::ProgressStyle::Quiet);
  study::RunSettings settings;
  settings.output_dir = (folder / (c.name + "_results")).string();
  settings.cache_dir = (folder / (c.name + "_cache")).string();
  study::run_study(p, settings, progress);
  const study::ResultsModel model = study::read_results_model(settings.output_dir);
  std::map<std::string, metrics::IlluminanceTable> tables;
  for (const study::GridResult& g : model.cases.at(0).grids)
    if (g.annual) tables[g.name] = study::read_illuminance_table(settings.output_dir, g);
  return tables;
}

/// Sensor classes of the report: every grid, and the work plane's back half (y >= 4.5 m).
std::vector<std::pair<std::string, std::vector<std::size_t>>> sensor_classes(const SensorGrid& g) {
  std::vector<std::size_t> all, deep;
  for (std::size_t s = 0; s < g.points.size(); ++s) {
    all.push_back(s);
    if (g.name == "workplane" && g.points[s].position.y >= 4.5) deep.push_back(s);
  }
  std::vector<std::pair<std::string, std::vector<std::size_t>>> out{{g.name, all}};
  if (!deep.empty()) out.emplace_back(g.name + " y>=4.5", deep);
  return out;
}

using bench::ErrorStats;

/// Relative errors (%): mean, RMS, worst (largest magnitude, signed), as a table's columns.
std::string text(const ErrorStats& e) {
  char b[96];
  if (e.n == 0) return "      -        -        -";
  std::snprintf(b, sizeof b, "%+7.2f %7.2f %+8.2f", e.mean(), e.rms(), e.worst);
  return b;
}

/// Hour indices of the given clearness bins, n of them evenly spread over the daytime records.
std::vector<std::size_t> pick_hours(const Climate& c, int bin_lo, int bin_hi, int n) {
  std::vector<std::size_t> candidates;
  for (std::size_t t = 0; t < c.steps.size(); ++t) {
    if (!c.sun[t] || std::asin(c.sun[t]->z) < MinimumSunAltitude_deg * Pi / 180.0) continue;
    if (!(c.epw.records[t].diffuse_horizontal_w_m2.value_or(0.0) > 0)) continue;
    const int bin = sky::perez_state(perez_inputs(c, t)).bin;
    if (bin >= bin_lo && bin <= bin_hi) candidates.push_back(t);
  }
  std::vector<std::size_t> out;
  for (int i = 0; i < n && !candidates.empty(); ++i)
    out.push_back(candidates[(2 * std::size_t(i) + 1) * candidates.size() / (2 * std::size_t(n))]);
  return out;
}

/// The direct part (coefficients) and its value under each sky, for a room's grid.
struct DirectPart {
  std::vector<Vec3> coefficients;
  engine::DirectOnSkies on_skies;
  std::vector<float> quadrants;  ///< the sub-patch shares (engine::direct_coefficients)
};

DirectPart direct_part(const Room& room, const SensorGrid& g, const std::vector<engine::ContinuousSky>& skies,
                       int samples, std::uint64_t seed) {
  engine::DirectOptions o;
  o.samples_per_source = samples;
  o.seed = seed;
  o.skies = skies;
  DirectPart d;
  d.coefficients = engine::direct_coefficients(room.scene, room.materials,
                                               engine::SourceSet::sky_bins(sky::PatchBasis::tregenza()), g.points,
                                               o, nullptr, {}, &d.on_skies, &d.quadrants);
  return d;
}

/// The annual product's sub-patch correction (study/sub_patch_shares.h) of row s at column t
/// of `m` (its quadrant deltas), lux: 179 sum_p sum_q Q_pq d_pq(t).
double sub_patch_lux(const DirectPart& d, std::size_t sources, std::size_t s, const sky::SkyMatrix& m,
                     std::size_t t) {
  double sum = 0;
  for (std::size_t p = 1; p < sources; ++p) {
    const float* q = d.quadrants.data() + (s * sources + p) * engine::StoredQuadrants;
    const double q3 = engine::luminance_of(d.coefficients[s * sources + p]) - q[0] - q[1] - q[2];
    for (std::size_t k = 0; k < 3; ++k) sum += double(q[k]) * m.quadrant_deltas.at(4 * p + k, t, 0);
    sum += q3 * m.quadrant_deltas.at(4 * p + 3, t, 0);
  }
  return RadianceWhiteEfficacy_lm_per_W * sum;
}

double continuous_lux(const DirectPart& d, std::size_t s, std::size_t k) {
  return RadianceWhiteEfficacy_lm_per_W * engine::luminance_of(d.on_skies.irradiance[s * d.on_skies.skies + k]);
}

/// A sky patch's tangent frame at its centre: u horizontal (east of north for the zenith cap),
/// v toward the zenith (north for the cap).
struct PatchFrame {
  Vec3 centre, u, v;
};

std::vector<PatchFrame> patch_frames(const sky::PatchBasis& basis) {
  std::vector<PatchFrame> frames(std::size_t(basis.bin_count()));
  for (int p = 1; p < basis.bin_count(); ++p) {
    PatchFrame& f = frames[std::size_t(p)];
    f.centre = basis.centre(p);
    if (f.centre.z > 0.999) {
      f.u = {1, 0, 0};
      f.v = {0, 1, 0};
    } else {
      f.u = normalize(cross(Vec3{0, 0, 1}, f.centre));
      f.v = cross(f.centre, f.u);
    }
  }
  return frames;
}

/// Two "skies" per sky patch p whose direct irradiance gives the fix candidates' moments from
/// the same samples (the values are grey, so the three channels carry three functions):
/// [2p - 2] = (u, v, 1) inside p: the patch's first moments about its centre and its
/// coefficient; [2p - 1] = the indicators of three of its quadrants (u < 0 or >= 0, v < 0 or
/// >= 0; the fourth is the coefficient less the three).
std::vector<engine::ContinuousSky> moment_skies(std::shared_ptr<const sky::PatchBasis> basis,
                                                std::shared_ptr<const std::vector<PatchFrame>> frames) {
  std::vector<engine::ContinuousSky> skies;
  for (int p = 1; p < basis->bin_count(); ++p) {
    engine::ContinuousSky a, b;
    a.key = "moments " + std::to_string(p);
    b.key = "quadrants " + std::to_string(p);
    a.radiance_rgb = [basis, frames, p](const Vec3& w) {
      if (basis->find_bin(w) != p) return Vec3{};
      const PatchFrame& f = (*frames)[std::size_t(p)];
      return Vec3{dot(w, f.u), dot(w, f.v), 1.0};
    };
    b.radiance_rgb = [basis, frames, p](const Vec3& w) {
      if (basis->find_bin(w) != p) return Vec3{};
      const PatchFrame& f = (*frames)[std::size_t(p)];
      const bool right = dot(w, f.u) >= 0, up = dot(w, f.v) >= 0;
      return Vec3{!right && !up ? 1.0 : 0.0, right && !up ? 1.0 : 0.0, !right && up ? 1.0 : 0.0};
    };
    skies.push_back(std::move(a));
    skies.push_back(std::move(b));
  }
  return skies;
}

/// Per hour, what the fix candidates need of the continuous sky (grey radiance, W/(sr m^2),
/// without the sky colour): each patch's centre value and tangent gradient, and its quadrants'
/// means.
struct PatchSky {
  std::vector<double> centre, grad_u, grad_v;
  std::vector<std::array<double, 4>> quadrant;
};

/// Tangent step of the central differences (rad): a quarter of a Tregenza row.
constexpr double GradientStep_rad = 0.05;
/// Midpoints per axis of a patch for its quadrants' means.
constexpr int QuadrantSamplesPerAxis = 8;

PatchSky patch_sky(const sky::SkyModel& model, const sky::PatchBasis& basis, const std::vector<PatchFrame>& frames) {
  const std::size_t n = std::size_t(basis.bin_count());
  PatchSky ps{std::vector<double>(n), std::vector<double>(n), std::vector<double>(n),
              std::vector<std::array<double, 4>>(n)};
  const double h = GradientStep_rad, t = h / std::sqrt(1 + h * h);  // the offset point's tangent coordinate
  auto L = [&](const Vec3& w) { return model.radiance_rgb(w).y; };
  for (std::size_t p = 1; p < n; ++p) {
    const PatchFrame& f = frames[p];
    ps.centre[p] = L(f.centre);
    ps.grad_u[p] = (L(normalize(f.centre + f.u * h)) - L(normalize(f.centre - f.u * h))) / (2 * t);
    ps.grad_v[p] = (L(normalize(f.centre + f.v * h)) - L(normalize(f.centre - f.v * h))) / (2 * t);
    std::array<double, 4> sum{}, count{};
    const int k = QuadrantSamplesPerAxis;
    for (int i = 0; i < k; ++i)
      for (int j = 0; j < k; ++j) {
        const Vec3 w = basis.sample_direction(int(p), (i + 0.5) / k, (j + 0.5) / k);
        const bool right = dot(w, f.u) >= 0, up = dot(w, f.v) >= 0;
        const std::size_t q = std::size_t(right) + 2 * std::size_t(up);
        sum[q] += L(w);
        count[q] += 1;
      }
    for (std::size_t q = 0; q < 4; ++q) ps.quadrant[p][q] = count[q] > 0 ? sum[q] / count[q] : ps.centre[p];
  }
  return ps;
}

/// The estimators compared with the continuous sky's direct part.
enum Estimator { StudyCentre, PatchMean, ContinuousCentre, FirstOrder, Quadrants, Shipped, EstimatorCount };
const char* estimator_name(int e) {
  static const char* names[] = {"centre vector (patch-uniform)", "mean vector", "centre, continuous normalisation",
                                "first order: centre + gradient", "2 x 2 sub-patch means (scored)",
                                "the study: centre + sub-patch"};
  return names[e];
}

void hours_mode(const std::vector<Climate>& climates, int per_class, const fs::path& folder) {
  const char* class_names[3] = {"overcast", "intermediate", "clear"};
  const int bins[3][2] = {{1, 1}, {2, 5}, {6, 8}};
  const auto basis = std::make_shared<const sky::PatchBasis>(sky::PatchBasis::tregenza());
  const auto frames = std::make_shared<const std::vector<PatchFrame>>(patch_frames(*basis));
  const Vec3 colour = sky::SkyMatrixOptions::gendaymtx_compatible().sky_colour;
  const double colour_luminance = engine::luminance_of(colour);
  std::printf("hours: %d per class and weather file; relative errors in %% (basis - continuous), RMS per sky "
              "class, then mean, RMS and worst over all hours\n",
              per_class);
  {
    // What the candidates' moments cost: the work plane's direct part alone, with the 145 x 2
    // moment skies, and with one continuous sky per hour (the project's 16 rays per bin).
    const Room room = make_room(climates.at(0).proj, false);
    const SensorGrid& g = room.grids.at(0);
    std::vector<engine::ContinuousSky> perez;
    for (std::size_t t : pick_hours(climates.at(0), 1, 8, 3 * per_class))
      perez.push_back(continuous_sky(climates.at(0), t));
    const int samples = climates.at(0).proj.simulation.direct_samples_per_bin;
    const std::uint64_t seed = std::uint64_t(climates.at(0).proj.simulation.seed);
    double cpu[3];
    const std::vector<engine::ContinuousSky> none, moments = moment_skies(basis, frames);
    const std::vector<engine::ContinuousSky>* sets[3] = {&none, &moments, &perez};
    for (int k = 0; k < 3; ++k) {
      const double c0 = bench::process_cpu_seconds();
      direct_part(room, g, *sets[k], samples, seed);
      cpu[k] = bench::process_cpu_seconds() - c0;
    }
    std::printf("cost, %s (%zu sensors, %d rays per bin): direct part %.2f CPU s; with the moment skies %.2f; with "
                "%zu continuous skies %.2f\n",
                g.name.c_str(), g.points.size(), samples, cpu[0], cpu[1], perez.size(), cpu[2]);
  }
  for (const bool black : {false, true}) {
    const Room room = make_room(climates.at(0).proj, black);
    // [class label] -> [estimator, then the patch-uniform and the study's share of the run's
    // total] -> [sky class, 3 = all]
    std::map<std::string, std::array<std::array<ErrorStats, 4>, EstimatorCount + 2>> stats;
    std::vector<std::string> order;
    for (const Climate& c : climates) {
      std::vector<std::size_t> hours;
      std::vector<int> class_of;
      for (int k = 0; k < 3; ++k)
        for (std::size_t t : pick_hours(c, bins[k][0], bins[k][1], per_class)) {
          hours.push_back(t);
          class_of.push_back(k);
        }
      std::vector<engine::ContinuousSky> skies;
      std::vector<PatchSky> patch_skies;
      for (std::size_t t : hours) {
        skies.push_back(continuous_sky(c, t));
        patch_skies.push_back(patch_sky(*sky::make_perez_sky(perez_inputs(c, t)).sky, *basis, *frames));
      }
      for (engine::ContinuousSky& m : moment_skies(basis, frames)) skies.push_back(std::move(m));
      const std::map<std::string, metrics::IlluminanceTable> totals =
          black ? std::map<std::string, metrics::IlluminanceTable>{} : annual_run(c, folder);
      if (!black) {
        std::printf("  %s hours (month/day hour, Perez bin, sun altitude deg, diffuse W/m2):", c.name.c_str());
        for (std::size_t i = 0; i < hours.size(); ++i) {
          const std::size_t t = hours[i];
          std::printf("%s %d/%d %.1f b%d %.0f %.0f", i % 6 == 0 ? "\n   " : "", c.steps[t].month, c.steps[t].day,
                      c.steps[t].hour_lst, sky::perez_state(perez_inputs(c, t)).bin,
                      std::asin(c.sun[t]->z) * 180.0 / Pi, c.epw.records[t].diffuse_horizontal_w_m2.value_or(0.0));
        }
        double worst = 0;
        for (std::size_t t : hours) worst = std::max(worst, centre_vector_difference(c, t));
        std::printf("\n  the continuous skies' patch-centre vectors against the study's matrix: at most %.1e "
                    "relative\n",
                    worst);
      }
      for (const SensorGrid& g : room.grids) {
        const DirectPart d = direct_part(room, g, skies, 64, std::uint64_t(c.proj.simulation.seed));
        const std::size_t sources = d.coefficients.size() / g.points.size();
        const std::size_t first_moment = hours.size();
        for (const auto& [label, members] : sensor_classes(g)) {
          if (std::find(order.begin(), order.end(), label) == order.end()) order.push_back(label);
          for (std::size_t i = 0; i < hours.size(); ++i) {
            const std::size_t t = hours[i];
            const PatchSky& ps = patch_skies[i];
            for (std::size_t s : members) {
              const double cont = continuous_lux(d, s, i);
              if (!(cont > 0)) continue;
              double e[EstimatorCount];
              e[StudyCentre] = basis_lux(d.coefficients, sources, s, c.centre.matrix, t);
              e[PatchMean] = basis_lux(d.coefficients, sources, s, c.mean.matrix, t);
              // The ground bin is uniform: the same in every estimator.
              const double ground = RadianceWhiteEfficacy_lm_per_W *
                                        engine::luminance_of(mul(d.coefficients[s * sources],
                                                                 Vec3{c.centre.matrix.at(0, t, 0),
                                                                      c.centre.matrix.at(0, t, 1),
                                                                      c.centre.matrix.at(0, t, 2)}));
              double centre = 0, first = 0, quadrants = 0;
              for (std::size_t p = 1; p < sources; ++p) {
                const Vec3 m = d.on_skies.irradiance[s * d.on_skies.skies + first_moment + 2 * (p - 1)];
                const Vec3 q = d.on_skies.irradiance[s * d.on_skies.skies + first_moment + 2 * (p - 1) + 1];
                const Vec3 cp_rgb = d.coefficients[s * sources + p];
                if (std::fabs(cp_rgb.x - cp_rgb.y) + std::fabs(cp_rgb.z - cp_rgb.y) > 1e-9 * std::fabs(cp_rgb.y))
                  throw std::runtime_error("the moment skies need a grey direct part (a grey glazing)");
                const double cp = cp_rgb.y;
                centre += cp * ps.centre[p];
                first += cp * ps.centre[p] + m.x * ps.grad_u[p] + m.y * ps.grad_v[p];
                quadrants += q.x * ps.quadrant[p][0] + q.y * ps.quadrant[p][1] + q.z * ps.quadrant[p][2] +
                             (cp - q.x - q.y - q.z) * ps.quadrant[p][3];
              }
              const double to_lux = RadianceWhiteEfficacy_lm_per_W * colour_luminance;
              e[ContinuousCentre] = ground + to_lux * centre;
              e[FirstOrder] = ground + to_lux * first;
              e[Quadrants] = ground + to_lux * quadrants;
              e[Shipped] = e[StudyCentre] + sub_patch_lux(d, sources, s, c.centre, t);
              for (int k : {class_of[i], 3}) {
                for (int x = 0; x < EstimatorCount; ++x)
                  stats[label][std::size_t(x)][std::size_t(k)].add(100.0 * (e[x] - cont) / cont);
                if (!black) {
                  const double total = totals.at(g.name).lux(t, s);
                  if (total > 0) {
                    stats[label][EstimatorCount][std::size_t(k)].add(100.0 * (e[StudyCentre] - cont) / total);
                    stats[label][EstimatorCount + 1][std::size_t(k)].add(100.0 * (e[Shipped] - cont) / total);
                  }
                }
              }
            }
          }
        }
      }
    }
    std::printf("%s room: RMS %% per sky class (%s, %s, %s), then mean, RMS, worst of all hours\n",
                black ? "black" : "glazed (wall_sensors)", class_names[0], class_names[1], class_names[2]);
    for (const std::string& label : order)
      for (int x = 0; x <= EstimatorCount + 1; ++x) {
        if (black && x >= EstimatorCount) continue;
        const auto& st = stats[label][std::size_t(x)];
        char rms[64];
        std::snprintf(rms, sizeof rms, "%6.2f %6.2f %6.2f", st[0].rms(), st[1].rms(), st[2].rms());
        std::printf("  %-16s %-34s %s | %s\n", label.c_str(),
                    x == EstimatorCount       ? "patch-uniform, share of the total"
                    : x == EstimatorCount + 1 ? "the study, share of the total"
                                              : estimator_name(x),
                    rms,
                    text(st[3]).c_str());
      }
  }
}

void year_mode(const std::vector<Climate>& climates, int samples, const fs::path& folder) {
  std::printf("year: every occupied daytime hour, %d shadow rays per bin\n", samples);
  const Room room = make_room(climates.at(0).proj, false);
  for (const Climate& c : climates) {
    const std::map<std::string, metrics::IlluminanceTable> totals = annual_run(c, folder);
    for (const SensorGrid& g : room.grids) {
      const study::AnnualStudySettings settings =
          study::annual_settings_of(c.proj, &c.epw, metrics::MetricSettings::Openings::VerticalOrInclined, g.name);
      const metrics::IlluminanceTable& before = totals.at(g.name);
      const metrics::OccupancySchedule occupied = study::occupancy_schedule(settings, before.steps());
      std::vector<std::size_t> hours;
      for (std::size_t t = 0; t < c.steps.size(); ++t)
        if (occupied.occupied(t) && c.sun[t] && c.epw.records[t].diffuse_horizontal_w_m2.value_or(0.0) > 0)
          hours.push_back(t);
      std::vector<engine::ContinuousSky> skies;
      for (std::size_t t : hours) skies.push_back(continuous_sky(c, t));
      const double cpu0 = bench::process_cpu_seconds();
      const DirectPart d = direct_part(room, g, skies, samples, std::uint64_t(c.proj.simulation.seed));
      const double cpu = bench::process_cpu_seconds() - cpu0;
      const std::size_t sources = d.coefficients.size() / g.points.size();
      // The run's table is the study's (patch values + the sub-patch correction); the
      // reference replaces its direct part by the continuous sky's (the same samples), and the
      // patch-uniform table takes the correction out.
      metrics::IlluminanceTable reference = before, uniform = before;
      ErrorStats error[2];  // [0] patch-uniform, [1] the study
      std::size_t over_2[2] = {}, over_5[2] = {}, worst_t[2] = {}, worst_s[2] = {};
      for (std::size_t i = 0; i < hours.size(); ++i)
        for (std::size_t s = 0; s < g.points.size(); ++s) {
          const std::size_t t = hours[i];
          const double correction = sub_patch_lux(d, sources, s, c.centre, t);
          const double run = before.lux(t, s);
          const double exact =
              run + continuous_lux(d, s, i) - basis_lux(d.coefficients, sources, s, c.centre.matrix, t) - correction;
          reference.lux(t, s) = float(std::max(0.0, exact));
          uniform.lux(t, s) = float(std::max(0.0, run - correction));
          if (!(exact > 0)) continue;
          const double value[2] = {run - correction, run};
          for (int k = 0; k < 2; ++k) {
            const double e = 100.0 * (value[k] - exact) / exact;
            if (std::fabs(e) > std::fabs(error[k].worst)) {
              worst_t[k] = t;
              worst_s[k] = s;
            }
            error[k].add(e);
            over_2[k] += std::fabs(e) > 2.0;
            over_5[k] += std::fabs(e) > 5.0;
          }
        }
      const std::vector<metrics::SensorMetrics> m_ref =
          metrics::compute_sensor_metrics(reference, occupied, settings.metrics);
      std::printf("  %-8s %-10s %4zu sensors x %4zu hours (%.0f CPU s): hourly total against the continuous sky's "
                  "direct part\n",
                  c.name.c_str(), g.name.c_str(), g.points.size(), hours.size(), cpu);
      for (int k = 0; k < 2; ++k) {
        const metrics::IlluminanceTable& table = k == 0 ? uniform : before;
        const std::vector<metrics::SensorMetrics> m0 = metrics::compute_sensor_metrics(table, occupied, settings.metrics);
        std::size_t da_flips = 0, udi_flips = 0;
        double da_shift = 0, da_worst = 0, udi_worst = 0, udi_shift = 0, mean_lux_shift = 0;
        for (std::size_t s = 0; s < m0.size(); ++s) {
          const double half = 100.0 * settings.metrics.sda_time_fraction;
          if ((m0[s].da_percent >= half) != (m_ref[s].da_percent >= half)) ++da_flips;
          if ((m0[s].udi_autonomous_percent >= half) != (m_ref[s].udi_autonomous_percent >= half)) ++udi_flips;
          const double dd = m0[s].da_percent - m_ref[s].da_percent;
          const double du = m0[s].udi_autonomous_percent - m_ref[s].udi_autonomous_percent;
          da_shift += dd;
          udi_shift += du;
          if (std::fabs(dd) > std::fabs(da_worst)) da_worst = dd;
          if (std::fabs(du) > std::fabs(udi_worst)) udi_worst = du;
          mean_lux_shift += 100.0 * (m0[s].mean_occupied_lux - m_ref[s].mean_occupied_lux) / m_ref[s].mean_occupied_lux;
        }
        const double n = double(m0.size());
        const std::size_t wt = worst_t[k], ws = worst_s[k];
        std::printf("    %-13s %s %%; off by > 2 %%: %.2f %%, > 5 %%: %.3f %% of sensor-hours; worst at %d/%d %.1f h "
                    "(sun %.1f deg up), sensor %zu: %.0f lx, reference %.0f\n"
                    "      DA300 (table - reference) mean %+.2f, worst %+.2f points, DA300 >= 50 %% verdicts moved: "
                    "%zu; UDI 300-3000 mean %+.2f, worst %+.2f points, >= 50 %% verdicts moved: %zu; mean occupied "
                    "lux %+.2f %%\n",
                    k == 0 ? "patch-uniform" : "the study", text(error[k]).c_str(),
                    100.0 * double(over_2[k]) / double(std::max<std::size_t>(1, error[k].n)),
                    100.0 * double(over_5[k]) / double(std::max<std::size_t>(1, error[k].n)), c.steps[wt].month,
                    c.steps[wt].day, c.steps[wt].hour_lst, std::asin(c.sun[wt]->z) * 180.0 / Pi, ws,
                    double(table.lux(wt, ws)), double(reference.lux(wt, ws)), da_shift / n, da_worst, da_flips,
                    udi_shift / n, udi_worst, udi_flips, mean_lux_shift / n);
      }
      std::fflush(stdout);
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  const std::string mode = argc > 1 ? argv[1] : "hours";
  const int number = argc > 2 ? std::atoi(argv[2]) : (mode == "year" ? 16 : 8);
  std::unique_ptr<tbb::global_control> limit;
  if (argc > 3 && std::atoi(argv[3]) > 0)
    limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                  std::size_t(std::atoi(argv[3])));
  if ((mode != "hours" && mode != "year") || number < 1) {
    std::fprintf(stderr, "usage: perez_sky_component_bench hours|year [N|S] [threads]\n");
    return 2;
  }
  const char* tmp = std::getenv("TMPDIR");
  const fs::path folder = fs::path(tmp && *tmp ? tmp : "/tmp") / "dayphoton_perez_sky_component_bench";
  fs::remove_all(folder);
  fs::create_directories(folder);
  const std::string source = DAYPHOTON_BENCH_SOURCE_DIR;
  project::Project proj = project::load_project(source + "/projects/wall_sensors/project.yaml");
  const auto w0 = std::chrono::steady_clock::now();
  const double c0 = bench::process_cpu_seconds();
  std::vector<Climate> climates;
  climates.push_back(make_climate("Oakland", proj, proj.weather.path));
  climates.push_back(make_climate("Mannheim", proj, source + "/tests/data/weather/DEU_Mannheim.epw"));
  std::printf("perez_sky_component_bench %s %d: projects/wall_sensors, load average %s\n", mode.c_str(), number,
              bench::load_average().c_str());
  if (mode == "hours")
    hours_mode(climates, number, folder);
  else
    year_mode(climates, number, folder);
  std::printf("%.0f s wall, %.0f s CPU, load average %s\n",
              std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count(),
              bench::process_cpu_seconds() - c0,
              bench::load_average().c_str());
  return 0;
}
