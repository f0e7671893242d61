// Hands a run's ops on in batches. The front end's code and the back end's
// together are more than the processor's first-level instruction cache
// holds: taking turns op by op, each evicted the other every block; a batch
// at a time, each runs from the cache (usina stats: 10-13 % of the run in
// the fanuc, grbl and romi dialects, trace 5 %; issue 19).
//
// The ops reach the next sink later than they were made, in their order.
// Whoever reports diagnostics beside that sink (the runner, the budget)
// calls flush() first, so that the sink's own diagnostics keep their place
// among them (cli::RunGuard does).
#pragma once

#include <cstddef>
#include <vector>

#include "canon/sink.hpp"

namespace usina::canon {

class BatchSink final : public Sink {
 public:
  // Ops held at most: the sink's code runs this many ops in a row.
  static constexpr std::size_t kDefaultBatch = 256;

  explicit BatchSink(Sink& next, std::size_t batch = kDefaultBatch);

  void on(const Op& op) override;

  // The ops held, then the next sink's finish.
  void finish() override;

  // The next sink's: a budget that stops the run stands before the batch.
  bool stopped() const override { return next_.stopped(); }

  // The next sink's (one that reads no ops gains nothing from a batch:
  // cli::RunGuard leaves it out then).
  bool reads_ops() const override { return next_.reads_ops(); }

  void pass(const core::SourceLoc& src) override;

  // Hands on the ops held. A flush asked for while the next sink takes a
  // batch (a diagnostic it reports through the runner's) does nothing.
  void flush();

 private:
  Sink& next_;
  std::size_t batch_;
  std::vector<Op> held_;
  bool flushing_ = false;
};

}  // namespace usina::canon
