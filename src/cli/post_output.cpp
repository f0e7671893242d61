#include "cli/post_output.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>

#include <fmt/format.h>

#include "cli/validators.hpp"
#include "core/file_ostream.hpp"
#include "core/held_output.hpp"
#include "core/output_file.hpp"

namespace usina::cli {

void add_post_options(CLI::App& app, PostOutput& o) {
  app.add_option("--post", o.post, "the control to write for")
      ->required()
      ->check(CLI::IsMember(post::post_names()));
  app.add_option("-o,--output", o.out, "the program file ('-' writes standard output)")
      ->capture_default_str();
  app.add_option("--program-number", o.options.program_number,
                 "O number (Fanuc), a comment elsewhere")
      ->check(CLI::Range(1, 9999))
      ->capture_default_str();
  app.add_option("--program-name", o.options.program_name, "a comment in the header");
  app.add_option("--decimals", o.options.decimals,
                 "digits after the point (default: the control's: rs274ngc 4, others 3)")
      ->check(CLI::Range(0, 6));
  app.add_flag("--line-numbers", o.options.line_numbers, "N words, step 10 (romi always)");
  app.add_flag("--tool-change", o.options.tool_change,
               "grbl: write T M6 (else a comment and an M0 pause)");
  app.add_option("--peck", o.options.peck, "holes as G83 pecks of this depth, mm (else G81)")
      ->check(kPositiveFinite);
}

namespace {

int unknown_post(const std::string& name) {
  fmt::print(stderr, "usina: error: unknown post '{}'\n", name);
  return 2;
}

}  // namespace

namespace {

// Standard output cannot be taken back, so the program is held until it is
// good (in a temporary file: core::HeldOutput), then written.
int write_to_stdout(const PostOutput& o,
                    const std::function<int(canon::Sink&, PostDiagnostics&)>& produce) {
  const core::HeldOutput held;
  if (held.stream() == nullptr) {
    fmt::print(stderr, "usina: error: no temporary file to hold the program in ({}): {}\n",
               held.folder(), std::strerror(errno));
    return 2;
  }
  core::FileOstream text(held.stream());
  PostDiagnostics post_diags;
  auto sink = post::make_post(o.post, text, o.options, post_diags);
  if (!sink) return unknown_post(o.post);
  int status = produce(*sink, post_diags);
  sink->finish();  // a post's finish is idempotent; a generator need not call it
  if (status == 0 && post_diags.errors() > 0) status = 1;
  if (status != 0) return status;
  text.flush();
  if (!held.send_to(stdout)) {
    fmt::print(stderr,
               "usina: error: the program held for standard output could not be written or read "
               "back (is the temporary folder full?)\n");
    return 2;
  }
  return 0;
}

}  // namespace

int write_program(const PostOutput& o,
                  const std::function<int(canon::Sink&, PostDiagnostics&)>& produce) {
  if (o.out == "-") return write_to_stdout(o, produce);
  // Written to a temporary beside the target and put in place only when the
  // program is good (core::OutputFile), so a failed run leaves nothing and a
  // big program is never held in memory.
  auto file = core::OutputFile::open(o.out, o.inputs);
  if (!file) {
    fmt::print(stderr, "usina: error: {}\n", file.error());
    return 2;
  }
  core::FileOstream text(file->stream());
  PostDiagnostics post_diags;
  auto sink = post::make_post(o.post, text, o.options, post_diags);
  if (!sink) return unknown_post(o.post);
  int status = produce(*sink, post_diags);
  sink->finish();
  if (status == 0 && post_diags.errors() > 0) status = 1;
  if (status != 0) return status;  // the temporary goes with `file`
  text.flush();
  if (auto committed = file->commit(); !committed) {
    fmt::print(stderr, "usina: error: {}\n", committed.error());
    return 2;
  }
  return 0;
}

}  // namespace usina::cli
