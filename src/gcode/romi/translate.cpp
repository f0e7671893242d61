#include "gcode/romi/translate.hpp"

#include <array>
#include <cmath>

#include <fmt/format.h>

#include "core/copy_in_pieces.hpp"

namespace usina::gcode::romi {
namespace {

struct NamedHandler {
  std::string_view name;
  Handler handler;
};

}  // namespace

Handler Translator::handler_named(std::string_view name) {
  // The names the dialect's table uses (romi/dialect.cpp).
  static constexpr std::array kHandlers = {
      NamedHandler{"motion", &Translator::h_motion},
      NamedHandler{"plane", &Translator::h_plane},
      NamedHandler{"distance", &Translator::h_distance},
      NamedHandler{"units", &Translator::h_units},
      NamedHandler{"retract", &Translator::h_retract},
      NamedHandler{"comp", &Translator::h_comp},
      NamedHandler{"cycle", &Translator::h_cycle},
      NamedHandler{"mirror", &Translator::h_mirror},
      NamedHandler{"scale", &Translator::h_scale},
      NamedHandler{"rotate", &Translator::h_rotate},
      NamedHandler{"grid", &Translator::h_grid},
      NamedHandler{"bolt_circle", &Translator::h_bolt_circle},
      NamedHandler{"pocket", &Translator::h_pocket},
      NamedHandler{"tool_change", &Translator::h_tool_change},
      NamedHandler{"spindle", &Translator::h_spindle},
      NamedHandler{"coolant", &Translator::h_coolant},
      NamedHandler{"stop", &Translator::h_stop},
      NamedHandler{"end", &Translator::h_end},
  };
  for (const NamedHandler& h : kHandlers) {
    if (h.name == name) return h.handler;
  }
  return nullptr;
}

Translator::Translator(const CodeTable& codes, Services& run, const InterpOptions& options,
                       const Options& dialect_options, Interpreter& interp)
    : codes_(codes),
      run_(run),
      options_(options),
      dialect_options_(dialect_options),
      interp_(interp) {
  pending_.reserve(16);
  work_.pos = options.start;
  work_.machine_at = options.start;
}

// The dialect's start codes set romi's modes; the interpreter is set to
// read what it is handed: millimetres, absolute, arc centres absolute.
void Translator::start(const std::vector<CodeEntry>& start_codes, const core::SourceLoc& loc) {
  at(loc);
  for (const CodeEntry& e : start_codes) {
    if (const Code* c = codes_.find(e.letter, e.code)) (this->*(c->handler))(e.code);
  }
  pending_.clear();
  give('G', 21);
  give('G', 90);
  give('G', 90.1);
  hand();
  modal_ = work_;
}

bool Translator::run_evaluated(const EvaluatedBlock& block, const std::function<bool()>& after) {
  begin_block(block);
  bool ok = hand_comments();
  for (const EvaluatedWord& w : block.words) {
    if (!(ok = ok && import(w))) break;
  }
  ok = ok && execute() && (!after || after());
  // The words given before romi refused the block (F, M03...) ran on the
  // control before the error, as the moves before it did.
  if (!interp_failed_) {
    at(block.loc);  // an error of a held blend arc pointed at the blend's block
    ok = hand() && ok;
  }
  end_block(ok);
  return ok;
}

void Translator::begin_block(const EvaluatedBlock& block) {
  at(block.loc);
  words_.reset();
  block_codes_.clear();
  // The span's pointer and size read one by one: the caller has just
  // stored them so, and a 16-byte read of both waits for the two stores
  // to land (a failed store forward; 1.5 % of romi's check, issue 19).
  comments_ = std::span(block.comments.data(), block.comments.size());
  pending_.clear();
}

bool Translator::import(const EvaluatedWord& w) {
  if (w.letter == 'G' || w.letter == 'M') return import_code(w.letter, w.value, w.col);
  return import_word(w);
}

// A G or M code as written (G01: 1, G38.2 would be 38.2) into its group:
// romi's codes are whole numbers, looked up in tenths.
bool Translator::import_code(char letter, double value, std::uint32_t col) {
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

bool Translator::import_word(const EvaluatedWord& w) {
  if (words_.has(w.letter)) {
    return error(core::Code::RepeatedWord, w.col,
                 fmt::format("{} word appears twice in the block", w.letter));
  }
  words_.set(w.letter, w.value, w.incremental, w.col);
  return true;
}

bool Translator::execute() {
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

void Translator::end_block(bool ok) {
  comments_ = {};
  if (ok) {
    core::copy_in_pieces(modal_, work_);
  } else {
    core::copy_in_pieces(work_, modal_);
  }
}

bool Translator::finish() {
  if (work_.blend) {
    at(work_.blend->loc);
    return error(core::Code::BlendNeedsMove, 0,
                 "an arc with only R blends into the next move, and the program ends");
  }
  return true;
}

std::optional<double> Translator::take_whole(char letter, int lo, int hi) {
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
bool Translator::values() {
  if (auto f = words_.take('F')) {
    if (*f < 0) return error(core::Code::BadWordValue, words_.col('F'), "negative feed rate");
    work_.machine.feed = mm(*f);
    give('F', work_.machine.feed);
  }
  if (auto s = words_.take('S')) {
    if (*s < 0) return error(core::Code::BadWordValue, words_.col('S'), "negative spindle speed");
    work_.machine.speed = *s;
    give('S', *s);
  }
  if (words_.has('T')) {
    auto t = take_whole('T', 0, kMaxToolNumber);
    if (!t) return false;
    work_.machine.selected_tool = static_cast<int>(*t);
    give('T', *t);
  }
  if (words_.has('O')) {
    auto o = take_whole('O', 0, 999);
    if (!o) return false;
    work_.offset_register = static_cast<int>(*o);
  }
  return true;
}

}  // namespace usina::gcode::romi
