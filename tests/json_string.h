// Test helper: a text as a JSON string literal (nlohmann::json's escaping), for writing HBJSON
// with a BSDF's XML inline.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace dayphoton::test {

inline std::string json_string(const std::string& text) { return nlohmann::json(text).dump(); }

}  // namespace dayphoton::test
