// The Open MPI implementation of Communicator and MpiSession; the only file that includes
// <mpi.h>, compiled when the CMake option DAYPHOTON_MPI is on. C bindings only (the C++
// bindings were removed in MPI 3.0).
//
// Every blocking operation is a non-blocking one (MPI_Isend, MPI_Ibcast, MPI_Igather,
// MPI_Ibarrier, MPI 3.1 sections 3.7 and 5.12) completed by polling MPI_Test with short
// sleeps: a rank waiting for a slower one then leaves its cores to the TBB workers of ranks
// sharing the node, where Open MPI's blocking calls would spin at 100% of a core.
// MPI errors keep the default handler MPI_ERRORS_ARE_FATAL: an MPI failure (a peer that
// died) ends the whole job with Open MPI's message, never a hang.
#define OMPI_SKIP_MPICXX 1
#define MPICH_SKIP_MPICXX 1
#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <thread>

#include "dayphoton/dist/message_limits.h"
#include "dayphoton/dist/mpi_session.h"

namespace dayphoton::dist {
namespace {

/// gather_to_root's point-to-point messages (dist/'s own tag range, communicator.h).
constexpr int GatherTag = LastCallerTag + 2;

/// Longest nap between two polls of a pending request: small against any job, long enough
/// that a waiting rank uses next to no processor time.
constexpr auto MaxPollInterval = std::chrono::microseconds(200);

void wait_for(MPI_Request& request) {
  auto nap = std::chrono::microseconds(1);
  for (;;) {
    int done = 0;
    MPI_Test(&request, &done, MPI_STATUS_IGNORE);
    if (done) return;
    std::this_thread::sleep_for(nap);
    nap = std::min(nap * 2, MaxPollInterval);
  }
}

/// The least upper bound of tags every MPI library accepts (MPI 3.1 section 8.1.2).
constexpr int LastTag = 32767;

void check_tag(int tag) {
  if (tag < 0 || tag > LastTag)
    throw std::out_of_range("dist: message tag " + std::to_string(tag) + " outside 0 to " + std::to_string(LastTag));
}

class MpiCommunicator final : public Communicator {
 public:
  MpiCommunicator() {
    MPI_Comm_dup(MPI_COMM_WORLD, &m_comm);
    MPI_Comm_rank(m_comm, &m_rank);
    MPI_Comm_size(m_comm, &m_size);
  }
  ~MpiCommunicator() override { MPI_Comm_free(&m_comm); }

  int rank() const override { return m_rank; }
  int size() const override { return m_size; }

  void barrier() override {
    MPI_Request request;
    MPI_Ibarrier(m_comm, &request);
    wait_for(request);
  }

  void send(int destination, int tag, const ByteBuffer& bytes) override {
    check_peer(destination);
    check_tag(tag);
    if (bytes.size() > MaxBufferBytes)
      throw std::length_error("dist: refusing to send " + std::to_string(bytes.size()) + " bytes (limit " +
                              std::to_string(MaxBufferBytes) + ")");
    std::uint64_t size = bytes.size();
    MPI_Request request;
    MPI_Isend(&size, 1, MPI_UINT64_T, destination, tag, m_comm, &request);
    wait_for(request);
    for (std::uint64_t at = 0; at < size; at += MaxChunkBytes) {
      const int n = static_cast<int>(std::min<std::uint64_t>(MaxChunkBytes, size - at));
      MPI_Isend(bytes.data() + at, n, MPI_BYTE, destination, tag, m_comm, &request);
      wait_for(request);
    }
  }

  ByteBuffer receive(int source, int tag) override {
    check_peer(source);
    check_tag(tag);
    std::uint64_t size = 0;
    MPI_Request request;
    MPI_Irecv(&size, 1, MPI_UINT64_T, source, tag, m_comm, &request);
    wait_for(request);
    // The sender refuses such sizes: this is corruption, and its chunks would never be matched.
    if (size > MaxBufferBytes)
      abort_all("a message from rank " + std::to_string(source) + " announces " + std::to_string(size) +
                    " bytes, above the limit of " + std::to_string(MaxBufferBytes),
                1);
    ByteBuffer bytes(size);
    for (std::uint64_t at = 0; at < size; at += MaxChunkBytes) {
      const int n = static_cast<int>(std::min<std::uint64_t>(MaxChunkBytes, size - at));
      MPI_Irecv(bytes.data() + at, n, MPI_BYTE, source, tag, m_comm, &request);
      wait_for(request);
    }
    return bytes;
  }

  std::vector<ByteBuffer> gather_to_root(const ByteBuffer& mine) override {
    if (m_rank != RootRank) {
      send(RootRank, GatherTag, mine);
      return {};
    }
    std::vector<ByteBuffer> all(static_cast<std::size_t>(m_size));
    all[0] = mine;
    for (int r = 1; r < m_size; ++r) all[static_cast<std::size_t>(r)] = receive(r, GatherTag);
    return all;
  }

  void broadcast_from_root(ByteBuffer& bytes) override {
    std::uint64_t size = bytes.size();
    if (m_rank == RootRank && size > MaxBufferBytes)
      abort_all("refusing to broadcast " + std::to_string(size) + " bytes (limit " + std::to_string(MaxBufferBytes) +
                    ")",
                1);
    MPI_Request request;
    MPI_Ibcast(&size, 1, MPI_UINT64_T, RootRank, m_comm, &request);
    wait_for(request);
    if (m_rank != RootRank) bytes.assign(size, std::byte{0});
    for (std::uint64_t at = 0; at < size; at += MaxChunkBytes) {
      const int n = static_cast<int>(std::min<std::uint64_t>(MaxChunkBytes, size - at));
      MPI_Ibcast(bytes.data() + at, n, MPI_BYTE, RootRank, m_comm, &request);
      wait_for(request);
    }
  }

  [[noreturn]] void abort_all(const std::string& message, int exit_code) override {
    // One write: mpirun interleaves the ranks' output at each write.
    const std::string line = "dayphoton: rank " + std::to_string(m_rank) + ": " + message + "\n";
    std::fwrite(line.data(), 1, line.size(), stderr);
    std::fflush(stderr);
    MPI_Abort(m_comm, exit_code == 0 ? 1 : exit_code);
    std::abort();  // MPI_Abort does not return
  }

 private:
  void check_peer(int peer) const {
    if (peer < 0 || peer >= m_size || peer == m_rank)
      throw std::out_of_range("dist: rank " + std::to_string(m_rank) + " cannot message rank " + std::to_string(peer) +
                              " of " + std::to_string(m_size));
  }

  MPI_Comm m_comm = MPI_COMM_NULL;
  int m_rank = 0;
  int m_size = 1;
};

}  // namespace

bool mpi_compiled_in() { return true; }

MpiSession::MpiSession(int* argc, char*** argv) {
  int provided = 0;
  if (MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS)
    throw std::runtime_error("MPI_Init_thread failed");
  if (provided < MPI_THREAD_FUNNELED) {
    MPI_Finalize();
    throw std::runtime_error("the MPI library does not offer MPI_THREAD_FUNNELED");
  }
}

MpiSession::~MpiSession() {
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (!finalized) MPI_Finalize();
}

std::unique_ptr<Communicator> MpiSession::world() const { return std::make_unique<MpiCommunicator>(); }

}  // namespace dayphoton::dist
