// Independent check of the office's daylight coefficients: brute-force BACKWARD Monte Carlo,
// the method of RADIANCE's rcontrib (refdata b_dc_classic), on dayphoton's own scene and
// materials but without photons, kernels or the direct component's shadow rays.
//
// From each sensor, cosine-distributed paths scatter through the room by the materials'
// sample() (all materials of the office are reciprocal: Lambertian surfaces and thin glass,
// whose straight transmission and reflection are the same both ways); a path leaving the
// scene adds pi x its throughput to the bin it escapes through (PatchBasis::find_bin,
// ground bin 0 below the horizon), i.e. irradiance per unit bin radiance, the coefficient's
// definition. Russian roulette on the throughput after the second event keeps it unbiased.
// This is the estimator of seeds/000 section 3.1 (path tracing) with no next-event estimate.
//
// Usage: office_backward_reference [paths_per_sensor=200000] [first_row=13] [last_row=14]
//                                  [our_coefficients=projects/office/results/workplane/coefficients_sky.mtx]
//                                  [write_matrix=FILE] [write_csv=FILE] [--seed S=7]
// `--seed S` may stand anywhere among the positional arguments; sensor s of the grid uses the
// random streams (seed, s, path), so another seed gives an independent estimate (two seeds'
// difference measures the reference's own noise) and the same seed the same numbers.
// Rows are the office grid's 15 rows (y = 0.5 + 0.5 r m). For the chosen rows it prints, with
// RADIANCE's CIE overcast sky vector, the mean DF of this estimate (with its standard error),
// of our photon-map coefficients, of RADIANCE's rfluxmtx matrix and of rtrace, then the
// same per 12-degree sky band, so that a difference can be placed in the sky. With all rows
// (0 14) and write_matrix, it writes its coefficients as a 165 x 146 RADIANCE matrix, which
// `dayphoton annual --coefficients` turns into annual metrics like any exported matrix
// (scripts/validate_office.py --backward FILE compares those with RADIANCE's). write_csv
// writes, per traced sensor, its DF under RADIANCE's sky vector with the standard error of
// the mean (`index,df_radiance_percent,df_radiance_se_percent`), the reference's own noise
// that a comparison with it has to allow for (scripts/office_df_error.py), then the DF of the
// same paths under four more skies (below).
//
// Continuous skies. A coefficient is per unit radiance of a UNIFORM patch; the sky's radiance
// varies within a patch, so coefficients x sky vector differ from the continuous sky's
// illuminance. The same paths therefore also score pi x throughput x the radiance of the
// continuous sky along their escape direction. Row mode scores five skies: RADIANCE's vector
// (genskyvec, as above); the sky rtrace saw (sky_overcast.rad evaluated as skybright.cal does:
// CIE overcast blended into the ground near the horizon) continuous, and its exact patch means;
// dayphoton's DF sky vector (project's ground reflectance) and that sky continuous (the sky
// module's CIE overcast luminance, the uniform ground rho E_h / pi below the horizon). A second
// table prints per row rtrace / continuous RADIANCE sky and the ratios continuous / patch means
// (the basis's error), patch means / genskyvec and continuous dayphoton / continuous RADIANCE
// sky, each with its standard error (ratios of the same paths: their errors are correlated).
// The CSV adds `df_radiance_continuous_percent,df_radiance_continuous_se_percent,
// df_radiance_patch_mean_percent,df_cie_percent,df_cie_se_percent,df_cie_continuous_percent,
// df_cie_continuous_se_percent`.
//
// Any sensors: office_backward_reference --pts FILE [--paths N=200000] [--seed S=7]
//                                        [--csv OUT] [--matrix OUT] [--project YAML] [--mf N=1]
// reads the sensors (position and normal, any normal) from a RADIANCE .pts file in the
// scene's world coordinates, traces `paths` paths from each (sensor k of the file uses the
// random streams (seed, k, path)), and prints and, with --csv, writes per sensor its daylight
// factor with the standard error of the mean, under two sky vectors: RADIANCE's overcast vector
// (refdata, as above; columns left empty without ../shared or with --mf > 1) and dayphoton's own CIE overcast
// vector with the project's ground reflectance (the sky of `dayphoton run`'s
// daylight_factor.csv), and that sky continuous (columns `df_cie_continuous_percent`,
// `df_cie_continuous_se_percent` and the standard error of continuous minus vector,
// `df_cie_continuous_minus_cie_se_percent`). --matrix writes the per-bin coefficients
// (sensors x bins, RGB, float). `--mf N` bins the paths in Reinhart MF:N patches instead of
// Tregenza's (dayphoton's vector and the continuous sky only; RADIANCE's vector is Tregenza's),
// for the basis error of a finer basis.
// The scene is projects/office/project.yaml unless --project names another project.
// Paths start at the sensor moved off its surface by the scene's ray epsilon along its
// normal (as the direct component's shadow rays), so sensors may lie on a surface.
#include <atomic>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iomanip>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <tbb/parallel_for.h>

#include "../tests/reference_data.h"
#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/units.h"
#include "dayphoton/engine/material.h"
#include "dayphoton/engine/random.h"
#include "dayphoton/engine/scene.h"
#include "dayphoton/project/project.h"
#include "dayphoton/project/pts_reader.h"
#include "dayphoton/sky/patch_basis.h"
#include "dayphoton/sky/sky_matrix.h"
#include "dayphoton/sky/sky_model.h"

using namespace dayphoton;
using Clock = std::chrono::steady_clock;

namespace {

constexpr double kPi = 3.14159265358979323846;
/// The DF skies are scaled to this horizontal illuminance (DF = E / 100 in percent).
constexpr double HorizontalLux = 10000;
/// The seed of both modes unless --seed is given (the references in tests/data/reference
/// and the figures of docs/validation.md were made with it).
constexpr std::uint64_t DefaultSeed = 7;

/// `text` as a seed (a whole number in [0, 2^64)); false for anything else.
bool parse_seed(const std::string& text, std::uint64_t& seed) {
  const char* end = text.data() + text.size();
  const auto [at, error] = std::from_chars(text.data(), end, seed);
  return error == std::errc() && at == end && !text.empty();
}

// Cosine-weighted direction about `n` from two uniforms (Malley's method).
Vec3 cosine_direction(const Vec3& n, double u1, double u2) {
  const double r = std::sqrt(u1), phi = 2 * kPi * u2;
  const Vec3 a = std::fabs(n.x) > 0.5 ? Vec3{0, 1, 0} : Vec3{1, 0, 0};
  const Vec3 t = normalize(cross(a, n));
  const Vec3 b = cross(n, t);
  return normalize(t * (r * std::cos(phi)) + b * (r * std::sin(phi)) + n * std::sqrt(1 - u1));
}

/// A project's scene as both modes trace it: the project, its scene description, the Embree
/// scene, the materials and the basis the escaping paths are binned in (Tregenza for mf 1,
/// Reinhart MF:mf otherwise).
struct Tracer {
  explicit Tracer(const std::string& project_path, int mf = 1)
      : proj(project::load_project(project_path)), description(project::build_scene_description(proj)),
        scene(engine::Scene::build(description)),
        basis(mf == 1 ? sky::PatchBasis::tregenza() : sky::PatchBasis::reinhart(mf)) {
    for (const MaterialSpec& m : description.materials) materials.push_back(engine::Material::from_spec(m));
  }
  project::Project proj;
  SceneDescription description;
  engine::Scene scene;
  sky::PatchBasis basis;
  std::vector<engine::Material> materials;
};

/// A sky as the paths see it: the RGB radiance (W/(sr m^2)) seen along an escape direction
/// (unit; below the horizon the ground). A sky vector in the basis is the step function
/// binned(); a continuous sky is its own luminance function, so that the two, scored on the
/// same paths, differ by the basis alone.
using SkyRadiance = std::function<Vec3(const Vec3& direction)>;

/// The sky vector `v` (per bin) as a step function of the escape direction.
SkyRadiance binned(const sky::PatchBasis& basis, const std::vector<Vec3>& v) {
  return [&basis, v](const Vec3& d) { return v[std::size_t(basis.find_bin(d))]; };
}

/// dayphoton's CIE overcast sky itself (sky::make_cie_overcast_sky, the sky the DF vector
/// averages over the patches) above the horizon, the uniform ground of `ground_rgb` below it.
SkyRadiance continuous(std::shared_ptr<const sky::SkyModel> sky_model, const Vec3& ground_rgb) {
  return [sky_model, ground_rgb](const Vec3& d) { return d.z > 0 ? sky_model->radiance_rgb(d) : ground_rgb; };
}

/// The sky of the rtrace reference as RADIANCE evaluates it (RADIANCE src/gen/skybright.cal,
/// CIE overcast case A1 = 2): L(Dz) = (a S + b G) / (a + b) with a = (Dz + 1.01)^10,
/// b = (Dz + 1.01)^-10, S = A2 (1 + 2 Dz) / 3 (Moon & Spencer's overcast formula, evaluated at
/// any Dz) and G = A3, the zenith and ground brightnesses gensky wrote into the sky file (as
/// rounded there). Near the horizon it blends into the ground (below the CIE sky above, above
/// the ground below). Grey; RADIANCE units (luminance / 179).
struct RadianceOvercast {
  double zenith = 0, ground = 0;
  double operator()(double dz) const {
    const double a = std::pow(dz + 1.01, 10), b = 1 / a;
    return (a * zenith * (1 + 2 * dz) / 3 + b * ground) / (a + b);
  }
};

/// A2 and A3 of `skyfunc` in a gensky -c sky file (`void brightfunc skyfunc / 2 skybr
/// skybright.cal / 0 / 3 A1 A2 A3`); throws if the file has no overcast skyfunc.
RadianceOvercast read_radiance_overcast(const std::string& path) {
  std::ifstream in(path);
  std::string token;
  while (in >> token && token != "skybright.cal") {
  }
  int zero = -1, count = 0, type = 0;
  RadianceOvercast sky;
  if (!(in >> zero >> count >> type >> sky.zenith >> sky.ground) || zero != 0 || count != 3 || type != 2)
    throw std::runtime_error(path + ": no CIE overcast skyfunc (skybright.cal 0 / 3 2 A2 A3)");
  return sky;
}

/// Per-bin mean of RADIANCE's overcast sky (the basis's exact value of that sky: patch means by
/// a 64 x 64 midpoint rule in solid angle; the ground bin's mean over the lower hemisphere, where
/// Dz is uniform in solid angle, by 100 000 midpoints), for the basis error of the same sky.
std::vector<Vec3> radiance_overcast_means(const RadianceOvercast& sky, const sky::PatchBasis& basis) {
  std::vector<Vec3> v(std::size_t(basis.bin_count()));
  constexpr int n = 64, ground_n = 100000;
  double ground = 0;
  for (int i = 0; i < ground_n; ++i) ground += sky(-(i + 0.5) / ground_n);
  v[0] = Vec3{1, 1, 1} * (ground / ground_n);
  for (int bin = 1; bin < basis.bin_count(); ++bin) {
    double sum = 0;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) sum += sky(basis.sample_direction(bin, (i + 0.5) / n, (j + 0.5) / n).z);
    v[std::size_t(bin)] = Vec3{1, 1, 1} * (sum / (n * n));
  }
  return v;
}

/// The backward estimate of one sensor: per-bin sums of pi x throughput (`coeff`, `bins`
/// entries) and, per sky, the sums of the illuminance estimate x_k and of x_k x_j (K x K, so
/// that the difference of two skies scored on the same paths has its own standard error).
struct SensorSums {
  std::vector<Vec3> coeff;
  std::vector<double> sum, sum_products;
  std::uint64_t rays = 0;
};

/// `paths` paths from `sensor`; path i uses the stream (seed, stream_index, i). Each path
/// scores pi x throughput x the radiance of each of `skies` along its escape direction.
SensorSums trace_sensor(const Tracer& t, const SensorPoint& sensor, std::size_t paths, std::uint64_t seed,
                        std::uint64_t stream_index, const std::vector<SkyRadiance>& skies) {
  const std::size_t bins = std::size_t(t.basis.bin_count()), k_skies = skies.size();
  SensorSums out;
  out.coeff.assign(bins, Vec3{0, 0, 0});
  out.sum.assign(k_skies, 0);
  out.sum_products.assign(k_skies * k_skies, 0);
  std::vector<double> x(k_skies);
  for (std::size_t i = 0; i < paths; ++i) {
    engine::Rng rng(seed, stream_index, i, engine::RandomStream::Scattering);
    Vec3 w{1, 1, 1};
    const Vec3 d0 = cosine_direction(sensor.normal, rng.uniform(), rng.uniform());
    engine::Ray ray{t.scene.offset_ray_origin(sensor.position, sensor.normal, d0), d0};
    bool escaped = false;
    for (int depth = 0; depth < 1000; ++depth) {
      ++out.rays;
      const std::optional<engine::Hit> hit = t.scene.intersect(ray);
      if (!hit) {
        const int escape_bin = t.basis.find_bin(ray.direction);
        out.coeff[std::size_t(escape_bin)] = out.coeff[std::size_t(escape_bin)] + w * kPi;
        escaped = true;
        break;
      }
      const auto s = t.materials[std::size_t(hit->material)].sample(ray.direction, hit->normal, rng.uniform(),
                                                                    rng.uniform(), rng.uniform());
      if (!s) break;
      w = mul(w, s->weight);
      if (depth >= 2) {  // roulette on the throughput: survive with q, divide by q
        const double q = std::min(1.0, std::max(w.x, std::max(w.y, w.z)));
        if (rng.uniform() >= q) break;
        w = w * (1 / q);
      }
      ray = engine::Ray{t.scene.offset_ray_origin(hit->position, hit->normal, s->direction), s->direction};
    }
    for (std::size_t k = 0; k < k_skies; ++k)
      x[k] = escaped ? kPi * rgb_to_photometric(mul(w, skies[k](normalize(ray.direction)))) : 0;
    for (std::size_t k = 0; k < k_skies; ++k) {
      out.sum[k] += x[k];
      for (std::size_t j = 0; j < k_skies; ++j) out.sum_products[k * k_skies + j] += x[k] * x[j];
    }
  }
  return out;
}

std::vector<Vec3> vector_rgb(const RadianceMatrix& m) {
  std::vector<Vec3> v(m.rows());
  for (std::size_t p = 0; p < m.rows(); ++p) v[p] = {m.at(p, 0, 0), m.at(p, 0, 1), m.at(p, 0, 2)};
  return v;
}

/// Mean of sky k minus `scale` x sky j's (j < 0: sky k alone) over the paths of one sensor, in
/// DF percent, and the variance of that mean (percent^2): the sample covariance of the same paths.
std::pair<double, double> df_moments(const SensorSums& s, int k, int j, double scale, std::size_t paths) {
  const std::size_t n_skies = s.sum.size(), a = std::size_t(k);
  const double n = double(paths), to_percent = 100 / HorizontalLux;
  const double mk = s.sum[a] / n;
  if (j < 0) return {mk * to_percent, std::max(0.0, s.sum_products[a * n_skies + a] / n - mk * mk) / n * to_percent * to_percent};
  const std::size_t b = std::size_t(j);
  const double mj = s.sum[b] / n;
  const double var = s.sum_products[a * n_skies + a] / n - mk * mk + scale * scale * (s.sum_products[b * n_skies + b] / n - mj * mj) -
                     2 * scale * (s.sum_products[a * n_skies + b] / n - mk * mj);
  return {(mk - scale * mj) * to_percent, std::max(0.0, var) / n * to_percent * to_percent};
}

/// Mean and standard error of the mean of a sensor's DF (percent) under sky k.
std::pair<double, double> df_percent(const SensorSums& s, std::size_t k, std::size_t paths) {
  const auto [mean, var] = df_moments(s, int(k), -1, 0, paths);
  return {mean, std::sqrt(var)};
}

std::string fixed(double v, int decimals) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(decimals) << v;
  return s.str();
}

/// --pts mode (see the header comment). Returns the exit code.
int run_pts(int argc, char** argv, const std::string& source_dir, const std::string& shared) {
  std::string pts_path, csv_path, matrix_path, project_path = source_dir + "/projects/office/project.yaml";
  std::size_t paths = 200000;
  std::uint64_t seed = DefaultSeed;
  int mf = 1;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool has_value = i + 1 < argc;
    if (a == "--pts" && has_value) pts_path = argv[++i];
    else if (a == "--paths" && has_value) paths = std::stoul(argv[++i]);
    else if (a == "--seed" && has_value) {
      if (!parse_seed(argv[++i], seed)) {
        std::fprintf(stderr, "office_backward_reference: --seed takes a whole number >= 0, not '%s'\n", argv[i]);
        return 2;
      }
    } else if (a == "--csv" && has_value) csv_path = argv[++i];
    else if (a == "--matrix" && has_value) matrix_path = argv[++i];
    else if (a == "--project" && has_value) project_path = argv[++i];
    else if (a == "--mf" && has_value) mf = std::stoi(argv[++i]);
    else {
      std::fprintf(stderr, "office_backward_reference: unknown or incomplete option '%s'\n", a.c_str());
      return 2;
    }
  }
  if (pts_path.empty() || paths == 0 || mf < 1) {
    std::fprintf(stderr, "office_backward_reference: --pts FILE, --paths N > 0 and --mf N >= 1 are needed\n");
    return 2;
  }
  Diagnostics diag;
  const std::vector<SensorPoint> sensors = project::read_pts(pts_path, diag);
  if (diag.has_errors() || sensors.empty()) {
    std::fprintf(stderr, "%s", diag.has_errors() ? diag.format().c_str() : (pts_path + ": no sensors\n").c_str());
    return 1;
  }
  const Tracer tracer(project_path, mf);
  const sky::PatchBasis& basis = tracer.basis;
  const std::size_t bins = std::size_t(basis.bin_count());

  // Sky 0: dayphoton's CIE overcast vector with the project's ground (as `dayphoton run`'s
  // daylight factor); sky 1: RADIANCE's (gensky -c -B 55.866 -g 0.2 | genskyvec -m 1), if present.
  const double rho = tracer.proj.simulation.ground_reflectance;
  // Sky 1: the same sky continuous (the CIE overcast luminance at the escape direction, the
  // same uniform ground below the horizon), so that sky 1 - sky 0 is the basis's error.
  const std::shared_ptr<const sky::SkyModel> overcast =
      sky::make_cie_overcast_sky(sky::SkyScale::horizontal_illuminance_lux(HorizontalLux));
  const Vec3 ground = sky::ground_radiance_rgb({rho, rho, rho}, HorizontalLux, 0, {0, 0, -1});
  std::vector<SkyRadiance> skies{binned(basis, vector_rgb(sky::sky_vector(*overcast, basis, ground))),
                                 continuous(overcast, ground)};
  const std::string radiance_vector = shared + "/refdata/results/a_daylight_factor/skyvec_overcast_m1.vec";
  const bool have_radiance = mf == 1 && std::ifstream(radiance_vector).good();  // a Tregenza vector
  if (have_radiance) skies.push_back(binned(basis, vector_rgb(RadianceMatrix::read_file(radiance_vector))));

  std::vector<SensorSums> sums(sensors.size());
  const auto t0 = Clock::now();
  tbb::parallel_for(std::size_t(0), sensors.size(), [&](std::size_t k) {
    sums[k] = trace_sensor(tracer, sensors[k], paths, seed, k, skies);
  });
  const double seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  std::uint64_t rays = 0;
  for (const SensorSums& s : sums) rays += s.rays;

  std::printf("backward reference: %s, %zu sensors from %s, %zu paths per sensor, seed %llu, %.1f s, %.3g rays/s\n",
              project_path.c_str(), sensors.size(), pts_path.c_str(), paths, static_cast<unsigned long long>(seed),
              seconds, double(rays) / seconds);
  std::printf("index      x       y       z      nx      ny      nz   DF cie %%  (+-se)     DF radiance %% (+-se)"
              "   continuous cie / cie (+-se)\n");
  double worst_relative_se = 0, sum_relative_se2 = 0;
  std::ostringstream csv;
  csv << "index,x,y,z,nx,ny,nz,df_cie_percent,df_cie_se_percent,df_radiance_percent,df_radiance_se_percent,"
         "df_cie_continuous_percent,df_cie_continuous_se_percent,df_cie_continuous_minus_cie_se_percent\n";
  csv << std::setprecision(17);
  for (std::size_t k = 0; k < sensors.size(); ++k) {
    const SensorPoint& sp = sensors[k];
    const auto [cie, cie_se] = df_percent(sums[k], 0, paths);
    const auto [cont, cont_se] = df_percent(sums[k], 1, paths);
    const double difference_se = std::sqrt(df_moments(sums[k], 1, 0, 1, paths).second);
    std::optional<std::pair<double, double>> rad;
    if (have_radiance) rad = df_percent(sums[k], 2, paths);
    const double relative = cie > 0 ? cie_se / cie : 0;
    worst_relative_se = std::max(worst_relative_se, relative);
    sum_relative_se2 += relative * relative;
    std::printf("%5zu %7.3f %7.3f %7.3f %7.3f %7.3f %7.3f  %8.4f (+-%.4f)   %s   %s\n", k, sp.position.x,
                sp.position.y, sp.position.z, sp.normal.x, sp.normal.y, sp.normal.z, cie, cie_se,
                rad ? (fixed(rad->first, 4) + " (+-" + fixed(rad->second, 4) + ")").c_str() : "-",
                cie > 0 ? (fixed(cont / cie, 4) + " (+-" + fixed(difference_se / cie, 4) + ")").c_str() : "-");
    csv << k << ',' << sp.position.x << ',' << sp.position.y << ',' << sp.position.z << ',' << sp.normal.x << ','
        << sp.normal.y << ',' << sp.normal.z << ',' << std::setprecision(6) << cie << ',' << cie_se << ',';
    if (rad) csv << rad->first << ',' << rad->second;
    else csv << ',';
    csv << ',' << cont << ',' << cont_se << ',' << difference_se << std::setprecision(17) << '\n';
  }
  std::printf("relative standard error of the DF (cie): RMS over sensors %.3f %%, largest %.3f %%\n",
              100 * std::sqrt(sum_relative_se2 / double(sensors.size())), 100 * worst_relative_se);
  if (!csv_path.empty()) {
    std::ofstream out(csv_path, std::ios::binary);
    out << csv.str();
    if (!out) {
      std::fprintf(stderr, "office_backward_reference: cannot write %s\n", csv_path.c_str());
      return 1;
    }
  }
  if (!matrix_path.empty()) {
    RadianceMatrix out(sensors.size(), bins, 3);
    for (std::size_t k = 0; k < sensors.size(); ++k)
      for (std::size_t p = 0; p < bins; ++p)
        for (int c = 0; c < 3; ++c) out.at(k, p, c) = float(sums[k].coeff[p][c] / double(paths));
    out.header_lines().push_back("office_backward_reference --pts " + pts_path + " --paths " + std::to_string(paths) +
                                 " --seed " + std::to_string(seed) + " --mf " + std::to_string(mf));
    out.write_file(matrix_path, MatrixFormat::Float);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string source_dir = DAYPHOTON_BENCH_SOURCE_DIR;
  const std::string shared = source_dir + "/../shared";
  for (int i = 1; i < argc; ++i)
    if (std::string(argv[i]) == "--pts") return run_pts(argc, argv, source_dir, shared);

  // Row mode: positional arguments, and --seed S anywhere among them.
  std::uint64_t seed = DefaultSeed;
  std::vector<std::string> args;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a != "--seed") {
      args.push_back(a);
      continue;
    }
    if (i + 1 >= argc || !parse_seed(argv[++i], seed)) {
      std::fprintf(stderr, "office_backward_reference: --seed takes a whole number >= 0\n");
      return 2;
    }
  }
  const std::size_t paths = args.size() > 0 ? std::stoul(args[0]) : 200000;
  const int first_row = args.size() > 1 ? std::stoi(args[1]) : 13;
  const int last_row = args.size() > 2 ? std::stoi(args[2]) : 14;
  const std::string ours_path =
      args.size() > 3 ? args[3] : source_dir + "/projects/office/results/workplane/coefficients_sky.mtx";
  const std::string write_path = args.size() > 4 ? args[4] : "";
  const std::string csv_path = args.size() > 5 ? args[5] : "";

  const Tracer tracer(source_dir + "/projects/office/project.yaml");
  const sky::PatchBasis& basis = tracer.basis;
  const std::size_t bins = std::size_t(basis.bin_count());
  const SensorGrid& grid = tracer.description.grids.at(0);
  const std::size_t columns = 11;  // the office grid: 11 sensors per row, 15 rows

  std::vector<std::size_t> sensors;
  for (int r = first_row; r <= last_row; ++r)
    for (std::size_t c = 0; c < columns; ++c) sensors.push_back(std::size_t(r) * columns + c);

  // Sky 0: RADIANCE's overcast sky vector (gensky -c -B 55.866 -g 0.2 | genskyvec -m 1).
  // Sky 1: the sky rtrace saw (sky_overcast.rad through skybright.cal), continuous; sky 2: its
  // exact patch means. Sky 3: dayphoton's DF sky vector (SimulationPlan::daylight_factor_sky,
  // the project's ground reflectance); sky 4: that sky continuous (CIE overcast, uniform ground).
  const std::string refdata = shared + "/refdata/results/a_daylight_factor";
  const RadianceMatrix sv = RadianceMatrix::read_file(refdata + "/skyvec_overcast_m1.vec");
  const std::vector<Vec3> sky_rgb = vector_rgb(sv);
  const RadianceOvercast radiance_sky = read_radiance_overcast(refdata + "/sky_overcast.rad");
  const double rho = tracer.proj.simulation.ground_reflectance;
  const std::shared_ptr<const sky::SkyModel> overcast =
      sky::make_cie_overcast_sky(sky::SkyScale::horizontal_illuminance_lux(HorizontalLux));
  const Vec3 ground = sky::ground_radiance_rgb({rho, rho, rho}, HorizontalLux, 0, {0, 0, -1});
  const std::vector<SkyRadiance> skies{
      binned(basis, sky_rgb),
      [radiance_sky](const Vec3& d) { return Vec3{1, 1, 1} * radiance_sky(d.z); },
      binned(basis, radiance_overcast_means(radiance_sky, basis)),
      binned(basis, vector_rgb(sky::sky_vector(*overcast, basis, ground))),
      continuous(overcast, ground)};

  // Per sensor: per-bin sums of pi x throughput, and the DF estimate's first two moments.
  std::vector<SensorSums> sums(sensors.size());
  const auto t0 = Clock::now();
  tbb::parallel_for(std::size_t(0), sensors.size(), [&](std::size_t k) {
    sums[k] = trace_sensor(tracer, grid.points[sensors[k]], paths, seed, sensors[k], skies);
  });
  const double seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  std::uint64_t rays = 0;
  for (const SensorSums& s : sums) rays += s.rays;
  std::vector<Vec3> coeff(sensors.size() * bins);
  for (std::size_t k = 0; k < sensors.size(); ++k)
    for (std::size_t p = 0; p < bins; ++p) coeff[k * bins + p] = sums[k].coeff[p];

  if (!write_path.empty()) {
    RadianceMatrix out(grid.points.size(), bins, 3);
    for (std::size_t k = 0; k < sensors.size(); ++k)
      for (std::size_t p = 0; p < bins; ++p)
        for (int c = 0; c < 3; ++c)
          out.at(sensors[k], p, c) = float(coeff[k * bins + p][c] / double(paths));
    out.header_lines().push_back("office_backward_reference " + std::to_string(paths) + " paths per sensor, rows " +
                                 std::to_string(first_row) + "-" + std::to_string(last_row) + ", seed " +
                                 std::to_string(seed));
    out.write_file(write_path, MatrixFormat::Float);
  }
  if (!csv_path.empty()) {
    std::ofstream out(csv_path, std::ios::binary);
    out << "index,df_radiance_percent,df_radiance_se_percent,df_radiance_continuous_percent,"
           "df_radiance_continuous_se_percent,df_radiance_patch_mean_percent,df_cie_percent,df_cie_se_percent,"
           "df_cie_continuous_percent,df_cie_continuous_se_percent\n"
        << std::setprecision(6);
    for (std::size_t k = 0; k < sensors.size(); ++k) {
      out << sensors[k];
      for (std::size_t sky = 0; sky < skies.size(); ++sky) {
        const auto [df, se] = df_percent(sums[k], sky, paths);
        out << ',' << df;
        if (sky != 2) out << ',' << se;
      }
      out << '\n';
    }
    if (!out) {
      std::fprintf(stderr, "office_backward_reference: cannot write %s\n", csv_path.c_str());
      return 1;
    }
  }
  const std::vector<double> ref = test::read_reference_df(shared + "/refdata/results/a_daylight_factor/df_office.csv");
  const RadianceMatrix dc = test::read_gzip_matrix(shared + "/refdata/results/b_dc_classic/office_dc_classic.mtx.gz");
  const RadianceMatrix dc2 = test::read_gzip_matrix(shared + "/refdata/results/b_dc_classic/office_dc_classic_ad131k.mtx.gz");
  const RadianceMatrix ours = RadianceMatrix::read_file(ours_path);
  auto matrix_df = [&](const RadianceMatrix& m, std::size_t s, std::size_t p0, std::size_t p1) {
    double e = 0;
    for (std::size_t p = p0; p < p1; ++p)
      e += rgb_to_photometric(mul(Vec3{m.at(s, p, 0), m.at(s, p, 1), m.at(s, p, 2)}, sky_rgb[p]));
    return e / 10000 * 100;  // the vector is for 10 000 lux horizontal: DF in %
  };

  std::printf("office backward reference: %zu paths per sensor, rows %d-%d (%zu sensors), seed %llu, %.1f s, %.3g rays/s\n",
              paths, first_row, last_row, sensors.size(), static_cast<unsigned long long>(seed), seconds,
              double(rays) / seconds);
  std::printf("row  y(m)   backward DF %% (+-1 se)   ours/bw   rfluxmtx65k/bw  rfluxmtx131k/bw  rtrace/bw\n");
  for (int r = first_row; r <= last_row; ++r) {
    double bw = 0, var = 0, o = 0, a = 0, a2 = 0, rt = 0;
    for (std::size_t k = 0; k < sensors.size(); ++k) {
      if (sensors[k] / columns != std::size_t(r)) continue;
      const std::size_t s = sensors[k];
      const auto [df, se] = df_percent(sums[k], 0, paths);
      bw += df;
      var += se * se;
      o += matrix_df(ours, s, 0, bins);
      a += matrix_df(dc, s, 0, bins);
      a2 += matrix_df(dc2, s, 0, bins);
      rt += ref[s];
    }
    std::printf("%3d  %4.1f   %8.4f (+-%.4f)     %.4f    %.4f          %.4f           %.4f\n", r,
                0.5 + 0.5 * r, bw / double(columns), std::sqrt(var) / double(columns), o / bw, a / bw, a2 / bw,
                rt / bw);
  }
  // The continuous skies: ratios of row sums over the same paths, each with the standard error of
  // the reference's own noise (of a ratio A/B of sums over the same paths: SE(A - (A/B) B) / B).
  std::printf("row   rtrace/cont.rad (+-se)   cont.rad/means.rad (+-se)   means.rad/genskyvec (+-se)   "
              "cont.cie/cie vector (+-se)   cont.cie/cont.rad (+-se)\n");
  auto row_ratio = [&](int r, int a, int b) {
    double sa = 0, sb = 0;
    for (std::size_t k = 0; k < sensors.size(); ++k)
      if (sensors[k] / columns == std::size_t(r)) {
        sa += df_percent(sums[k], std::size_t(a), paths).first;
        sb += df_percent(sums[k], std::size_t(b), paths).first;
      }
    double var = 0;
    for (std::size_t k = 0; k < sensors.size(); ++k)
      if (sensors[k] / columns == std::size_t(r)) var += df_moments(sums[k], a, b, sa / sb, paths).second;
    return fixed(sa / sb, 4) + " (+-" + fixed(std::sqrt(var) / sb, 4) + ")";
  };
  for (int r = first_row; r <= last_row; ++r) {
    double cont = 0, var = 0, rt = 0;
    for (std::size_t k = 0; k < sensors.size(); ++k)
      if (sensors[k] / columns == std::size_t(r)) {
        const auto [df, se] = df_percent(sums[k], 1, paths);
        cont += df;
        var += se * se;
        rt += ref[sensors[k]];
      }
    std::printf("%3d   %s        %s           %s            %s           %s\n", r,
                (fixed(rt / cont, 4) + " (+-" + fixed(rt / cont * std::sqrt(var) / cont, 4) + ")").c_str(),
                row_ratio(r, 1, 2).c_str(), row_ratio(r, 2, 0).c_str(), row_ratio(r, 4, 3).c_str(),
                row_ratio(r, 4, 1).c_str());
  }
  // Per 12-degree band (ground, rows 0..6 of the sky, zenith cap), all chosen sensors.
  std::printf("band     share of bw   ours/bw   rfluxmtx65k/bw  rfluxmtx131k/bw\n");
  std::vector<std::pair<std::size_t, std::size_t>> bands{{0, 1}};
  std::size_t next = 1;
  for (int r = 0; r < basis.row_count(); ++r) {
    bands.push_back({next, next + std::size_t(basis.row(r).patch_count)});
    next += std::size_t(basis.row(r).patch_count);
  }
  double total = 0;
  for (std::size_t k = 0; k < sensors.size(); ++k)
    for (std::size_t p = 0; p < bins; ++p) total += rgb_to_photometric(mul(coeff[k * bins + p], sky_rgb[p])) / double(paths);
  for (std::size_t b = 0; b < bands.size(); ++b) {
    double bw = 0, o = 0, a = 0, a2 = 0;
    for (std::size_t k = 0; k < sensors.size(); ++k) {
      for (std::size_t p = bands[b].first; p < bands[b].second; ++p)
        bw += rgb_to_photometric(mul(coeff[k * bins + p], sky_rgb[p])) / double(paths);
      o += matrix_df(ours, sensors[k], bands[b].first, bands[b].second);
      a += matrix_df(dc, sensors[k], bands[b].first, bands[b].second);
      a2 += matrix_df(dc2, sensors[k], bands[b].first, bands[b].second);
    }
    bw /= 100;  // DF %
    const std::string name = b == 0 ? "ground" : "sky row " + std::to_string(b - 1);
    std::printf("%-9s  %6.1f %%     %.4f    %.4f          %.4f\n", name.c_str(), 100 * bw * 100 / total, o / bw,
                a / bw, a2 / bw);
  }
  return 0;
}
