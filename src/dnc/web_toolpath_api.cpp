// GET /api/programs/{name}/revisions/{rev}/toolpath[?max_vertices=N]: the
// revision's tool path as the viewer's binary stream (web_toolpath.hpp).
#include <charconv>

#include <fmt/format.h>

#include "dnc/api_router.hpp"
#include "dnc/store_revisions.hpp"
#include "dnc/web_toolpath.hpp"

namespace usina::dnc {
namespace {

constexpr std::uint32_t kMinVertices = 2;
constexpr std::uint32_t kMaxVertices = 2'000'000;

// `max_vertices` of the query: the default when absent, nothing when malformed.
std::optional<std::uint32_t> max_vertices_of(const Target& target) {
  const auto it = target.query.find("max_vertices");
  if (it == target.query.end()) return ToolpathSettings{}.max_vertices;
  std::uint32_t n = 0;
  const std::string& s = it->second;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), n);
  if (ec != std::errc() || end != s.data() + s.size() || n < kMinVertices || n > kMaxVertices)
    return std::nullopt;
  return n;
}

}  // namespace

HttpResponse api_toolpath(ApiCall& c) {
  const auto max_vertices = max_vertices_of(c.target);
  if (!max_vertices) {
    return error_response(c.req, http::status::bad_request,
                          fmt::format("max_vertices must be a whole number from {} to {}",
                                      kMinVertices, kMaxVertices));
  }
  auto program = find_program(c.ctx.store, c.params[0]);
  if (!program) return error_response(c.req, status_of(program.error()), program.error().message);
  auto bytes = revision_bytes(c.ctx.store, c.params[0], c.params[1]);
  if (!bytes) return error_response(c.req, status_of(bytes.error()), bytes.error().message);
  ToolpathSettings settings;
  settings.dialect = program->dialect;
  settings.max_vertices = *max_vertices;
  const ToolpathResult path = program_toolpath(*bytes, settings);
  HttpResponse res{http::status::ok, c.req.version()};
  res.set(http::field::server, "usina");
  res.set(http::field::content_type, "application/octet-stream");
  res.set("X-Content-Type-Options", "nosniff");
  // A revision's bytes never change (its name is their hash).
  res.set(http::field::cache_control, "private, max-age=86400");
  res.keep_alive(c.req.keep_alive());
  res.body() = encode_toolpath(path);
  res.prepare_payload();
  return res;
}

}  // namespace usina::dnc
