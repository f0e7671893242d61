// The romi dialect's parametric statements (Fagor style, spec/romi.md,
// "Parametric programming"): (P1 = expr), (IF cond GOTO N..), (GOTO N..),
// (RPT N.., N.., n), (CALL n), (SUB n) ... (RET). Jumps go by block number
// through an index of the file built on the first jump; every backward jump
// counts against the run's iteration limit.
#include <cmath>

#include <fmt/format.h>

#include "gcode/romi/engine.hpp"

namespace usina::gcode::romi {
namespace {

class QuietDiagnostics final : public core::DiagnosticSink {
 public:
  void report(core::Diagnostic) override {}
};

long key(double n) {
  return std::lround(n);
}

}  // namespace

void Engine::build_index() {
  numbers_.emplace();
  const std::string_view text = sources_.get(file_)->text();
  QuietDiagnostics quiet;
  RomiBlock b;
  Cursor c;
  while (c.offset < text.size()) {
    const BlockText bt = block_at(text, c.offset);
    Cursor next = c;
    next.offset = bt.next;
    if (bt.ends_line) {
      ++next.line;
      next.line_start = bt.next;
    }
    if (parse_romi_block(bt.text, {file_, c.line, c.line_start}, 1, b, quiet)) {
      if (b.base.line_number) numbers_->emplace(key(*b.base.line_number), IndexEntry{c, next});
      for (const Statement& st : b.statements) {
        if (st.kind == StmtKind::Sub) subs_.emplace(key(st.label), next);
        if (st.kind == StmtKind::Return) returns_.push_back(next.offset);
      }
    }
    c = next;
  }
}

bool Engine::jump_to_block(double n, std::uint32_t col) {
  if (!numbers_) build_index();
  auto it = numbers_->find(key(n));
  if (it == numbers_->end()) {
    return error(core::Code::UnknownBlockNumber, col,
                 fmt::format("no block N{} in the program", key(n)));
  }
  if (it->second.at.offset <= cursor_.offset && !run_.count_jump(kJumps)) return false;
  cursor_ = it->second.at;
  return true;
}

// After a block: the end of a repeated section goes back to its start, or
// on to the block after the RPT.
bool Engine::after_block_number() {
  if (frames_.empty() || frames_.back().call || !block_.base.line_number) return true;
  Frame& f = frames_.back();
  if (key(*block_.base.line_number) != key(f.last)) return true;
  if (--f.remaining > 0) return jump_to_block(f.first, 0);
  cursor_ = f.ret;
  frames_.pop_back();
  return true;
}

// Assignments run before the block's words (flow false); jumps after them.
bool Engine::statements(bool flow) {
  for (const Statement& st : block_.statements) {
    const bool jump = st.kind != StmtKind::Assign;
    if (jump != flow) continue;
    if (!run_statement(st)) return false;
    if (jump) return true;  // one jump per block
  }
  return true;
}

// The value of a statement's expression; nullopt after reporting why not.
std::optional<double> Engine::statement_value(ExprRef e) {
  EvalError err;
  auto v = gcode::evaluate(block_.base, e, *this, err);
  if (!v) error(err.error.code, err.col, err.error.message);
  return v;
}

bool Engine::run_statement(const Statement& st) {
  switch (st.kind) {
  case StmtKind::Assign: {
    auto v = statement_value(st.expr);
    if (!v) return false;
    params_[static_cast<std::size_t>(st.param)] = *v;
    return true;
  }
  case StmtKind::IfGoto: {
    auto v = statement_value(st.expr);
    if (!v) return false;
    return *v == 0.0 || jump_to_block(st.label, st.col);
  }
  case StmtKind::Goto: return jump_to_block(st.label, st.col);
  case StmtKind::Repeat: return repeat(st);
  case StmtKind::Call: return call(st);
  case StmtKind::Sub: return skip_sub(st);
  case StmtKind::Return:
    if (frames_.empty() || !frames_.back().call) {
      return error(core::Code::UnmatchedControl, st.col, "(RET) with no (CALL) to return to");
    }
    cursor_ = frames_.back().ret;
    frames_.pop_back();
    return true;
  }
  return true;
}

// (RPT N<first>, N<last>[, n]): the section runs n more times (default 1).
bool Engine::repeat(const Statement& st) {
  double times = 1;
  if (st.expr != kNoExpr) {
    auto v = statement_value(st.expr);
    if (!v) return false;
    times = std::round(*v);
    if (!(times >= 0 && times <= 1e9)) {
      return error(core::Code::BadWordValue, st.col,
                   fmt::format("RPT count {} is not 0 or more", *v));
    }
  }
  if (times < 1) return true;
  if (frames_.size() >= static_cast<std::size_t>(options_.max_call_depth)) {
    return error(core::Code::RecursionTooDeep, st.col, "RPT and CALL nested too deep");
  }
  frames_.push_back({false, cursor_, st.label, st.label_end, static_cast<long>(times)});
  return jump_to_block(st.label, st.col);
}

bool Engine::call(const Statement& st) {
  if (!numbers_) build_index();
  auto it = subs_.find(key(st.label));
  if (it == subs_.end()) {
    return error(core::Code::UnknownBlockNumber, st.col,
                 fmt::format("CALL {}: no (SUB {}) in the program", key(st.label), key(st.label)));
  }
  if (frames_.size() >= static_cast<std::size_t>(options_.max_call_depth)) {
    return error(core::Code::RecursionTooDeep, st.col, "RPT and CALL nested too deep");
  }
  if (!run_.count_jump(kJumps)) return false;
  frames_.push_back({true, cursor_, 0, 0, 0});
  cursor_ = it->second;
  return true;
}

// (SUB n) met in the flow of the program: the subroutine's body is skipped.
bool Engine::skip_sub(const Statement& st) {
  if (!numbers_) build_index();
  for (const std::uint64_t r : returns_) {
    if (r > cursor_.offset) return skip_to(r);
  }
  return error(core::Code::UnclosedBlock, st.col,
               fmt::format("(SUB {}) has no (RET)", key(st.label)));
}

// Moves the cursor forward to `offset`, counting the lines passed.
bool Engine::skip_to(std::uint64_t offset) {
  const std::string_view text = sources_.get(file_)->text();
  while (cursor_.offset < offset && cursor_.offset < text.size()) {
    if (text[cursor_.offset] == '\n') {
      ++cursor_.line;
      cursor_.line_start = cursor_.offset + 1;
    }
    ++cursor_.offset;
  }
  return true;
}

}  // namespace usina::gcode::romi
