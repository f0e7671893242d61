// The grbl dialect (Grbl 1.1, docs/grbl.md): its table and options, and the
// runner. The runner reads the program once, line by line, as Grbl reads a
// stream: each line is checked as Grbl would (grbl/lines.cpp,
// grbl/check.cpp, grbl/system.cpp, grbl/reader.cpp), run by the RS274NGC
// interpreter, and its moves checked from the position
// (grbl/machine_check.cpp). Grbl reports an error and reads the next line;
// so does the runner, the refused line changing nothing (grbl/runner.cpp).
#include "gcode/grbl/runner.hpp"

namespace usina::gcode {
namespace {

// Grbl's modal groups (gcode.h); M groups from 100. grbl/check.cpp uses the
// same numbers.
constexpr int kNonModal = 0, kMotion = 1, kPlane = 2, kDistance = 3, kArcDistance = 4,
              kFeedMode = 5, kUnits = 6, kCutterComp = 7, kToolLength = 8, kCoordSystem = 12,
              kPath = 13, kStop = 104, kSpindle = 107, kCoolant = 108;

std::unique_ptr<ProgramRunner> make(RunContext context) {
  return std::make_unique<grbl::Runner>(grbl_dialect(), std::move(context));
}

}  // namespace

const Dialect& grbl_dialect() {
  static const Dialect d{
      "grbl",
      LexicalRules{"\n", false},
      {
          {'G', 0, kMotion, "motion"},
          {'G', 10, kMotion, "motion"},
          {'G', 20, kMotion, "motion"},
          {'G', 30, kMotion, "motion"},
          {'G', 382, kMotion, "probe"},
          {'G', 383, kMotion, "probe"},
          {'G', 384, kMotion, "probe"},
          {'G', 385, kMotion, "probe"},
          {'G', 800, kMotion, "motion"},
          {'G', 40, kNonModal, "dwell"},
          {'G', 100, kNonModal, "offsets"},
          {'G', 280, kNonModal, "home"},
          {'G', 281, kNonModal, "home"},
          {'G', 300, kNonModal, "home"},
          {'G', 301, kNonModal, "home"},
          {'G', 530, kNonModal, "machine_coords"},
          {'G', 920, kNonModal, "offsets"},
          {'G', 921, kNonModal, "offsets"},
          {'G', 170, kPlane, "plane"},
          {'G', 180, kPlane, "plane"},
          {'G', 190, kPlane, "plane"},
          {'G', 900, kDistance, "distance"},
          {'G', 910, kDistance, "distance"},
          {'G', 911, kArcDistance, "distance"},
          {'G', 930, kFeedMode, "feed_mode"},
          {'G', 940, kFeedMode, "feed_mode"},
          {'G', 200, kUnits, "units"},
          {'G', 210, kUnits, "units"},
          {'G', 400, kCutterComp, "comp_off"},
          {'G', 431, kToolLength, "tool_length"},
          {'G', 490, kToolLength, "tool_length"},
          {'G', 540, kCoordSystem, "coord_system"},
          {'G', 550, kCoordSystem, "coord_system"},
          {'G', 560, kCoordSystem, "coord_system"},
          {'G', 570, kCoordSystem, "coord_system"},
          {'G', 580, kCoordSystem, "coord_system"},
          {'G', 590, kCoordSystem, "coord_system"},
          {'G', 610, kPath, "path"},
          {'M', 0, kStop, "stop"},
          {'M', 10, kStop, "stop"},
          {'M', 20, kStop, "end"},
          {'M', 300, kStop, "end"},
          {'M', 30, kSpindle, "spindle"},
          {'M', 40, kSpindle, "spindle"},
          {'M', 50, kSpindle, "spindle"},
          {'M', 70, kCoolant, "coolant"},
          {'M', 80, kCoolant, "coolant"},
          {'M', 90, kCoolant, "coolant"},
      },
      {
          {'G', 0, kMotion, "motion"},
          {'G', 540, kCoordSystem, "coord_system"},
          {'G', 170, kPlane, "plane"},
          {'G', 210, kUnits, "units"},
          {'G', 900, kDistance, "distance"},
          {'G', 940, kFeedMode, "feed_mode"},
          {'M', 50, kSpindle, "spindle"},
          {'M', 90, kCoolant, "coolant"},
          {'G', 911, kArcDistance, "distance"},
          {'G', 400, kCutterComp, "comp_off"},
          {'G', 490, kToolLength, "tool_length"},
          {'G', 610, kPath, "path"},
      },
      {
          {"after_error",
           {"continue", "stop"},
           "continue: report the error and read the next line, as the firmware does; stop: end "
           "at the first error, as a sender that stops streaming"},
          {"grbl_m7", {"off", "on"}, "M7 (mist) exists only in Grbl builds with ENABLE_M7"},
          {"line_buffer",
           {"80", "256"},
           "LINE_BUFFER_SIZE of the build (config.h): a line holds one character less "
           "(error:11); above 80 a $Nx= start-up line can be too long for the EEPROM (error:14)"},
          {"max_step_rate",
           {"off", "30000"},
           "MAX_STEP_RATE_HZ of the build (config.h; off by default): with 30000, a $10x/$11x "
           "setting whose steps/mm x max rate passes 30 kHz is error:12"},
      },
      &make};
  return d;
}

}  // namespace usina::gcode
