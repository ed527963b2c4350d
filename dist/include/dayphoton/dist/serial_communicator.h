#pragma once
// The communicator of an ordinary run: one process, rank 0 of 1. Collectives are immediate;
// a message sent to itself is queued until received.
#include <memory>

#include "dayphoton/dist/communicator.h"

namespace dayphoton::dist {

std::unique_ptr<Communicator> make_serial_communicator();

}  // namespace dayphoton::dist
