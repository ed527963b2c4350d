// The dayphoton subcommands. Each is a function from parsed options to an exit code; they
// only wire the libraries together (all modelling lives in core/ weather/ sky/ project/ engine/).
#pragma once

#include "dayphoton/dist/communicator.h"
#include <cstdint>
#include <exception>
#include <iosfwd>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "dayphoton/core/resource_limits.h"
#include "dayphoton/sky/patch_basis.h"

namespace dayphoton::app {

/// Process exit codes, documented in docs/cli.md.
enum ExitCode : int {
  ExitOk = 0,
  ExitInputError = 1,      ///< a project, weather or geometry file is invalid (located messages)
  ExitUsageError = 2,      ///< bad command line
  ExitNotImplemented = 3,  ///< the requested step does not exist yet (said plainly, nothing written)
  ExitInternalError = 4,   ///< a bug or an I/O failure
  ExitOutputBusy = 5,      ///< `run`: another running dayphoton holds the output folder's lock
};

/// A command line that parses but makes no sense (bad --basis, conflicting options): exit 2.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// What the program prints for an exception a command threw, and its exit code (an input
/// error's located messages as they are, anything else after "dayphoton: error: ").
struct CommandFailure {
  int exit_code = ExitInternalError;
  std::string message;  ///< ends with a line break
};
CommandFailure describe_failure(const std::exception_ptr& failure);

/// Thrown on every rank of an MPI job once the ranks agreed that the command failed before any
/// of them wrote anything, and rank 0 printed why (agree_on_failure): the process exits with
/// `exit_code` and the job ends without MPI_Abort.
class AgreedFailure : public std::runtime_error {
 public:
  explicit AgreedFailure(int exit_code) : std::runtime_error("failure agreed on by every rank"), m_code(exit_code) {}
  int exit_code() const { return m_code; }

 private:
  int m_code;
};

/// Collective over `ranks`: each rank passes its failure (null if none). If any failed, rank 0
/// prints the failure of the lowest failing rank to `err` (prefixed by its rank if not 0) and
/// every rank throws AgreedFailure with its exit code; otherwise returns. For checks that every
/// rank makes alike before anything is written (the project files, the weather file), so that
/// their messages appear once, not once per rank.
void agree_on_failure(dist::Communicator& ranks, const std::exception_ptr& failure, std::ostream& err);

/// Flush `out` and throw if anything written to it was lost (full disk, closed pipe).
void require_written(std::ostream& out, const std::string& what);

/// The --basis option: "tregenza" or "reinhart:N" (N in 1..64); UsageError otherwise.
sky::PatchBasis parse_basis_option(const std::string& text);

/// UsageError if a matrix of bins x steps x components values (`what`, e.g. "the sky
/// matrix") would exceed --max-matrix-values; checked before the matrix is built.
void require_matrix_within_limit(const std::string& what, std::uint64_t bins, std::uint64_t steps, int components,
                                 std::uint64_t max_values);

struct CheckOptions {
  std::string project_path;
};
int run_check(const CheckOptions& options, std::ostream& out);

struct RunOptions {
  std::vector<std::string> project_paths;
  std::string output_dir;
  int threads = 0;
  std::string cache_dir;  ///< empty: beside each output folder (study/cache_folder.h)
  bool force = false;
  bool quiet = false;
  /// The ranks of an `mpirun`/`srun` job every rank of which runs this command (docs/cluster.md);
  /// null: one process. Rank 0 writes the outputs and the cache; the others compute their
  /// share of the steps and write nothing.
  dist::Communicator* ranks = nullptr;
};
int run_run(const RunOptions& options, std::ostream& out, std::ostream& err);

struct CleanOptions {
  std::string target;     ///< an output folder of `run`, or a project file (its outputs.folder)
  std::string cache_dir;  ///< empty: the output folder's (study/cache_folder.h)
  bool all = false;       ///< remove the whole cache folder
  bool dry_run = false;
};
int run_clean(const CleanOptions& options, std::ostream& out);

struct SunOptions {
  std::string weather_path;
  std::string solar_position = "spa";
  bool no_refraction = false;
  std::string output_path;  ///< empty: standard output
};
int run_sun(const SunOptions& options, std::ostream& out);

struct SkyOptions {
  std::string weather_path;       ///< EPW or .wea for an annual matrix
  std::string cie;                ///< or a CIE sky: "1".."15", "overcast", "uniform"
  double sun_altitude_deg = 45, sun_azimuth_deg = 180;  ///< for CIE general skies
  double horizontal_illuminance_lux = 10000;            ///< for CIE skies
  bool cie_options_given = false;  ///< --altitude/--azimuth/--illuminance on the command line
  std::string basis = "tregenza";
  std::string sun = "spread";
  std::string solar_position = "spa";
  double ground_reflectance = 0.2;
  std::string format = "ascii";
  std::string output_path;
  std::uint64_t max_matrix_values = ResourceLimits{}.matrix_values;
};
int run_sky(const SkyOptions& options, const std::string& command_line, std::ostream& out);

struct AnnualOptions {
  std::string coefficients_dir;  ///< grid folder of `dayphoton run` (coefficients_sky.mtx, sensors.csv)
  std::string weather_path;      ///< EPW or .wea: time stamps, and the sky unless sky_matrix_path is given
  std::string sky_matrix_path;   ///< RADIANCE matrix file (plain or .gz); empty: built from the weather file
  /// One sky (a one-column RADIANCE matrix, e.g. `dayphoton sky --cie N`): the illuminance
  /// per sensor under it instead of the annual study; no weather file needed.
  std::string sky_vector_path;
  std::string output_dir;        ///< empty: <coefficients_dir>/annual
  std::string basis;             ///< empty: from the coefficients' column count
  /// "exact" (the exported direct sun and sun bins), "spread" (sky coefficients only), or
  /// empty: exact where the grid folder has direct_sun.bin.gz and no --sky-matrix is given.
  std::string sun;
  double ground_reflectance = 0.2;     ///< used if given, else the run's (results.json), else 0.2
  bool ground_reflectance_given = false;
  bool quiet = false;
  bool illuminance_csv = false;  ///< illuminance.csv beside illuminance.bin
  std::uint64_t max_matrix_values = ResourceLimits{}.matrix_values;            ///< each matrix and the table
  std::uint64_t max_decompressed_bytes = ResourceLimits{}.decompressed_bytes;  ///< a .gz sky matrix
  /// Metric settings (thresholds, occupancy) and the default weather file from this project
  /// (default: the settings the run recorded in results.json).
  std::string project_path;
  /// Overrides of the metric settings (docs/cli.md); each unset when empty.
  std::vector<double> occupancy_hours;  ///< START END: every day, replaces the schedule
  std::string daylight_saving;          ///< none, eu, us
  std::string january_1;                ///< weekday of 1 January
  std::optional<double> da_threshold_lux, udi_lower_lux, udi_upper_original_lux, udi_upper_revised_lux,
      sda_time_fraction, ase_threshold_lux, ase_hours;
};
int run_annual(const AnnualOptions& options, std::ostream& out);

struct ReportOptions {
  std::string results_dir;   ///< output folder of `dayphoton run` (summary.json)
  std::string output_path;   ///< empty: <results_dir>/report.html
  bool no_images = false;    ///< only report.html (no grid EXR/PNG, no sky fisheyes)
  std::string sky_hour = "6/21/12.5";  ///< M/D/H of sky_hour.exr
  bool pdf = false;          ///< also print the report to a PDF beside it (report/report_pdf.h)
  double pdf_timeout_s = 120;  ///< Chromium's time limit
  bool quiet = false;
};
int run_report(const ReportOptions& options, std::ostream& out);

struct RenderOptions {
  std::string project_path;
  std::string view;            ///< "x,y,z" camera position (m)
  std::string direction;       ///< "dx,dy,dz" view direction
  std::string up = "0,0,1";    ///< "ux,uy,uz" up vector
  double fov_deg = 60;         ///< horizontal field of view (perspective) or image circle (fisheye)
  bool fisheye = false;
  int width = 512, height = 384;
  std::string sky = "overcast";  ///< overcast | uniform | cie:N | hour:M/D/H
  double sun_altitude_deg = 45, sun_azimuth_deg = 180;  ///< for cie:N with a sun
  double horizontal_illuminance_lux = 10000;            ///< for overcast, uniform, cie:N
  int samples_per_pixel = 4;
  int direct_samples = 16;
  long long photons_per_bin = 0;  ///< 0: the project's photons_per_bin
  int bandwidth = 200;
  std::string output_path;     ///< .exr; the tone-mapped PNG is written beside it (.png)
  int threads = 0;
  bool quiet = false;
};
int run_render(const RenderOptions& options, std::ostream& out);

}  // namespace dayphoton::app
