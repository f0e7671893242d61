// usina trace FILE: the canonical operations of a program (spec/trace.md),
// or its CL data (--format cldata|iso4343|cldump: docs/apt.md).
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "apt/cl_from_canon.hpp"
#include "apt/cldata.hpp"
#include "apt/iso4343.hpp"
#include "canon/trace_writer.hpp"
#include "cli/run.hpp"
#include "cli/verbs.hpp"
#include "core/held_output.hpp"
#include "core/output_file.hpp"

namespace usina::cli {
namespace {

int status = 0;

struct TraceOptions {
  RunOptions run;
  std::string format = "jsonl";
  std::string out = "-";
};

bool cl_format(const std::string& f) {
  return f == "cldata" || f == "iso4343" || f == "cldump";
}

// The CL data of the canon stream. cldata and iso4343 feed a post or a
// machine: none when the program has an error (as `usina apt` does); the
// record print shows what was read, errors and all. The records go out in
// parts as they come (never held whole in memory): into a file, which is
// put in place only when good, or, for standard output, into a held
// temporary file sent on when the run is over (the record print goes out
// at once).
int trace_cl(const TraceOptions& o, std::FILE* out) {
  std::optional<core::HeldOutput> held;
  if (o.out == "-" && o.format != "cldump") {
    held.emplace();
    if (held->stream() == nullptr) {
      fmt::print(stderr, "usina: error: trace: no temporary file to hold the CL data in ({}): {}\n",
                 held->folder(), std::strerror(errno));
      return 2;
    }
  }
  std::FILE* sink = held ? held->stream() : out;
  std::size_t written = 0;  // records
  apt::CanonToCl cl([&](std::vector<apt::ClRecord>&& records) {
    std::string bytes;
    if (o.format == "cldata")
      bytes = apt::write_cldata(records, static_cast<std::uint32_t>(written + 1));
    if (o.format == "iso4343") bytes = apt::write_iso4343(records, written == 0 ? "MM" : "");
    if (o.format == "cldump") bytes = apt::record_print(records, written + 1);
    written += records.size();
    std::fwrite(bytes.data(), 1, bytes.size(), sink);
  });
  const int run = run_program(o.run, cl);
  cl.finish();
  if (run == 2 || (run != 0 && o.format != "cldump")) return run;
  if (held && !held->send_to(out)) {
    fmt::print(stderr,
               "usina: error: trace: the CL data held for standard output could not be written or "
               "read back (is the temporary folder full?)\n");
    return 2;
  }
  return run;
}

int trace_ops(const TraceOptions& o, std::FILE* out) {
  canon::TraceWriter writer(
      out, o.format == "text" ? canon::TraceFormat::Text : canon::TraceFormat::Jsonl);
  return run_program(o.run, writer, [&writer](const core::SourceManager& sources) {
    writer.set_sources(&sources);
  });
}

// -o FILE through core::OutputFile (opened before the run, so that a bad
// path costs no run; put in place only after it).
int run_trace(const TraceOptions& o) {
  // Bytes are no text: a terminal would show them as noise, or obey them.
  if (o.format == "cldata" && o.out == "-" && ::isatty(STDOUT_FILENO) != 0) {
    fmt::print(stderr,
               "usina: error: trace: --format cldata is binary; give -o FILE or send standard "
               "output to a file or a pipe\n");
    return 2;
  }
  std::optional<core::OutputFile> file;
  if (o.out != "-") {
    auto opened = core::OutputFile::open(o.out, input_paths(o.run));
    if (!opened) {
      fmt::print(stderr, "usina: error: {}\n", opened.error());
      return 2;
    }
    file.emplace(std::move(*opened));
  }
  std::FILE* out = file ? file->stream() : stdout;
  const int run = cl_format(o.format) ? trace_cl(o, out) : trace_ops(o, out);
  if (!file || run == 2 || (run != 0 && (o.format == "cldata" || o.format == "iso4343")))
    return run;
  if (auto done = file->commit(); !done) {
    fmt::print(stderr, "usina: error: {}\n", done.error());
    return 2;
  }
  return run;
}

}  // namespace

int exit_status() {
  return status;
}

void set_exit_status(int s) {
  status = s;
}

void add_trace(CLI::App& app) {
  auto opts = std::make_shared<TraceOptions>();
  CLI::App* cmd = app.add_subcommand("trace", "print the canonical operations of a program");
  add_run_options(*cmd, opts->run);
  cmd->add_option("--format", opts->format,
                  "jsonl (one operation a line, JSON), text, or the program's CL data: cldata "
                  "(binary CLDATA), iso4343 (CL text), cldump (the record print)")
      ->check(CLI::IsMember({"jsonl", "text", "cldata", "iso4343", "cldump"}))
      ->capture_default_str();
  cmd->add_option("-o,--output", opts->out, "the output file ('-' writes standard output)")
      ->capture_default_str();
  cmd->callback([opts] { set_exit_status(run_trace(*opts)); });
}

}  // namespace usina::cli
