// zlib's gzip file functions (gzopen/gzread: J.-l. Gailly and M. Adler, zlib 1.2 manual,
// "Gzip File Access Functions") behind a std::streambuf.
#include "dayphoton/core/gzip_input.h"

#include <zlib.h>

#include <array>
#include <streambuf>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/input_file.h"
#include "dayphoton/core/resource_limits.h"

namespace dayphoton {

class GzipInput::Buffer : public std::streambuf {
 public:
  Buffer(const std::string& path, std::uint64_t max_bytes, std::string what, std::string raised_by)
      : m_path(path), m_max_bytes(max_bytes), m_what(std::move(what)), m_raised_by(std::move(raised_by)) {
    const std::string problem = input_file_problem(path);
    if (!problem.empty()) fail(problem);
    m_file = gzopen(path.c_str(), "rb");
    if (!m_file) fail("cannot be opened");
    gzbuffer(m_file, 1 << 17);
  }
  ~Buffer() override {
    if (m_file) gzclose(m_file);
  }

  std::uint64_t bytes_read() const { return m_total; }

 protected:
  int_type underflow() override {
    if (gptr() < egptr()) return traits_type::to_int_type(*gptr());
    if (m_done) return traits_type::eof();
    const int n = gzread(m_file, m_chunk.data(), static_cast<unsigned>(m_chunk.size()));
    if (n < 0) fail_with_zlib("has corrupt gzip data");
    if (m_total == 0 && n > 0 && gzdirect(m_file)) fail("is not gzip-compressed (its name ends in .gz)");
    if (n == 0) {
      int code = Z_OK;
      gzerror(m_file, &code);
      if (code != Z_OK) fail_with_zlib("has truncated or corrupt gzip data");
      m_done = true;
      return traits_type::eof();
    }
    m_total += static_cast<std::uint64_t>(n);
    if (m_total > m_max_bytes)
      fail("decompresses to " + over_limit_text(m_max_bytes, m_raised_by, "bytes"));
    setg(m_chunk.data(), m_chunk.data(), m_chunk.data() + n);
    return traits_type::to_int_type(*gptr());
  }

 private:
  [[noreturn]] void fail(const std::string& problem) const {
    throw InputError(SourceLocation{m_path, 0, 0}, m_what + " " + problem);
  }
  [[noreturn]] void fail_with_zlib(const std::string& problem) const {
    int code = Z_OK;
    std::string text = gzerror(m_file, &code);
    // zlib prefixes its message with the path: keep the message only.
    if (text.compare(0, m_path.size() + 2, m_path + ": ") == 0) text.erase(0, m_path.size() + 2);
    fail(problem + " (zlib: " + (text.empty() ? "error " + std::to_string(code) : text) + ")");
  }

  std::string m_path;
  std::uint64_t m_max_bytes;
  std::string m_what, m_raised_by;
  gzFile m_file = nullptr;
  std::array<char, 1 << 16> m_chunk{};
  std::uint64_t m_total = 0;
  bool m_done = false;
};

GzipInput::GzipInput(const std::string& path, std::uint64_t max_bytes, const std::string& what,
                     const std::string& raised_by)
    : std::istream(nullptr), m_buffer(std::make_unique<Buffer>(path, max_bytes, what, raised_by)) {
  rdbuf(m_buffer.get());
  exceptions(std::ios::badbit);  // a located error inside read() propagates as itself
}

GzipInput::~GzipInput() = default;

std::uint64_t GzipInput::bytes_read() const { return m_buffer->bytes_read(); }

bool has_gzip_extension(const std::string& path) {
  return path.size() >= 3 && path.compare(path.size() - 3, 3, ".gz") == 0;
}

}  // namespace dayphoton
