// A shop's existing folder of programs in one call, and the released set
// out to a folder. Each imported file is one revision (its own transaction:
// an import stopped half-way leaves whole revisions only), named after the
// file without its extension; a file whose name is not a valid program name,
// a duplicate name, a symbolic link or a file past the size limit is
// reported and skipped, never guessed at. Sub-folders and hidden files are
// not read.
#pragma once

#include <string>
#include <vector>

#include "dnc/store_revisions.hpp"

namespace usina::dnc {

struct ImportOptions {
  std::string machine_class = "default";
  std::string dialect;  // empty: guessed for each file
  std::string reason = "imported";
  const sim::MachineProfile* profile = nullptr;
};

struct ImportedFile {
  std::string file;     // the file's name in the folder
  std::string program;  // the program it became a revision of
  std::string hash;
  bool created = false;  // false: that revision was there already
  std::string state;     // "draft" or "check-failed"
  std::string error;     // why it was skipped; empty when imported
};

struct ImportReport {
  std::vector<ImportedFile> files;  // in name order
  std::size_t imported = 0;
  std::size_t unchanged = 0;
  std::size_t skipped = 0;
};

StoreResult<ImportReport> import_folder(Store& store, const std::string& folder,
                                        const ImportOptions& options, const Actor& actor);

// One file's text as a revision of the program named after `f.file` without
// its extension: what import_folder does with each file, and what
// `POST /api/import` does with each entry. Fills `f` (its error when the
// name is not a program name or the store refuses the text).
void import_text(Store& store, ImportedFile& f, std::string text, const ImportOptions& options,
                 const Actor& actor);
// Counts `f` into the report (imported, unchanged or skipped) and keeps it.
void tally(ImportReport& report, ImportedFile f);

struct ExportedFile {
  std::string program;
  std::string hash;
  std::string file;       // name in the folder
  std::int64_t size = 0;  // the revision's bytes, as recorded
};

// Writes the last released revision of every program as NAME + extension
// (each verified against its hash first), and `released.sha256` listing
// them in sha256sum's format, so `sha256sum -c released.sha256` checks the
// copy. `extension` is empty or a dot and 1 to 8 letters or digits.
StoreResult<std::vector<ExportedFile>> export_released(Store& store, const std::string& folder,
                                                       const std::string& extension,
                                                       const Actor& actor);

// The released revision of every program, named NAME + extension (not read
// yet: revision_bytes verifies each when it is); what export_released and
// `GET /api/export` write.
StoreResult<std::vector<ExportedFile>> released_set(Store& store, const std::string& extension);
// The export's audit entry (`export.released`, with the count and where to).
StoreResult<void> audit_export(Store& store, const Actor& actor, std::size_t programs,
                               std::string_view to);
// `extension` is empty or a dot and 1 to 8 letters or digits.
bool valid_extension(std::string_view extension);

}  // namespace usina::dnc
