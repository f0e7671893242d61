// `usina serve ...`: the DNC server is the executable usina-serve beside
// usina (docs/performance.md, "Start-up"), run in this process's place with
// the same arguments, so its process id, signals, standard streams and exit
// status are the ones `usina serve` always had.
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "cli/beside_executable.hpp"
#include "cli/entry.hpp"
#include "cli/verbs.hpp"

namespace usina::cli {

// Listed among the verbs (usina --help); main runs usina-serve before any
// parsing, so this subcommand never parses anything itself.
void add_serve(CLI::App& app) {
  app.add_subcommand(
         "serve", "the DNC server: program store, machines' links, HTTP API (docs/dnc-server.md)")
      ->prefix_command();
}

int exec_serve(std::vector<char*> args) {
  const auto server = beside_executable("usina-serve");
  if (!server) {
    fmt::print(stderr, "usina: error: serve: {}\n", server.error());
    return kUsageStatus;
  }
  std::string path = *server;
  std::vector<char*> argv;
  argv.reserve(args.size() + 2);
  argv.push_back(path.data());
  argv.insert(argv.end(), args.begin(), args.end());
  argv.push_back(nullptr);
  ::execv(path.c_str(), argv.data());
  // Still here: the server could not be run.
  fmt::print(stderr,
             "usina: error: serve: cannot run the server program {}: {} (usina serve is the "
             "executable usina-serve installed beside usina)\n",
             path, std::strerror(errno));
  return kUsageStatus;
}

}  // namespace usina::cli
