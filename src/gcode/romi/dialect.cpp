// The romi dialect (ROMI MACH / Interact milling control of seed 000;
// spec/romi.md): its lexical rules, its G/M table, the codes in force at
// program start and its options. The handlers named here are the romi
// translator's (romi/translate.hpp); code_table() resolves them once.
#include "gcode/romi/engine.hpp"

namespace usina::gcode {
namespace {

// Groups in the order they run within a block: below romi::kAfterMoveGroup
// before the block's move, the rest after it (romi/translate.cpp).
enum Group : int {
  ToolChange = 1,
  Spindle = 2,
  Coolant = 3,
  Units = 10,
  Distance = 11,
  Plane = 12,
  Retract = 13,
  Mirror = 20,
  Scale = 21,
  Rotate = 22,
  Comp = 30,
  Cycle = 40,
  Motion = 50,
  Pattern = 51,
  Stop = 90,
};

static_assert(Motion < romi::kAfterMoveGroup && Pattern < romi::kAfterMoveGroup &&
              Stop >= romi::kAfterMoveGroup);

std::unique_ptr<ProgramRunner> make(RunContext context);

}  // namespace

const Dialect& romi_dialect() {
  static const Dialect kDialect{
      "romi",
      LexicalRules{"\n#", true},
      {
          {'G', 0, Motion, "motion"},
          {'G', 10, Motion, "motion"},
          {'G', 20, Motion, "motion"},
          {'G', 30, Motion, "motion"},
          {'G', 170, Plane, "plane"},
          {'G', 240, Pattern, "bolt_circle"},
          {'G', 250, Pattern, "grid"},
          {'G', 260, Pattern, "pocket"},
          {'G', 300, Mirror, "mirror"},
          {'G', 310, Mirror, "mirror"},
          {'G', 400, Comp, "comp"},
          {'G', 410, Comp, "comp"},
          {'G', 420, Comp, "comp"},
          {'G', 700, Units, "units"},
          {'G', 710, Units, "units"},
          {'G', 720, Scale, "scale"},
          {'G', 730, Rotate, "rotate"},
          {'G', 800, Cycle, "cycle"},
          {'G', 810, Cycle, "cycle"},
          {'G', 900, Distance, "distance"},
          {'G', 910, Distance, "distance"},
          {'G', 980, Retract, "retract"},
          {'G', 990, Retract, "retract"},
          {'M', 0, Stop, "stop"},
          {'M', 10, Stop, "stop"},
          {'M', 20, Stop, "end"},
          {'M', 300, Stop, "end"},
          {'M', 30, Spindle, "spindle"},
          {'M', 40, Spindle, "spindle"},
          {'M', 50, Spindle, "spindle"},
          {'M', 60, ToolChange, "tool_change"},
          {'M', 70, Coolant, "coolant"},
          {'M', 80, Coolant, "coolant"},
          {'M', 90, Coolant, "coolant"},
      },
      // G00 G17 G90 G71 G40 G80 G30, and G99 (our choice: the seed's first block).
      {{'G', 0, Motion, "motion"},
       {'G', 170, Plane, "plane"},
       {'G', 900, Distance, "distance"},
       {'G', 710, Units, "units"},
       {'G', 400, Comp, "comp"},
       {'G', 800, Cycle, "cycle"},
       {'G', 300, Mirror, "mirror"},
       {'G', 990, Retract, "retract"}},
      {
          {"lowercase_incremental",
           {"on", "off"},
           "a lower-case axis or polar letter (x500, r10) is incremental for that word alone"},
          {"typographic_dash",
           {"minus", "error"},
           "a typographic dash (U+2013, U+2014, U+2212) before a number: a minus sign with a "
           "warning, or an error"},
          {"motion_cancels_cycle",
           {"off", "on"},
           "whether a G00/G01/G02/G03 code cancels an active G81 (off: only G80 does, and "
           "every later position drills)"},
          {"comp_radius",
           {"register", "tool"},
           "the G41/G42 radius: the tool table's entry of the O register (else the tool in "
           "the spindle), or always the tool in the spindle"},
      },
      &make};
  return kDialect;
}

namespace {

std::unique_ptr<ProgramRunner> make(RunContext context) {
  return std::make_unique<romi::Engine>(romi_dialect(), romi::code_table(), std::move(context));
}

}  // namespace

const romi::CodeTable& romi::code_table() {
  static const CodeTable kTable(romi_dialect(), &Translator::handler_named, kAfterMoveGroup);
  return kTable;
}

}  // namespace usina::gcode
