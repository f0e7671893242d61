#include "dnc/store_library.hpp"

#include <fmt/format.h>

namespace usina::dnc {
namespace {

// The programs the filters keep, with their newest revision (r) and its
// facts (f) joined. $1 class, $2 dialect, $3 state, $4 '1' for released
// only, $5 the LIKE pattern of the name ('' for any), $6 the pattern of the
// name, a comment or a program number (the facts are stored lower case),
// $7 a tool (-1 for any).
constexpr std::string_view kMatching =
    "FROM programs p LEFT JOIN revisions r ON r.id = "
    "(SELECT MAX(id) FROM revisions WHERE program = p.name) "
    "LEFT JOIN revision_facts f ON f.revision = r.id "
    "WHERE ($1 = '' OR p.machine_class = $1) AND ($2 = '' OR p.dialect = $2) "
    "AND ($3 = '' OR r.state = $3) "
    "AND ($4 = '' OR EXISTS (SELECT 1 FROM revisions x WHERE x.program = p.name "
    "AND x.state = 'released')) "
    "AND ($5 = '' OR lower(p.name) LIKE $5 ESCAPE '!') "
    "AND ($6 = '' OR lower(p.name) LIKE $6 ESCAPE '!' OR f.o_numbers LIKE $6 ESCAPE '!' "
    "OR f.comments LIKE $6 ESCAPE '!') "
    "AND (CAST($7 AS BIGINT) < 0 OR EXISTS (SELECT 1 FROM revision_tools t "
    "WHERE t.revision = r.id AND t.tool = CAST($7 AS BIGINT)))";

// `part` lower-cased (ASCII) between % signs, its own %, _ and ! escaped
// with '!' (a backslash means different things to the two databases'
// string literals).
std::string like_pattern(const std::string& part) {
  if (part.empty()) return {};
  std::string out = "%";
  for (const char ch : part) {
    if (ch == '%' || ch == '_' || ch == '!') out += '!';
    out += (ch >= 'A' && ch <= 'Z') ? static_cast<char>(ch - 'A' + 'a') : ch;
  }
  out += '%';
  return out;
}

LibraryEntry entry_of(const SqlRow& r) {
  LibraryEntry e;
  e.program = {r.text(0), r.text(1), r.text(2), r.integer(3)};
  e.newest_revision = r.text(4);
  e.newest_state = r.text(5);
  e.newest_at_us = r.integer(6);
  e.released_revision = r.text(7);
  e.revisions = r.integer(8);
  return e;
}

}  // namespace

StoreResult<LibraryPage> library_page(Store& store, const LibraryQuery& q) {
  const std::string pattern = like_pattern(q.name_part);
  const std::string text = like_pattern(q.text);
  const SqlParams filters = {std::string_view(q.machine_class),
                             std::string_view(q.dialect),
                             q.state ? state_name(*q.state) : std::string_view(),
                             std::string_view(q.released_only ? "1" : ""),
                             std::string_view(pattern),
                             std::string_view(text),
                             q.tool.value_or(-1)};
  auto counted = store.db().query(fmt::format("SELECT COUNT(*) {}", kMatching), filters);
  if (!counted) return tl::unexpected(counted.error());
  SqlParams params = filters;
  params.emplace_back(q.limit);
  params.emplace_back(q.offset);
  auto rows = store.db().query(
      fmt::format("SELECT p.name, p.machine_class, p.dialect, p.created_at, r.hash, r.state, "
                  "r.created_at, (SELECT y.hash FROM revisions y WHERE y.program = p.name AND "
                  "y.state = 'released' ORDER BY y.state_at DESC, y.id DESC LIMIT 1), "
                  "(SELECT COUNT(*) FROM revisions z WHERE z.program = p.name) "
                  "{} ORDER BY p.name LIMIT $8 OFFSET $9",
                  kMatching),
      params);
  if (!rows) return tl::unexpected(rows.error());
  LibraryPage page;
  page.total = counted->empty() ? 0 : counted->front().integer(0);
  page.programs.reserve(rows->size());
  for (const SqlRow& r : *rows)
    page.programs.push_back(entry_of(r));
  return page;
}

StoreResult<std::vector<std::string>> library_machine_classes(Store& store) {
  auto rows =
      store.db().query("SELECT DISTINCT machine_class FROM programs ORDER BY machine_class");
  if (!rows) return tl::unexpected(rows.error());
  std::vector<std::string> out;
  out.reserve(rows->size());
  for (const SqlRow& r : *rows)
    out.push_back(r.text(0));
  return out;
}

}  // namespace usina::dnc
