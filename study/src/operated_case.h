// The operated result of a run (operated_shading.h): per grid and hour the shaded case's
// illuminance when the open case's direct sun exceeds the rule, from the two cases' annual
// tables, into <output>/operated/<grid>/.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dayphoton/core/scene_description.h"
#include "dayphoton/metrics/illuminance_table.h"
#include "dayphoton/project/project.h"
#include "run_context.h"

namespace dayphoton::study {

/// What the operated result takes from one case (sun: bins), per grid in the case's order.
struct CaseTables {
  struct Grid {
    std::string name;
    std::vector<SensorPoint> sensors;
    std::vector<double> area_m2;  ///< SensorGrid::area_m2
    metrics::IlluminanceTable illuminance;  ///< the annual illuminance
    metrics::IlluminanceTable direct_sun;   ///< direct-sun-only, zero-bounce (ASE's table)
  };
  std::vector<Grid> grids;
};

/// The operated result (operated_shading.h) of every grid into `dir`/<grid>/: the files of an
/// annual case (sensors, illuminance, metrics) plus shading_schedule.csv and operation.json.
/// Returns summary.json's `operated` object.
nlohmann::json run_operated(const project::Project& project, const project::OperationSpec& op,
                            const CaseTables& open, const CaseTables& shaded, const std::string& dir,
                            RunContext& ctx);

}  // namespace dayphoton::study
