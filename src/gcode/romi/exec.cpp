#include "gcode/romi/exec.hpp"

#include <array>
#include <cmath>

#include <fmt/format.h>

namespace usina::gcode::romi {
namespace {

struct NamedHandler {
  std::string_view name;
  Handler handler;
};

}  // namespace

Handler Executor::handler_named(std::string_view name) {
  // The names the dialect's table uses (romi/dialect.cpp).
  static constexpr std::array kHandlers = {
      NamedHandler{"motion", &Executor::h_motion},
      NamedHandler{"plane", &Executor::h_plane},
      NamedHandler{"distance", &Executor::h_distance},
      NamedHandler{"units", &Executor::h_units},
      NamedHandler{"retract", &Executor::h_retract},
      NamedHandler{"comp", &Executor::h_comp},
      NamedHandler{"cycle", &Executor::h_cycle},
      NamedHandler{"mirror", &Executor::h_mirror},
      NamedHandler{"scale", &Executor::h_scale},
      NamedHandler{"rotate", &Executor::h_rotate},
      NamedHandler{"grid", &Executor::h_grid},
      NamedHandler{"bolt_circle", &Executor::h_bolt_circle},
      NamedHandler{"pocket", &Executor::h_pocket},
      NamedHandler{"tool_change", &Executor::h_tool_change},
      NamedHandler{"spindle", &Executor::h_spindle},
      NamedHandler{"coolant", &Executor::h_coolant},
      NamedHandler{"stop", &Executor::h_stop},
      NamedHandler{"end", &Executor::h_end},
  };
  for (const NamedHandler& h : kHandlers) {
    if (h.name == name) return h.handler;
  }
  return nullptr;
}

Executor::Executor(const CodeTable& codes, Services& run, const InterpOptions& options,
                   const Options& dialect_options, canon::Sink& sink, core::DiagnosticSink& diags)
    : codes_(codes),
      run_(run),
      options_(options),
      dialect_options_(dialect_options),
      machine_(sink, work_.machine, diags) {}

void Executor::start(const std::vector<CodeEntry>& start_codes, const core::SourceLoc& loc) {
  at(loc);
  for (const CodeEntry& e : start_codes) {
    if (const Code* c = codes_.find(e.letter, e.code)) (this->*(c->handler))(e.code);
  }
  modal_ = work_;
}

bool Executor::run_evaluated(const EvaluatedBlock& block, const std::function<bool()>& after) {
  begin_block(block);
  comments();
  bool ok = true;
  for (const EvaluatedWord& w : block.words) {
    if (!(ok = import(w))) break;
  }
  ok = ok && execute() && (!after || after());
  end_block(ok);
  return ok;
}

void Executor::begin_block(const EvaluatedBlock& block) {
  at(block.loc);
  words_.reset();
  block_codes_.clear();
  comments_ = block.comments;
}

void Executor::comments() {
  for (const CommentText& c : comments_) {
    in_order([this, text = std::string(c.text)] { machine_.emit(canon::Comment{text}); });
  }
}

bool Executor::import(const EvaluatedWord& w) {
  if (w.letter == 'G' || w.letter == 'M') return import_code(w.letter, w.value, w.col);
  return import_word(w);
}

// A G or M code as written (G01: 1, G38.2 would be 38.2) into its group:
// romi's codes are whole numbers, looked up in tenths.
bool Executor::import_code(char letter, double value, std::uint32_t col) {
  const double tenths = std::round(value * 10.0);
  if (!(value >= 0 && tenths <= CodeTable::kMaxTenths) || std::fabs(value * 10.0 - tenths) > 1e-6) {
    return error(letter == 'G' ? core::Code::UnknownGCode : core::Code::UnknownMCode, col,
                 fmt::format("{}{} is not a code", letter, value));
  }
  const Code* c = codes_.find(letter, static_cast<int>(tenths));
  if (c == nullptr) {
    return error(letter == 'G' ? core::Code::UnknownGCode : core::Code::UnknownMCode, col,
                 fmt::format("{} is not a code of the {} dialect",
                             code_name(letter, static_cast<int>(tenths)), codes_.dialect_name()));
  }
  if (const Code* other = block_codes_.place(*c)) {
    return error(core::Code::ModalGroupConflict, col,
                 fmt::format("{} and {} are in the same group; one per block",
                             code_name(other->entry->letter, other->entry->code),
                             code_name(letter, static_cast<int>(tenths))));
  }
  return true;
}

bool Executor::import_word(const EvaluatedWord& w) {
  if (words_.has(w.letter)) {
    return error(core::Code::RepeatedWord, w.col,
                 fmt::format("{} word appears twice in the block", w.letter));
  }
  words_.set(w.letter, w.value, w.incremental, w.col);
  return true;
}

bool Executor::execute() {
  if (!values()) return false;
  moved_by_handler_ = false;
  const auto run = [this](const Code& c) { return (this->*(c.handler))(c.entry->code); };
  if (!block_codes_.each(0, codes_.first_after_move(), run)) return false;
  if (!move()) return false;
  if (const char c = words_.untaken()) {
    return error(core::Code::UnusedWord, words_.col(c),
                 fmt::format("{} word with no code of the block that uses it", c));
  }
  return block_codes_.each(codes_.first_after_move(), codes_.ranks(), run);
}

void Executor::end_block(bool ok) {
  comments_ = {};
  if (ok && !machine_.faulted()) {
    modal_ = work_;
  } else {
    work_ = modal_;
  }
}

bool Executor::finish() {
  if (work_.blend) {
    at(work_.blend->loc);
    return error(core::Code::BlendNeedsMove, 0,
                 "an arc with only R blends into the next move, and the program ends");
  }
  if (auto e = work_.comp.flush(machine_); !e) return error(e.error());
  modal_ = work_;
  return true;
}

std::optional<double> Executor::take_whole(char letter, int lo, int hi) {
  const auto v = words_.take(letter);
  if (!v) return std::nullopt;
  const double r = std::round(*v);
  if (!(std::fabs(*v - r) <= 1e-4 && r >= lo && r <= hi)) {
    error(core::Code::BadWordValue, words_.col(letter),
          fmt::format("{}{} must be a whole number from {} to {}", letter, *v, lo, hi));
    return std::nullopt;
  }
  return r;
}

// F, S, T and O: values every block may carry.
bool Executor::values() {
  if (auto f = words_.take('F')) {
    if (*f < 0) return error(core::Code::BadWordValue, words_.col('F'), "negative feed rate");
    work_.machine.feed = mm(*f);
    in_order([this, f = work_.machine.feed] { machine_.set_feed(f, FeedMode::UnitsPerMinute); });
  }
  if (auto s = words_.take('S')) {
    if (*s < 0) return error(core::Code::BadWordValue, words_.col('S'), "negative spindle speed");
    work_.machine.speed = *s;
  }
  if (words_.has('T')) {
    auto t = take_whole('T', 0, kMaxToolNumber);
    if (!t) return false;
    work_.machine.selected_tool = static_cast<int>(*t);
  }
  if (words_.has('O')) {
    auto o = take_whole('O', 0, 999);
    if (!o) return false;
    work_.offset_register = static_cast<int>(*o);
  }
  return true;
}

// Work that must come out in order with the moves compensation holds.
void Executor::in_order(std::function<void()> effect) {
  if (!work_.comp.holding()) {
    effect();
    return;
  }
  work_.comp.defer(
      run_.loc(), [effect = std::move(effect)](MotionTarget&) { effect(); }, machine_);
}

}  // namespace usina::gcode::romi
