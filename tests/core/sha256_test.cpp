// Tests for core/sha256.h: the FIPS 180-2 appendix B examples ("abc", the 448-bit message and
// one million 'a'), the empty string, lengths around the padding boundary checked against
// feeding the same bytes in pieces, the processor's SHA rounds against the portable ones (on
// the published examples and on pseudo-random bytes of many lengths and offsets), and a file
// digest equal to the string digest.
#include "dayphoton/core/sha256.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <stdexcept>

namespace dayphoton {
namespace {

TEST(Sha256, PublishedTestVectors) {
  EXPECT_EQ(sha256_hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  EXPECT_EQ(sha256_hex(std::string(1000000, 'a')),
            "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST(Sha256, PiecewiseUpdatesEqualOneUpdateAroundThePaddingBoundary) {
  for (std::size_t n : {0u, 1u, 55u, 56u, 57u, 63u, 64u, 65u, 119u, 120u, 128u, 1000u}) {
    std::string s;
    for (std::size_t i = 0; i < n; ++i) s += static_cast<char>('a' + i % 26);
    Sha256 pieces;
    for (std::size_t i = 0; i < n; i += 7) pieces.update(s.data() + i, std::min<std::size_t>(7, n - i));
    EXPECT_EQ(pieces.hex(), sha256_hex(s)) << n << " bytes";
  }
}

std::string digest(const std::string& bytes, Sha256::Rounds rounds, std::size_t piece) {
  Sha256 h(rounds);
  for (std::size_t i = 0; i < bytes.size(); i += piece) h.update(bytes.data() + i, std::min(piece, bytes.size() - i));
  return h.hex();
}

TEST(Sha256, PortableRoundsGiveThePublishedDigests) {
  EXPECT_EQ(digest("abc", Sha256::Rounds::Portable, 1),
            "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(digest(std::string(1000000, 'a'), Sha256::Rounds::Portable, 1000000),
            "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST(Sha256, HardwareRoundsEqualThePortableOnes) {
  if (!Sha256::hardware_rounds()) GTEST_SKIP() << "this processor has no SHA extensions";
  EXPECT_EQ(digest(std::string(1000000, 'a'), Sha256::Rounds::Fastest, 4096),
            "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
  // Pseudo-random bytes (fixed seed), whole and from odd offsets (unaligned loads), in pieces
  // that split blocks anywhere.
  std::mt19937 random(20261203);
  std::string bytes(70000, '\0');
  for (char& c : bytes) c = static_cast<char>(random() & 0xffu);
  for (std::size_t n : {0u, 1u, 63u, 64u, 65u, 127u, 128u, 129u, 1000u, 4095u, 4096u, 65536u, 69999u})
    for (std::size_t offset : {0u, 1u, 3u})
      for (std::size_t piece : {1u, 13u, 64u, 100000u}) {
        if (offset + n > bytes.size() || (piece == 1 && n > 5000)) continue;
        const std::string s = bytes.substr(offset, n);
        EXPECT_EQ(digest(s, Sha256::Rounds::Fastest, piece), digest(s, Sha256::Rounds::Portable, piece))
            << n << " bytes from offset " << offset << " in pieces of " << piece;
      }
}

TEST(Sha256, FileDigestAndSize) {
  const std::string path = ::testing::TempDir() + "/sha256_test.bin";
  const std::string content = std::string(200000, 'x') + "tail";
  std::ofstream(path, std::ios::binary) << content;
  std::uint64_t size = 0;
  EXPECT_EQ(sha256_file_hex(path, &size), sha256_hex(content));
  EXPECT_EQ(size, content.size());
  std::filesystem::remove(path);
  EXPECT_THROW(sha256_file_hex(path), std::runtime_error);
}

}  // namespace
}  // namespace dayphoton
