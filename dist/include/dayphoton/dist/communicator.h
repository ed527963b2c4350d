#pragma once
// Communicator: the processes of one run and the messages between them. dayphoton's only
// view of MPI: a run is written against this interface, and runs alike in one process
// (serial_communicator.h) or as the ranks of an `mpirun`/`srun` job (mpi_session.h).
//
// Every operation is called by the main thread of a rank only (never from inside a TBB task):
// the MPI implementation initialises MPI with MPI_THREAD_FUNNELED (MPI 3.1 standard, section
// 12.4.3). Collective operations (barrier, gather_to_root, broadcast_from_root) must be called
// by every rank, in the same order. Sizes are checked against message_limits.h.
#include <string>
#include <vector>

#include "dayphoton/dist/byte_buffer.h"

namespace dayphoton::dist {

/// Rank 0 is the root: it gathers results and writes the outputs.
constexpr int RootRank = 0;

/// Message tags 0 to LastCallerTag are the caller's; the tags above, up to 32767 (the least
/// upper bound MPI guarantees, MPI 3.1 section 8.1.2), are dist/'s own (distribute_jobs,
/// gather_to_root).
constexpr int LastCallerTag = 31999;

class Communicator {
 public:
  virtual ~Communicator() = default;

  /// This process's number, 0 to size() - 1.
  virtual int rank() const = 0;
  /// The number of processes of the run (1 for the serial communicator).
  virtual int size() const = 0;

  /// Returns once every rank has called it. Waiting ranks sleep rather than spin.
  virtual void barrier() = 0;

  /// Sends `bytes` to rank `destination`; `tag` (0 to LastCallerTag) tells messages apart. Returns when
  /// the buffer may be reused. Buffers above MaxChunkBytes go as several messages; a buffer
  /// above MaxBufferBytes is refused (std::length_error). Messages between one pair of ranks
  /// with one tag arrive in the order they were sent.
  virtual void send(int destination, int tag, const ByteBuffer& bytes) = 0;
  /// Receives the next buffer sent by rank `source` with `tag` (blocks until it arrives).
  virtual ByteBuffer receive(int source, int tag) = 0;

  /// Collective: every rank passes its buffer; rank 0 gets all of them, indexed by rank
  /// (its own included), the other ranks get an empty vector.
  virtual std::vector<ByteBuffer> gather_to_root(const ByteBuffer& mine) = 0;
  /// Collective: rank 0's `bytes` replace every other rank's `bytes`.
  virtual void broadcast_from_root(ByteBuffer& bytes) = 0;

  /// Ends every process of the run now, after printing `message` (prefixed by this rank) to
  /// standard error; the launcher exits with a non-zero status. For failures that leave no
  /// way to keep the ranks in step (a rank cannot reach the others); recoverable errors are
  /// exceptions agreed on by every rank (distribute_jobs does so).
  [[noreturn]] virtual void abort_all(const std::string& message, int exit_code) = 0;
};

}  // namespace dayphoton::dist
