#include "dayphoton/dist/serial_communicator.h"

#include <cstdlib>
#include <deque>
#include <iostream>
#include <map>
#include <stdexcept>
#include <string>

#include "dayphoton/dist/message_limits.h"

namespace dayphoton::dist {
namespace {

class SerialCommunicator final : public Communicator {
 public:
  int rank() const override { return RootRank; }
  int size() const override { return 1; }
  void barrier() override {}

  void send(int destination, int tag, const ByteBuffer& bytes) override {
    check_peer(destination);
    if (bytes.size() > MaxBufferBytes)
      throw std::length_error("dist: refusing to send " + std::to_string(bytes.size()) +
                              " bytes (limit " + std::to_string(MaxBufferBytes) + ")");
    m_queued[tag].push_back(bytes);
  }

  ByteBuffer receive(int source, int tag) override {
    check_peer(source);
    auto it = m_queued.find(tag);
    // One process waiting for a message nobody will send would wait forever.
    if (it == m_queued.end() || it->second.empty())
      throw std::logic_error("dist: receive with tag " + std::to_string(tag) +
                             " on the serial communicator, but nothing was sent");
    ByteBuffer bytes = std::move(it->second.front());
    it->second.pop_front();
    return bytes;
  }

  std::vector<ByteBuffer> gather_to_root(const ByteBuffer& mine) override { return {mine}; }
  void broadcast_from_root(ByteBuffer&) override {}

  [[noreturn]] void abort_all(const std::string& message, int exit_code) override {
    std::cerr << "dayphoton: " << message << std::endl;
    std::_Exit(exit_code == 0 ? 1 : exit_code);
  }

 private:
  static void check_peer(int peer) {
    if (peer != RootRank)
      throw std::out_of_range("dist: rank " + std::to_string(peer) + " of a 1-process run");
  }
  std::map<int, std::deque<ByteBuffer>> m_queued;
};

}  // namespace

std::unique_ptr<Communicator> make_serial_communicator() { return std::make_unique<SerialCommunicator>(); }

}  // namespace dayphoton::dist
