// usina apt PART.apt: an APT part program processed into CL records, printed
// as the record print of the conformance files (--format cldump) or as the
// canon trace (--format jsonl); --canonical lists the geometry definitions;
// --post writes the program for a control through the posts of `convert`.
#include <cmath>
#include <memory>
#include <string>

#include <fmt/format.h>

#include "apt/canon_out.hpp"
#include "apt/processor.hpp"
#include "canon/trace_writer.hpp"
#include "cli/diagnostic_printer.hpp"
#include "cli/post_output.hpp"
#include "cli/verbs.hpp"
#include "core/source.hpp"

namespace usina::cli {
namespace {

struct AptOptions {
  std::string file;
  std::string format = "cldump";
  std::string units = "mm";
  bool canonical = false;
  DiagnosticOptions diagnostics;
  PostOutput output;  // --post, -o and the post's options
};

// A number of a canonical form: -0 and rounding residues below 1e-12 as 0.
std::string canon_number(double v) {
  if (std::fabs(v) < 1e-12) v = 0.0;
  return fmt::format("{}", v);
}

void print_definitions(const std::vector<apt::Definition>& defs) {
  for (const apt::Definition& d : defs) {
    std::string nums;
    for (std::size_t i = 0; i < apt::canon_size(d.geom.type); ++i)
      nums += (i ? "," : "") + canon_number(d.geom.c[i]);
    fmt::print("{{\"name\":\"{}\",\"type\":\"{}\",\"canon\":[{}]}}\n", d.name,
               apt::type_name(d.geom.type), nums);
  }
}

double scale_of(const AptOptions& o) {
  return o.units == "inch" ? 25.4 : 1.0;
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

int run_apt(const AptOptions& o) {
  core::SourceManager sources;
  std::uint32_t id = 0;
  if (!read_program(o, sources, id)) return 2;
  DiagnosticPrinter diags(o.diagnostics);
  diags.set_sources(&sources);
  const apt::AptResult result = apt::process(sources.get(id)->text(), id, diags);
  if (o.canonical) {
    print_definitions(result.definitions);
  } else if (o.format == "cldump") {
    fmt::print("{}", apt::record_print(result.records));
  } else {
    canon::TraceWriter writer(stdout, canon::TraceFormat::Jsonl);
    apt::to_canon(result.records, scale_of(o), writer);
  }
  return diags.errors() > 0 ? 1 : 0;
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
    apt::to_canon(result.records, scale_of(o), sink);
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
  for (const char* opt : {"--output", "--program-number", "--program-name", "--decimals",
                          "--line-numbers", "--tool-change", "--peck"})
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
                  "cldump (the CL records, one a line) or jsonl (the canon trace)")
      ->check(CLI::IsMember({"cldump", "jsonl"}))
      ->capture_default_str();
  cmd->add_option("--units", opts->units, "the program's unit, for jsonl: mm or inch")
      ->check(CLI::IsMember({"mm", "inch"}))
      ->capture_default_str();
  cmd->add_flag("--canonical", opts->canonical,
                "print each geometry definition's canonical form as a JSON line");
  add_diagnostic_options(*cmd, opts->diagnostics);
  add_post_options(*cmd, opts->output);
  cmd->get_option("--post")->required(false);  // only to write a program
  cmd->callback([opts, cmd] {
    if (!settle_output(*cmd, *opts)) return set_exit_status(2);
    set_exit_status(opts->output.post.empty() ? run_apt(*opts) : post_apt(*opts));
  });
}

}  // namespace usina::cli
