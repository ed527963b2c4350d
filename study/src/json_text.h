// The text of the JSON files `run` writes (summary.json, grid_metrics.json, operation.json).
//
// JSON text is UTF-8 (RFC 8259, section 8.1). Every string from a project file is UTF-8
// (the loader refuses other bytes), but file paths come from the command line and the file
// system, where a folder may be named in another encoding (Latin-1 'café'). nlohmann::json
// throws on such bytes by default, which ended a finished run with exit 4 just before its
// summary; here each invalid byte becomes U+FFFD instead, and the file is still written.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace dayphoton::study {

inline std::string json_text(const nlohmann::json& j) {
  return j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace dayphoton::study
