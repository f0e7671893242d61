// What the verbs that write a program share (convert, gen ...): the post and
// its options, the output file, and one run of a generator into the post.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "canon/sink.hpp"
#include "cli/diagnostic_printer.hpp"
#include "core/diagnostic.hpp"
#include "core/source.hpp"
#include "post/post.hpp"

namespace usina::cli {

struct PostOutput {
  std::string post;
  std::string out = "-";
  post::PostOptions options;
  std::vector<std::string> inputs;  // files the verb reads: never the output
};

void add_post_options(CLI::App& app, PostOutput& o);

// The post's diagnostics, rendered on stderr as they come, against the
// sources of the run that made the ops (when there is one).
using PostDiagnostics = DiagnosticPrinter;

// Runs `produce` (it feeds ops to the sink it is given and returns an exit
// status) into the chosen post and writes the program to o.out only when
// both succeeded: a failed run leaves no half program behind.
int write_program(const PostOutput& o,
                  const std::function<int(canon::Sink&, PostDiagnostics&)>& produce);

}  // namespace usina::cli
