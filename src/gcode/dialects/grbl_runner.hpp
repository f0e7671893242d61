// The runner of the grbl dialect: Grbl's checks line by line, then the
// RS274NGC interpreter on a copy of the program holding only the lines Grbl
// accepts (grbl.cpp says why).
#pragma once

#include <cstdint>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "gcode/dialect.hpp"
#include "gcode/dialects/grbl.hpp"

namespace usina::gcode {

const Dialect& grbl_dialect();

namespace grbl {

// The program as the interpreter is to run it, and what the checks found.
struct Prepared {
  std::string text;                     // one line per line of the program
  std::vector<core::Diagnostic> diags;  // Grbl's errors and usina's warnings, in the program
  MachineFacts facts;                   // for the soft-limit check of the moves
};

class Runner final : public ProgramRunner {
 public:
  Runner(const Dialect& d, RunContext context) : dialect_(d), c_(std::move(context)) {}

  void set_parameter(int index, double value) override { params_.emplace_back(index, value); }

  bool run(std::uint32_t file) override;

  // At most this many lines refused by the interpreter are skipped and the
  // program run again; after that the run ends at the next one.
  static constexpr int kMaxReruns = 50;

 private:
  struct Line {
    std::uint64_t offset = 0;
    std::string_view text;
  };

  Prepared prepare(std::uint32_t file, const std::set<std::uint32_t>& refused,
                   std::uint32_t cut_from) const;
  void split_lines(std::string_view text);
  void to_file(core::SourceLoc& loc, std::uint32_t file) const;
  bool report_diagnostics(std::uint32_t file, std::vector<core::Diagnostic> diags,
                          const core::DiagnosticList& last_run,
                          const std::vector<core::Diagnostic>& found);
  void stream_accepted(std::uint32_t file, std::uint32_t copy, const MachineFacts& facts);

  const Dialect& dialect_;
  RunContext c_;
  std::vector<std::pair<int, double>> params_;
  std::vector<Line> lines_;
};

}  // namespace grbl
}  // namespace usina::gcode
