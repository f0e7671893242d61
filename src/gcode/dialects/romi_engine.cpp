#include "gcode/dialects/romi_engine.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

#include <fmt/format.h>

#include "gcode/program_text.hpp"
#include "gcode/word_range.hpp"

namespace usina::gcode::romi {
namespace {

// Groups from this one on run after the block's move (romi.cpp).
constexpr int kAfterMove = 60;

std::string code_name(char letter, int code) {
  return code % 10 == 0 ? fmt::format("{}{:02}", letter, code / 10)
                        : fmt::format("{}{}.{}", letter, code / 10, code % 10);
}

}  // namespace

const std::unordered_map<std::string_view, Engine::Handler>& Engine::handlers() {
  static const std::unordered_map<std::string_view, Engine::Handler> map = {
      {"motion", &Engine::h_motion},     {"plane", &Engine::h_plane},
      {"distance", &Engine::h_distance}, {"units", &Engine::h_units},
      {"retract", &Engine::h_retract},   {"comp", &Engine::h_comp},
      {"cycle", &Engine::h_cycle},       {"mirror", &Engine::h_mirror},
      {"scale", &Engine::h_scale},       {"rotate", &Engine::h_rotate},
      {"grid", &Engine::h_grid},         {"bolt_circle", &Engine::h_bolt_circle},
      {"pocket", &Engine::h_pocket},     {"tool_change", &Engine::h_tool_change},
      {"spindle", &Engine::h_spindle},   {"coolant", &Engine::h_coolant},
      {"stop", &Engine::h_stop},         {"end", &Engine::h_end},
  };
  return map;
}

Vec2 Transform::apply(Vec2 p) const {
  Vec2 q = p;
  if (rotation_deg != 0.0) {
    const Vec2 r = core::rotate(Vec2{q.x - rotation_at.x, q.y - rotation_at.y},
                                core::deg_to_rad(rotation_deg));
    q = {r.x + rotation_at.x, r.y + rotation_at.y};
  }
  q = {q.x * scale_x, q.y * scale_y};
  if (mirror_x) q.x = 2.0 * mirror_at.x - q.x;
  if (mirror_y) q.y = 2.0 * mirror_at.y - q.y;
  return q;
}

Engine::Engine(const Dialect& dialect, RunContext context)
    : dialect_(dialect),
      sources_(context.sources),
      options_(std::move(context.options)),
      dialect_options_(std::move(context.dialect_options)),
      sink_(context.sink),
      diags_(context.diags),
      machine_(context.sink, machine_state_, context.diags) {
  // Options not given (a runner made without resolve_options): the defaults.
  for (const DialectOption& o : dialect_.options)
    dialect_options_.emplace(std::string(o.name), std::string(o.values.front()));
}

void Engine::set_parameter(int index, double value) {
  if (index >= 0 && index <= kMaxParam) params_[static_cast<std::size_t>(index)] = value;
}

double Engine::numbered(int) const {
  return 0.0;
}

std::optional<double> Engine::named(std::string_view name) const {
  // "p12": the parser only makes names of P and 1-3 digits.
  if (name.size() < 2 || name[0] != 'p') return std::nullopt;
  int n = 0;
  for (const char c : name.substr(1)) {
    if (c < '0' || c > '9') return std::nullopt;
    n = n * 10 + (c - '0');
    if (n > kMaxParam) return std::nullopt;
  }
  return params_[static_cast<std::size_t>(n)];
}

const std::string& Engine::option(std::string_view name) const {
  return dialect_options_.find(name)->second;
}

bool Engine::option_on(std::string_view name) const {
  return option(name) == "on";
}

bool Engine::incremental(char letter) const {
  return incremental_ || (words_.lower(letter) && option_on("lowercase_incremental"));
}

bool Engine::error(core::Code code, std::uint32_t col, std::string message) {
  core::SourceLoc loc = loc_;
  if (col > 0) {
    loc.col = col;
    loc.length = 1;
  }
  diags_.report({code, core::Severity::Error, loc, std::move(message)});
  failed_ = true;
  return false;
}

void Engine::note(core::Code code, core::Severity sev, std::uint32_t col, std::string message) {
  core::SourceLoc loc = loc_;
  if (col > 0) loc.col = col;
  diags_.report({code, sev, loc, std::move(message)});
}

std::optional<double> Engine::take_whole(char letter, int lo, int hi) {
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

bool Engine::run(std::uint32_t file) {
  file_ = file;
  cursor_ = {};
  const core::SourceFile* f = sources_.get(file);
  if (f == nullptr) return false;
  loc_ = {file, 1, 1, 0, 0};
  machine_.set_source(loc_);
  cursor_.offset = skip_byte_order_mark(f->text(), file, diags_);
  for (const CodeEntry& c : dialect_.start_codes) {
    auto h = handlers().find(c.handler);
    if (h != handlers().end()) (this->*(h->second))(c.code);
  }
  while (!ended_ && !failed_ && cursor_.offset < sources_.get(file_)->text().size()) {
    step();
    if (sink_.stopped()) failed_ = true;  // the operation budget ran out
    // The canonical machine refused an op for a number out of range (reported).
    if (machine_.faulted()) failed_ = true;
  }
  if (!failed_ && blend_) {
    loc_ = blend_->loc;
    error(core::Code::BlendNeedsMove, 0,
          "an arc with only R blends into the next move, and the program ends");
  }
  if (!failed_ && !ended_) {
    if (auto e = comp_.flush(machine_)) error(*e);
  }
  if (machine_.faulted()) failed_ = true;
  if (!failed_ && !ended_) {
    loc_ = {file, cursor_.line > 1 ? cursor_.line - 1 : 1, 0, 0, 0};
    note(core::Code::NoProgramEnd, core::Severity::Warning, 0,
         "the program ends without M02 or M30; taken as its end");
  }
  sink_.finish();
  return !failed_;
}

void Engine::step() {
  core::SourceFile* f = sources_.get(file_);
  const BlockText bt = block_at(f->text(), cursor_.offset);
  const auto col = static_cast<std::uint32_t>(cursor_.offset - cursor_.line_start + 1);
  const LinePos where{file_, cursor_.line, cursor_.line_start};
  cursor_.offset = bt.next;
  if (bt.ends_line) {
    ++cursor_.line;
    cursor_.line_start = bt.next;
  }
  if (auto too_long = block_too_long(bt.text, {file_, where.line, col, 1, where.offset})) {
    diags_.report(std::move(*too_long));
    failed_ = true;
    return;
  }
  if (!parse_romi_block(bt.text, where, col, block_, diags_)) {
    failed_ = true;
    return;
  }
  if (block_.base.percent) return;
  loc_ = block_.base.loc;
  machine_.set_source(loc_);
  if (!block()) {
    failed_ = true;
    return;
  }
  if (!ended_ && !failed_) after_block_number();
}

bool Engine::block() {
  for (const std::uint32_t dash : block_.dashes) {
    if (option("typographic_dash") == "error") {
      return error(core::Code::TypographicDash, dash,
                   "a typographic dash instead of '-' (typographic_dash=error)");
    }
    note(core::Code::TypographicDash, core::Severity::Warning, dash,
         "a typographic dash read as a minus sign");
  }
  for (const CommentText& c : block_.base.comments) {
    in_order([this, text = std::string(c.text)] { machine_.emit(canon::Comment{text}); });
  }
  if (!statements(false)) return false;
  if (!evaluate_words() || !values()) return false;
  moved_by_handler_ = false;
  explicit_motion_ = false;
  for (const auto& [entry, col] : codes_) {
    if (entry->group >= kAfterMove) break;
    if (!(this->*(handlers().at(entry->handler)))(entry->code)) return false;
  }
  if (!move()) return false;
  if (const char c = words_.untaken()) {
    return error(core::Code::UnusedWord, words_.col(c),
                 fmt::format("{} word with no code of the block that uses it", c));
  }
  for (const auto& [entry, col] : codes_) {
    if (entry->group < kAfterMove) continue;
    if (!(this->*(handlers().at(entry->handler)))(entry->code)) return false;
  }
  return statements(true);
}

bool Engine::evaluate_words() {
  words_.reset();
  codes_.clear();
  EvalError err;
  for (const RomiWord& w : block_.words) {
    const ExprNode& node = block_.base.expr(w.value);
    auto v = node.kind == ExprKind::Number ? std::optional<double>(node.value)
                                           : gcode::evaluate(block_.base, w.value, *this, err);
    if (!v) return error(err.error.code, err.col, err.error.message);
    if (auto why = word_out_of_range(w.letter, *v)) {
      return error(core::Code::ValueOutOfRange, w.col, *why);
    }
    if (w.letter == 'G' || w.letter == 'M') {
      const double tenths = std::round(*v * 10.0);
      if (!(*v >= 0 && tenths <= 9990) || std::fabs(*v * 10.0 - tenths) > 1e-6) {
        return error(w.letter == 'G' ? core::Code::UnknownGCode : core::Code::UnknownMCode, w.col,
                     fmt::format("{}{} is not a code", w.letter, *v));
      }
      if (!place(w.letter, static_cast<int>(tenths), w.col)) return false;
      continue;
    }
    if (words_.has(w.letter)) {
      return error(core::Code::RepeatedWord, w.col,
                   fmt::format("{} word appears twice in the block", w.letter));
    }
    words_.set(w.letter, *v, w.lower, w.col);
  }
  std::stable_sort(codes_.begin(), codes_.end(),
                   [](const auto& a, const auto& b) { return a.first->group < b.first->group; });
  return true;
}

bool Engine::place(char letter, int code, std::uint32_t col) {
  const CodeEntry* e = dialect_.find_code(letter, code);
  if (e == nullptr) {
    return error(
        letter == 'G' ? core::Code::UnknownGCode : core::Code::UnknownMCode, col,
        fmt::format("{} is not a code of the {} dialect", code_name(letter, code), dialect_.name));
  }
  for (const auto& [other, c] : codes_) {
    if (other->group == e->group) {
      return error(core::Code::ModalGroupConflict, col,
                   fmt::format("{} and {} are in the same group; one per block",
                               code_name(other->letter, other->code), code_name(letter, code)));
    }
  }
  codes_.emplace_back(e, col);
  return true;
}

// F, S, T and O: values every block may carry.
bool Engine::values() {
  if (auto f = words_.take('F')) {
    if (*f < 0) return error(core::Code::BadWordValue, words_.col('F'), "negative feed rate");
    feed_ = mm(*f);
    in_order([this, f = feed_] { machine_.set_feed(f, FeedMode::UnitsPerMinute); });
  }
  if (auto s = words_.take('S')) {
    if (*s < 0) return error(core::Code::BadWordValue, words_.col('S'), "negative spindle speed");
    machine_state_.speed = *s;
  }
  if (words_.has('T')) {
    auto t = take_whole('T', 0, kMaxToolNumber);
    if (!t) return false;
    selected_tool_ = static_cast<int>(*t);
  }
  if (words_.has('O')) {
    auto o = take_whole('O', 0, 999);
    if (!o) return false;
    offset_register_ = static_cast<int>(*o);
  }
  return true;
}

void Engine::in_order(std::function<void()> effect) {
  if (!comp_.holding()) {
    effect();
    return;
  }
  comp_.defer(
      loc_, [effect = std::move(effect)](MotionTarget&) { effect(); }, machine_);
}

bool Engine::h_plane(int) {
  return true;  // G17 only: the table has no G18/G19
}

bool Engine::h_distance(int code) {
  incremental_ = code == 910;
  return true;
}

bool Engine::h_units(int code) {
  units_ = code == 700 ? core::LengthUnit::Inch : core::LengthUnit::Mm;
  return true;
}

bool Engine::h_retract(int code) {
  retract_to_r_ = code == 990;
  return true;
}

bool Engine::h_motion(int code) {
  motion_ = code / 10;
  explicit_motion_ = true;
  if (option_on("motion_cancels_cycle")) drill_.active = false;
  return true;
}

bool Engine::h_comp(int code) {
  if (code == 400) {
    const auto programmed = comp_.programmed_position();
    if (auto e = comp_.stop(machine_)) return error(*e);
    if (programmed) set_xyz(machine_state_.pos, *programmed);
    return true;
  }
  if (comp_.active()) {
    return error(core::Code::CompNotAllowed, 0, "cutter compensation is already on: G40 first");
  }
  double diameter = tool_diameter_;
  if (option("comp_radius") == "register" && offset_register_ > 0) {
    if (const ToolEntry* t = options_.tools.find(offset_register_)) diameter = t->diameter;
  }
  double radius = options_.ignore_cutter_comp ? 0.0 : diameter / 2.0;
  // With one axis mirrored the part is drawn the other way round: the
  // side swaps (spec/romi.md, "Transformations").
  const bool left = (code == 410) != tf_.flips();
  if (auto e = comp_.start(left ? CompSide::Left : CompSide::Right, radius, core::Plane::XY)) {
    return error(*e);
  }
  return true;
}

std::optional<double> Engine::tool_diameter_from_comments() const {
  for (const CommentText& c : block_.base.comments) {
    const std::string_view t = c.text;
    for (std::size_t i = 0; i + 1 < t.size(); ++i) {
      const bool start = i == 0 || t[i - 1] == ' ' || t[i - 1] == '\t';
      if (!start || (t[i] != 'd' && t[i] != 'D')) continue;
      std::size_t j = i + 1;
      double v = 0.0;
      const auto r = std::from_chars(t.data() + j, t.data() + t.size(), v);
      if (r.ec == std::errc() && v > 0 && std::isfinite(v)) return v;
    }
  }
  return std::nullopt;
}

bool Engine::h_tool_change(int) {
  if (comp_.active()) {
    return error(core::Code::CompNotAllowed, 0,
                 "a tool change with cutter radius compensation on: G40 first");
  }
  if (selected_tool_ < 0) return error(core::Code::MissingWord, 0, "M06 with no T: give T<n>");
  const int tool = selected_tool_;
  std::optional<double> d;
  if (const ToolEntry* t = options_.tools.find(tool); t != nullptr && t->diameter > 0) {
    d = t->diameter;
  } else {
    d = tool_diameter_from_comments();
  }
  if (!d) {
    return error(core::Code::UnknownToolDiameter, 0,
                 fmt::format("the diameter of tool T{:02} is unknown: give a tool table "
                             "(--tool-table) or write d<diameter> in the block's comment",
                             tool));
  }
  const auto x = words_.take('X');
  const auto y = words_.take('Y');
  const Vec3 back = xyz(machine_state_.pos);
  // The tool-change position is the machine's, not a programmed point:
  // no transformation, and the program goes on from where it was.
  machine_.set_origin(canon::Origin::ToolChange);
  if (x || y) machine_.traverse({x ? mm(*x) : back.x, y ? mm(*y) : back.y, back.z});
  machine_state_.tool = tool;
  tool_diameter_ = *d;
  machine_.set_tool_diameter(*d);
  machine_.emit(canon::ToolChange{tool, *d});
  if (x || y) machine_.traverse(back);
  machine_.set_origin(canon::Origin::Program);
  return true;
}

bool Engine::h_spindle(int code) {
  const auto dir = code == 30 ? canon::SpindleDir::Cw
                              : (code == 40 ? canon::SpindleDir::Ccw : canon::SpindleDir::Off);
  in_order([this, dir] { machine_.spindle(dir); });
  return true;
}

bool Engine::h_coolant(int code) {
  if (code == 70) machine_state_.mist = true;
  if (code == 80) machine_state_.flood = true;
  if (code == 90) machine_state_.mist = machine_state_.flood = false;
  in_order(
      [this, c = canon::Coolant{machine_state_.mist, machine_state_.flood}] { machine_.emit(c); });
  return true;
}

bool Engine::h_stop(int code) {
  if (auto e = comp_.flush(machine_)) return error(*e);
  machine_.emit(canon::Comment{fmt::format("M{:02} (program stop)", code / 10)});
  return true;
}

bool Engine::h_end(int) {
  if (blend_) {
    return error(core::Code::BlendNeedsMove, 0,
                 "an arc with only R blends into the next move, and the program ends");
  }
  if (auto e = comp_.flush(machine_)) return error(*e);
  comp_.reset();
  if (machine_state_.spindle != canon::SpindleDir::Off) machine_.spindle(canon::SpindleDir::Off);
  machine_.emit(canon::ProgramEnd{});
  ended_ = true;
  return true;
}

}  // namespace usina::gcode::romi
