// Test support for the project tests: the diagnostics of a failing load or build as
// "line:column: message" strings, the form the error tests compare against.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "dayphoton/core/diagnostics.h"

namespace dayphoton::project::test {

/// Runs `step` (loading and/or building a project); returns "line:col: message" for each
/// diagnostic of the InputError it throws, or nothing if it succeeds. With `expected_file`,
/// every diagnostic must also name that file.
template <typename Step>
std::vector<std::string> located_errors(Step&& step, const std::string& expected_file = "") {
  try {
    step();
  } catch (const InputError& e) {
    std::vector<std::string> out;
    for (const auto& d : e.diagnostics()) {
      if (!expected_file.empty()) {
        EXPECT_EQ(d.location.file, expected_file);
      }
      out.push_back(std::to_string(d.location.line) + ":" + std::to_string(d.location.column) + ": " + d.message);
    }
    return out;
  }
  return {};
}

}  // namespace dayphoton::project::test
