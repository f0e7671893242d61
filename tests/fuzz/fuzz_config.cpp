// libFuzzer target for the readers of usina's configuration files and of
// option values: the first byte picks the reader by its low four bits (mod
// 7: the seeds begin with '0'..'6'), the rest is the reader's text.
//
//   0  a machine profile (TOML: stats, job, serve read it)
//   1  usina-serve.toml (the [[machine]] links, [server], [web], [mtconnect],
//      [mqtt], machine classes, profiles' names and data patterns)
//   2  a LinuxCNC tool table (bit 6 of the first byte, 'B': an inch machine)
//   3  a LinuxCNC parameter (.var) file, then written back
//   4  `usina simulate --stock` (box:WxLxH), checked as the height map does
//   5  `usina simulate --tool-shape` (T=SHAPE[/D][,WORD]...) and a tool table
//      comment's shape and words above the end (flutes:, holder:, stickout:, no-plunge)
//   6  a link's port (device, tcp://, tcp-listen://) and mqtt.url
//
// Any input must give a value or a diagnostic, never a crash, a hang, or a
// number out of the range the reader promises (a non-finite one first).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <map>
#include <string>
#include <string_view>

#include "core/diagnostic.hpp"
#include "core/source.hpp"
#include "dnc/data_config.hpp"
#include "dnc/link_port.hpp"
#include "dnc/server_config.hpp"
#include "gcode/tool_table.hpp"
#include "gcode/var_file.hpp"
#include "sim/machine_profile.hpp"
#include "sim/stock/height_map.hpp"
#include "sim/stock/tool_shape.hpp"

namespace {

using namespace usina;

class DiscardDiagnostics final : public core::DiagnosticSink {
 public:
  void report(core::Diagnostic d) override { (void)d; }
};

// Traps unless `v` is finite and within [lo, hi].
void trap_outside(double v, double lo, double hi) {
  if (!std::isfinite(v) || v < lo || v > hi) std::abort();
}

void machine_profile(std::string_view text) {
  DiscardDiagnostics diags;
  const auto p = sim::read_machine_profile(text, 0, diags);
  if (!p) return;
  for (const sim::AxisLimits& a : p->axes) {
    if (!a.present) continue;
    trap_outside(a.min, -3e7, a.max);
    trap_outside(a.max, a.min, 3e7);
    trap_outside(a.rapid, 1e-9, 3e7);
    trap_outside(a.max_feed, 1e-9, 3e7);
    trap_outside(a.accel, 1e-9, 3e7);
    trap_outside(a.jerk, 0.0, 3e10);
  }
  trap_outside(p->spindle_max_rpm, 0.0, 1e6);
  trap_outside(p->junction_deviation, 0.0, 300.0);
  trap_outside(p->arc_tolerance, 1e-9, 30.0);
  trap_outside(p->linuxcnc.servo_period, 1e-6, 1.0);
  trap_outside(static_cast<double>(p->linuxcnc.optimization_depth), 2.0, 10000.0);
}

void server_config(std::string_view text) {
  DiscardDiagnostics diags;
  const auto c = dnc::read_server_config(text, 0, diags);
  if (!c) return;
  trap_outside(c->session_hours, 1e-9, 720.0);
  for (const dnc::ServerMachine& m : c->machines) {
    trap_outside(m.link.xon_timeout, 1.0, 86400.0);
    trap_outside(m.link.receive_idle, 0.1, 3600.0);
    if (!dnc::standard_baud(m.link.baud)) std::abort();
    if (m.part_count_pattern.size() > dnc::kMaxDataPatternLength) std::abort();
  }
}

// A tool as the simulation takes it: its end within the bounds, and the
// words above it within theirs and going together (check_shape passes).
void check_tool(const sim::stock::ToolShape& t) {
  trap_outside(t.diameter, 1e-9, sim::stock::kMaxToolDiameter);
  trap_outside(t.corner_radius, 0.0, t.radius());
  trap_outside(t.angle, sim::stock::kMinToolAngle, sim::stock::kMaxToolAngle);
  trap_outside(t.lift(t.radius()), 0.0, 1e7);
  trap_outside(t.flutes, 0.0, sim::stock::kMaxToolLength);
  trap_outside(t.holder, 0.0, sim::stock::kMaxToolLength);
  trap_outside(t.stickout, 0.0, sim::stock::kMaxToolLength);
  trap_outside(t.plunge_ramp, 0.0, 90.0);
  if (!sim::stock::check_shape(t)) std::abort();
}

void tool_table(std::string_view text, bool inch) {
  DiscardDiagnostics diags;
  const auto file = core::SourceFile::from_string("fuzz.tbl", std::string(text));
  const auto table = gcode::read_tool_table(*file, 0, inch ? 25.4 : 1.0, diags);
  if (!table) return;
  for (const gcode::ToolEntry& t : table->entries()) {
    trap_outside(t.diameter, 0.0, 1000.0);
    trap_outside(t.offset.x, -1e4, 1e4);
    trap_outside(t.offset.y, -1e4, 1e4);
    trap_outside(t.offset.z, -1e4, 1e4);
    if (t.diameter <= 0.0) continue;
    if (const auto tool = sim::stock::tool_from_comment(t.comment, t.diameter)) check_tool(*tool);
  }
}

void var_file(std::string_view text) {
  DiscardDiagnostics diags;
  const auto file = core::SourceFile::from_string("fuzz.var", std::string(text));
  const auto entries = gcode::read_var_file(*file, 0, diags);
  if (!entries) return;
  for (const gcode::VarFileEntry& e : *entries) {
    if (e.number < gcode::kMinVarFileParameter || e.number > gcode::kMaxVarFileParameter)
      std::abort();
    trap_outside(e.value, -std::numeric_limits<double>::max(), std::numeric_limits<double>::max());
  }
  (void)gcode::write_var_file(*entries);  // throws (and so traps) on what it cannot write
}

void stock(std::string_view text) {
  const auto box = sim::stock::parse_stock(text);
  if (!box) return;
  if (sim::stock::check_stock(*box, 0.1)) {
    trap_outside(box->width, 1e-9, 1e7);
    trap_outside(box->length, 1e-9, 1e7);
    trap_outside(box->height, 1e-9, 1e7);
  }
}

void tool_shape(std::string_view text) {
  std::map<int, sim::stock::ToolShape> known;
  known[1].diameter = 6.0;
  if (const auto spec = sim::stock::parse_tool_spec(text, known)) check_tool(spec->second);
  check_tool(sim::stock::shape_from_comment(text, 10.0));
  if (const auto tool = sim::stock::tool_from_comment(text, 10.0)) check_tool(*tool);
}

void addresses(std::string_view text) {
  if (const auto port = dnc::parse_port(text)) {
    if (port->kind != dnc::PortAddress::Kind::Device && (port->port == 0 || port->host.empty()))
      std::abort();
  }
  dnc::MqttConfig mqtt;
  if (dnc::parse_mqtt_url(text, mqtt) && (mqtt.port == 0 || mqtt.host.empty())) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string_view text(reinterpret_cast<const char*>(data) + 1, size - 1);
  switch ((data[0] & 0x0f) % 7) {
  case 0: machine_profile(text); break;
  case 1: server_config(text); break;
  case 2: tool_table(text, (data[0] & 0x40) != 0); break;
  case 3: var_file(text); break;
  case 4: stock(text); break;
  case 5: tool_shape(text); break;
  default: addresses(text); break;
  }
  return 0;
}
