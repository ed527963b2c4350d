// EngineError: failures inside the engine that are not the user's input (Embree errors,
// out of memory, misuse of the API). Input problems (bad geometry in a project) are
// dayphoton::InputError with a source location instead (core/diagnostics.h).
//
// Embree reports errors through a C callback (rtcSetDeviceErrorFunction, Embree's
// doc/src/api/rtcSetDeviceErrorFunction.md). The callback must not throw through C code, so
// engine/src/embree_accel.cpp records the first error and throws EngineError after the
// Embree call has returned.
#pragma once

#include <stdexcept>
#include <string>

namespace dayphoton::engine {

class EngineError : public std::runtime_error {
 public:
  explicit EngineError(const std::string& message, int embree_code = 0)
      : std::runtime_error(message), m_embree_code(embree_code) {}

  /// Embree's RTCError value if the error came from Embree, else 0 (RTC_ERROR_NONE).
  int embree_code() const { return m_embree_code; }

 private:
  int m_embree_code;
};

/// Name of an Embree RTCError value ("RTC_ERROR_INVALID_ARGUMENT", ...; "RTC_ERROR_<n>" for
/// values Embree 3.13 does not define).
std::string embree_error_name(int embree_code);

/// The EngineError for an Embree error code and Embree's message:
/// "Embree error RTC_ERROR_INVALID_ARGUMENT: <message>".
EngineError embree_error(int embree_code, const std::string& message);

/// The Embree library's version as the loaded library reports it (e.g. "3.13.5").
std::string embree_version();

namespace detail {
/// Test hook: make a deliberately invalid Embree call (a geometry of a type that does not
/// exist) on a fresh device with our error callback installed, and throw the EngineError
/// the callback recorded. Exists so the tests can prove Embree errors reach callers.
[[noreturn]] void provoke_embree_error();
}  // namespace detail

}  // namespace dayphoton::engine
