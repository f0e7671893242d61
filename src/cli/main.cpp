// usina: a workbench for CNC part programs. One file per verb.
//
// Exit status, for every verb (docs/cli.md): 0 done; 1 the program or
// drawing read has errors; 2 a usage error, an input that cannot be read or
// an output that cannot be written (a full disk included).
#include <string>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "cli/entry.hpp"
#include "cli/verbs.hpp"

namespace {

constexpr int kUsage = usina::cli::kUsageStatus;

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

struct Verb {
  std::string_view name;
  void (*add)(CLI::App&);
};

// In the order `usina --help` lists them.
constexpr Verb kVerbs[] = {
    {"trace", usina::cli::add_trace},       {"check", usina::cli::add_check},
    {"calc", usina::cli::add_calc},         {"stats", usina::cli::add_stats},
    {"draw", usina::cli::add_draw},         {"convert", usina::cli::add_convert},
    {"gen", usina::cli::add_gen},           {"serve", usina::cli::add_serve},
    {"resume", usina::cli::add_resume},     {"apt", usina::cli::add_apt},
    {"simulate", usina::cli::add_simulate}, {"job", usina::cli::add_job},
};

// Every verb's options cost CLI11 thousands of allocations to set up (most
// of a small `check`'s start-up once the libraries were split off): a
// command line that names its verb first gets that verb alone, `--version`
// none; anything else (help, a mistake) all of them, to list them.
void add_verbs(CLI::App& app, int argc, char** argv) {
  const std::string_view first = argc > 1 ? argv[1] : "";
  if (first == "--version") return;
  for (const Verb& verb : kVerbs) {
    if (verb.name == first) {
      verb.add(app);
      return;
    }
  }
  for (const Verb& verb : kVerbs)
    verb.add(app);
}

int run(int argc, char** argv) {
  CLI::App app{"usina: see, check and write CNC part programs"};
  app.set_version_flag("--version", std::string("usina ") + USINA_VERSION);
  app.require_subcommand(0, 1);
  app.footer("Exit status: 0 done, 1 the input has errors, 2 usage or I/O error.");
  add_verbs(app, argc, argv);
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
  // The server is its own executable (usina-serve): its libraries (Boost,
  // OpenSSL, libpq, SQLite, ...) stay off every other verb's start-up.
  if (argc > 1 && std::string_view(argv[1]) == "serve") {
    return usina::cli::exec_serve(std::vector<char*>(argv + 2, argv + argc));
  }
  if (argc > 2 && std::string_view(argv[1]) == "help" && std::string_view(argv[2]) == "serve") {
    static char help_flag[] = "--help";
    return usina::cli::exec_serve({help_flag});
  }
  return usina::cli::run_guarded(argc, argv, run);
}
