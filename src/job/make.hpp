// A loaded job made into one program: for each operation in order, the
// geometry off its layer, its tool (named, or chosen by the job's rules),
// its spindle speed and feeds (from the cutting data, or given), then the
// generator of usina gen that makes it (cam/), into one canon stream: tool
// changes in order, a retract to the safe Z between operations, one end.
// The program's comments say why each number is what it is.
#pragma once

#include "canon/sink.hpp"
#include "core/diagnostic.hpp"
#include "job/load.hpp"
#include "job/sheet.hpp"

namespace usina::job {

// False after an error (reported at the job file's line when it has one).
// Ops may have reached the sink by then: the caller writes no program.
// `sheet`, when given, learns each step (operation and tool) as it begins:
// the setup sheet's (job/sheet.hpp).
bool make_job(const LoadedJob& j, canon::Sink& sink, core::DiagnosticSink& diags,
              SheetLog* sheet = nullptr);

}  // namespace usina::job
