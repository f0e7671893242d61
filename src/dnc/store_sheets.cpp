#include "dnc/store_sheets.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "dnc/sha256.hpp"
#include "dnc/store_audit.hpp"
#include "dnc/store_blobs.hpp"
#include "dnc/store_names.hpp"
#include "dnc/store_revisions.hpp"

namespace usina::dnc {
namespace {

constexpr std::string_view kPdfStart = "%PDF-";

// What a sheet's bytes must be: its format's, so a browser or a PDF
// reader shown them gets what the format says.
StoreResult<void> check_sheet(const Store& store, const SheetUpload& u) {
  if (!is_sheet_format(u.format)) {
    return store_error(
        StoreErrorKind::Invalid,
        fmt::format("no sheet format \"{}\"; the formats are html and pdf", u.format));
  }
  if (u.bytes.empty()) return store_error(StoreErrorKind::Invalid, "the sheet is empty");
  if (u.bytes.size() > store.options().max_program_bytes) {
    return store_error(StoreErrorKind::TooLarge,
                       fmt::format("the sheet has {} bytes; the store takes at most {}",
                                   u.bytes.size(), store.options().max_program_bytes));
  }
  const bool pdf = u.bytes.starts_with(kPdfStart);
  if (u.format == "pdf" && !pdf)
    return store_error(StoreErrorKind::Invalid, "a PDF sheet starts with %PDF-; this one does not");
  if (u.format == "html" && (pdf || u.bytes.find('\0') != std::string::npos)) {
    return store_error(StoreErrorKind::Invalid,
                       "an HTML sheet is text: this one is a PDF or holds a NUL byte");
  }
  return check_text("reason", u.reason, kMaxReasonBytes);
}

Sheet sheet_of(const SqlRow& r) {
  return Sheet{r.text(0), r.text(1), r.integer(2), r.text(3), r.integer(4)};
}

StoreResult<std::optional<Sheet>> find_sheet(Store& store, std::string_view program,
                                             std::string_view revision, std::string_view format) {
  auto rows = store.db().query(
      "SELECT format, blob, size, author, created_at FROM revision_sheets "
      "WHERE program = $1 AND revision = $2 AND format = $3",
      {program, revision, format});
  if (!rows) return tl::unexpected(rows.error());
  if (rows->empty()) return std::optional<Sheet>();
  return std::optional<Sheet>(sheet_of(rows->front()));
}

StoreResult<void> write_sheet(Store& store, const SheetUpload& u, const Sheet& sheet) {
  if (auto b = put_blob(store, sheet.hash, u.bytes); !b) return b;
  auto r = store.db().query(
      "INSERT INTO revision_sheets (program, revision, format, blob, size, author, created_at) "
      "VALUES ($1, $2, $3, $4, $5, $6, $7) ON CONFLICT (program, revision, format) DO UPDATE "
      "SET blob = excluded.blob, size = excluded.size, author = excluded.author, "
      "created_at = excluded.created_at",
      {std::string_view(u.program), std::string_view(u.revision), std::string_view(u.format),
       std::string_view(sheet.hash), sheet.size, std::string_view(sheet.author),
       sheet.created_at_us});
  if (!r) return tl::unexpected(r.error());
  return {};
}

StoreResult<void> audit_sheet(Store& store, const SheetUpload& u, const PutSheetResult& put,
                              const Actor& actor) {
  const nlohmann::json detail = {
      {"format", u.format},
      {"sheet", put.sheet.hash},
      {"size", put.sheet.size},
      {"replaced", put.replaced ? nlohmann::json(*put.replaced) : nlohmann::json(nullptr)}};
  const AuditRecord record{"revision.sheet", fmt::format("{}@{}", u.program, u.revision), u.reason,
                           detail.dump()};
  if (auto a = append_audit(store, actor, record); !a) return tl::unexpected(a.error());
  return {};
}

}  // namespace

bool is_sheet_format(std::string_view format) {
  return format == "html" || format == "pdf";
}

StoreResult<PutSheetResult> put_sheet(Store& store, const SheetUpload& u, const Actor& actor) {
  if (auto ok = check_sheet(store, u); !ok) return tl::unexpected(ok.error());
  if (auto ok = check_name("user name", actor.user); !ok) return tl::unexpected(ok.error());
  if (auto ok = check_text("origin", actor.origin, kMaxOriginBytes); !ok)
    return tl::unexpected(ok.error());
  PutSheetResult put;
  put.sheet = Sheet{u.format, sha256_hex(u.bytes), static_cast<std::int64_t>(u.bytes.size()),
                    actor.user, store.now_us()};
  Transaction tx(store.db());
  if (auto b = tx.begin_write(); !b) return tl::unexpected(b.error());
  if (auto rev = find_revision(store, u.program, u.revision); !rev)
    return tl::unexpected(rev.error());
  auto old = find_sheet(store, u.program, u.revision, u.format);
  if (!old) return tl::unexpected(old.error());
  if (*old && (*old)->hash == put.sheet.hash) return PutSheetResult{**old, std::nullopt, false};
  if (*old) put.replaced = (*old)->hash;
  if (auto w = write_sheet(store, u, put.sheet); !w) return tl::unexpected(w.error());
  if (auto a = audit_sheet(store, u, put, actor); !a) return tl::unexpected(a.error());
  if (auto c = tx.commit(); !c) return tl::unexpected(c.error());
  return put;
}

StoreResult<std::vector<Sheet>> list_sheets(Store& store, std::string_view program,
                                            std::string_view revision) {
  auto rows = store.db().query(
      "SELECT format, blob, size, author, created_at FROM revision_sheets "
      "WHERE program = $1 AND revision = $2 ORDER BY format",
      {program, revision});
  if (!rows) return tl::unexpected(rows.error());
  std::vector<Sheet> out;
  for (const SqlRow& r : *rows)
    out.push_back(sheet_of(r));
  return out;
}

StoreResult<std::pair<Sheet, std::string>> read_sheet(Store& store, std::string_view program,
                                                      std::string_view revision,
                                                      std::optional<std::string_view> format) {
  if (format && !is_sheet_format(*format)) {
    return store_error(
        StoreErrorKind::Invalid,
        fmt::format("no sheet format \"{}\"; the formats are html and pdf", *format));
  }
  if (auto rev = find_revision(store, program, revision); !rev) return tl::unexpected(rev.error());
  std::optional<Sheet> found;
  for (const std::string_view f : {std::string_view("pdf"), std::string_view("html")}) {
    if (format && *format != f) continue;
    auto s = find_sheet(store, program, revision, f);
    if (!s) return tl::unexpected(s.error());
    if (*s) {
      found = std::move(*s);
      break;
    }
  }
  if (!found) {
    return store_error(StoreErrorKind::NotFound,
                       fmt::format("revision {} of {} has no {}setup sheet", revision, program,
                                   format ? fmt::format("{} ", *format) : std::string()));
  }
  auto bytes = read_blob(store, found->hash);
  if (!bytes) return tl::unexpected(bytes.error());
  return std::pair<Sheet, std::string>{std::move(*found), std::move(*bytes)};
}

}  // namespace usina::dnc
