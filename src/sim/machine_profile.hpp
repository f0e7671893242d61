// A machine profile (issue 6): axes, limits, rates and times of one machine,
// read from TOML. Every length is kept in mm, every rate in mm/min, every
// acceleration in mm/s² (rotary axes: degrees), whatever units the file uses.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>

#include "core/diagnostic.hpp"

namespace usina::sim {

struct AxisLimits {
  bool present = false;
  double min = 0.0;
  double max = 0.0;
  double rapid = 0.0;     // per minute
  double max_feed = 0.0;  // per minute
  double accel = 0.0;     // per second squared
  double jerk = 0.0;      // per second cubed; 0 = trapezoidal profile
};

enum class PlannerModel { Textbook, Linuxcnc, Grbl };

// The model's name in a profile ("textbook", "linuxcnc", "grbl").
const char* planner_model_name(PlannerModel m);

// LinuxCNC 2.9's trajectory planner (tpmod), its INI settings (src/sim/planner_linuxcnc.hpp).
struct LinuxcncPlannerSettings {
  double servo_period = 0.001;  // s, [EMCMOT] SERVO_PERIOD
  double max_velocity = 0.0;    // mm/s along the path, [TRAJ] MAX_LINEAR_VELOCITY; 0: none
  double kink_ratio = 0.1;      // [TRAJ] ARC_BLEND_KINK_RATIO
  bool arc_blend = true;        // [TRAJ] ARC_BLEND_ENABLE
  double gap_cycles = 4.0;      // [TRAJ] ARC_BLEND_GAP_CYCLES
  double max_feed_scale = 1.0;  // [DISPLAY] MAX_FEED_OVERRIDE
  // [TRAJ] ARC_BLEND_OPTIMIZATION_DEPTH: queue entries planned back from the
  // newest; a run of tiny moves goes no faster than it can stop within them.
  std::size_t optimization_depth = 50;
  // The blend tolerance LinuxCNC 2.9 behaves as if it had before a program's
  // first G61/G61.1/G64 (fitted to measurements, not an INI setting).
  double startup_tolerance = 0.0044;  // mm
};

struct MachineProfile {
  std::string name;
  bool file_in_inch = false;         // the units the file was written in
  std::array<AxisLimits, 6> axes{};  // X Y Z A B C
  double spindle_max_rpm = 0.0;
  double spindle_accel_time = 0.0;  // s, from stop to full speed
  double tool_change_time = 0.0;    // s
  double block_time = 0.0;          // s of processing per block
  double cost_per_hour = 0.0;
  // [planner] junction_deviation: how far inside a sharp corner the path may
  // round it (grbl's junction deviation), setting the speed through corners.
  double junction_deviation = 0.01;  // mm
  // [planner] model: whose rules plan the motion (docs/stats.md, "Planner
  // models"); the textbook's by default.
  PlannerModel model = PlannerModel::Textbook;
  // [planner] arc_tolerance (grbl's $12): an arc runs as chords that leave
  // it by at most this.
  double arc_tolerance = 0.002;  // mm
  LinuxcncPlannerSettings linuxcnc;
};

// Reads a profile; every problem is a diagnostic (E_BAD_MACHINE_PROFILE)
// at the line and column of the key. Nullopt when the profile is unusable.
std::optional<MachineProfile> read_machine_profile(std::string_view toml_text,
                                                   std::uint32_t file_id,
                                                   core::DiagnosticSink& diags);

}  // namespace usina::sim
