#include "dayphoton/core/resource_limits.h"

namespace dayphoton {

std::string over_limit_text(std::uint64_t limit, const std::string& raised_by, const std::string& unit) {
  return "more than the limit of " + std::to_string(limit) + (unit.empty() ? "" : " " + unit) + " (raise it with " +
         raised_by + " if you mean it)";
}

}  // namespace dayphoton
