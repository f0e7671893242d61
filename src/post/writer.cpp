#include "post/writer.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <type_traits>

#include <fmt/format.h>

#include "core/arc.hpp"

namespace usina::post {

using core::Vec3;

Writer::Writer(std::ostream& out, Control control, const PostOptions& options,
               core::DiagnosticSink& diags)
    : control_(std::move(control)),
      options_(options),
      out_(out, control_, options.line_numbers),
      diags_(diags) {
  if (options_.decimals >= 0) control_.decimals = options_.decimals;
}

void Writer::append(std::string& words, const std::string& w) {
  if (w.empty()) return;
  if (!words.empty()) words += ' ';
  words += w;
}

std::string Writer::code(char letter, int n) const {
  return control_.two_digit_codes ? fmt::format("{}{:02}", letter, n)
                                  : fmt::format("{}{}", letter, n);
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
  control_.footer(out_, options_);
}

void Writer::finish() {
  end();
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
          feed(k.to, k.f, k.abc, op);
        } else if constexpr (std::is_same_v<T, canon::Arc>) {
          arc(k, op);
        } else if constexpr (std::is_same_v<T, canon::Spline>) {
          for (const Vec3& p : k.points)
            feed(p, k.f, canon::Abc{}, op);
        } else if constexpr (std::is_same_v<T, canon::Probe>) {
          if (!control_.probe) return unsupported(op, "a probing move");
          cancel_cycle();
          std::string w = "G38.2";
          motion_.clear();
          append(w, axis_words(k.to, k.abc, op));
          out_.block(w);
          pos_ = k.to;
        } else if constexpr (std::is_same_v<T, canon::Dwell>) {
          out_.block(fmt::format("{} {}{}", code('G', 4), control_.dwell_word, out_.number(k.s)));
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
        }
        // A Pocket is a drawing's feature; its moves are in the stream.
      },
      op.kind);
}

std::string Writer::axis_words(const Vec3& to, const canon::Abc& abc, const canon::Op& op) {
  static constexpr char kLetters[] = {'X', 'Y', 'Z', 'A', 'B', 'C'};
  std::string w;
  for (std::size_t i = 0; i < 6; ++i) {
    const double v = i < 3 ? to[static_cast<int>(i)] : abc[i - 3];
    if (i >= 3 && !control_.rotary_axes) {
      if (out_.rounded(v) != 0.0) unsupported(op, "a rotary axis move");
      continue;
    }
    const double r = out_.rounded(v);
    if (axes_[i] && *axes_[i] == r) continue;
    if (i >= 3 && !axes_[i] && r == 0.0) continue;  // rotary axes start at 0
    axes_[i] = r;
    append(w, fmt::format("{}{}", kLetters[i], out_.number(v)));
  }
  return w;
}

std::string Writer::motion_word(const char* g) {
  if (motion_ == g) return {};
  motion_ = g;
  return g;
}

std::string Writer::feed_word(std::optional<double> f, const canon::Op& op) {
  if (!f) {
    // Inverse-time and per-revolution feeds come as moves without a rate.
    if (!feed_) unsupported(op, "a feed move without a feed rate in mm/min");
    return {};
  }
  last_feed_ = f;
  const double r = out_.rounded(*f);
  if (feed_ && *feed_ == r) return {};
  feed_ = r;
  return "F" + out_.number(*f);
}

void Writer::cancel_cycle() {
  if (motion_ != code('G', 81) && motion_ != code('G', 83)) return;
  out_.block(code('G', 80));
  motion_.clear();
  cycle_z_.reset();
  cycle_r_.reset();
  cycle_q_.reset();
}

void Writer::traverse(const canon::Traverse& t, const canon::Op& op) {
  cancel_cycle();
  const std::string axes = axis_words(t.to, t.abc, op);
  pos_ = t.to;
  pos_known_ = true;
  if (axes.empty()) return;
  std::string w = motion_word(code('G', 0).c_str());
  append(w, axes);
  out_.block(w);
}

void Writer::feed(const Vec3& to, std::optional<double> f, const canon::Abc& abc,
                  const canon::Op& op) {
  cancel_cycle();
  const std::string axes = axis_words(to, abc, op);
  pos_ = to;
  pos_known_ = true;
  if (axes.empty()) return;
  std::string w = motion_word(code('G', 1).c_str());
  append(w, axes);
  append(w, feed_word(f, op));
  out_.block(w);
}

}  // namespace usina::post
