// Post-processors: the canon stream written as one control's G-code
// (DESIGN.md, "post"). One file per control; writer.cpp holds what they share.
#pragma once

#include <memory>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "canon/sink.hpp"
#include "core/diagnostic.hpp"

namespace usina::post {

// What a user may choose about the program a post writes.
struct PostOptions {
  int program_number = 1000;    // O word (fanuc, rs274ngc comment, romi comment)
  std::string program_name;     // a comment in the header
  int decimals = -1;            // digits after the point; -1: the control's own
  bool line_numbers = false;    // N words step 10 (romi always writes them)
  bool tool_change = false;     // grbl: write T M6 (grbl 1.1 rejects M6 without a tool changer)
  double peck = 0.0;            // > 0: bare holes as G83 pecks of this depth, else G81
  double peck_clearance = 1.0;  // expanded G83: rapid back down to this above the last peck
};

// The names of the controls, in the order `usina ... --post` lists them.
const std::vector<std::string>& post_names();

// A post for `control` (one of post_names()) writing to `out`. Ops a control
// cannot express are reported to `diags` (E_UNSUPPORTED) at their block; the
// program is then not valid for that control. Returns nullptr for an unknown name.
std::unique_ptr<canon::Sink> make_post(std::string_view control, std::ostream& out,
                                       const PostOptions& options, core::DiagnosticSink& diags);

}  // namespace usina::post
