#include "canon/op.hpp"

namespace usina::canon {
namespace {

struct NameOf {
  const char* operator()(const Traverse&) const { return "traverse"; }

  const char* operator()(const Feed&) const { return "feed"; }

  const char* operator()(const Arc&) const { return "arc"; }

  const char* operator()(const Spline&) const { return "spline"; }

  const char* operator()(const Probe&) const { return "probe"; }

  const char* operator()(const Dwell&) const { return "dwell"; }

  const char* operator()(const ToolChange&) const { return "tool"; }

  const char* operator()(const Spindle&) const { return "spindle"; }

  const char* operator()(const Coolant&) const { return "coolant"; }

  const char* operator()(const Hole&) const { return "hole"; }

  const char* operator()(const Pocket&) const { return "pocket"; }

  const char* operator()(const Comment&) const { return "comment"; }

  const char* operator()(const ProgramEnd&) const { return "end"; }

  const char* operator()(const MachineCode&) const { return "machine_code"; }

  const char* operator()(const PathMode&) const { return "path_mode"; }
};

}  // namespace

const char* op_name(const OpKind& kind) {
  return std::visit(NameOf{}, kind);
}

const char* path_mode_code(PathMode::Mode m) {
  switch (m) {
  case PathMode::Mode::ExactPath: return "G61";
  case PathMode::Mode::ExactStop: return "G61.1";
  case PathMode::Mode::Blend: return "G64";
  }
  return "G64";
}

const char* spindle_dir_name(SpindleDir d) {
  switch (d) {
  case SpindleDir::Cw: return "cw";
  case SpindleDir::Ccw: return "ccw";
  case SpindleDir::Off: return "off";
  }
  return "off";
}

bool is_motion(const OpKind& kind) {
  return std::holds_alternative<Traverse>(kind) || std::holds_alternative<Feed>(kind) ||
         std::holds_alternative<Arc>(kind) || std::holds_alternative<Spline>(kind) ||
         std::holds_alternative<Probe>(kind);
}

}  // namespace usina::canon
