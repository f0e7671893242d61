// usina: a workbench for CNC part programs. One file per verb.
//
// Exit status, for every verb (docs/cli.md): 0 done; 1 the program or
// drawing read has errors; 2 a usage error, an input that cannot be read or
// an output that cannot be written (a full disk included).
#include <cstdio>
#include <exception>
#include <new>
#include <string>
#include <string_view>
#include <system_error>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "cli/verbs.hpp"
#include "core/output_file.hpp"

namespace {

constexpr int kUsage = 2;

std::string verb_list(const CLI::App& app) {
  std::string out;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
    out += (out.empty() ? "" : ", ") + sub->get_name();
  return out;
}

// `usina help [VERB]`, as git and cargo have it.
int help(const CLI::App& app, int argc, char** argv) {
  if (argc < 3) {
    fmt::print("{}", app.help());
    return 0;
  }
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) {
    if (sub->get_name() == argv[2]) {
      fmt::print("{}", sub->help());
      return 0;
    }
  }
  fmt::print(stderr, "usina: error: no verb '{}'; the verbs are {}\n", argv[2], verb_list(app));
  return kUsage;
}

// CLI11's messages, said the way usina's other errors are, with the verb
// and where to read more; every usage error exits 2.
int usage_error(const CLI::App& app, const CLI::ParseError& e, int argc, char** argv) {
  if (app.get_subcommands().empty() && argc > 1 && argv[1][0] != '-') {
    fmt::print(stderr, "usina: error: no verb '{}'; the verbs are {} (usina --help)\n", argv[1],
               verb_list(app));
    return kUsage;
  }
  std::string verb;  // "calc bcd": the deepest subcommand given
  for (const CLI::App* at = &app; !at->get_subcommands().empty();) {
    at = at->get_subcommands().front();
    verb += (verb.empty() ? "" : " ") + at->get_name();
  }
  if (verb.empty()) {
    fmt::print(stderr, "usina: error: {} (usina --help)\n", e.what());
  } else {
    fmt::print(stderr, "usina: error: {}: {} (usina {} --help)\n", verb, e.what(), verb);
  }
  return kUsage;
}

// Everything written to standard output reached it, or the run failed: a
// full disk must never look like success.
int close_stdout(usina::core::OutputFile& out, int status) {
  if (auto done = out.commit(); !done) {
    fmt::print(stderr, "usina: error: {}\n", done.error());
    return kUsage;
  }
  return status;
}

int run(int argc, char** argv) {
  CLI::App app{"usina: see, check and write CNC part programs"};
  app.set_version_flag("--version", std::string("usina ") + USINA_VERSION);
  app.require_subcommand(0, 1);
  app.footer("Exit status: 0 done, 1 the input has errors, 2 usage or I/O error.");
  usina::cli::add_trace(app);
  usina::cli::add_check(app);
  usina::cli::add_calc(app);
  usina::cli::add_stats(app);
  usina::cli::add_draw(app);
  usina::cli::add_convert(app);
  usina::cli::add_gen(app);
  usina::cli::add_serve(app);
  usina::cli::add_resume(app);
  usina::cli::add_apt(app);
  usina::cli::add_simulate(app);
  usina::cli::add_job(app);
  if (argc > 1 && std::string_view(argv[1]) == "help") return help(app, argc, argv);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    return usage_error(app, e, argc, argv);
  }
  if (app.get_subcommands().empty()) {
    fmt::print(stderr, "usina: error: no verb given; the verbs are {} (usina --help)\n",
               verb_list(app));
    return kUsage;
  }
  return usina::cli::exit_status();
}

}  // namespace

int main(int argc, char** argv) {
  auto out = usina::core::OutputFile::standard_output();
  if (!out) {
    fmt::print(stderr, "usina: error: {}\n", out.error());
    return kUsage;
  }
  stdout = out->stream();  // glibc's stdout is a variable: every print goes through `out`
  int status = kUsage;
  try {
    status = run(argc, argv);
  } catch (const std::bad_alloc&) {
    std::fputs("usina: error: out of memory\n", stderr);
  } catch (const std::system_error& e) {
    // fmt::print throws when standard output fails; commit says why.
    if (std::ferror(stdout) == 0) fmt::print(stderr, "usina: error: {}\n", e.what());
  } catch (const std::exception& e) {
    fmt::print(stderr, "usina: error: {}\n", e.what());
  }
  return close_stdout(*out, status);
}
