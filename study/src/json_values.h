// The JSON objects of grid_metrics.json and operation.json as values. summary.json holds the
// same objects: it takes these values, so nothing the run wrote as JSON text is parsed again.
// grid_metrics_json and operation_json (public headers) are their text.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "dayphoton/study/annual_study.h"
#include "dayphoton/study/operated_shading.h"

namespace dayphoton::study {

nlohmann::json grid_metrics_value(const AnnualStudy& study, const AnnualStudySettings& settings);

nlohmann::json operation_value(const OperatedStudy& operated, const ShadingRule& rule, const std::string& open_case,
                               const std::string& shaded_case);

}  // namespace dayphoton::study
