#pragma once
// Test double: N ranks as N threads of one process, with the Communicator semantics of the MPI
// implementation (per-pair, per-tag FIFO queues; collectives built from them). Lets the
// multi-rank protocol of distribute_jobs be tested without MPI (and under the sanitizers).
#include <condition_variable>
#include <cstdlib>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

#include "dayphoton/dist/communicator.h"

namespace dayphoton::dist::test {

class InProcessNetwork {
 public:
  explicit InProcessNetwork(int size) : m_size(size) {}
  int size() const { return m_size; }

  void post(int from, int to, int tag, ByteBuffer bytes) {
    {
      std::lock_guard<std::mutex> lock(m_mutex);
      m_queues[{from, to, tag}].push_back(std::move(bytes));
    }
    m_arrived.notify_all();
  }

  ByteBuffer take(int from, int to, int tag) {
    std::unique_lock<std::mutex> lock(m_mutex);
    auto& q = m_queues[{from, to, tag}];
    m_arrived.wait(lock, [&] { return !q.empty(); });
    ByteBuffer bytes = std::move(q.front());
    q.pop_front();
    return bytes;
  }

 private:
  int m_size;
  std::mutex m_mutex;
  std::condition_variable m_arrived;
  std::map<std::tuple<int, int, int>, std::deque<ByteBuffer>> m_queues;
};

class InProcessCommunicator final : public Communicator {
 public:
  InProcessCommunicator(InProcessNetwork& net, int rank) : m_net(net), m_rank(rank) {}
  int rank() const override { return m_rank; }
  int size() const override { return m_net.size(); }
  void barrier() override {
    ByteBuffer none;
    gather_to_root(none);
    broadcast_from_root(none);
  }
  void send(int destination, int tag, const ByteBuffer& bytes) override {
    check(destination);
    m_net.post(m_rank, destination, tag, bytes);
  }
  ByteBuffer receive(int source, int tag) override {
    check(source);
    return m_net.take(source, m_rank, tag);
  }
  std::vector<ByteBuffer> gather_to_root(const ByteBuffer& mine) override {
    if (m_rank != RootRank) {
      m_net.post(m_rank, RootRank, GatherTag, mine);
      return {};
    }
    std::vector<ByteBuffer> all{mine};
    for (int r = 1; r < size(); ++r) all.push_back(m_net.take(r, RootRank, GatherTag));
    return all;
  }
  void broadcast_from_root(ByteBuffer& bytes) override {
    if (m_rank == RootRank)
      for (int r = 1; r < size(); ++r) m_net.post(RootRank, r, BroadcastTag, bytes);
    else
      bytes = m_net.take(RootRank, m_rank, BroadcastTag);
  }
  [[noreturn]] void abort_all(const std::string& message, int) override {
    throw std::logic_error("abort_all in a test: " + message);
  }

 private:
  static constexpr int GatherTag = 40001;
  static constexpr int BroadcastTag = 40002;
  void check(int peer) const {
    if (peer < 0 || peer >= size() || peer == m_rank) throw std::out_of_range("bad peer");
  }
  InProcessNetwork& m_net;
  int m_rank;
};

/// Runs body(comm) on `size` ranks, one thread each; returns each rank's exception (or null).
inline std::vector<std::exception_ptr> run_ranks(int size, const std::function<void(Communicator&)>& body) {
  InProcessNetwork net(size);
  std::vector<std::exception_ptr> errors(static_cast<std::size_t>(size));
  std::vector<std::thread> threads;
  for (int r = 0; r < size; ++r)
    threads.emplace_back([&, r] {
      InProcessCommunicator comm(net, r);
      try {
        body(comm);
      } catch (...) {
        errors[static_cast<std::size_t>(r)] = std::current_exception();
      }
    });
  for (auto& t : threads) t.join();
  return errors;
}

}  // namespace dayphoton::dist::test
