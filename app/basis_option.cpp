// The --basis option shared by `sky` and `annual`, and the size check of the matrices it implies.
#include <exception>
#include <string>

#include "commands.h"
#include "dayphoton/core/diagnostics.h"

namespace dayphoton::app {

sky::PatchBasis parse_basis_option(const std::string& text) {
  if (text == "tregenza") return sky::PatchBasis::tregenza();
  const std::string prefix = "reinhart:";
  if (text.rfind(prefix, 0) == 0) {
    try {
      std::size_t used = 0;
      const int mf = std::stoi(text.substr(prefix.size()), &used);
      if (used == text.size() - prefix.size() && mf >= 1 && mf <= 64) return sky::PatchBasis::reinhart(mf);
    } catch (const std::exception&) {
    }
  }
  throw UsageError("--basis must be 'tregenza' or 'reinhart:N' with N in 1..64, not '" + text + "'");
}

void require_matrix_within_limit(const std::string& what, std::uint64_t bins, std::uint64_t steps, int components,
                                 std::uint64_t max_values) {
  const std::uint64_t k = static_cast<std::uint64_t>(components);
  if (bins == 0 || (steps <= max_values / bins && bins * steps <= max_values / k)) return;
  const double values = double(bins) * double(steps) * double(k);  // may exceed 2^64
  throw UsageError(what + " would hold " + std::to_string(bins) + " x " + std::to_string(steps) + " x " +
                   std::to_string(components) + " = " + format_number(values) + " values, " +
                   over_limit_text(max_values, "--max-matrix-values"));
}

}  // namespace dayphoton::app
