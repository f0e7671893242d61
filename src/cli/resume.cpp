// usina resume: the restart program of a program from a block or the first
// change to a tool (docs/resume.md), for a shop without the DNC server. The
// same text the server sends for a job with start_block or start_tool.
#include "dnc/resume.hpp"

#include <fstream>
#include <memory>
#include <sstream>
#include <string>

#include <fmt/format.h>

#include "cli/verbs.hpp"
#include "core/output_file.hpp"
#include "gcode/dialect.hpp"

namespace usina::cli {
namespace {

struct ResumeOptions {
  std::string file;
  std::string dialect = "rs274ngc";
  std::string block;
  long tool = -1;
  std::string output;
};

int fail(int status, const std::string& message) {
  fmt::print(stderr, "usina: error: resume: {}\n", message);
  return status;
}

int run_resume(const ResumeOptions& o) {
  if (o.block.empty() == (o.tool < 0)) return fail(2, "give one of --block N and --tool T");
  gcode::ResumeStart start{gcode::ResumeStart::Kind::Tool, o.tool};
  if (!o.block.empty()) {
    auto b = gcode::parse_start_block(o.block);
    if (!b)
      return fail(2,
                  fmt::format("--block {}: give a line number (120) or an N word (N120)", o.block));
    start = *b;
  }
  if (gcode::find_dialect(o.dialect) == nullptr)
    return fail(2, fmt::format("unknown dialect {}", o.dialect));
  std::ifstream in(o.file, std::ios::binary);
  if (!in) return fail(2, fmt::format("cannot read {}", o.file));
  std::ostringstream text;
  text << in.rdbuf();
  auto program = dnc::resume_program(text.str(), o.dialect, start);
  if (!program) return fail(1, fmt::format("{}: {}", o.file, program.error()));
  if (auto ok = core::write_file(o.output, *program, {o.file}); !ok) return fail(2, ok.error());
  return 0;
}

}  // namespace

void add_resume(CLI::App& app) {
  auto opts = std::make_shared<ResumeOptions>();
  CLI::App* cmd =
      app.add_subcommand("resume",
                         "write a restart program: from block N or tool T, with a preamble that "
                         "restores the modal state and a safe approach");
  cmd->add_option("FILE", opts->file, "the program")->required();
  cmd->add_option("--dialect", opts->dialect,
                  "the program's dialect (rs274ngc, fanuc, romi, grbl)");
  cmd->add_option("--block", opts->block,
                  "start at this line of the file (120) or the block with this N word (N120)");
  cmd->add_option("--tool", opts->tool, "start at the first change to this tool")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("-o,--output", opts->output, "the restart program's file")->required();
  cmd->callback([opts] { set_exit_status(run_resume(*opts)); });
}

}  // namespace usina::cli
