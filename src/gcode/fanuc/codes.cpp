// The fanuc dialect's G/M table, the language a Fanuc program is written in:
// LinuxCNC's G codes the two share, the codes of Fanuc's controls usina
// cannot run (named, never "unknown"), and the M codes of the control; any
// other M code is the machine's logic (fanuc/words.cpp hands it on). The
// macro front end reads it; what it hands the interpreter are LinuxCNC's
// words, run with LinuxCNC's table.
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

// LinuxCNC's codes a Fanuc has with another meaning (G41.1 dynamic cutter
// compensation there, normal direction control here) or not at all (its
// lathe cycles G70–G72.1 on a mill).
bool not_fanucs(const CodeEntry& e) {
  if (e.letter != 'G') return false;
  if (e.code >= 700 && e.code <= 721) return true;
  for (const Unsupported& u : kUnsupportedG)
    if (u.code == e.code) return true;
  return false;
}

}  // namespace

std::vector<CodeEntry> fanuc_codes() {
  std::vector<CodeEntry> t = linuxcnc_codes();
  std::erase_if(t, [](const CodeEntry& e) { return e.letter == 'M' || not_fanucs(e); });
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
