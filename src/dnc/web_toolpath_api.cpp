// GET /api/programs/{name}/revisions/{rev}/toolpath[?max_vertices=N]: the
// revision's tool path as the viewer's binary stream (web_toolpath.hpp),
// computed on the tool-path service's pool and kept in its cache
// (web_toolpath_service.hpp), so the event loop goes on serving meanwhile.
#include "dnc/web_toolpath_api.hpp"

#include <charconv>

#include <fmt/format.h>
#include <tl/expected.hpp>

#include "dnc/api_router.hpp"
#include "dnc/store_revisions.hpp"
#include "dnc/web_toolpath.hpp"
#include "dnc/web_toolpath_service.hpp"

namespace usina::dnc {
namespace {

constexpr std::uint32_t kMinVertices = 2;
constexpr std::uint32_t kMaxVertices = 2'000'000;
constexpr std::string_view kStreamType = "application/octet-stream";

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

HttpResponse computed_response(const ToolpathReply& r, std::string_view content_type,
                               const std::string& bytes, ToolpathFrom from) {
  HttpResponse res{http::status::ok, r.version};
  res.set(http::field::server, "usina");
  res.set(http::field::content_type, std::string(content_type));
  res.set("X-Content-Type-Options", "nosniff");
  res.set("X-Toolpath-Cache", toolpath_from_name(from));
  // A revision's bytes never change (its name is their hash).
  res.set(http::field::cache_control, "private, max-age=86400");
  res.keep_alive(r.keep_alive);
  res.body() = bytes;
  res.prepare_payload();
  return res;
}

HttpResponse run_failed(const ToolpathReply& r, const std::string& why) {
  HttpRequest req;
  req.version(r.version);
  req.keep_alive(r.keep_alive);
  return error_response(req, http::status::internal_server_error,
                        "the tool path could not be computed: " + why);
}

tl::expected<NamedRevision, HttpResponse> named_revision(ApiCall& c) {
  auto program = find_program(c.ctx.store, c.params[0]);
  if (!program)
    return tl::unexpected(
        error_response(c.req, status_of(program.error()), program.error().message));
  auto revision = find_revision(c.ctx.store, c.params[0], c.params[1]);
  if (!revision)
    return tl::unexpected(
        error_response(c.req, status_of(revision.error()), revision.error().message));
  return NamedRevision{std::move(*program), std::move(*revision)};
}

namespace {

Respond plain(std::string_view content_type) {
  return [type = std::string(content_type)](const ToolpathReply& r, const std::string& bytes,
                                            ToolpathFrom from) {
    return computed_response(r, type, bytes, from);
  };
}

}  // namespace

HttpResponse answer_now(ApiCall& c, std::string_view content_type, const RevisionWork& work) {
  return answer_now(c, plain(content_type), work);
}

HttpResponse answer_now(ApiCall& c, const Respond& respond, const RevisionWork& work) {
  auto bytes = revision_bytes(c.ctx.store, c.params[0], c.params[1]);
  if (!bytes) return error_response(c.req, status_of(bytes.error()), bytes.error().message);
  const ToolpathReply reply{c.req.version(), c.req.keep_alive()};
  return respond(reply, work(*bytes), ToolpathFrom::Computed);
}

void answer_later(ApiCall& c, HttpAnswer answer, const std::string& key,
                  std::string_view content_type, RevisionWork work) {
  answer_later(c, std::move(answer), key, plain(content_type), std::move(work));
}

void answer_later(ApiCall& c, HttpAnswer answer, const std::string& key, Respond respond,
                  RevisionWork work) {
  const ToolpathReply reply{c.req.version(), c.req.keep_alive()};
  ToolpathService& service = *c.ctx.toolpaths;
  if (ToolpathStream kept = service.cached(key))
    return answer(respond(reply, *kept, ToolpathFrom::Cache));
  auto bytes = revision_bytes(c.ctx.store, c.params[0], c.params[1]);
  if (!bytes) return answer(error_response(c.req, status_of(bytes.error()), bytes.error().message));
  service.run(
      key, [text = std::move(*bytes), work = std::move(work)] { return work(text); },
      [reply, respond = std::move(respond), answer = std::move(answer)](
          ToolpathStream s, ToolpathFrom from, const std::string& error) {
        answer(s ? respond(reply, *s, from) : run_failed(reply, error));
      });
}

namespace {

// The revision's settings and cache key, or the error answer.
struct Wanted {
  ToolpathSettings settings;
  std::string key;
};

tl::expected<Wanted, HttpResponse> wanted(ApiCall& c) {
  const auto max_vertices = max_vertices_of(c.target);
  if (!max_vertices) {
    return tl::unexpected(
        error_response(c.req, http::status::bad_request,
                       fmt::format("max_vertices must be a whole number from {} to {}",
                                   kMinVertices, kMaxVertices)));
  }
  auto named = named_revision(c);
  if (!named) return tl::unexpected(std::move(named.error()));
  const Program& program = named->program;
  Wanted w;
  w.settings.dialect = program.dialect;
  w.settings.max_vertices = *max_vertices;
  // The vertices' times come from the class's profile, as its check's cycle time.
  const auto it = c.ctx.profiles.find(program.machine_class);
  if (it != c.ctx.profiles.end()) w.settings.profile = it->second;
  w.key = toolpath_key(named->revision.hash, program.dialect + "@" + program.machine_class,
                       w.settings.max_vertices);
  return w;
}

RevisionWork toolpath_work(ToolpathSettings settings) {
  return [settings = std::move(settings)](const std::string& text) {
    return encode_toolpath(program_toolpath(text, settings));
  };
}

}  // namespace

// Without the service (an Api made without one): computed here, on the loop.
HttpResponse api_toolpath(ApiCall& c) {
  auto w = wanted(c);
  if (!w) return std::move(w.error());
  return answer_now(c, kStreamType, toolpath_work(w->settings));
}

void api_toolpath_later(ApiCall& c, HttpAnswer answer) {
  auto w = wanted(c);
  if (!w) return answer(std::move(w.error()));
  answer_later(c, std::move(answer), w->key, kStreamType, toolpath_work(std::move(w->settings)));
}

}  // namespace usina::dnc
