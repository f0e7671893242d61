// The sink interface every back end implements, and sinks that wrap sinks.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "canon/op.hpp"
#include "core/diagnostic.hpp"

namespace usina::canon {

class Sink {
 public:
  virtual ~Sink() = default;
  virtual void on(const Op& op) = 0;

  // Called once after the last op (flush files, close drawings).
  virtual void finish() {}

  // True once the sink takes no more ops (an operation budget ran out): a
  // runner then ends its run between blocks, as after an error. A sink that
  // wraps another answers for it too.
  virtual bool stopped() const { return false; }

  // False when the sink reads nothing of an op but that it came (usina
  // check): a front end may then check a move's numbers and call pass()
  // instead of building the op (a million moves built and dropped were a
  // tenth of check's time). A sink that wraps another answers for it too.
  // The answer may change between ops (fanuc's stroke check reads ops only
  // while a forbidden area is armed), so it is asked for each op; only the
  // sinks of canon/ and of a verb answer the same all run, and only there
  // may it be asked once (grbl's LineOps, cli::RunGuard's batch).
  virtual bool reads_ops() const { return true; }

  // An op of block `src` went by unbuilt; called only when !reads_ops().
  virtual void pass(const core::SourceLoc& src) { static_cast<void>(src); }
};

// Discards everything (usina check).
class NullSink final : public Sink {
 public:
  void on(const Op&) override {}

  bool reads_ops() const override { return false; }
};

// Sends every op to several sinks in turn.
class TeeSink final : public Sink {
 public:
  explicit TeeSink(std::vector<Sink*> sinks) : sinks_(std::move(sinks)) {}

  void on(const Op& op) override;
  void finish() override;
  bool stopped() const override;
  bool reads_ops() const override;
  void pass(const core::SourceLoc& src) override;

 private:
  std::vector<Sink*> sinks_;
};

// The operations one run may produce (DESIGN.md: limits that keep hostile
// input finite). The first op beyond `max_ops` is reported at its block
// (E_TOO_MANY_OPERATIONS) and dropped with every later one; stopped() then
// ends the run. The back ends behind it see a finite stream, so a runaway
// loop cannot fill a disk or the memory.
class OpBudget final : public Sink {
 public:
  // 100 million: programs of tens of millions of moves (3D surfacing, with
  // their feed, spindle and comment ops) run whole; a trace of this many
  // ops is some 5 GB.
  static constexpr std::uint64_t kDefaultMaxOps = 100'000'000;

  OpBudget(Sink& next, std::uint64_t max_ops, core::DiagnosticSink& diags)
      : next_(next), max_ops_(max_ops), diags_(diags) {}

  void on(const Op& op) override;
  void pass(const core::SourceLoc& src) override;

  void finish() override { next_.finish(); }

  bool stopped() const override { return exceeded_ || next_.stopped(); }

  bool reads_ops() const override { return next_.reads_ops(); }

  std::uint64_t passed() const { return passed_; }

 private:
  // Counts an op of block `src` against the budget; false (reported at the
  // first) beyond it.
  bool admit(const core::SourceLoc& src);

  Sink& next_;
  std::uint64_t max_ops_;
  core::DiagnosticSink& diags_;
  std::uint64_t passed_ = 0;
  bool exceeded_ = false;
};

// When a ProgressSink speaks.
struct ProgressTiming {
  double delay = 1.0;              // seconds of silence first: short runs show nothing
  double period = 0.5;             // seconds between two lines
  std::uint32_t every = 1u << 14;  // ops between two looks at the clock
};

// How far a long run has got, for a person watching a terminal: every few
// thousand ops it reads the clock and, from `delay` seconds after the start
// on and at most once a `period`, hands `show` a progress_line; at the end
// `show("")` (erase it). Who shows it, and whether at all (only on a
// terminal), is the caller's choice.
class ProgressSink final : public Sink {
 public:
  using Show = std::function<void(std::string_view)>;
  using Clock = std::function<double()>;  // seconds, steadily increasing

  ProgressSink(Sink& next, Show show, std::uint64_t max_ops, ProgressTiming timing = {},
               Clock clock = steady_seconds);

  void on(const Op& op) override;
  void pass(const core::SourceLoc& src) override;
  void finish() override;

  bool stopped() const override { return next_.stopped(); }

  bool reads_ops() const override { return next_.reads_ops(); }

  // Whether a line is on show (so a diagnostic printed now erases it first).
  bool showing() const { return showing_; }

  // Erases the line on show, if any.
  void erase();

  static double steady_seconds();

 private:
  void tick(const core::SourceLoc& src);

  Sink& next_;
  Show show_;
  std::uint64_t max_ops_;
  ProgressTiming timing_;
  Clock clock_;
  double start_ = 0.0;
  double next_show_ = 0.0;
  std::uint64_t ops_ = 0;
  bool showing_ = false;
};

// "usina: 12,345,678 operations of at most 100,000,000 (--max-ops), line 4,
// 12 s": the text a ProgressSink shows.
std::string progress_line(std::uint64_t ops, std::uint64_t max_ops, std::uint32_t line,
                          double seconds);

}  // namespace usina::canon
