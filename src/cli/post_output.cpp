#include "cli/post_output.hpp"

#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

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
      ->check(CLI::PositiveNumber);
}

void PostDiagnostics::report(core::Diagnostic d) {
  if (d.severity == core::Severity::Error) ++errors_;
  static const core::SourceManager kNone;
  const std::string text = core::render(d, sources_ != nullptr ? *sources_ : kNone);
  std::fwrite(text.data(), 1, text.size(), stderr);
}

int write_program(const PostOutput& o,
                  const std::function<int(canon::Sink&, PostDiagnostics&)>& produce) {
  // A file is written beside its name and renamed once the program is good,
  // so a failed run leaves no file and a big program is never held in
  // memory; standard output is held, as it cannot be taken back.
  const bool to_stdout = o.out == "-";
  const std::string partial = o.out + ".partial-" + std::to_string(::getpid());
  std::ostringstream held;
  std::ofstream file;
  if (!to_stdout) {
    file.open(partial, std::ios::binary);
    if (!file) {
      fmt::print(stderr, "usina: error: cannot write {}\n", o.out);
      return 2;
    }
  }
  std::ostream& text = to_stdout ? static_cast<std::ostream&>(held) : file;
  PostDiagnostics post_diags;
  auto sink = post::make_post(o.post, text, o.options, post_diags);
  if (!sink) {
    fmt::print(stderr, "usina: error: unknown post '{}'\n", o.post);
    if (!to_stdout) std::remove(partial.c_str());
    return 2;
  }
  int status = produce(*sink, post_diags);
  sink->finish();  // a post's finish is idempotent; a generator need not call it
  if (status == 0 && post_diags.errors() > 0) status = 1;
  if (to_stdout) {
    if (status == 0) fmt::print("{}", held.str());
    return status;
  }
  const bool written = static_cast<bool>(file.flush());
  file.close();
  if (status == 0 && (!written || std::rename(partial.c_str(), o.out.c_str()) != 0)) {
    fmt::print(stderr, "usina: error: cannot write {}\n", o.out);
    status = 2;
  }
  if (status != 0) std::remove(partial.c_str());
  return status;
}

}  // namespace usina::cli
