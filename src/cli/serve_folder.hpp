// usina serve --import DIR / --export DIR: a shop's existing folder of
// programs into the store in one command, and the released set out to a
// folder (docs/dnc-server.md, "A folder in, the released set out"). Both
// run on the store directly, as --init does, and name in the audit log the
// store's user given by --user, whose role must allow it.
#pragma once

#include <map>
#include <string>

#include "sim/machine_profile.hpp"

namespace usina::cli {

struct FolderOptions {
  std::string where;  // the store: a data folder or a postgresql:// URL
  std::string user;   // the store's user the audit log names
  std::string folder;
  std::string machine_class = "default";  // --import: the class of every new program
  std::string dialect;                    // --import: empty, guessed per file
  std::string reason;                     // --import: the revisions' reason
  std::string extension = "nc";           // --export: the files' extension, no dot
  const std::map<std::string, sim::MachineProfile>* profiles = nullptr;  // by machine class
};

// Each file a revision; one line a file on standard output. 0 when every
// file was imported or was there already, 1 when one was skipped, 2 when
// nothing could be done (store, user, folder).
int import_folder_command(const FolderOptions& o);
// The last released revision of every program, and released.sha256. 0, or
// 2 with the reason.
int export_folder_command(const FolderOptions& o);

}  // namespace usina::cli
