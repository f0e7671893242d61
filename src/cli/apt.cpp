// usina apt PART.apt: an APT part program processed into CL records, printed
// as the record print of the conformance files (--format cldump), as the
// canon trace (--format jsonl), as binary CLDATA (--format cldata) or as
// ISO 4343 text (--format iso4343); --canonical lists the geometry
// definitions; --post writes the program for a control through the posts of
// `convert`.
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include <fmt/format.h>

#include "apt/canon_out.hpp"
#include "apt/cldata.hpp"
#include "apt/iso4343.hpp"
#include "apt/processor.hpp"
#include "canon/trace_writer.hpp"
#include "cli/diagnostic_printer.hpp"
#include "cli/post_output.hpp"
#include "cli/verbs.hpp"
#include "core/output_file.hpp"
#include "core/source.hpp"

namespace usina::cli {
namespace {

struct AptOptions {
  std::string file;
  std::string format = "cldump";
  std::string units = "mm";
  bool canonical = false;
  bool chords = false;  // --chords: IBM's chords of a circle in the canon stream, not the arc
  DiagnosticOptions diagnostics;
  PostOutput output;  // --post, -o (of every format too) and the post's options
};

// A number of a canonical form: -0 and rounding residues below 1e-12 as 0.
std::string canon_number(double v) {
  if (std::fabs(v) < 1e-12) v = 0.0;
  return fmt::format("{}", v);
}

std::string definitions(const std::vector<apt::Definition>& defs) {
  std::string out;
  for (const apt::Definition& d : defs) {
    std::string nums;
    for (double v : apt::canonical(d.geom))
      nums += (nums.empty() ? "" : ",") + canon_number(v);
    out += fmt::format("{{\"name\":\"{}\",\"type\":\"{}\",\"canon\":[{}]}}\n", d.name,
                       apt::type_name(d.geom.type), nums);
  }
  return out;
}

double scale_of(const AptOptions& o) {
  return o.units == "inch" ? 25.4 : 1.0;
}

apt::Circles circles_of(const AptOptions& o) {
  return o.chords ? apt::Circles::Chords : apt::Circles::Arcs;
}

// Reads the program into `sources`; false (and a message) when it cannot.
bool read_program(const AptOptions& o, core::SourceManager& sources, std::uint32_t& id) {
  std::string err;
  auto file = core::SourceFile::open(o.file, err, 1ull << 30);
  if (!file) {
    fmt::print(stderr, "usina: error: cannot read {}: {}\n", o.file, err);
    return false;
  }
  id = sources.add(std::move(file));
  return true;
}

// The canon trace, as `usina trace` writes it (docs/trace.md).
class JsonlText final : public canon::Sink {
 public:
  void on(const canon::Op& op) override { text += canon::to_jsonl(op) + "\n"; }

  std::string text;
};

// cldata and iso4343 feed a post or a machine: written only when the program
// has no error. cldump, jsonl and --canonical show what was read, errors and all.
bool whole_only(const AptOptions& o) {
  return !o.canonical && (o.format == "cldata" || o.format == "iso4343");
}

std::string formatted(const AptOptions& o, const apt::AptResult& result) {
  if (o.canonical) return definitions(result.definitions);
  if (o.format == "cldata") return apt::write_cldata(result.records);
  if (o.format == "iso4343")
    return apt::write_iso4343(result.records, o.units == "inch" ? "INCHES" : "MM");
  if (o.format == "cldump") return apt::record_print(result.records);
  JsonlText trace;
  apt::to_canon(result.records, scale_of(o), trace, circles_of(o));
  return std::move(trace.text);
}

// Standard output or -o FILE (core::OutputFile: replaced only when whole).
int write_out(const AptOptions& o, const std::string& bytes) {
  if (o.output.out == "-") {
    std::fwrite(bytes.data(), 1, bytes.size(), stdout);
    return 0;
  }
  if (auto written = core::write_file(o.output.out, bytes, {o.file}); !written) {
    fmt::print(stderr, "usina: error: {}\n", written.error());
    return 2;
  }
  return 0;
}

int run_apt(const AptOptions& o) {
  // Bytes are no text: a terminal would show them as noise, or obey them.
  if (!o.canonical && o.format == "cldata" && o.output.out == "-" && ::isatty(STDOUT_FILENO) != 0) {
    fmt::print(stderr,
               "usina: error: apt: --format cldata is binary; give -o FILE or send standard "
               "output to a file or a pipe\n");
    return 2;
  }
  if (o.output.out != "-") {
    if (auto ok = core::check_not_input(o.output.out, o.file); !ok) {
      fmt::print(stderr, "usina: error: {}\n", ok.error());
      return 2;
    }
  }
  core::SourceManager sources;
  std::uint32_t id = 0;
  if (!read_program(o, sources, id)) return 2;
  DiagnosticPrinter diags(o.diagnostics);
  diags.set_sources(&sources);
  const apt::AptResult result = apt::process(sources.get(id)->text(), id, diags);
  const int status = diags.errors() > 0 ? 1 : 0;
  if (status != 0 && whole_only(o)) return status;
  if (!o.canonical && o.format == "jsonl" && o.output.out == "-") {
    canon::TraceWriter writer(stdout, canon::TraceFormat::Jsonl);  // streamed, not held
    apt::to_canon(result.records, scale_of(o), writer, circles_of(o));
    return status;
  }
  const int written = write_out(o, formatted(o, result));
  return written != 0 ? written : status;
}

// --post: the canon stream into the post; nothing is written when the
// program has an error.
int post_apt(const AptOptions& o) {
  core::SourceManager sources;
  std::uint32_t id = 0;
  if (!read_program(o, sources, id)) return 2;
  PostOutput output = o.output;
  output.inputs = {o.file};
  return write_program(output, [&](canon::Sink& sink, PostDiagnostics& diags) {
    diags.set_sources(&sources);
    const apt::AptResult result = apt::process(sources.get(id)->text(), id, diags);
    if (diags.errors() > 0) return 1;
    apt::to_canon(result.records, scale_of(o), sink, circles_of(o));
    return diags.errors() > 0 ? 1 : 0;
  });
}

// --post excludes --format and --canonical; -o and the post's options need --post.
bool settle_output(CLI::App& cmd, const AptOptions& o) {
  const bool post = !o.output.post.empty();
  if (post && (cmd.count("--format") > 0 || o.canonical)) {
    fmt::print(stderr,
               "usina: error: apt: --post writes a program; give it or --format/--canonical\n");
    return false;
  }
  for (const char* opt : {"--program-number", "--program-name", "--decimals", "--line-numbers",
                          "--tool-change", "--peck"})
    if (!post && cmd.count(opt) > 0) {
      fmt::print(stderr, "usina: error: apt: {} goes with --post\n", opt);
      return false;
    }
  return true;
}

}  // namespace

void add_apt(CLI::App& app) {
  auto opts = std::make_shared<AptOptions>();
  CLI::App* cmd =
      app.add_subcommand("apt", "process an APT part program into CL data (docs/apt.md)");
  cmd->add_option("file", opts->file, "the APT program")->required();
  cmd->add_option("--format", opts->format,
                  "cldump (the CL records, one a line), jsonl (the canon trace), cldata (binary "
                  "CLDATA records) or iso4343 (CL text); -o FILE writes it to a file")
      ->check(CLI::IsMember({"cldump", "jsonl", "cldata", "iso4343"}))
      ->capture_default_str();
  cmd->add_option("--units", opts->units,
                  "the program's unit, mm or inch: jsonl in mm, iso4343's UNITS statement")
      ->check(CLI::IsMember({"mm", "inch"}))
      ->capture_default_str();
  cmd->add_flag("--canonical", opts->canonical,
                "print each geometry definition's canonical form as a JSON line");
  cmd->add_flag("--chords", opts->chords,
                "jsonl and --post: a circle as the chords of the CL (IBM's points), not an arc");
  add_diagnostic_options(*cmd, opts->diagnostics);
  add_post_options(*cmd, opts->output);
  cmd->get_option("--post")->required(false);  // only to write a program
  cmd->callback([opts, cmd] {
    if (!settle_output(*cmd, *opts)) return set_exit_status(2);
    set_exit_status(opts->output.post.empty() ? run_apt(*opts) : post_apt(*opts));
  });
}

}  // namespace usina::cli
