// The fanuc dialect's G/M table: the codes the RS274NGC interpreter runs
// for it (LinuxCNC's G codes, which the macro front end hands on), the
// codes of Fanuc's controls usina cannot run (named, never "unknown"), and
// the M codes the control runs itself; any other M code is the machine's
// logic (fanuc/words.cpp hands it on).
#include "gcode/interp/codes.hpp"

#include <algorithm>

#include "gcode/fanuc/engine.hpp"

namespace usina::gcode {
namespace {

struct Unsupported {
  int code;
  std::string_view what;
};

// 5-axis, mill-turn and lathe codes usina does not model: running on
// without them would draw a wrong part.
constexpr Unsupported kUnsupportedG[] = {
    {24, "3-dimensional circular interpolation"},
    {34, "3-dimensional circular interpolation"},
    {71, "cylindrical interpolation"},
    {311, "multi-step skip"},
    {312, "multi-step skip"},
    {313, "multi-step skip"},
    {314, "multi-step skip"},
    {401, "normal direction control"},
    {411, "normal direction control"},
    {421, "normal direction control"},
    {412, "3-dimensional cutter compensation"},
    {422, "3-dimensional cutter compensation"},
    {434, "tool centre point control, type 1"},
    {435, "tool centre point control, type 2"},
    {531, "tool axis direction control"},
    {536, "tool axis direction control with tool centre point retention"},
    {542, "rotary table dynamic fixture offset"},
    {544, "workpiece setting error compensation"},
    {682, "tilted working plane"},
    {683, "tilted working plane by tool axis direction"},
    {684, "tilted working plane, incremental multi-command"},
    {700, "finishing cycle of a lathe"},
    {710, "stock removal in turning, a lathe's cycle"},
    {720, "stock removal in facing, a lathe's cycle"},
    {721, "figure copying, rotation"},
    {722, "figure copying, parallel"},
    {811, "chopping"},
};

bool lathe_cycle_of_linuxcnc(const CodeEntry& e) {
  return e.letter == 'G' && e.code >= 700 && e.code <= 721;
}

}  // namespace

std::vector<CodeEntry> fanuc_codes() {
  std::vector<CodeEntry> t = linuxcnc_codes();
  std::erase_if(t,
                [](const CodeEntry& e) { return e.letter == 'M' || lathe_cycle_of_linuxcnc(e); });
  for (const Unsupported& u : kUnsupportedG)
    t.push_back({'G', u.code, kGroupNonModal, "unsupported", u.what});
  // The control's own M codes: program stop and end, spindle (M19 its
  // orientation), tool change, coolant, subprogram call and return.
  for (int m : {0, 10, 20, 300})
    t.push_back({'M', m, kMGroupStop, "group_step"});
  for (int m : {30, 40, 50, 190})
    t.push_back({'M', m, kMGroupSpindle, "group_step"});
  t.push_back({'M', 60, kMGroupToolChange, "group_step"});
  for (int m : {70, 80, 90})
    t.push_back({'M', m, kMGroupCoolant, "group_step"});
  for (int m : {980, 990})
    t.push_back({'M', m, kMGroupSubprogram, "group_step"});
  t.push_back(
      {'M', 1980, kMGroupSubprogram, "unsupported", "subprogram call from external memory"});
  return t;
}

const InterpCodes& fanuc::code_table() {
  static const InterpCodes table = interp_code_table("fanuc", fanuc_dialect().codes);
  return table;
}

}  // namespace usina::gcode
