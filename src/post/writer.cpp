#include "post/writer.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <type_traits>

#include <fmt/format.h>

#include "core/arc.hpp"

namespace usina::post {

using core::Vec3;

namespace {

Control with_options(Control c, const PostOptions& o) {
  if (o.decimals >= 0) c.decimals = o.decimals;
  return c;
}

}  // namespace

Writer::Writer(std::ostream& out, Control control, const PostOptions& options,
               core::DiagnosticSink& diags)
    : control_(with_options(std::move(control), options)),
      options_(options),
      out_(out, control_, options.line_numbers),
      diags_(diags),
      g0_(code('G', 0)),
      g1_(code('G', 1)),
      g81_(code('G', 81)),
      g83_(code('G', 83)),
      g85_(code('G', 85)),
      g86_(code('G', 86)),
      g89_(code('G', 89)) {}

void Writer::append(std::string& words, const std::string& w) {
  if (w.empty()) return;
  if (!words.empty()) words += ' ';
  words += w;
}

std::string Writer::code(char letter, int n) const {
  return control_.two_digit_codes ? fmt::format("{}{:02}", letter, n)
                                  : fmt::format("{}{}", letter, n);
}

// A P or Q of the machine's code as it came: a whole number (a relay, a
// pallet) without the point a Fanuc distance gets.
std::string Writer::machine_word(double v) const {
  if (v == std::floor(v) && std::fabs(v) < 1e15)
    return fmt::format("{}", static_cast<long long>(v));
  return out_.number(v);
}

void Writer::unsupported(const canon::Op& op, const std::string& what) {
  diags_.report({core::Code::Unsupported, core::Severity::Error, op.src,
                 fmt::format("the {} post cannot write {}", control_.name, what)});
}

void Writer::start() {
  if (started_) return;
  started_ = true;
  control_.header(out_, options_);
}

void Writer::end() {
  if (ended_) return;
  start();
  cancel_cycle();
  ended_ = true;
  // One spindle stop and one coolant off at the end, whoever asked for them:
  // the program before (a generator ends with its own spindle stop) or the
  // writer here, for a program that did not.
  if (!spindle_stop_written_) out_.block(code('M', 5));
  if (!coolant_off_written_) out_.block(code('M', 9));
  out_.block(control_.program_end);
  if (control_.footer) control_.footer(out_, options_);
}

void Writer::finish() {
  end();
  out_.flush();
}

void Writer::on(const canon::Op& op) {
  start();
  if (ended_) return;  // nothing after the program end
  std::visit(
      [&](const auto& k) {
        using T = std::decay_t<decltype(k)>;
        if constexpr (std::is_same_v<T, canon::Traverse>) {
          traverse(k, op);
        } else if constexpr (std::is_same_v<T, canon::Feed>) {
          feed(k.to, k.f, k.abc, op, k.programmed);
        } else if constexpr (std::is_same_v<T, canon::Arc>) {
          arc(k, op);
        } else if constexpr (std::is_same_v<T, canon::Spline>) {
          spline(k, op);
        } else if constexpr (std::is_same_v<T, canon::Probe>) {
          if (!control_.probe) return unsupported(op, "a probing move");
          cancel_cycle();
          std::string w = "G38.2";
          motion_.clear();
          append(w, axis_words(k.to, k.abc, op));
          out_.block(w);
          pos_ = k.to;
        } else if constexpr (std::is_same_v<T, canon::Dwell>) {
          // romi's only dwell is G81's D: a G04 its reader refuses is no program.
          if (!control_.standalone_dwell)
            return unsupported(op, "a dwell: the control's only dwell is its drilling cycle's");
          dwell(k.s);
        } else if constexpr (std::is_same_v<T, canon::ToolChange>) {
          tool_change(k);
        } else if constexpr (std::is_same_v<T, canon::Spindle>) {
          spindle(k);
        } else if constexpr (std::is_same_v<T, canon::Coolant>) {
          coolant(k);
        } else if constexpr (std::is_same_v<T, canon::Hole>) {
          hole(k, op);
        } else if constexpr (std::is_same_v<T, canon::Comment>) {
          out_.block(out_.comment(k.text));
        } else if constexpr (std::is_same_v<T, canon::ProgramEnd>) {
          end();
        } else if constexpr (std::is_same_v<T, canon::MachineCode>) {
          // The machine's own, as it came.
          std::string w = code(k.letter, k.code);
          if (!control_.machine_codes) return unsupported(op, "the machine's " + w);
          if (k.p) w += " P" + machine_word(*k.p);
          if (k.q) w += " Q" + machine_word(*k.q);
          out_.block(w);
        }
        // A Pocket is a drawing's feature; its moves are in the stream.
      },
      op.kind);
}

std::string Writer::axis_words(const Vec3& to, const canon::Abc& abc, const canon::Op& op) {
  std::string w;
  append_axis_words(w, to, abc, op);
  return w;
}

void Writer::append_axis_words(std::string& w, const Vec3& to, const canon::Abc& abc,
                               const canon::Op& op) {
  static constexpr char kLetters[] = {'X', 'Y', 'Z', 'A', 'B', 'C'};
  for (std::size_t i = 0; i < 6; ++i) {
    const double v = i < 3 ? to[static_cast<int>(i)] : abc[i - 3];
    if (i >= 3 && !control_.rotary_axes) {
      // Remembered though never written, so that each move of the axis is
      // reported once, not every later move that leaves it where it is.
      const double r = out_.rounded(v);
      if (r != axes_[i].value_or(0.0)) unsupported(op, "a rotary axis move");
      axes_[i] = r;
      continue;
    }
    const double r = out_.rounded(v);
    if (axes_[i] && *axes_[i] == r) continue;
    if (i >= 3 && !axes_[i] && r == 0.0) continue;  // rotary axes start at 0
    axes_[i] = r;
    out_.append_rounded(w, kLetters[i], r);
  }
}

void Writer::dwell(double s) {
  out_.block(fmt::format("{} {}{}", code('G', 4), control_.dwell_word, out_.number(s)));
}

std::string Writer::motion_word(const char* g) {
  if (motion_ == g) return {};
  motion_ = g;
  return g;
}

void Writer::cancel_cycle() {
  if (motion_ != g81_ && motion_ != g83_ && motion_ != g85_ && motion_ != g86_ && motion_ != g89_)
    return;
  out_.block(code('G', 80));
  motion_.clear();
  cycle_z_.reset();
  cycle_r_.reset();
  cycle_q_.reset();
}

void Writer::traverse(const canon::Traverse& t, const canon::Op& op) {
  straight(g0_, t.to, std::nullopt, t.abc, op);
}

void Writer::feed(const Vec3& to, std::optional<double> f, const canon::Abc& abc,
                  const canon::Op& op, const canon::ProgrammedFeed& programmed) {
  straight(g1_, to, f, abc, op, programmed);
}

// The hot path (a generator's program is mostly these): one reused buffer.
void Writer::straight(const std::string& g, const Vec3& to, std::optional<double> f,
                      const canon::Abc& abc, const canon::Op& op,
                      const canon::ProgrammedFeed& programmed) {
  cancel_cycle();
  const bool rotary = moves_rotary(abc);
  const double length = pos_known_ ? core::norm(to - pos_) : 0.0;
  axes_buf_.clear();
  append_axis_words(axes_buf_, to, abc, op);
  pos_ = to;
  pos_known_ = true;
  if (axes_buf_.empty()) return;
  words_.clear();
  RateWords rate;
  if (&g == &g1_) rate = rate_words({f, programmed, length, rotary}, op);
  append(words_, rate.mode);
  if (motion_ != g) {
    motion_ = g;
    append(words_, g);
  }
  append(words_, axes_buf_);
  append(words_, rate.f);
  out_.block(words_);
}

}  // namespace usina::post
