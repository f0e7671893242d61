// The sink interface every back end implements, and sinks that wrap sinks.
#pragma once

#include <vector>

#include "canon/op.hpp"

namespace usina::canon {

class Sink {
 public:
  virtual ~Sink() = default;
  virtual void on(const Op& op) = 0;

  // Called once after the last op (flush files, close drawings).
  virtual void finish() {}
};

// Discards everything (usina check).
class NullSink final : public Sink {
 public:
  void on(const Op&) override {}
};

// Sends every op to several sinks in turn.
class TeeSink final : public Sink {
 public:
  explicit TeeSink(std::vector<Sink*> sinks) : sinks_(std::move(sinks)) {}

  void on(const Op& op) override;
  void finish() override;

 private:
  std::vector<Sink*> sinks_;
};

}  // namespace usina::canon
