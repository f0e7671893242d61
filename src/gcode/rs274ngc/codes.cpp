// LinuxCNC's G and M codes and their modal groups (the RS274NGC
// interpreter's table: its groups numbered as LinuxCNC numbers them,
// interp/codes.hpp). Every code the interpreter runs is here; the fanuc
// dialect starts from this table (fanuc/codes.cpp).
#include "gcode/interp/codes.hpp"

namespace usina::gcode {
namespace {

void add(std::vector<CodeEntry>& table, char letter, std::initializer_list<int> codes, int group,
         std::string_view handler = "group_step") {
  for (int code : codes)
    table.push_back({letter, code, group, handler});
}

void add_g_codes(std::vector<CodeEntry>& t) {
  add(t, 'G', {40, 100, 280, 281, 300, 301, 520, 530, 920, 921, 922, 923}, kGroupNonModal);
  add(t, 'G', {0,   10,  20,  30,  50,  51,  52,  53,  62,  330, 331, 382, 383, 384,
               385, 730, 740, 760, 800, 810, 820, 830, 840, 850, 860, 870, 880, 890},
      kGroupMotion);
  add(t, 'G', {170, 180, 190}, kGroupPlane);
  add(t, 'G', {900, 910}, kGroupDistance);
  add(t, 'G', {901, 911}, kGroupArcDistance);
  add(t, 'G', {930, 940, 950}, kGroupFeedMode);
  add(t, 'G', {200, 210}, kGroupUnits);
  add(t, 'G', {400, 410, 411, 420, 421}, kGroupCutterComp);
  add(t, 'G', {430, 431, 432, 490}, kGroupToolLength);
  add(t, 'G', {980, 990}, kGroupRetract);
  add(t, 'G', {540, 550, 560, 570, 580, 590, 591, 592, 593}, kGroupCoordSystem);
  add(t, 'G', {610, 611, 640}, kGroupPathControl);
  add(t, 'G', {960, 970}, kGroupSpindleMode);
  add(t, 'G', {70, 80}, kGroupLathe);
  for (int code : {700, 710, 711, 720, 721}) {
    t.push_back(
        {'G', code, kGroupMotion, "unsupported", "LinuxCNC's lathe roughing/finishing cycle"});
  }
}

void add_m_codes(std::vector<CodeEntry>& t) {
  add(t, 'M', {0, 10, 20, 300, 600}, kMGroupStop);
  add(t, 'M', {620, 630, 640, 650, 660, 670, 680}, kMGroupIo);
  add(t, 'M', {60, 610}, kMGroupToolChange);
  add(t, 'M', {30, 40, 50, 190}, kMGroupSpindle);
  add(t, 'M', {70, 80, 90}, kMGroupCoolant);
  add(t, 'M', {480, 490, 500, 510, 520, 530}, kMGroupOverride);
  add(t, 'M', {700, 710, 720, 730}, kMGroupModalState);
  add(t, 'M', {980, 990}, kMGroupSubprogram);
  // M100-M199 run a program of the machine's (LinuxCNC: a file named so).
  for (int m = 100; m <= 199; ++m)
    t.push_back({'M', m * 10, kMGroupUser, "user_m"});
}

}  // namespace

std::vector<CodeEntry> linuxcnc_codes() {
  std::vector<CodeEntry> t;
  add_g_codes(t);
  add_m_codes(t);
  return t;
}

}  // namespace usina::gcode
