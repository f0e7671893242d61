// Two links joined in memory, for tests and the benchmark: what one side
// writes the other reads, through a bounded buffer per direction (the
// kernel queue and UART of a real line). Closing either side ends both, as
// a cable pulled out does. Completions run on the event loop, never inside
// the call that starts them.
#pragma once

#include <memory>

#include "dnc/link.hpp"

namespace usina::dnc {

struct LinkPair {
  std::unique_ptr<Link> a;  // usina's end
  std::unique_ptr<Link> b;  // the machine's end
};

LinkPair memory_link_pair(asio::io_context& io, std::size_t capacity = 4096);

}  // namespace usina::dnc
