// A revision's setup sheet (schema version 9): the page `usina job --sheet`
// writes for the operator, HTML or PDF, stored with the program it was made
// with. Its bytes are a blob (content-addressed, verified on every read,
// never deleted); a revision has at most one sheet of each format, and a
// later one replaces it: the sheet is the program's paperwork, not the
// program, so it may be corrected without a new revision, and the audit
// entry (`revision.sheet`) names the sheet it replaced.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "dnc/store.hpp"

namespace usina::dnc {

struct Sheet {
  std::string format;  // "html" | "pdf"
  std::string hash;    // SHA-256 hex of the bytes: the blob's address
  std::int64_t size = 0;
  std::string author;
  std::int64_t created_at_us = 0;
};

struct SheetUpload {
  std::string program;
  std::string revision;
  std::string format;
  std::string bytes;
  std::string reason;
};

struct PutSheetResult {
  Sheet sheet;
  std::optional<std::string> replaced;  // the hash of the sheet it replaced
  bool changed = true;                  // false: these bytes were that sheet already
};

// Whether `format` names a sheet format ("html", "pdf").
bool is_sheet_format(std::string_view format);

// Stores the sheet with its audit entry in one transaction. Invalid for an
// unknown format, empty bytes, a PDF that does not start "%PDF-", an HTML
// sheet with a NUL byte or a PDF's start; TooLarge past the store's
// max_program_bytes; NotFound for an unknown revision.
StoreResult<PutSheetResult> put_sheet(Store& store, const SheetUpload& upload, const Actor& actor);

// The revision's sheets (html before pdf); empty when it has none.
StoreResult<std::vector<Sheet>> list_sheets(Store& store, std::string_view program,
                                            std::string_view revision);

// A sheet and its bytes, verified against its hash. Without a format: the
// PDF when there is one, else the HTML. NotFound when there is none.
StoreResult<std::pair<Sheet, std::string>> read_sheet(Store& store, std::string_view program,
                                                      std::string_view revision,
                                                      std::optional<std::string_view> format);

}  // namespace usina::dnc
