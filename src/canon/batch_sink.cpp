#include "canon/batch_sink.hpp"

#include <algorithm>

namespace usina::canon {

BatchSink::BatchSink(Sink& next, std::size_t batch)
    : next_(next), batch_(std::max<std::size_t>(batch, 1)) {
  held_.reserve(batch_);
}

void BatchSink::on(const Op& op) {
  held_.push_back(op);
  if (held_.size() >= batch_) flush();
}

void BatchSink::finish() {
  flush();
  next_.finish();
}

// In order with the ops held before it.
void BatchSink::pass(const core::SourceLoc& src) {
  flush();
  next_.pass(src);
}

void BatchSink::flush() {
  if (flushing_) return;  // the ops held are on their way already
  flushing_ = true;
  for (const Op& op : held_)
    next_.on(op);
  held_.clear();
  flushing_ = false;
}

}  // namespace usina::canon
