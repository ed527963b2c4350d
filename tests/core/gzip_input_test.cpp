// GzipInput: zlib decompression as a stream, with a decompressed-size limit; files named like
// command-line options are files; a plain file named .gz, a truncated or corrupt gzip file,
// and a FIFO are located errors.
#include "dayphoton/core/gzip_input.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/radiance_matrix.h"

using namespace dayphoton;

namespace {

void write_gzip(const std::string& path, const std::string& text) {
  gzFile f = gzopen(path.c_str(), "wb9");
  ASSERT_NE(f, nullptr);
  ASSERT_EQ(gzwrite(f, text.data(), static_cast<unsigned>(text.size())), static_cast<int>(text.size()));
  ASSERT_EQ(gzclose(f), Z_OK);
}

std::string read_all(const std::string& path, std::uint64_t max_bytes) {
  GzipInput in(path, max_bytes, "matrix file", "--max-decompressed-bytes");
  std::string text;
  char buffer[4096];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) text.append(buffer, static_cast<std::size_t>(in.gcount()));
  return text;
}

std::string error_of(const std::string& path, std::uint64_t max_bytes = 1 << 20) {
  try {
    read_all(path, max_bytes);
  } catch (const InputError& e) {
    return e.diagnostics().front().location.to_string() + ": " + e.diagnostics().front().message;
  }
  return "no error";
}

}  // namespace

TEST(GzipInput, DecompressesAsItReads) {
  const std::string path = testing::TempDir() + "gzip_input_test.mtx.gz";
  std::string text = "#?RADIANCE\nNROWS=2\nNCOLS=1\nNCOMP=3\nFORMAT=ascii\n\n1 2 3\n4 5 6\n";
  write_gzip(path, text);
  EXPECT_EQ(read_all(path, 1 << 20), text);
  GzipInput in(path, 1 << 20, "matrix file", "--max-decompressed-bytes");
  const RadianceMatrix m = RadianceMatrix::read(in, path);
  EXPECT_EQ(m.at(1, 0, 2), 6.0f);
  std::filesystem::remove(path);
}

TEST(GzipInput, ANameStartingWithADashIsAFile) {
  // popen("gzip -dc -x.gz") would have read it as an option of gzip.
  const auto here = std::filesystem::current_path();
  std::filesystem::current_path(testing::TempDir());
  write_gzip("-c.gz", "hello");
  EXPECT_EQ(read_all("-c.gz", 100), "hello");
  std::filesystem::remove("-c.gz");
  std::filesystem::current_path(here);
}

TEST(GzipInput, DecompressedSizeIsLimitedWhileStreaming) {
  const std::string path = testing::TempDir() + "gzip_input_bomb.gz";
  write_gzip(path, std::string(1 << 20, ' '));  // 1 MiB of spaces in about 1 KB
  EXPECT_LT(std::filesystem::file_size(path), 5000u);
  EXPECT_EQ(error_of(path, 100000),
            path + ": matrix file decompresses to more than the limit of 100000 bytes (raise it with "
                   "--max-decompressed-bytes if you mean it)");
  EXPECT_EQ(read_all(path, 1 << 20).size(), std::size_t(1) << 20);  // exactly at the limit: fine
  // Through the matrix reader (which reads with istream::read): the same located error.
  write_gzip(path, "#?RADIANCE\nNROWS=1000000\nNCOLS=1\nNCOMP=1\nFORMAT=float\n\n" + std::string(1 << 20, 'x'));
  GzipInput in(path, 100000, "matrix file", "--max-decompressed-bytes");
  MatrixReadOptions unlimited;
  unlimited.max_values = std::uint64_t(1) << 40;
  try {
    RadianceMatrix::read(in, path, unlimited);
    FAIL() << "read past the limit";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("decompresses to more than the limit of 100000 bytes"), std::string::npos)
        << e.what();
  }
  std::filesystem::remove(path);
}

TEST(GzipInput, BadFilesAreLocatedErrors) {
  const std::string dir = testing::TempDir();
  const std::string plain = dir + "gzip_input_plain.gz";
  std::ofstream(plain) << "#?RADIANCE\n";
  EXPECT_EQ(error_of(plain), plain + ": matrix file is not gzip-compressed (its name ends in .gz)");

  const std::string truncated = dir + "gzip_input_truncated.gz";
  write_gzip(truncated, std::string(10000, 'a') + std::string(10000, 'b'));
  std::filesystem::resize_file(truncated, std::filesystem::file_size(truncated) - 10);
  EXPECT_EQ(error_of(truncated), truncated + ": matrix file has truncated or corrupt gzip data (zlib: unexpected end of file)");

  const std::string fifo = dir + "gzip_input.fifo";
  ::unlink(fifo.c_str());
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_EQ(error_of(fifo), fifo + ": matrix file is a named pipe (FIFO), not a regular file");
  ::unlink(fifo.c_str());
  EXPECT_EQ(error_of(dir + "gzip_input_missing.gz"), dir + "gzip_input_missing.gz: matrix file not found");
  std::filesystem::remove(plain);
  std::filesystem::remove(truncated);
}
