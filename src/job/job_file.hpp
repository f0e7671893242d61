// A job file (docs/job.md): the machine, the stock and its material, the
// drawing, the tool library, and the operations in the order they are cut
// (seed 004, table 7.6: the CAM steps from the model to the program). Read
// here and checked for shape (keys, types, ranges); what the names refer to
// (tools, material, layers) is checked when the job is made (job/make.hpp).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/diagnostic.hpp"

namespace usina::job {

enum class OpType {
  Drill,
  Spot,
  Tap,
  Bore,
  Pocket,
  Profile,
  EllipsePocket,
  Face,
  Engrave,
  Chamfer
};

std::string_view op_type_name(OpType t);

// How a bore leaves its hole (docs/job.md, "Boring"): fed out (G85, the
// default), fed out after a dwell at the bottom (G89), or out at rapid
// with the spindle stopped (G86).
enum class BoreCycle { FeedOut, DwellFeedOut, StopRapidOut };

struct Operation {
  OpType type = OpType::Pocket;
  core::SourceLoc loc;  // its [[operation]] header
  std::string layer;    // of the drawing; empty for an ellipse pocket, a facing, an engraving
  core::SourceLoc layer_loc;
  std::optional<int> tool;  // nullopt: "auto", the job chooses
  core::SourceLoc tool_loc;
  double depth = 0;  // mm below the stock's top (Z0); a chamfer's follows from its width
  core::SourceLoc depth_loc;
  std::optional<double> step_down;  // default: half the tool's diameter
  std::optional<double> stepover;   // pocket, ellipse: default half the tool's diameter; face: 70 %
  std::optional<double> diameter;   // drill: only the holes of this diameter
  double peck = 0;                  // drill: G83 pecks, 0 for G81
  double retract = 1.0;             // drill: the R plane above Z0
  // bore: the holes are there before the job (cast, or drilled in another
  // setup): no earlier operation of the job need drill them.
  bool predrilled = false;
  BoreCycle bore_cycle = BoreCycle::FeedOut;  // bore: `cycle`
  double dwell = 0;                           // bore, G89: s at the bottom
  std::string side = "outside";               // profile, chamfer
  double width = 0;                           // chamfer: its leg on the top face, mm
  core::SourceLoc width_loc;
  double tip_offset = 0.5;  // chamfer: how far the tip goes below the chamfer's foot
  double lead_radius = 0;   // profile
  int tabs = 0;             // profile
  double tab_width = 3.0;
  double tab_height = 1.0;
  std::array<double, 2> center{0, 0};  // ellipse
  double rx = 0;
  double ry = 0;
  std::string text;                // engrave: the text, in a single-stroke Hershey font
  std::string font = "rowmans";    // engrave
  double height = 5.0;             // engrave: a capital letter's height, mm
  std::array<double, 2> at{0, 0};  // engrave: where the first letter's baseline starts
  core::SourceLoc place_loc;       // the ellipse's `center`, the engraving's `at`
  std::optional<double> rpm;       // given: the cutting data are not used
  std::optional<double> feed;
  std::optional<double> plunge_feed;
};

struct Stock {
  std::string shape = "box";            // or "cylinder"
  std::array<double, 3> size{0, 0, 0};  // box: x y z; cylinder: diameter, height, 0
  std::array<double, 2> origin{0, 0};   // the stock's corner (box) or centre (cylinder)
  std::string material;
  core::SourceLoc material_loc;
};

struct Job {
  std::string name;
  std::string machine;  // paths, already relative to the job file's folder
  std::string tools;
  std::string materials;
  std::string drawing;  // empty: no drawing (an ellipse pocket needs none)
  core::SourceLoc tools_loc, materials_loc, drawing_loc, machine_loc;
  // A LinuxCNC tool table as the library (`tools` ending in ".tbl"): the
  // mm of its machine's unit (1, or 25.4 for "inch"); 0: not given.
  double tool_table_mm = 0;
  core::SourceLoc tool_table_units_loc;
  double safe_z = 5.0;
  std::string setup_note;  // fixtures, clamping, zero: for the setup sheet (--sheet)
  Stock stock;
  std::vector<Operation> operations;
};

// Reads a job; `folder` is the job file's folder, which its paths are
// relative to. Every problem a diagnostic at its line; nullopt when unusable.
std::optional<Job> read_job(std::string_view toml_text, std::uint32_t file,
                            const std::string& folder, core::DiagnosticSink& diags);

}  // namespace usina::job
