#include "cli/serve_folder.hpp"

#include <fmt/format.h>

#include "core/text.hpp"
#include "dnc/store_import.hpp"
#include "dnc/store_users.hpp"
#include "gcode/dialect.hpp"

namespace usina::cli {
namespace {

constexpr int kSkipped = 1;
constexpr int kCannot = 2;

int cannot(const std::string& why) {
  fmt::print(stderr, "usina: error: {}\n", why);
  return kCannot;
}

// The store's user the audit log names, if the role allows `what`: a
// folder run from a shell is still somebody's act, never an anonymous one.
tl::expected<dnc::Actor, std::string> actor_for(dnc::Store& store, const std::string& name,
                                                dnc::Permission what, const char* verb) {
  if (name.empty()) {
    return tl::unexpected(
        fmt::format("serve --{} needs --user NAME: the store's user the audit log names", verb));
  }
  auto user = dnc::find_user(store, name);
  if (!user) return tl::unexpected(fmt::format("--user {}: {}", name, user.error().message));
  if (user->disabled)
    return tl::unexpected(fmt::format("--user {}: the account is disabled", name));
  if (!dnc::role_may(user->role, what)) {
    return tl::unexpected(fmt::format("--user {} is {}: that role may not {} programs", name,
                                      dnc::role_name(user->role), verb));
  }
  return dnc::Actor{user->name, "cli"};
}

// A folder's file names are anyone's: printed with their control bytes escaped.
void print_file(const dnc::ImportedFile& f) {
  const std::string file = core::printable(f.file);
  if (!f.error.empty()) {
    fmt::print("{}: skipped: {}\n", file, core::printable(f.error));
  } else if (!f.created) {
    fmt::print("{}: program {}, revision {} there already\n", file, f.program,
               f.hash.substr(0, 12));
  } else {
    fmt::print("{}: program {}, revision {} ({})\n", file, f.program, f.hash.substr(0, 12),
               f.state);
  }
}

const sim::MachineProfile* profile_of(const FolderOptions& o) {
  if (o.profiles == nullptr) return nullptr;
  const auto it = o.profiles->find(o.machine_class);
  return it == o.profiles->end() ? nullptr : &it->second;
}

}  // namespace

int import_folder_command(const FolderOptions& o) {
  const std::string dialect = o.dialect == "auto" ? "" : o.dialect;
  if (!dialect.empty() && gcode::find_dialect(dialect) == nullptr)
    return cannot(fmt::format("--dialect {}: no such dialect", dialect));
  auto store = dnc::Store::open(o.where);
  if (!store) return cannot(store.error().message);
  auto actor = actor_for(**store, o.user, dnc::Permission::ImportPrograms, "import");
  if (!actor) return cannot(actor.error());
  dnc::ImportOptions options;
  options.machine_class = o.machine_class;
  options.dialect = dialect;
  options.reason = o.reason.empty() ? fmt::format("imported from {}", o.folder) : o.reason;
  options.profile = profile_of(o);
  auto report = dnc::import_folder(**store, o.folder, options, *actor);
  if (!report) return cannot(report.error().message);
  for (const dnc::ImportedFile& f : report->files)
    print_file(f);
  fmt::print(stderr, "usina serve: {} imported, {} there already, {} skipped\n", report->imported,
             report->unchanged, report->skipped);
  return report->skipped > 0 ? kSkipped : 0;
}

int export_folder_command(const FolderOptions& o) {
  const std::string extension = o.extension.empty() ? "" : "." + o.extension;
  if (!dnc::valid_extension(extension))
    return cannot(fmt::format("--extension {}: 1 to 8 letters or digits", o.extension));
  auto store = dnc::Store::open(o.where);
  if (!store) return cannot(store.error().message);
  auto actor = actor_for(**store, o.user, dnc::Permission::ExportReleased, "export");
  if (!actor) return cannot(actor.error());
  auto files = dnc::export_released(**store, o.folder, extension, *actor);
  if (!files) return cannot(files.error().message);
  for (const dnc::ExportedFile& f : *files)
    fmt::print("{}  {}\n", f.hash, f.file);
  fmt::print(stderr,
             "usina serve: {} released programs written to {} (released.sha256 lists them)\n",
             files->size(), o.folder);
  return 0;
}

}  // namespace usina::cli
