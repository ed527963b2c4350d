// Tests for study/artifact_store.h: payloads round-trip byte for byte (empty, sizes around
// the checksum's 8- and 32-byte blocks, large random), the directory is created on first
// write, and every kind of damage makes an artefact absent with a reason: truncation at
// every length, any flipped payload byte, a wrong magic, version, kind or key, trailing
// bytes. Concurrent writes from several threads all land intact, and a temporary file left
// by a killed write is ignored.
#include "dayphoton/study/artifact_store.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>
#include "../temp_folder.h"

namespace dayphoton::study {
namespace {

namespace fs = std::filesystem;

using test::fresh_dir;

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void put(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

std::string random_bytes(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::string s(n, '\0');
  for (char& c : s) c = static_cast<char>(rng() & 0xff);
  return s;
}

TEST(ArtifactStore, RoundTripsPayloadsAndCreatesTheDirectory) {
  const fs::path dir = fresh_dir("artifact_store_roundtrip") / "out" / ".cache";
  const ArtifactStore store(dir.string());
  EXPECT_FALSE(fs::exists(dir));  // created on first write, not before
  const std::vector<std::size_t> sizes = {0, 1, 7, 8, 9, 31, 32, 33, 63, 64, 65, 1000003};
  for (const std::size_t n : sizes) {
    const std::string key = "k" + std::to_string(n);
    const std::string payload = random_bytes(n, n + 1);
    EXPECT_FALSE(store.contains("blob", key));
    store.write("blob", key, payload);
    EXPECT_TRUE(store.contains("blob", key));
    std::string problem = "stale";
    const auto back = store.read("blob", key, &problem);
    ASSERT_TRUE(back.has_value()) << n << ": " << problem;
    EXPECT_EQ(*back, payload) << n;
    EXPECT_TRUE(problem.empty());
  }
  EXPECT_EQ(store.path_for("photons", "00ff"), (dir / "photons-00ff.bin").string());
  EXPECT_TRUE(fs::exists(store.path_for("blob", "k0")));
  // Overwriting replaces.
  store.write("blob", "k1", "new");
  EXPECT_EQ(store.read("blob", "k1").value_or("absent"), "new");
  // Only the artefacts: no temporaries left behind.
  std::size_t files = 0;
  for (const auto& e : fs::directory_iterator(dir)) {
    EXPECT_EQ(e.path().extension(), ".bin") << e.path();
    ++files;
  }
  EXPECT_EQ(files, sizes.size());
  fs::remove_all(dir.parent_path().parent_path());
}

TEST(ArtifactStore, MissingIsAbsentWithReason) {
  const ArtifactStore store(fresh_dir("artifact_store_missing").string());
  std::string problem;
  EXPECT_FALSE(store.read("dc", "0123", &problem).has_value());
  EXPECT_EQ(problem, "missing");
  EXPECT_FALSE(store.contains("dc", "0123"));
}

TEST(ArtifactStore, RejectsNamesThatAreNotPlainFileNameParts) {
  const ArtifactStore store(fresh_dir("artifact_store_names").string());
  for (const std::string bad : {"", "../x", "a/b", ".hidden", "a b", "a\\b"}) {
    EXPECT_THROW(store.path_for(bad, "key"), std::invalid_argument) << bad;
    EXPECT_THROW(store.path_for("kind", bad), std::invalid_argument) << bad;
  }
  EXPECT_NO_THROW(store.path_for("sky_matrix-v1.2", "0123abcdef"));
}

TEST(ArtifactStore, TruncatedFileIsAbsentAtEveryLength) {
  const fs::path dir = fresh_dir("artifact_store_truncated");
  const ArtifactStore store(dir.string());
  const std::string payload = random_bytes(40, 7);
  store.write("photons", "abc", payload);
  const std::string path = store.path_for("photons", "abc");
  const std::string whole = slurp(path);
  ASSERT_GT(whole.size(), payload.size());
  for (std::size_t n = 0; n < whole.size(); ++n) {
    put(path, whole.substr(0, n));
    std::string problem;
    EXPECT_FALSE(store.read("photons", "abc", &problem).has_value()) << n;
    EXPECT_NE(problem.find("truncated"), std::string::npos) << n << ": " << problem;
  }
  put(path, whole);
  EXPECT_EQ(store.read("photons", "abc").value_or("absent"), payload);
  put(path, whole + "x");
  std::string problem;
  EXPECT_FALSE(store.read("photons", "abc", &problem).has_value());
  EXPECT_NE(problem.find("after the payload"), std::string::npos) << problem;
  fs::remove_all(dir);
}

TEST(ArtifactStore, AnyFlippedByteIsAbsent) {
  const fs::path dir = fresh_dir("artifact_store_flipped");
  const ArtifactStore store(dir.string());
  // 77 bytes: two full 32-byte blocks, one word and a 5-byte tail of the checksum.
  const std::string payload = random_bytes(77, 3);
  store.write("dc", "k", payload);
  const std::string path = store.path_for("dc", "k");
  const std::string whole = slurp(path);
  const std::size_t header = whole.size() - payload.size();
  for (std::size_t i = 0; i < whole.size(); ++i) {
    for (const unsigned char mask : {0x01, 0x80, 0xff}) {
      std::string damaged = whole;
      damaged[i] = static_cast<char>(damaged[i] ^ mask);
      put(path, damaged);
      std::string problem;
      EXPECT_FALSE(store.read("dc", "k", &problem).has_value()) << "byte " << i;
      EXPECT_FALSE(problem.empty());
      if (i >= header) {
        EXPECT_NE(problem.find("checksum"), std::string::npos) << problem;
      }
    }
  }
  fs::remove_all(dir);
}

TEST(ArtifactStore, ForeignFilesAreAbsentWithReason) {
  const fs::path dir = fresh_dir("artifact_store_foreign");
  const ArtifactStore store(dir.string());
  store.write("dc", "k1", "payload");
  const std::string good = slurp(store.path_for("dc", "k1"));
  auto problem_with = [&](const std::string& bytes, const std::string& kind, const std::string& key) {
    put(store.path_for(kind, key), bytes);
    std::string problem;
    EXPECT_FALSE(store.read(kind, key, &problem).has_value());
    return problem;
  };
  std::string wrong_magic = good;
  wrong_magic[0] = 'X';
  EXPECT_NE(problem_with(wrong_magic, "dc", "k1").find("magic"), std::string::npos);
  EXPECT_NE(problem_with("#?RADIANCE\nNROWS=1\n", "dc", "k1").find("magic"), std::string::npos);
  std::string newer = good;
  newer[4] = static_cast<char>(ArtifactStore::FormatVersion + 1);
  EXPECT_NE(problem_with(newer, "dc", "k1").find("version"), std::string::npos);
  // The right frame under another name: a copied or renamed file is refused.
  EXPECT_NE(problem_with(good, "sky", "k1").find("kind"), std::string::npos);
  EXPECT_NE(problem_with(good, "dc", "k2").find("key"), std::string::npos);
  fs::remove_all(dir);
}

TEST(ArtifactStore, ConcurrentWritesOfDifferentKeysAllLand) {
  const fs::path dir = fresh_dir("artifact_store_concurrent");
  const ArtifactStore store(dir.string());  // several threads race to create the folder
  constexpr int Threads = 6, PerThread = 20;
  std::vector<std::thread> threads;
  for (int t = 0; t < Threads; ++t)
    threads.emplace_back([&store, t] {
      for (int i = 0; i < PerThread; ++i) {
        const std::string key = std::to_string(t) + "-" + std::to_string(i);
        store.write("part", key, random_bytes(1000 + 13 * i, 100 * t + i));
      }
    });
  // Two more threads write the same key over and over: the file is always one whole
  // payload or the other, never a mix.
  const std::string a = random_bytes(5000, 1), b = random_bytes(5000, 2);
  threads.emplace_back([&] { for (int i = 0; i < 20; ++i) store.write("part", "shared", a); });
  threads.emplace_back([&] { for (int i = 0; i < 20; ++i) store.write("part", "shared", b); });
  for (auto& th : threads) th.join();

  for (int t = 0; t < Threads; ++t)
    for (int i = 0; i < PerThread; ++i) {
      const std::string key = std::to_string(t) + "-" + std::to_string(i);
      std::string problem;
      const auto back = store.read("part", key, &problem);
      ASSERT_TRUE(back.has_value()) << key << ": " << problem;
      EXPECT_EQ(*back, random_bytes(1000 + 13 * i, 100 * t + i)) << key;
    }
  const auto shared = store.read("part", "shared");
  ASSERT_TRUE(shared.has_value());
  EXPECT_TRUE(*shared == a || *shared == b);
  fs::remove_all(dir);
}

TEST(ArtifactStore, LeftoverTemporaryOfAKilledWriteIsIgnored) {
  const fs::path dir = fresh_dir("artifact_store_leftover");
  const ArtifactStore store(dir.string());
  store.write("photons", "done", "finished artefact");
  // What kill -9 during write() leaves: the start of a frame in "<path>.tmp.<pid>" and no
  // artefact under the real name.
  const std::string path = store.path_for("photons", "k");
  const std::string partial = slurp(store.path_for("photons", "done")).substr(0, 20);
  put(path + ".tmp.999999", partial);

  std::string problem;
  EXPECT_FALSE(store.read("photons", "k", &problem).has_value());
  EXPECT_EQ(problem, "missing");
  EXPECT_EQ(store.read("photons", "done").value_or("absent"), "finished artefact");
  // Recomputing writes the artefact normally; the leftover does not disturb it.
  store.write("photons", "k", "recomputed");
  EXPECT_EQ(store.read("photons", "k").value_or("absent"), "recomputed");
  EXPECT_EQ(slurp(path + ".tmp.999999"), partial);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace dayphoton::study
