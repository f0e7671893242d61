#include "dnc/machine_config.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <set>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "dnc/link_port.hpp"
#include "gcode/dialect.hpp"
#include "sim/profile_keys.hpp"

namespace usina::dnc {
namespace {

// machine_class, profile, the data patterns, calendar and tool_life are the server's
// (server_config.cpp).
constexpr std::array<std::string_view, 27> kKeys{"name",
                                                 "dialect",
                                                 "port",
                                                 "baud",
                                                 "data_bits",
                                                 "parity",
                                                 "stop_bits",
                                                 "flow",
                                                 "code",
                                                 "eob",
                                                 "mode",
                                                 "skid",
                                                 "xon",
                                                 "xoff",
                                                 "leader",
                                                 "trailer",
                                                 "wait_for_xon",
                                                 "xon_timeout",
                                                 "receive_idle",
                                                 "request_program",
                                                 "request_lines",
                                                 "machine_class",
                                                 "profile",
                                                 "part_count_pattern",
                                                 "cycle_time_pattern",
                                                 "calendar",
                                                 "tool_life"};

class Reader {
 public:
  Reader(std::uint32_t file, core::DiagnosticSink& diags) : file_(file), diags_(diags) {}

  void report(core::Code code, core::Severity severity, const toml::source_region& where,
              std::string message) {
    core::SourceLoc loc{file_, static_cast<std::uint32_t>(where.begin.line),
                        static_cast<std::uint32_t>(where.begin.column), 1, 0};
    diags_.report({code, severity, loc, std::move(message)});
  }

  void fail(const toml::source_region& where, std::string message) {
    ok_ = false;
    report(core::Code::DncConfig, core::Severity::Error, where, std::move(message));
  }

  void set_machine(std::string name) { machine_ = std::move(name); }

  std::string where(std::string_view key) const {
    return machine_.empty() ? fmt::format("[[machine]] {}", key)
                            : fmt::format("machine `{}`: {}", machine_, key);
  }

  // A whole number in [lo, hi]; `fallback` when the key is missing.
  template <typename T>
  T integer(const toml::table& t, std::string_view key, std::int64_t lo, std::int64_t hi,
            T fallback) {
    const toml::node* n = t.get(key);
    if (n == nullptr) return fallback;
    const std::optional<std::int64_t> v = n->value_exact<std::int64_t>();
    if (!v || *v < lo || *v > hi) {
      fail(n->source(), fmt::format("{} must be a whole number from {} to {}", where(key), lo, hi));
      return fallback;
    }
    return static_cast<T>(*v);
  }

  double seconds(const toml::table& t, std::string_view key, double lo, double hi,
                 double fallback) {
    const toml::node* n = t.get(key);
    if (n == nullptr) return fallback;
    const std::optional<double> v = n->value<double>();
    if (!v || !std::isfinite(*v) || *v < lo || *v > hi) {
      fail(n->source(),
           fmt::format("{} must be a number of seconds from {:g} to {:g}", where(key), lo, hi));
      return fallback;
    }
    return *v;
  }

  bool boolean(const toml::table& t, std::string_view key, bool fallback) {
    const toml::node* n = t.get(key);
    if (n == nullptr) return fallback;
    if (!n->is_boolean()) {
      fail(n->source(), fmt::format("{} must be true or false", where(key)));
      return fallback;
    }
    return n->value_or(fallback);
  }

  // A string; nullopt (and an error when `required`) when missing or not a string.
  std::optional<std::string> text(const toml::table& t, std::string_view key, bool required) {
    const toml::node* n = t.get(key);
    if (n == nullptr) {
      if (required)
        fail(t.source(), fmt::format("{} is missing: every machine needs one", where(key)));
      return std::nullopt;
    }
    if (!n->is_string()) {
      fail(n->source(), fmt::format("{} must be a string", where(key)));
      return std::nullopt;
    }
    return n->value_or<std::string>("");
  }

  template <typename E, typename Parse>
  E choice(const toml::table& t, std::string_view key, Parse parse, std::string_view values,
           E fallback) {
    const std::optional<std::string> s = text(t, key, false);
    if (!s) return fallback;
    const std::optional<E> v = parse(*s);
    if (!v) {
      fail(t.get(key)->source(),
           fmt::format("{} = \"{}\" is not one of {}", where(key), *s, values));
      return fallback;
    }
    return *v;
  }

  void unknown_keys(const toml::table& t) {
    for (auto&& [key, node] : t) {
      const std::string_view name = key.str();
      if (std::find(kKeys.begin(), kKeys.end(), name) != kKeys.end()) continue;
      const std::string_view near = sim::nearest_key(name, kKeys);
      const std::string hint = near.empty() ? std::string("docs/dnc.md lists the keys")
                                            : fmt::format("did you mean `{}`?", near);
      report(core::Code::UnknownDncKey, core::Severity::Warning, key.source(),
             fmt::format("unknown key `{}` in {} is not read; {}", name,
                         machine_.empty() ? "a [[machine]]" : fmt::format("machine `{}`", machine_),
                         hint));
    }
  }

  bool ok() const { return ok_; }

 private:
  std::uint32_t file_;
  core::DiagnosticSink& diags_;
  std::string machine_;
  bool ok_ = true;
};

bool valid_name(std::string_view s) {
  if (s.empty() || s.size() > 64 || s.front() == '.' || s.front() == '-') return false;
  return std::all_of(s.begin(), s.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' ||
           c == '_' || c == '.';
  });
}

void read_identity(Reader& r, const toml::table& t, LinkConfig& c) {
  const std::optional<std::string> name = r.text(t, "name", true);
  if (name && !valid_name(*name)) {
    r.fail(t.get("name")->source(),
           fmt::format("name = \"{}\": a machine's name is 1 to 64 letters, digits, `-`, `_` or "
                       "`.` (it is part of the API's routes)",
                       *name));
  }
  c.name = name.value_or("");
  r.set_machine(c.name);
  c.dialect = r.text(t, "dialect", false).value_or("rs274ngc");
  // An unknown dialect was accepted here and refused every punch later.
  if (gcode::find_dialect(c.dialect) == nullptr) {
    std::string known;
    for (const gcode::Dialect* d : gcode::all_dialects())
      known += fmt::format("{}{}", known.empty() ? "" : ", ", d->name);
    r.fail(t.get("dialect")->source(),
           fmt::format("{} = \"{}\" is no dialect usina reads; give one of {}", r.where("dialect"),
                       c.dialect, known));
  }
  const std::optional<std::string> port = r.text(t, "port", true);
  if (port) {
    if (const auto parsed = parse_port(*port); !parsed) {
      r.fail(t.get("port")->source(), fmt::format("{}: {}", r.where("port"), parsed.error()));
    }
    c.port = *port;
  }
}

void read_frame(Reader& r, const toml::table& t, LinkConfig& c) {
  c.baud = r.integer<std::uint32_t>(t, "baud", 110, 115200, c.baud);
  if (!standard_baud(c.baud)) {
    r.fail(t.get("baud")->source(),
           fmt::format("{} = {} is no UART rate; give one of 110, 300, 600, 1200, 2400, 4800, "
                       "9600, 19200, 38400, 57600, 115200",
                       r.where("baud"), c.baud));
  }
  c.data_bits = r.integer<std::uint8_t>(t, "data_bits", 7, 8, c.data_bits);
  c.parity = r.choice(t, "parity", parse_parity, "none, even, odd", c.parity);
  c.stop_bits = r.integer<std::uint8_t>(t, "stop_bits", 1, 2, c.stop_bits);
  c.flow = r.choice(t, "flow", parse_flow, "none, xonxoff, rtscts, dtrdsr", c.flow);
  c.code = r.choice(t, "code", parse_code, "ascii, iso, eia", c.code);
  c.eob = r.choice(t, "eob", parse_eob, "lf, crlf, cr, semicolon, hash", c.eob);
  c.mode = r.choice(t, "mode", parse_mode, "production, tryout", c.mode);
}

void read_limits(Reader& r, const toml::table& t, LinkConfig& c) {
  c.skid = r.integer<std::uint32_t>(t, "skid", 1, 65536, c.skid);
  c.xon = r.integer<std::uint8_t>(t, "xon", 0, 255, c.xon);
  c.xoff = r.integer<std::uint8_t>(t, "xoff", 0, 255, c.xoff);
  c.leader = r.integer<std::uint32_t>(t, "leader", 0, 10000, c.leader);
  c.trailer = r.integer<std::uint32_t>(t, "trailer", 0, 10000, c.trailer);
  c.wait_for_xon = r.boolean(t, "wait_for_xon", c.wait_for_xon);
  c.xon_timeout = r.seconds(t, "xon_timeout", 1.0, 86400.0, c.xon_timeout);
  c.receive_idle = r.seconds(t, "receive_idle", 0.1, 3600.0, c.receive_idle);
  c.request_program =
      r.integer<std::uint32_t>(t, "request_program", 0, 99999999, c.request_program);
  c.request_lines = r.integer<std::uint32_t>(t, "request_lines", 1, 1000, c.request_lines);
}

// The combinations no link carries.
void check_together(Reader& r, const toml::table& t, const LinkConfig& c) {
  if (c.code == TapeCode::Eia && (c.data_bits != 8 || c.parity != Parity::None)) {
    r.fail(t.source(), fmt::format("machine `{}`: code = \"eia\" needs data_bits = 8 and parity = "
                                   "\"none\" (EIA carries its own odd parity on channel 5)",
                                   c.name));
  }
  if (c.code == TapeCode::Eia && (c.eob == EndOfBlock::Semicolon || c.eob == EndOfBlock::Hash)) {
    r.fail(t.source(), fmt::format("machine `{}`: EIA ends a block with its own code (channel 8); "
                                   "give eob = \"cr\" or \"lf\", not \"{}\"",
                                   c.name, eob_name(c.eob)));
  }
  if (c.flow == Flow::XonXoff && c.xon == c.xoff) {
    r.fail(t.source(),
           fmt::format("machine `{}`: xon and xoff are the same byte ({})", c.name, c.xon));
  }
}

}  // namespace

std::span<const std::string_view> machine_keys() {
  return kKeys;
}

std::optional<std::vector<LinkConfig>> read_machine_links(std::string_view toml_text,
                                                          std::uint32_t file_id,
                                                          core::DiagnosticSink& diags) {
  Reader r(file_id, diags);
  toml::table root;
  try {
    root = toml::parse(toml_text);
  } catch (const toml::parse_error& e) {
    r.fail(e.source(), fmt::format("not valid TOML: {}", e.description()));
    return std::nullopt;
  }
  std::vector<LinkConfig> machines;
  const toml::node* list = root.get("machine");
  if (list == nullptr) return machines;
  if (!list->is_array_of_tables()) {
    r.fail(list->source(), "machine must be an array of tables: write each as [[machine]]");
    return std::nullopt;
  }
  std::set<std::string> names;
  for (const toml::node& n : *list->as_array()) {
    const toml::table& t = *n.as_table();
    LinkConfig c;
    r.set_machine("");
    read_identity(r, t, c);
    r.unknown_keys(t);
    read_frame(r, t, c);
    read_limits(r, t, c);
    check_together(r, t, c);
    if (!c.name.empty() && !names.insert(c.name).second) {
      r.fail(t.source(), fmt::format("two machines are named `{}`; names must differ", c.name));
    }
    machines.push_back(std::move(c));
  }
  if (!r.ok()) return std::nullopt;
  return machines;
}

}  // namespace usina::dnc
