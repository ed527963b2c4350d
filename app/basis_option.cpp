// The --basis option shared by `sky` and `annual`.
#include <exception>
#include <string>

#include "commands.h"

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

}  // namespace dayphoton::app
