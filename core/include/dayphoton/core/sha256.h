// SHA-256 (NIST FIPS 180-4, "Secure Hash Standard", section 6.2) of byte strings and files:
// the hash of every output file in a run's manifest (summary.json `files`, docs/outputs.md),
// so that `sha256sum` can check a results folder without dayphoton.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

namespace dayphoton {

/// Incremental SHA-256: update() any number of times, then hex() once. The rounds run on the
/// processor's SHA extensions where it has them (x86 SHA-NI, checked once by CPUID), else
/// portably; both give the same digest.
class Sha256 {
 public:
  enum class Rounds { Fastest, Portable };  ///< Portable: never the SHA extensions (tests)
  explicit Sha256(Rounds rounds = Rounds::Fastest);
  void update(const void* data, std::size_t size);
  /// The digest as 64 lowercase hex digits; the object must not be updated afterwards.
  std::string hex();
  /// Whether Rounds::Fastest uses the processor's SHA extensions on this machine.
  static bool hardware_rounds();

 private:
  void blocks(const std::uint8_t* p, std::size_t count);
  void block(const std::uint8_t* p);
  bool m_hardware = false;
  std::array<std::uint32_t, 8> m_state;
  std::array<std::uint8_t, 64> m_buffer{};
  std::size_t m_buffered = 0;
  std::uint64_t m_bytes = 0;
};

/// SHA-256 of a string's bytes, 64 lowercase hex digits.
std::string sha256_hex(const std::string& bytes);

/// SHA-256 of a file's content, read in blocks; throws std::runtime_error naming the file if
/// it cannot be read. `size_bytes` (optional) receives the number of bytes hashed.
std::string sha256_file_hex(const std::string& path, std::uint64_t* size_bytes = nullptr);

}  // namespace dayphoton
