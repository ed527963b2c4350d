// GatherAccuracy (gather_accuracy.h) as JSON: in the accuracy step's cached outcome
// (accuracy_rounds.cpp) and in summary.json's `grids[].accuracy.gather` (docs/outputs.md).
#pragma once

#include <vector>

#include <nlohmann/json.hpp>

#include "dayphoton/study/gather_accuracy.h"

namespace dayphoton::study {

/// One grid's record; summary.json writes it for gathered grids only.
inline nlohmann::json gather_accuracy_json(const GatherAccuracy& a) {
  return {{"gathered", a.gathered},
          {"first_gather_rays", a.first_rays},
          {"gather_rays", a.rays},
          {"rounds", a.rounds},
          {"stop_reason", a.stop_reason}};
}

inline nlohmann::json gather_accuracy_json(const std::vector<GatherAccuracy>& grids) {
  nlohmann::json j = nlohmann::json::array();
  for (const GatherAccuracy& a : grids) j.push_back(gather_accuracy_json(a));
  return j;
}

/// Throws nlohmann::json::exception on a malformed record.
inline std::vector<GatherAccuracy> gather_accuracy_from_json(const nlohmann::json& j) {
  std::vector<GatherAccuracy> out;
  for (const nlohmann::json& g : j) {
    GatherAccuracy a;
    a.gathered = g.at("gathered").get<bool>();
    a.first_rays = g.at("first_gather_rays").get<int>();
    a.rays = g.at("gather_rays").get<int>();
    a.rounds = g.at("rounds").get<std::size_t>();
    a.stop_reason = g.at("stop_reason").get<std::string>();
    out.push_back(a);
  }
  return out;
}

/// One grid's sensors next to a cut (NearCutReached), against `target_percent`: summary.json's
/// `grids[].accuracy.near_cut`.
inline nlohmann::json near_cut_reached_json(const NearCutReached& r, double target_percent) {
  return {{"sensors", r.sensors},
          {"gather_rays", r.gather_rays},
          {"rounds", r.rounds},
          {"stop_reason", r.stop_reason},
          {"largest_relative_stderr_percent", r.largest_percent},
          {"status", r.largest_percent <= target_percent ? "met" : "above target"}};
}

/// Every grid's, as the accuracy steps' cached outcomes keep them.
inline nlohmann::json near_cut_reached_json(const std::vector<NearCutReached>& grids) {
  nlohmann::json j = nlohmann::json::array();
  for (const NearCutReached& r : grids)
    j.push_back({{"sensors", r.sensors},
                 {"gather_rays", r.gather_rays},
                 {"largest_percent", r.largest_percent},
                 {"rounds", r.rounds},
                 {"stop_reason", r.stop_reason}});
  return j;
}

/// Throws nlohmann::json::exception on a malformed record.
inline std::vector<NearCutReached> near_cut_reached_from_json(const nlohmann::json& j) {
  std::vector<NearCutReached> out;
  for (const nlohmann::json& g : j)
    out.push_back({g.at("sensors").get<std::size_t>(), g.at("gather_rays").get<int>(), g.at("largest_percent").get<double>(),
                   g.at("rounds").get<std::size_t>(), g.at("stop_reason").get<std::string>()});
  return out;
}

}  // namespace dayphoton::study
