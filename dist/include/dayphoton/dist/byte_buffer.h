#pragma once
// The unit every message of dist/ carries: an owned run of bytes. What the bytes mean is the
// caller's business (an artefact's encoding, docs/cache.md); dist/ only moves them.
#include <cstddef>
#include <vector>

namespace dayphoton::dist {

using ByteBuffer = std::vector<std::byte>;

}  // namespace dayphoton::dist
