// usina serve: the DNC server of issue 13 (docs/dnc-server.md; the flags
// are the contract of spec/dnc-api.md). This file is the executable
// usina-serve, which `usina serve` runs with the same arguments: the
// server's libraries load only for it (docs/performance.md, "Start-up").
//   usina serve --init --data DIR --admin NAME --password-file F
//   usina serve --data DIR --config usina-serve.toml [--listen HOST:PORT]
//               [--tls-cert FILE --tls-key FILE]   (HTTPS and WSS)
//   usina serve --store postgresql://... ...   (PostgreSQL instead of DIR)
//   usina serve --verify-audit --data DIR       (exit 1 when the chain is broken)
//   usina serve --import DIR --user NAME [--machine-class C] [--dialect D] [--reason R]
//   usina serve --export DIR --user NAME [--extension EXT]   (cli/serve_folder.cpp)
// SIGTERM or SIGINT stops it: running jobs end interrupted, their ends written.
#include <csignal>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>

#include <CLI/CLI.hpp>
#include <boost/asio/signal_set.hpp>
#include <fmt/format.h>

#include "cli/entry.hpp"
#include "cli/serve_folder.hpp"
#include "core/diagnostic.hpp"
#include "dnc/server.hpp"
#include "dnc/store_audit.hpp"
#include "dnc/store_users.hpp"

namespace usina::cli {
namespace {

constexpr int kInputError = 1;
constexpr int kUsage = 2;

struct ServeOptions {
  bool init = false;
  bool verify_audit = false;
  std::string data = "usina-data";
  std::string store;  // a postgresql:// URL instead of the data folder
  std::string admin;
  std::string password_file;
  std::string config;
  std::string listen;
  std::string tls_cert;  // with tls_key: HTTPS instead of HTTP
  std::string tls_key;
  FolderOptions folder;  // --import / --export
  std::string import_dir;
  std::string export_dir;
};

std::string where(const ServeOptions& o) {
  return o.store.empty() ? o.data : o.store;
}

// The file's first line (a password file ends with a newline or not).
std::optional<std::string> read_password(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::string line;
  std::getline(in, line);
  if (!line.empty() && line.back() == '\r') line.pop_back();
  return line;
}

int init(const ServeOptions& o) {
  if (o.admin.empty() || o.password_file.empty()) {
    fmt::print(stderr, "usina: error: serve --init needs --admin NAME and --password-file FILE\n");
    return kUsage;
  }
  const auto password = read_password(o.password_file);
  if (!password) {
    fmt::print(stderr, "usina: error: cannot read the password file {}\n", o.password_file);
    return kUsage;
  }
  auto store = dnc::Store::open(where(o));
  if (!store) {
    fmt::print(stderr, "usina: error: {}\n", store.error().message);
    return kUsage;
  }
  auto admin = dnc::create_first_admin(**store, o.admin, *password);
  if (!admin) {
    fmt::print(stderr, "usina: error: {}\n", admin.error().message);
    return kUsage;
  }
  fmt::print(stderr, "usina serve: store ready in {}, admin {} created\n", where(o), admin->name);
  return 0;
}

int verify(const ServeOptions& o) {
  auto store = dnc::Store::open(where(o));
  if (!store) {
    fmt::print(stderr, "usina: error: {}\n", store.error().message);
    return kUsage;
  }
  auto v = dnc::verify_audit(**store);
  if (!v) {
    fmt::print(stderr, "usina: error: {}\n", v.error().message);
    return kUsage;
  }
  if (v->ok) {
    fmt::print("audit log: {} entries, the chain holds; head {}\n", v->entries, v->head);
    return 0;
  }
  fmt::print("audit log: BROKEN at entry {}: {}\n", v->first_bad, v->problem);
  return kInputError;
}

// The configuration (--config, else ./usina-serve.toml when there is one).
std::optional<dnc::ServerConfig> configuration(const ServeOptions& o) {
  std::string path = o.config;
  if (path.empty() && std::filesystem::exists("usina-serve.toml")) path = "usina-serve.toml";
  if (path.empty()) return dnc::ServerConfig{};
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    fmt::print(stderr, "usina: error: cannot read the configuration {}\n", path);
    return std::nullopt;
  }
  std::ostringstream text;
  text << in.rdbuf();
  core::DiagnosticList diags;
  auto config = dnc::read_server_config(text.str(), 0, diags);
  const std::string base = std::filesystem::path(path).parent_path().string();
  if (config && !dnc::load_profiles(*config, base.empty() ? "." : base, diags)) config.reset();
  // [web] root and the TLS files are relative to the configuration's folder,
  // as a profile is.
  if (config && !base.empty()) {
    for (std::string* file : {&config->web_root, &config->tls_cert, &config->tls_key}) {
      if (!file->empty()) *file = (std::filesystem::path(base) / *file).string();
    }
  }
  for (const core::Diagnostic& d : diags.all()) {
    fmt::print(stderr, "{}:{}:{}: {} {}: {}\n", path, d.loc.line, d.loc.col,
               core::severity_name(d.severity), core::code_name(d.code), d.message);
  }
  return config;
}

int run_server(const ServeOptions& o) {
  if (o.tls_cert.empty() != o.tls_key.empty()) {
    fmt::print(stderr, "usina: error: --tls-cert and --tls-key go together: give both\n");
    return kUsage;
  }
  auto config = configuration(o);
  if (!config) return kUsage;
  if (!o.tls_cert.empty()) {
    config->tls_cert = o.tls_cert;
    config->tls_key = o.tls_key;
  }
  const std::string listen = o.listen.empty() ? config->listen : o.listen;
  boost::asio::io_context io;
  auto server = dnc::Server::open(io, where(o), std::move(*config));
  if (!server) {
    fmt::print(stderr, "usina: error: {}\n", server.error());
    return kUsage;
  }
  if (std::string error = (*server)->start(listen); !error.empty()) {
    fmt::print(stderr, "usina: error: {}\n", error);
    return kUsage;
  }
  const auto at = (*server)->endpoint();
  fmt::print(stderr, "usina serve: listening on {}://{}:{} ({} machines)\n", (*server)->scheme(),
             at.address().to_string(), at.port(), (*server)->machines().all().size());
  if ((*server)->scheme() == "http" && !at.address().is_loopback()) {
    fmt::print(stderr,
               "usina serve: warning: plain HTTP on {}: passwords and tokens cross the network in "
               "the clear; give --tls-cert and --tls-key (docs/dnc-server.md, \"TLS\")\n",
               at.address().to_string());
  }
  if (const auto shdr = (*server)->mtconnect_endpoint()) {
    fmt::print(stderr, "usina serve: MTConnect SHDR adapter on {}:{}\n",
               shdr->address().to_string(), shdr->port());
  }
  boost::asio::signal_set signals(io, SIGTERM, SIGINT);
  signals.async_wait([&](const boost::system::error_code& ec, int signal) {
    if (ec) return;
    const std::string why =
        fmt::format("the server was stopped ({})", signal == SIGTERM ? "SIGTERM" : "SIGINT");
    (*server)->stop(why, [&io] { io.stop(); });
  });
  io.run();
  fmt::print(stderr, "usina serve: stopped\n");
  return 0;
}

// The flags of spec/dnc-api.md on `cmd`; `o` gets their values.
void add_serve_options(CLI::App& cmd, ServeOptions& o) {
  cmd.add_flag("--init", o.init, "create the store and its first admin, then exit");
  cmd.add_flag("--verify-audit", o.verify_audit,
               "check the audit log's hash chain, then exit (1 when broken)");
  cmd.add_option("--data", o.data, "the store's folder (SQLite)")->capture_default_str();
  cmd.add_option("--store", o.store, "a postgresql:// URL: the store in PostgreSQL");
  cmd.add_option("--admin", o.admin, "--init: the first admin's name");
  cmd.add_option("--password-file", o.password_file,
                 "--init: a file whose first line is the admin's password");
  cmd.add_option("--config", o.config,
                 "the machines and [server] settings (default ./usina-serve.toml)");
  cmd.add_option("--listen", o.listen, "HOST:PORT to serve HTTP on (default 127.0.0.1:8080)");
  cmd.add_option("--tls-cert", o.tls_cert,
                 "a PEM certificate (chain): serve HTTPS and WSS (with --tls-key)");
  cmd.add_option("--tls-key", o.tls_key, "the PEM private key of --tls-cert");
  cmd.add_option("--import", o.import_dir,
                 "make each file of DIR a revision of the program named after it, then exit");
  cmd.add_option("--export", o.export_dir,
                 "write the released revision of every program to DIR, then exit");
  cmd.add_option("--user", o.folder.user, "--import/--export: the store's user the audit names");
  cmd.add_option("--machine-class", o.folder.machine_class,
                 "--import: the machine class of new programs")
      ->capture_default_str();
  cmd.add_option("--dialect", o.folder.dialect,
                 "--import: rs274ngc|fanuc|grbl|romi (default: guessed for each file)");
  cmd.add_option("--reason", o.folder.reason, "--import: the revisions' reason");
  cmd.add_option("--extension", o.folder.extension, "--export: the files' extension, no dot")
      ->capture_default_str();
}

// --import or --export: the configuration gives the machine classes' profiles.
int folder(ServeOptions& o) {
  const auto config = configuration(o);
  if (!config) return kUsage;
  o.folder.where = where(o);
  o.folder.profiles = &config->profiles;
  o.folder.folder = o.import_dir.empty() ? o.export_dir : o.import_dir;
  return o.import_dir.empty() ? export_folder_command(o.folder) : import_folder_command(o.folder);
}

int serve(ServeOptions& o) {
  if (!o.store.empty() && !dnc::is_postgres_url(o.store)) {
    fmt::print(stderr, "usina: error: --store takes a postgresql:// URL; a folder is --data\n");
    return kUsage;
  }
  const int tasks =
      int{o.init} + int{o.verify_audit} + int{!o.import_dir.empty()} + int{!o.export_dir.empty()};
  if (tasks > 1) {
    fmt::print(stderr,
               "usina: error: --init, --verify-audit, --import and --export: one at a time\n");
    return kUsage;
  }
  if (o.init) return init(o);
  if (o.verify_audit) return verify(o);
  if (!o.import_dir.empty() || !o.export_dir.empty()) return folder(o);
  return run_server(o);
}

// argv: what followed `usina serve`. Help and usage errors are said as
// `usina serve` always said them.
int serve_command(int argc, char** argv) {
  ServeOptions o;
  CLI::App cmd{"the DNC server: program store, machines' links, HTTP API (docs/dnc-server.md)",
               "usina serve"};
  add_serve_options(cmd, o);
  try {
    cmd.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return cmd.exit(e);
  } catch (const CLI::ParseError& e) {
    fmt::print(stderr, "usina: error: serve: {} (usina serve --help)\n", e.what());
    return kUsage;
  }
  return serve(o);
}

}  // namespace
}  // namespace usina::cli

int main(int argc, char** argv) {
  return usina::cli::run_guarded(argc, argv, usina::cli::serve_command);
}
