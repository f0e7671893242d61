// GET /api/programs: the library, one page at a time, filtered in the store
// (store_library.hpp). Query: machine_class, dialect, state (of the newest
// revision), released=1 (programs with a released revision), q (a part of
// the name, any case), text (a part of the name, a comment or a program
// number of the newest revision, any case), tool (a tool the newest
// revision calls), limit (1 to 10,000; 10,000 when absent), offset.
#include <charconv>

#include <fmt/format.h>

#include "dnc/api_json.hpp"
#include "dnc/api_router.hpp"
#include "dnc/store_facts.hpp"
#include "dnc/store_library.hpp"
#include "dnc/store_names.hpp"

namespace usina::dnc {
namespace {

constexpr std::int64_t kMaxLimit = 10'000;
constexpr std::int64_t kMaxOffset = 1'000'000'000;
constexpr std::size_t kMaxText = 200;  // bytes of a filter's value

// A whole number from `lo` to `hi` in `value`, or nothing.
std::optional<std::int64_t> whole(const std::string& value, std::int64_t lo, std::int64_t hi) {
  std::int64_t n = 0;
  const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), n);
  if (ec != std::errc() || end != value.data() + value.size() || n < lo || n > hi)
    return std::nullopt;
  return n;
}

tl::expected<LibraryQuery, std::string> library_query(const Target& target) {
  LibraryQuery q;
  const auto& in = target.query;
  const std::pair<std::string_view, std::string*> texts[] = {{"machine_class", &q.machine_class},
                                                             {"dialect", &q.dialect},
                                                             {"q", &q.name_part},
                                                             {"text", &q.text}};
  for (const auto& [key, into] : texts) {
    const auto it = in.find(std::string(key));
    if (it == in.end()) continue;
    if (it->second.size() > kMaxText)
      return tl::unexpected(fmt::format("{} is longer than {} bytes", key, kMaxText));
    if (!valid_utf8(it->second)) return tl::unexpected(fmt::format("{} is not UTF-8", key));
    *into = it->second;
  }
  if (const auto it = in.find("tool"); it != in.end() && !it->second.empty()) {
    q.tool = whole(it->second, 0, kMaxToolNumber);
    if (!q.tool) {
      return tl::unexpected(fmt::format(
          "tool must be a whole number from 0 to {} (the T word's number, without the T)",
          kMaxToolNumber));
    }
  }
  if (const auto it = in.find("state"); it != in.end() && !it->second.empty()) {
    q.state = parse_state(it->second);
    if (!q.state)
      return tl::unexpected(std::string(
          "state must be draft, checked, approved, released, rejected or check-failed"));
  }
  if (const auto it = in.find("released"); it != in.end()) {
    if (it->second != "1" && it->second != "0")
      return tl::unexpected(std::string("released must be 1 or 0"));
    q.released_only = it->second == "1";
  }
  if (const auto it = in.find("limit"); it != in.end()) {
    const auto n = whole(it->second, 1, kMaxLimit);
    if (!n)
      return tl::unexpected(fmt::format("limit must be a whole number from 1 to {}", kMaxLimit));
    q.limit = *n;
  }
  if (const auto it = in.find("offset"); it != in.end()) {
    const auto n = whole(it->second, 0, kMaxOffset);
    if (!n)
      return tl::unexpected(fmt::format("offset must be a whole number from 0 to {}", kMaxOffset));
    q.offset = *n;
  }
  return q;
}

nlohmann::json entry_json(const LibraryEntry& e) {
  return {{"name", e.program.name},
          {"machine_class", e.program.machine_class},
          {"dialect", e.program.dialect},
          {"revisions", e.revisions},
          {"newest_revision", e.newest_revision},
          {"newest_state", e.newest_state},
          {"newest_at_us", e.newest_at_us},
          {"released_revision", e.released_revision.empty() ? nlohmann::json(nullptr)
                                                            : nlohmann::json(e.released_revision)}};
}

}  // namespace

HttpResponse api_list_programs(ApiCall& c) {
  auto q = library_query(c.target);
  if (!q) return error_response(c.req, http::status::bad_request, q.error());
  auto page = library_page(c.ctx.store, *q);
  if (!page) return error_response(c.req, status_of(page.error()), page.error().message);
  auto classes = library_machine_classes(c.ctx.store);
  if (!classes) return error_response(c.req, status_of(classes.error()), classes.error().message);
  nlohmann::json out = nlohmann::json::array();
  for (const LibraryEntry& e : page->programs)
    out.push_back(entry_json(e));
  return json_response(c.req, http::status::ok,
                       {{"programs", std::move(out)},
                        {"total", page->total},
                        {"machine_classes", std::move(*classes)},
                        {"limit", q->limit},
                        {"offset", q->offset}});
}

}  // namespace usina::dnc
