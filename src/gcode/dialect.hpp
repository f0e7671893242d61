// A dialect: what one control's language is (DESIGN.md, "Dialects are data
// plus a few handlers"). The lexical rules, the G/M table (code → modal
// group → handler name), the codes in force at program start and the named
// options are data; the handlers are functions registered by name in the
// dialect's own files. The runner is the interpreter that reads the table:
// the RS274NGC interpreter (interp/) or a dialect's own block engine.
// Adding a control is adding a folder src/gcode/<dialect>/ and one line in
// dialect.cpp's list.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <tl/expected.hpp>

#include "canon/sink.hpp"
#include "core/diagnostic.hpp"
#include "core/source.hpp"
#include "gcode/code_entry.hpp"
#include "gcode/interp/interpreter.hpp"
#include "gcode/var_file.hpp"

namespace usina::gcode {

// How the text is cut into blocks, as far as readers other than the
// dialect's runner need it (the store's normalised diff).
struct LexicalRules {
  std::string_view block_ends = "\n";  // characters that end a block besides end of file
  bool lower_case_meaning = false;     // a lower-case letter means something else
};

// An open choice of the dialect, set with --dialect-option name=value.
struct DialectOption {
  std::string_view name;
  // The first is the default. A last value "<list>" also takes a list of
  // whole numbers ("29,11,262").
  std::vector<std::string_view> values;
  std::string_view help;
};

using OptionValues = std::map<std::string, std::string, std::less<>>;

// What runs a program in a dialect.
// The modes in force after a run, as the program's G words name them: what
// a restart's preamble writes back (gcode/resume_point.hpp). The runner
// knows them from running the program, subroutines, macros and computed
// words included; no reading of the text can.
struct RunModes {
  bool inch = false;
  int plane = 17;                // 17, 18 or 19
  bool incremental = false;      // G91
  int work_offset = 0;           // G54 ... G59.3 in tenths when the program chose one, else 0
  int length_h = -1;             // ModalState::length_h
  int feed_mode = 94;            // 93, 94 or 95
  int motion = 0;                // the motion mode in tenths (G80: 800)
  bool offsets_written = false;  // ModalState::offsets_written
  bool frame_moved = false;      // a G92 or G52 offset, or a rotation, in force
};

// The modes of the RS274NGC interpreter's state (rs274ngc, fanuc, grbl).
RunModes run_modes(const ModalState& s);

class ProgramRunner {
 public:
  virtual ~ProgramRunner() = default;
  // A numbered parameter before the run (a parameter file).
  virtual void set_parameter(int index, double value) = 0;
  // Runs the program to its end or first error; true when no error.
  virtual bool run(std::uint32_t file) = 0;

  // The variables the control keeps across power-off, as they stand (after
  // the run, or after its error: the control keeps what was set), for
  // usina's --save-vars. nullopt: the dialect has none.
  virtual std::optional<std::vector<VarFileEntry>> persistent_variables() const {
    return std::nullopt;
  }

  // The modes in force where the run ended (RunModes). nullopt: the
  // dialect's runner does not report them.
  virtual std::optional<RunModes> modes() const { return std::nullopt; }
};

struct RunContext {
  core::SourceManager& sources;
  InterpOptions options;
  OptionValues dialect_options;  // every option of the dialect, defaults filled in
  canon::Sink& sink;
  core::DiagnosticSink& diags;
};

struct Dialect {
  std::string_view name;
  LexicalRules lexical;
  std::vector<CodeEntry> codes;        // the G/M table (code_table.hpp resolves it)
  std::vector<CodeEntry> start_codes;  // in force at program start
  std::vector<DialectOption> options;
  std::unique_ptr<ProgramRunner> (*make_runner)(RunContext context) = nullptr;

  const CodeEntry* find_code(char letter, int code) const;
};

// The dialects usina knows, by name.
const std::vector<const Dialect*>& all_dialects();
const Dialect* find_dialect(std::string_view name);

// Every option of the dialect at its default (the first of its values).
OptionValues default_options(const Dialect& d);

// Reads "name=value" settings against the dialect's options, the defaults
// filled in for the others. On an unknown name or value, the error is a
// message listing the valid ones.
tl::expected<OptionValues, std::string> resolve_options(const Dialect& d,
                                                        const std::vector<std::string>& given);

}  // namespace usina::gcode
