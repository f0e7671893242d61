// The fanuc dialect (Fanuc 0i/16i/31i milling with Custom Macro B;
// docs/fanuc.md): its lexical rules, its G/M table (fanuc/codes.cpp) and
// its options. Its runner is the macro
// front end of fanuc/engine.hpp over the RS274NGC interpreter.
#include "gcode/fanuc/engine.hpp"

namespace usina::gcode {
namespace {

std::unique_ptr<ProgramRunner> make(RunContext context) {
  return std::make_unique<fanuc::Engine>(context);
}

}  // namespace

const Dialect& fanuc_dialect() {
  static const Dialect d{
      "fanuc",
      LexicalRules{"\n;", false},
      fanuc_codes(),
      {},
      {{"decimal_point",
        {"calculator", "fanuc"},
        "a number without a point: calculator = as written (warned once), fanuc = least "
        "increments (0.001 mm, 0.0001 in; parameter 3401 DPI = 0)"},
       {"program_digits",
        {"4", "8"},
        "4: M98 P30010 is O0010 three times; 8: P is the program number"},
       {"rotation_incremental",
        {"0", "1"},
        "G68 R in G91: 0 = always absolute, 1 = adds to the angle in force (parameter 5400 "
        "RIN)"},
       {"scaling_axes",
        {"xy", "xyz"},
        "the axes G51 P scales (parameter 5401 SCLx); I J K scale any axis"},
       {"stroke_area",
        {"inside", "outside"},
        "the forbidden side of the G22 box: inside or outside (parameter 1300 bit 0 OUT)"},
       {"boring_shift",
        {"+x", "-x", "+y", "-y"},
        "the G76/G87 shift at the hole bottom, in the machine's axes (parameter 5101 RD1 RD2)"},
       {"machine_m_codes",
        {"all", "<list>"},
        "the M codes of the machine's logic, which the control hands on (a machine_code op): "
        "all = every M code that is not the control's own; a list (29,11,262) = those, any "
        "other is E_UNKNOWN_M_CODE"},
       {"polar_axes",
        {"XC", "XA", "XB", "YA", "YB", "YC", "ZA", "ZB", "ZC"},
        "G12.1's linear and rotary axes (parameters 5460/5461): the rotary axis's words are "
        "the virtual axis in mm"}},
      &make};
  return d;
}

}  // namespace usina::gcode
