// What a failed command prints, and the ranks' agreement on a failure: see commands.h.
#include <cstring>
#include <ostream>

#include "commands.h"
#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/terminal_text.h"
#include "dayphoton/study/output_lock.h"

namespace dayphoton::app {

CommandFailure describe_failure(const std::exception_ptr& failure) {
  try {
    std::rethrow_exception(failure);
  } catch (const study::OutputFolderBusy& e) {
    return {ExitOutputBusy, std::string("dayphoton: error: ") + e.what() + "\n"};
  } catch (const InputError& e) {
    return {ExitInputError, e.what()};
  } catch (const UsageError& e) {
    return {ExitUsageError, "dayphoton: error: " + printable_text(e.what()) + "\n"};
  } catch (const std::exception& e) {
    return {ExitInternalError, "dayphoton: error: " + printable_text(e.what()) + "\n"};
  } catch (...) {
    return {ExitInternalError, "dayphoton: error: an unknown exception\n"};
  }
}

void agree_on_failure(dist::Communicator& ranks, const std::exception_ptr& failure, std::ostream& err) {
  // Each rank's verdict: nothing, or its exit code (4 bytes) and its message.
  dist::ByteBuffer mine;
  if (failure) {
    const CommandFailure f = describe_failure(failure);
    const std::int32_t code = f.exit_code;
    mine.resize(sizeof code + f.message.size());
    std::memcpy(mine.data(), &code, sizeof code);
    std::memcpy(mine.data() + sizeof code, f.message.data(), f.message.size());
  }
  const std::vector<dist::ByteBuffer> all = ranks.gather_to_root(mine);
  dist::ByteBuffer verdict;  // rank 0's: the exit code of the lowest failing rank, or nothing
  for (std::size_t r = 0; r < all.size(); ++r) {
    if (all[r].size() < sizeof(std::int32_t)) continue;
    const std::string message(reinterpret_cast<const char*>(all[r].data()) + sizeof(std::int32_t),
                              all[r].size() - sizeof(std::int32_t));
    err << (r == 0 ? std::string() : "rank " + std::to_string(r) + ": ") << message << std::flush;
    verdict.assign(all[r].begin(), all[r].begin() + sizeof(std::int32_t));
    break;
  }
  ranks.broadcast_from_root(verdict);
  if (verdict.empty()) return;
  std::int32_t code = ExitInternalError;
  std::memcpy(&code, verdict.data(), sizeof code);
  throw AgreedFailure(code);
}

}  // namespace dayphoton::app
