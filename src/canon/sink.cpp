#include "canon/sink.hpp"

namespace usina::canon {

void TeeSink::on(const Op& op) {
  for (Sink* s : sinks_)
    s->on(op);
}

void TeeSink::finish() {
  for (Sink* s : sinks_)
    s->finish();
}

}  // namespace usina::canon
