// ArtifactStore: framed, checksummed, atomically written cache files (artifact_store.h;
// docs/cache.md).
#include "dayphoton/study/artifact_store.h"

#include <array>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <mutex>
#include <set>
#include <stdexcept>
#include <system_error>
#include <utility>

#include "dayphoton/core/atomic_file.h"
#include "dayphoton/core/error_text.h"

namespace dayphoton::study {

namespace {

namespace fs = std::filesystem;

constexpr char Magic[4] = {'D', 'P', 'H', 'A'};

std::uint64_t load_le(const unsigned char* p, int n) {
  std::uint64_t v = 0;
  for (int i = 0; i < n; ++i) v |= std::uint64_t(p[i]) << (8 * i);
  return v;
}

void append_le(std::string& out, std::uint64_t v, int n) {
  for (int i = 0; i < n; ++i) out.push_back(static_cast<char>((v >> (8 * i)) & 0xff));
}

std::uint64_t rotl(std::uint64_t x, int r) { return (x << r) | (x >> (64 - r)); }

std::uint64_t mix(std::uint64_t h) {  // murmur3 fmix64: a bijection that avalanches
  h ^= h >> 33;
  h *= 0xff51afd7ed558ccdull;
  h ^= h >> 33;
  h *= 0xc4ceb9fe1a85ec53ull;
  h ^= h >> 33;
  return h;
}

// The payload checksum. Four independent lanes take one 8-byte word each per 32-byte
// block (so the multiplies overlap and large photon artefacts check at memory speed). A
// lane's round v -> rotl(v ^ w * M1, 29) * M2 is a bijection of v for a fixed word and of w
// for a fixed v (M1, M2 odd), and so is each step of the final combination, so a change
// confined to one word (any flipped byte) always changes the checksum; other damage goes
// unnoticed with probability about 2^-64.
std::uint64_t checksum64(const std::string& payload) {
  constexpr std::uint64_t M1 = 0x9E3779B97F4A7C15ull, M2 = 0xD6E8FEB86659FD93ull;
  const auto* p = reinterpret_cast<const unsigned char*>(payload.data());
  const std::size_t n = payload.size();
  std::array<std::uint64_t, 4> lane = {0x243F6A8885A308D3ull, 0x13198A2E03707344ull,
                                       0xA4093822299F31D0ull, 0x082EFA98EC4E6C89ull};
  auto round = [](std::uint64_t v, std::uint64_t w) { return rotl(v ^ (w * M1), 29) * M2; };
  std::size_t i = 0;
  for (; i + 32 <= n; i += 32)
    for (int l = 0; l < 4; ++l) lane[l] = round(lane[l], load_le(p + i + 8 * l, 8));
  for (; i + 8 <= n; i += 8) lane[0] = round(lane[0], load_le(p + i, 8));
  if (i < n) lane[1] = round(lane[1], load_le(p + i, static_cast<int>(n - i)) ^ (std::uint64_t(n - i) << 56));
  std::uint64_t h = mix(lane[0] ^ n);
  for (int l = 1; l < 4; ++l) h = mix(h + lane[l]);
  return h;
}

bool valid_name(const std::string& s) {
  if (s.empty() || s[0] == '.') return false;
  for (const char c : s) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                    c == '_' || c == '-' || c == '.';
    if (!ok) return false;
  }
  return true;
}

// Writes of the same path from two threads would share the temporary "<path>.tmp.<pid>":
// a fixed set of mutexes, picked by the path's hash, serialises them while writes of
// different artefacts (almost always on different stripes) proceed in parallel.
std::mutex& write_lock_for(const std::string& path) {
  static std::array<std::mutex, 64> stripes;
  return stripes[std::hash<std::string>{}(path) % stripes.size()];
}

std::optional<std::string> absent(std::string* problem, std::string why) {
  if (problem) *problem = std::move(why);
  return std::nullopt;
}

}  // namespace

struct ArtifactStore::Used {
  std::mutex mutex;
  std::set<std::string> names;
  void note(const std::string& path) {
    const std::string name = fs::path(path).filename().string();
    std::lock_guard<std::mutex> lock(mutex);
    names.insert(name);
  }
};

ArtifactStore::ArtifactStore(std::string directory)
    : m_directory(std::move(directory)), m_used(std::make_shared<Used>()) {}

std::vector<std::string> ArtifactStore::used_files() const {
  std::lock_guard<std::mutex> lock(m_used->mutex);
  return {m_used->names.begin(), m_used->names.end()};
}

std::string ArtifactStore::path_for(const std::string& kind, const std::string& key) const {
  if (!valid_name(kind)) throw std::invalid_argument("invalid artefact kind '" + kind + "'");
  if (!valid_name(key)) throw std::invalid_argument("invalid artefact key '" + key + "'");
  return (fs::path(m_directory) / (kind + "-" + key + ".bin")).string();
}

bool ArtifactStore::contains(const std::string& kind, const std::string& key) const {
  return read(kind, key).has_value();
}

void ArtifactStore::write(const std::string& kind, const std::string& key,
                          const std::string& payload) const {
  const std::string path = path_for(kind, key);
  std::error_code ec;
  fs::create_directories(m_directory, ec);
  // create_directories may report an error when another thread created the folder first;
  // what matters is that it exists now.
  if (!fs::is_directory(m_directory))
    throw std::runtime_error("cannot create the cache folder " + m_directory + ": " +
                             (ec ? ec.message() : std::string("not a directory")));

  std::string header(Magic, sizeof Magic);
  append_le(header, FormatVersion, 4);
  append_le(header, kind.size(), 4);
  header += kind;
  append_le(header, key.size(), 4);
  header += key;
  append_le(header, payload.size(), 8);
  append_le(header, checksum64(payload), 8);

  std::lock_guard<std::mutex> lock(write_lock_for(path));
  write_file_atomically(
      path,
      [&](std::ostream& out) {
        out.write(header.data(), static_cast<std::streamsize>(header.size()));
        out.write(payload.data(), static_cast<std::streamsize>(payload.size()));
      },
      /*binary=*/true, /*sync=*/false);  // the frame's checksum catches what a sync would
  m_used->note(path);
}

std::optional<std::string> ArtifactStore::read(const std::string& kind, const std::string& key,
                                               std::string* problem) const {
  const std::string path = path_for(kind, key);
  std::error_code exists_error;
  if (!fs::exists(path, exists_error)) return absent(problem, "missing");
  std::ifstream in(path, std::ios::binary);
  if (!in) return absent(problem, "cannot open: " + error_text(errno));
  std::string file;
  {
    in.seekg(0, std::ios::end);
    const std::streamoff size = in.tellg();
    in.seekg(0, std::ios::beg);
    if (size < 0 || !in) return absent(problem, "cannot read its size");
    file.resize(static_cast<std::size_t>(size));
    in.read(file.data(), size);
    if (in.gcount() != size) return absent(problem, "read error");
  }

  const auto* p = reinterpret_cast<const unsigned char*>(file.data());
  const std::size_t n = file.size();
  std::size_t at = 0;
  auto have = [&](std::size_t bytes) { return n - at >= bytes; };
  auto truncated = [&](const char* where) {
    return absent(problem, "truncated (" + std::to_string(n) + " bytes, ends inside the " + where + ")");
  };

  if (!have(4)) return truncated("magic");
  if (std::memcmp(p, Magic, 4) != 0) return absent(problem, "not a dayphoton artefact (bad magic)");
  at = 4;
  if (!have(4)) return truncated("format version");
  const std::uint64_t version = load_le(p + at, 4);
  at += 4;
  if (version != FormatVersion)
    return absent(problem, "format version " + std::to_string(version) + " (this build reads " +
                               std::to_string(FormatVersion) + ")");
  for (const auto& [expected, what] : {std::pair<const std::string&, const char*>{kind, "kind"},
                                       std::pair<const std::string&, const char*>{key, "key"}}) {
    if (!have(4)) return truncated(what);
    const std::uint64_t length = load_le(p + at, 4);
    at += 4;
    if (!have(length)) return truncated(what);
    const std::string found(file, at, length);
    at += length;
    if (found != expected)
      return absent(problem, std::string("holds ") + what + " '" + found + "', not '" + expected + "'");
  }
  if (!have(16)) return truncated("payload header");
  const std::uint64_t size = load_le(p + at, 8);
  const std::uint64_t checksum = load_le(p + at + 8, 8);
  at += 16;
  if (n - at < size)
    return absent(problem, "truncated (payload of " + std::to_string(size) + " bytes, " +
                               std::to_string(n - at) + " present)");
  if (n - at > size)
    return absent(problem, std::to_string(n - at - size) + " bytes after the payload");
  file.erase(0, at);
  if (checksum64(file) != checksum) return absent(problem, "corrupted (checksum mismatch)");
  if (problem) problem->clear();
  m_used->note(path);
  return file;
}

}  // namespace dayphoton::study
