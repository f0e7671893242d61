#include "canon/sink.hpp"

#include <chrono>
#include <cmath>

#include <fmt/format.h>

namespace usina::canon {

void TeeSink::on(const Op& op) {
  for (Sink* s : sinks_)
    s->on(op);
}

void TeeSink::finish() {
  for (Sink* s : sinks_)
    s->finish();
}

bool TeeSink::stopped() const {
  for (const Sink* s : sinks_)
    if (s->stopped()) return true;
  return false;
}

bool TeeSink::reads_ops() const {
  for (const Sink* s : sinks_)
    if (s->reads_ops()) return true;
  return false;
}

void TeeSink::pass(const core::SourceLoc& src) {
  for (Sink* s : sinks_)
    s->pass(src);
}

bool OpBudget::admit(const core::SourceLoc& src) {
  if (exceeded_) return false;
  if (passed_ >= max_ops_) {
    exceeded_ = true;
    diags_.report({core::Code::TooManyOperations, core::Severity::Error, src,
                   fmt::format("the run made {} operations (moves, arcs, tool changes, ...), its "
                               "budget; stopped here: a loop that does not end? A longer program "
                               "runs with a larger --max-ops",
                               max_ops_)});
    return false;
  }
  ++passed_;
  return true;
}

void OpBudget::on(const Op& op) {
  if (admit(op.src)) next_.on(op);
}

void OpBudget::pass(const core::SourceLoc& src) {
  if (admit(src)) next_.pass(src);
}

ProgressSink::ProgressSink(Sink& next, Show show, std::uint64_t max_ops, ProgressTiming timing,
                           Clock clock)
    : next_(next),
      show_(std::move(show)),
      max_ops_(max_ops),
      timing_(timing),
      clock_(std::move(clock)) {
  start_ = clock_();
  next_show_ = start_ + timing_.delay;
}

double ProgressSink::steady_seconds() {
  using namespace std::chrono;
  return duration<double>(steady_clock::now().time_since_epoch()).count();
}

void ProgressSink::on(const Op& op) {
  next_.on(op);
  // The clock is read once every `every` ops: the cost per op stays a count.
  if (++ops_ % timing_.every == 0) tick(op.src);
}

void ProgressSink::pass(const core::SourceLoc& src) {
  next_.pass(src);
  if (++ops_ % timing_.every == 0) tick(src);
}

void ProgressSink::tick(const core::SourceLoc& src) {
  const double now = clock_();
  if (now < next_show_) return;
  next_show_ = now + timing_.period;
  show_(progress_line(ops_, max_ops_, src.line, now - start_));
  showing_ = true;
}

void ProgressSink::erase() {
  if (!showing_) return;
  show_("");
  showing_ = false;
}

void ProgressSink::finish() {
  erase();
  next_.finish();
}

namespace {

// 12345678 → "12,345,678".
std::string grouped(std::uint64_t n) {
  std::string digits = fmt::format("{}", n);
  std::string out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}

}  // namespace

std::string progress_line(std::uint64_t ops, std::uint64_t max_ops, std::uint32_t line,
                          double seconds) {
  std::string text =
      fmt::format("usina: {} operations of at most {} (--max-ops)", grouped(ops), grouped(max_ops));
  if (line > 0) text += fmt::format(", line {}", line);
  text += fmt::format(", {:.0f} s", std::floor(seconds));
  return text;
}

}  // namespace usina::canon
