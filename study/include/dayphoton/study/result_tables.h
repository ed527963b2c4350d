// Reading the per-grid result tables back (daylight_factor.csv, metrics.csv; docs/outputs.md)
// so that the report and the images are made from the files on disk alone: `dayphoton report
// RESULTS_DIR` needs nothing but the output folder.
#pragma once

#include <string>
#include <vector>

namespace dayphoton::study {

/// A per-sensor CSV table: one header row starting index,x,y,z, then numeric rows.
struct SensorTable {
  std::string path;
  std::vector<std::string> columns;         ///< header names, in order
  std::vector<std::vector<double>> rows;    ///< one per sensor, one value per column

  /// Position of a column; -1 if absent.
  int column(const std::string& name) const;
  /// All values of a column (throws std::out_of_range naming the file if absent).
  std::vector<double> values(const std::string& name) const;
};

/// Read a per-sensor table. Throws InputError located file:line:field on a missing file, a
/// header not starting with index,x,y,z, a row with the wrong number of fields, a value that
/// is not a finite number, or an index out of sequence.
SensorTable read_sensor_table(const std::string& path);

}  // namespace dayphoton::study
