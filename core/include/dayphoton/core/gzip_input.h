// GzipInput: a gzip-compressed file read as a std::istream, decompressed by zlib as it is read
// (never whole into memory), with a limit on the decompressed size, so that a small file that
// expands to gigabytes (a "gzip bomb") stops with a located error instead of filling memory
// or running for minutes. The path is opened as a file whatever its first character (no
// shell, no gzip command line), and must be a regular file (input_file.h).
//
// Errors are InputError located at the file: not a gzip file, corrupt or truncated data,
// more than max_bytes decompressed. They propagate out of the stream's read functions
// (badbit is in the exception mask).
#pragma once

#include <cstdint>
#include <istream>
#include <memory>
#include <string>

namespace dayphoton {

class GzipInput : public std::istream {
 public:
  /// `what` names the file in messages ("matrix file"); `raised_by` says how the user raises
  /// max_bytes ("--max-decompressed-bytes").
  GzipInput(const std::string& path, std::uint64_t max_bytes, const std::string& what, const std::string& raised_by);
  ~GzipInput() override;
  GzipInput(const GzipInput&) = delete;
  GzipInput& operator=(const GzipInput&) = delete;

  /// Decompressed bytes delivered so far.
  std::uint64_t bytes_read() const;

 private:
  class Buffer;
  std::unique_ptr<Buffer> m_buffer;
};

/// True if `path` names a gzip file by its extension (".gz").
bool has_gzip_extension(const std::string& path);

}  // namespace dayphoton
