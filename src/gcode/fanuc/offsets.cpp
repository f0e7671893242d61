// The fanuc dialect's offset registers (docs/fanuc.md §7, "The offset
// file"): H (tool length) and D (cutter radius), each geometry + wear, read
// from the control's offset page as a small TOML file, used by G43/G44 H
// and G41/G42 D, written by G10 L10-L13 and read as #2001-#2800.
#include <cmath>
#include <filesystem>

#include <fmt/format.h>

#include "gcode/fanuc/engine.hpp"
#include "gcode/word_range.hpp"

namespace usina::gcode::fanuc {
namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t'))
    s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r'))
    s.remove_suffix(1);
  return s;
}

std::optional<double> parse_number(std::string_view s) {
  s = trim(s);
  if (s.empty()) return std::nullopt;
  std::string text(s);
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size()) return std::nullopt;
  return v;
}

}  // namespace

// Lines: '[H]' or '[D]', then 'n = [geometry, wear]' or 'n = value'; '#'
// starts a comment.
bool Engine::read_offsets(const std::string& path) {
  std::string why;
  auto file = core::SourceFile::open(path, why);
  if (!file) {
    diags_.report(
        {core::Code::FileNotFound, core::Severity::Error, {}, fmt::format("{}: {}", path, why)});
    return false;
  }
  const std::uint32_t id = sources_.add(std::move(file));
  const std::string_view text = sources_.get(id)->text();
  std::map<long, std::array<double, 2>>* table = nullptr;
  std::uint32_t line = 0;
  for (std::size_t start = 0; start < text.size();) {
    ++line;
    std::size_t nl = text.find('\n', start);
    if (nl == std::string_view::npos) nl = text.size();
    std::string_view l = text.substr(start, nl - start);
    start = nl + 1;
    if (const std::size_t hash = l.find('#'); hash != std::string_view::npos) l = l.substr(0, hash);
    l = trim(l);
    if (l.empty()) continue;
    auto bad = [&](const std::string& what) {
      diags_.report({core::Code::BadToolTable,
                     core::Severity::Error,
                     {id, line, 1, 1, 0},
                     fmt::format("offset file: {}", what)});
      return false;
    };
    if (l == "[H]" || l == "[D]") {
      table = l == "[H]" ? &h_regs_ : &d_regs_;
      continue;
    }
    const std::size_t eq = l.find('=');
    if (table == nullptr || eq == std::string_view::npos)
      return bad("expected [H], [D] or 'register = [geometry, wear]'");
    auto reg = parse_number(l.substr(0, eq));
    if (!reg || *reg < 0 || *reg > 99999999 || *reg != std::floor(*reg))
      return bad("a register number is a whole number");
    std::string_view v = trim(l.substr(eq + 1));
    std::array<double, 2> entry{0, 0};
    if (!v.empty() && v.front() == '[' && v.back() == ']') {
      v = v.substr(1, v.size() - 2);
      const std::size_t comma = v.find(',');
      auto g = parse_number(v.substr(0, comma));
      auto w = comma == std::string_view::npos ? std::optional<double>(0.0)
                                               : parse_number(v.substr(comma + 1));
      if (!g || !w) return bad("expected [geometry, wear]");
      entry = {*g, *w};
    } else {
      auto g = parse_number(v);
      if (!g) return bad("expected a number or [geometry, wear]");
      entry = {*g, 0};
    }
    (*table)[static_cast<long>(*reg)] = entry;
  }
  return true;
}

double Engine::offset_register(bool h, long n, const TapeBlock& b) {
  if (n <= 0 || n > 99'999'999) return 0.0;
  const auto& table = h ? h_regs_ : d_regs_;
  auto it = table.find(n);
  if (it == table.end()) {
    if (warned_registers_.insert((h ? 1 : -1) * n).second) {
      warn(core::Code::UnknownRegister, b, 0,
           fmt::format("offset register {}{} is not in the offset file (--offsets): taken as 0",
                       h ? 'H' : 'D', n));
    }
    return 0.0;
  }
  return it->second[0] + it->second[1];
}

// G43/G44 H and G41/G42 D name offset registers: the interpreter is given
// the values (G43.1 Z, G41.1/G42.1 D diameter).
bool Engine::offset_codes(const TapeBlock& b, Words& w) {
  // H and D select registers (modal, #4111 #4107), also outside G43/G41.
  const NcWord* h = w.find('H');
  const NcWord* d = w.find('D');
  if (h != nullptr) h_register_ = std::lround(h->raw);
  if (d != nullptr) d_register_ = std::lround(d->raw);
  const bool g43 = w.has_g(430), g44 = w.has_g(440);
  if (g43 || g44) length_sign_ = g43 ? 1 : -1;
  if (w.has_g(490)) length_sign_ = 0;
  if (g43 || g44 || (h != nullptr && length_sign_ != 0)) {
    // The offset first, in a block of its own: 'G43 H1 Z50.' then moves
    // to Z50 with it, as on the control.
    const double v = length_sign_ * offset_register(true, h_register_, b);
    if (const auto ok = word_out_of_range('H', v); !ok) {
      return error(core::Code::ValueOutOfRange, b, h != nullptr ? h->pos : 0,
                   fmt::format("the length in offset register H{}: {}", h_register_, ok.error()));
    }
    if (!hand(b, {{'G', 43.1}, {'Z', v}})) return false;
  }
  w.take_g(430);
  w.take_g(440);
  w.take('H');
  w.take('D');
  const bool g41 = w.has_g(410), g42 = w.has_g(420);
  if (g41 || g42) comp_side_ = g41 ? 41 : 42;
  if (w.has_g(400)) comp_side_ = 40;
  if (g41 || g42 || (d != nullptr && comp_side_ != 40)) {
    const double r = offset_register(false, d_register_, b);
    int side = comp_side_;
    if (r < 0) side = side == 41 ? 42 : 41;  // a negative radius swaps the side
    w.take_g(410);
    w.take_g(420);
    const double g = side + 0.1;
    w.add({'G', g, g, false, false, false, 0});
    w.add({'D', 2 * std::fabs(r), 2 * std::fabs(r), false, false, false, 0});
  }
  return true;
}

// G10 L10-L13 P n R v: the four columns of the offset page.
bool Engine::write_register(const TapeBlock& b, Words& w, long l) {
  const long n = std::lround(w.get('P', -1));
  if (n < 1)
    return error(core::Code::BadWordValue, b, 0, fmt::format("G10 L{} needs P (the register)", l));
  auto& entry = (l <= 11 ? h_regs_ : d_regs_)[n];
  double& slot = entry[static_cast<std::size_t>(l % 2 == 0 ? 0 : 1)];
  const bool incremental = w.has_g(910) || (interp_.state().incremental && !w.has_g(900));
  const double v = w.get('R', 0.0);
  slot = incremental ? slot + v : v;
  w.take_g(100);
  for (char c : std::string_view("LPR"))
    w.take(c);
  return true;
}

std::optional<double> Engine::register_variable(long index) const {
  if (index < 2001 || index > 2800) return std::nullopt;
  const long k = index - 2001;
  const long n = k % 200 + 1;
  const bool h = k < 400;
  const std::size_t column = (k / 200) % 2 == 0 ? 1 : 0;  // wear, then geometry
  const auto& table = h ? h_regs_ : d_regs_;
  auto it = table.find(n);
  return it == table.end() ? 0.0 : it->second[column];
}

}  // namespace usina::gcode::fanuc
