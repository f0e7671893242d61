#include "gcode/interp/codes.hpp"

#include <cstdio>

namespace usina::gcode {

int g_group(GCode g) {
  switch (g) {
  case 40:
  case 100:
  case 280:
  case 281:
  case 300:
  case 301:
  case 520:
  case 530:
  case 920:
  case 921:
  case 922:
  case 923: return kGroupNonModal;
  case 0:
  case 10:
  case 20:
  case 30:
  case 50:
  case 51:
  case 52:
  case 53:
  case 62:
  case 330:
  case 331:
  case 382:
  case 383:
  case 384:
  case 385:
  case 730:
  case 740:
  case 760:
  case 800:
  case 810:
  case 820:
  case 830:
  case 840:
  case 850:
  case 860:
  case 870:
  case 880:
  case 890: return kGroupMotion;
  case 170:
  case 180:
  case 190: return kGroupPlane;
  case 900:
  case 910: return kGroupDistance;
  case 901:
  case 911: return kGroupArcDistance;
  case 930:
  case 940:
  case 950: return kGroupFeedMode;
  case 200:
  case 210: return kGroupUnits;
  case 400:
  case 410:
  case 411:
  case 420:
  case 421: return kGroupCutterComp;
  case 430:
  case 431:
  case 432:
  case 490: return kGroupToolLength;
  case 980:
  case 990: return kGroupRetract;
  case 540:
  case 550:
  case 560:
  case 570:
  case 580:
  case 590:
  case 591:
  case 592:
  case 593: return kGroupCoordSystem;
  case 610:
  case 611:
  case 640: return kGroupPathControl;
  case 960:
  case 970: return kGroupSpindleMode;
  case 70:
  case 80: return kGroupLathe;
  default: return -1;
  }
}

int m_group(int m) {
  if (m >= 100 && m <= 199) return kMGroupUser;
  switch (m) {
  case 0:
  case 1:
  case 2:
  case 30:
  case 60: return kMGroupStop;
  case 62:
  case 63:
  case 64:
  case 65:
  case 66:
  case 67:
  case 68: return kMGroupIo;
  case 6:
  case 61: return kMGroupToolChange;
  case 3:
  case 4:
  case 5:
  case 19: return kMGroupSpindle;
  case 7:
  case 8:
  case 9: return kMGroupCoolant;
  case 48:
  case 49:
  case 50:
  case 51:
  case 52:
  case 53: return kMGroupOverride;
  case 70:
  case 71:
  case 72:
  case 73: return kMGroupModalState;
  case 98:
  case 99: return kMGroupSubprogram;
  default: return -1;
  }
}

std::array<char, 32> g_name(GCode g) {
  std::array<char, 32> out{};
  if (g % 10 == 0) {
    std::snprintf(out.data(), out.size(), "G%d", g / 10);
  } else {
    std::snprintf(out.data(), out.size(), "G%d.%d", g / 10, g % 10);
  }
  return out;
}

}  // namespace usina::gcode
