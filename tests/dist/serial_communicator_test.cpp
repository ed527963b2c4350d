#include "dayphoton/dist/serial_communicator.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "dayphoton/dist/message_limits.h"

namespace dayphoton::dist {
namespace {

ByteBuffer bytes_of(std::initializer_list<int> values) {
  ByteBuffer out;
  for (int v : values) out.push_back(static_cast<std::byte>(v));
  return out;
}

TEST(SerialCommunicator, IsRankZeroOfOne) {
  auto comm = make_serial_communicator();
  EXPECT_EQ(comm->rank(), 0);
  EXPECT_EQ(comm->size(), 1);
  comm->barrier();
}

TEST(SerialCommunicator, MessagesToItselfArriveInOrderPerTag) {
  auto comm = make_serial_communicator();
  comm->send(0, 7, bytes_of({1, 2}));
  comm->send(0, 8, bytes_of({9}));
  comm->send(0, 7, bytes_of({3}));
  EXPECT_EQ(comm->receive(0, 7), bytes_of({1, 2}));
  EXPECT_EQ(comm->receive(0, 8), bytes_of({9}));
  EXPECT_EQ(comm->receive(0, 7), bytes_of({3}));
}

TEST(SerialCommunicator, ReceivingWhatWasNeverSentIsAnErrorNotAHang) {
  auto comm = make_serial_communicator();
  EXPECT_THROW(comm->receive(0, 1), std::logic_error);
}

TEST(SerialCommunicator, OtherRanksDoNotExist) {
  auto comm = make_serial_communicator();
  EXPECT_THROW(comm->send(1, 0, {}), std::out_of_range);
  EXPECT_THROW(comm->receive(-1, 0), std::out_of_range);
}

TEST(SerialCommunicator, CollectivesOfOne) {
  auto comm = make_serial_communicator();
  const auto all = comm->gather_to_root(bytes_of({4, 5}));
  ASSERT_EQ(all.size(), 1u);
  EXPECT_EQ(all[0], bytes_of({4, 5}));
  ByteBuffer b = bytes_of({6});
  comm->broadcast_from_root(b);
  EXPECT_EQ(b, bytes_of({6}));
}

TEST(MessageLimits, ChunksFitAnMpiCountAndTheLimitHoldsWholeChunks) {
  EXPECT_LT(MaxChunkBytes, std::uint64_t{1} << 31);  // MPI counts are int
  EXPECT_EQ(MaxBufferBytes % MaxChunkBytes, 0u);
}

}  // namespace
}  // namespace dayphoton::dist
