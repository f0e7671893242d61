// Work coordinate systems of the fanuc dialect (docs/fanuc.md §7, "G10
// offsets", "G54.1"): G54-G59 are the interpreter's, each holding Fanuc's
// offset plus the external work offset (EXT, G10 L2 P0, #5201-), which
// shifts every system; the 48 additional systems of G54.1 P1-P48 (G10 L20,
// #7001-) are kept here and the active one is loaded into the interpreter's
// G59.3 slot, a system Fanuc does not have.
#include <cmath>

#include <fmt/format.h>

#include "gcode/fanuc/engine.hpp"

namespace usina::gcode::fanuc {
namespace {

constexpr int kSlot = 9;  // the interpreter's G59.3
constexpr long kAdditionalSystems = 48;

bool is_rotary(int axis) {
  return axis >= 3 && axis <= 5;
}

int offset_parameter(long system, int axis) {
  return static_cast<int>(5201 + 20 * system + axis);
}

long axis_of(char letter) {
  const std::size_t a = std::string_view(kAxisLetters).find(letter);
  return a == std::string_view::npos ? -1 : static_cast<long>(a);
}

}  // namespace

double Engine::program_units(int axis, double machine_value) const {
  if (is_rotary(axis)) return machine_value;
  return machine_value * core::mm_per(options_.machine_units) / core::mm_per(interp_.state().units);
}

double Engine::machine_units(int axis, double program_value) const {
  if (is_rotary(axis)) return program_value;
  return program_value * core::mm_per(interp_.state().units) / core::mm_per(options_.machine_units);
}

// A parameter file's EXT (#5201-) shifts the systems it was read with.
void Engine::apply_start_external() {
  if (external_ == Axes{}) return;
  for (long system = 1; system <= 6; ++system) {
    for (int a = 0; a < kAxisCount; ++a) {
      const int n = offset_parameter(system, a);
      interp_.set_parameter(n,
                            interp_.parameters().get(n) + external_[static_cast<std::size_t>(a)]);
    }
  }
  if (const TapeBlock first = tape_.cut(main_start_); !first.end) reselect(first);
}

// The interpreter applies a system's parameters when it is selected: select
// the active one again after its parameters changed.
bool Engine::reselect(const TapeBlock& b) {
  const int n = interp_.state().coord_system;
  return hand(b, {{'G', n <= 6 ? 53.0 + n : 59.3}});
}

// The active G54.1 system (plus EXT) into the G59.3 slot.
bool Engine::load_additional(const TapeBlock& b) {
  if (additional_p_ == 0) return true;
  const auto p = static_cast<std::size_t>(additional_p_);
  for (int a = 0; a < kAxisCount; ++a) {
    const auto i = static_cast<std::size_t>(a);
    interp_.set_parameter(offset_parameter(kSlot, a), additional_[p][i] + external_[i]);
  }
  return interp_.state().coord_system != kSlot || reselect(b);
}

// G54.1 P n, or G54 P n: an additional system, given to the interpreter as
// G59.3. G54-G59 without P leave the additional systems.
bool Engine::work_codes(const TapeBlock& b, Words& w) {
  // P in a G54 block is G54.1's, unless the block has its own use for P.
  const bool own_p = w.has_g(100) || w.has_g(40) || w.has_m(98) || w.has_m(99);
  const bool additional = w.has_g(541) || (w.has_g(540) && w.has('P') && !own_p);
  if (!additional) {
    for (int g = 540; g <= 590; g += 10)
      if (w.has_g(g)) additional_p_ = 0;
    return true;
  }
  const NcWord* p = w.find('P');
  // P left out is P1 (manual).
  const long n = p != nullptr ? std::lround(p->raw) : 1;
  if (n < 1 || n > kAdditionalSystems || (p != nullptr && p->raw != std::floor(p->raw))) {
    return error(core::Code::BadWordValue, b, p != nullptr ? p->pos : 0,
                 fmt::format("G54.1 P takes 1..{} (the additional work coordinate systems)",
                             kAdditionalSystems));
  }
  w.take_g(541);
  w.take_g(540);
  w.take('P');
  additional_p_ = n;
  if (!load_additional(b)) return false;
  w.add({'G', 59.3, 59.3, false, false, false, 0});
  return true;
}

// G10 L2 P0-P6 and L20 P1-P48 (G90 sets, G91 adds), L50 (parameter input).
bool Engine::work_offset(const TapeBlock& b, Words& w, long l) {
  if (l == 50) {
    for (const NcWord& word : w.list) {
      if (!word.taken && word.letter != 'G' && word.letter != 'L') {
        return error(core::Code::NotAllowedInMode, b, word.pos,
                     "G10 L50 (parameter input) stands alone in its block");
      }
    }
    w.take_g(100);
    w.take('L');
    parameter_mode_ = true;
    return true;
  }
  if (l == 20) return additional_offset(b, w);
  const NcWord* pw = w.find('P');
  const long p = pw != nullptr ? std::lround(pw->raw) : -1;
  if (l != 2) {
    return error(
        core::Code::BadWordValue, b, 0,
        fmt::format("G10 L{} is not a Fanuc milling data setting (L2, L10-L13, L20, L50)", l));
  }
  if (p < 0 || p > 6) {
    return error(core::Code::BadWordValue, b, pw != nullptr ? pw->pos : 0,
                 "G10 L2 P takes 0..6 (0: external work offset, 1..6: G54..G59)");
  }
  const bool incremental = w.has_g(910) || (interp_.state().incremental && !w.has_g(900));
  Axes given{};
  std::array<bool, 9> named{};
  for (NcWord& word : w.list) {
    const long a = axis_of(word.letter);
    if (word.taken || word.vacant || a < 0) continue;
    const auto i = static_cast<std::size_t>(a);
    named[i] = true;
    given[i] = word.value;
    // The interpreter stores what it is given: Fanuc's value plus EXT, and
    // in G91 the stored value too (LinuxCNC's G10 always sets).
    const double stored = incremental
                              ? interp_.parameters().get(offset_parameter(p, static_cast<int>(a)))
                              : external_[i];
    if (p != 0) word.value += program_units(static_cast<int>(a), stored);
  }
  if (p != 0) return true;
  w.take_g(100);
  for (char c : std::string_view("LPXYZABCUVW"))
    w.take(c);
  for (std::size_t i = 0; i < given.size(); ++i) {
    if (named[i]) {
      given[i] = machine_units(static_cast<int>(i), given[i]) + (incremental ? external_[i] : 0.0);
    }
  }
  return external_offset(b, given, named);
}

// EXT changed: every system moves by the difference.
bool Engine::external_offset(const TapeBlock& b, const Axes& value,
                             const std::array<bool, 9>& given) {
  for (int a = 0; a < kAxisCount; ++a) {
    const auto i = static_cast<std::size_t>(a);
    if (!given[i]) continue;
    const double shift = value[i] - external_[i];
    external_[i] = value[i];
    for (long system = 1; system <= 6; ++system) {
      const int n = offset_parameter(system, a);
      interp_.set_parameter(n, interp_.parameters().get(n) + shift);
    }
  }
  if (additional_p_ != 0) return load_additional(b);
  return reselect(b);
}

// G10 L20 P n X Y Z ...: the additional system n (G90 sets, G91 adds).
bool Engine::additional_offset(const TapeBlock& b, Words& w) {
  const NcWord* pw = w.find('P');
  const long n = pw != nullptr ? std::lround(pw->raw) : -1;
  if (n < 1 || n > kAdditionalSystems) {
    return error(core::Code::BadWordValue, b, pw != nullptr ? pw->pos : 0,
                 fmt::format("G10 L20 P takes 1..{} (G54.1 P1..P{})", kAdditionalSystems,
                             kAdditionalSystems));
  }
  const bool incremental = w.has_g(910) || (interp_.state().incremental && !w.has_g(900));
  Axes& system = additional_[static_cast<std::size_t>(n)];
  for (NcWord& word : w.list) {
    const long a = axis_of(word.letter);
    if (word.taken || word.vacant || a < 0) continue;
    const double v = machine_units(static_cast<int>(a), word.value);
    double& slot = system[static_cast<std::size_t>(a)];
    slot = incremental ? slot + v : v;
  }
  w.take_g(100);
  for (char c : std::string_view("LPXYZABCUVW"))
    w.take(c);
  return n != additional_p_ || load_additional(b);
}

// #4130, #5201-, #5221-#5329 (Fanuc's values, without EXT), #7001-#7960.
std::optional<double> Engine::work_variable(long index) const {
  if (index == 4130) return static_cast<double>(additional_p_);
  const long axis = index % 20 - 1;
  if (axis < 0 || axis >= kAxisCount) return std::nullopt;
  const auto i = static_cast<std::size_t>(axis);
  if (index >= 5201 && index <= 5209) return external_[i];
  if (index >= 5221 && index <= 5329)
    return interp_.parameters().get(static_cast<int>(index)) - external_[i];
  if (index >= 7001 && index <= 7000 + 20 * kAdditionalSystems)
    return additional_[static_cast<std::size_t>((index - 7001) / 20 + 1)][i];
  return std::nullopt;
}

// The writable ones of work_variable(); nullopt when `index` is not one.
std::optional<bool> Engine::write_work_variable(long index, double v, const TapeBlock& b) {
  const long axis = index % 20 - 1;
  if (axis < 0 || axis >= kAxisCount) return std::nullopt;
  const auto i = static_cast<std::size_t>(axis);
  if (index >= 5201 && index <= 5209) {
    Axes value = external_;
    std::array<bool, 9> given{};
    value[i] = v;
    given[i] = true;
    return external_offset(b, value, given);
  }
  if (index >= 5221 && index <= 5329) {
    interp_.set_parameter(static_cast<int>(index), v + external_[i]);
    const long system = (index - 5201) / 20;
    return interp_.state().coord_system != system || reselect(b);
  }
  if (index >= 7001 && index <= 7000 + 20 * kAdditionalSystems) {
    const long n = (index - 7001) / 20 + 1;
    additional_[static_cast<std::size_t>(n)][i] = v;
    return n != additional_p_ || load_additional(b);
  }
  return std::nullopt;
}

}  // namespace usina::gcode::fanuc
