#include "gcode/dialect.hpp"

#include <algorithm>

#include <fmt/format.h>

namespace usina::gcode {

// Each dialect's file defines one of these.
const Dialect& rs274ngc_dialect();
const Dialect& romi_dialect();
const Dialect& fanuc_dialect();
const Dialect& grbl_dialect();

const std::vector<const Dialect*>& all_dialects() {
  static const std::vector<const Dialect*> list = {&rs274ngc_dialect(), &romi_dialect(),
                                                   &fanuc_dialect(), &grbl_dialect()};
  return list;
}

const Dialect* find_dialect(std::string_view name) {
  for (const Dialect* d : all_dialects()) {
    if (d->name == name) return d;
  }
  return nullptr;
}

RunModes run_modes(const ModalState& s) {
  RunModes m;
  m.inch = s.units == core::LengthUnit::Inch;
  m.plane = s.plane == core::Plane::XY ? 17 : (s.plane == core::Plane::ZX ? 18 : 19);
  m.incremental = s.incremental;
  // 1 = G54 ... 6 = G59, 7 = G59.1 ... 9 = G59.3
  if (s.coord_system_chosen)
    m.work_offset = s.coord_system <= 6 ? 530 + 10 * s.coord_system : 590 + s.coord_system - 6;
  m.length_h = s.length_h;
  m.offsets_written = s.offsets_written;
  m.feed_mode = s.feed_mode == FeedMode::InverseTime   ? 93
                : s.feed_mode == FeedMode::UnitsPerRev ? 95
                                                       : 94;
  m.motion = s.motion;
  for (std::size_t a = 0; a < 3; ++a)
    m.frame_moved = m.frame_moved || s.g92[a] != 0.0;
  m.frame_moved = m.frame_moved || s.rotation_deg != 0.0;
  return m;
}

const CodeEntry* Dialect::find_code(char letter, int code) const {
  for (const CodeEntry& e : codes) {
    if (e.letter == letter && e.code == code) return &e;
  }
  return nullptr;
}

namespace {

std::string list_options(const Dialect& d) {
  if (d.options.empty()) return fmt::format("dialect {} has no options", d.name);
  std::string out = fmt::format("the options of dialect {}:", d.name);
  for (const DialectOption& o : d.options) {
    out += fmt::format(" {}={}", o.name, fmt::join(o.values, "|"));
  }
  return out;
}

}  // namespace

namespace {

// "29,11,262": whole numbers of up to 8 digits (a code), comma-separated.
bool whole_number_list(const std::string& value) {
  std::size_t digits = 0;
  for (char c : value) {
    if (c == ',') {
      if (digits == 0) return false;
      digits = 0;
    } else if (c >= '0' && c <= '9') {
      if (++digits > 8) return false;
    } else {
      return false;
    }
  }
  return digits > 0;
}

}  // namespace

OptionValues default_options(const Dialect& d) {
  OptionValues out;
  for (const DialectOption& o : d.options)
    out[std::string(o.name)] = std::string(o.values.front());
  return out;
}

tl::expected<OptionValues, std::string> resolve_options(const Dialect& d,
                                                        const std::vector<std::string>& given) {
  OptionValues out = default_options(d);
  for (const std::string& g : given) {
    const std::size_t eq = g.find('=');
    if (eq == std::string::npos) {
      return tl::unexpected(
          fmt::format("--dialect-option {} is not name=value; {}", g, list_options(d)));
    }
    const std::string name = g.substr(0, eq);
    const std::string value = g.substr(eq + 1);
    auto it = std::find_if(d.options.begin(), d.options.end(),
                           [&](const DialectOption& o) { return o.name == name; });
    if (it == d.options.end()) {
      return tl::unexpected(fmt::format("unknown dialect option '{}'; {}", name, list_options(d)));
    }
    const bool list = it->values.back() == "<list>" && whole_number_list(value);
    if (!list && std::find(it->values.begin(), it->values.end(), value) == it->values.end()) {
      return tl::unexpected(fmt::format("dialect option {} takes {}, not '{}'", name,
                                        fmt::join(it->values, "|"), value));
    }
    out[name] = value;
  }
  return out;
}

}  // namespace usina::gcode
