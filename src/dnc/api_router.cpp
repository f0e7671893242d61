#include "dnc/api_router.hpp"

#include <array>

#include <fmt/format.h>

#include "dnc/store_names.hpp"

namespace usina::dnc {
namespace {

using P = Permission;
using A = Access;
using V = http::verb;

constexpr std::array kRoutes{
    ApiRoute{V::post, "/api/login", A::Public, P::ReadPrograms, api_login},
    ApiRoute{V::post, "/api/logout", A::AnyUser, P::ReadPrograms, api_logout},
    ApiRoute{V::get, "/api/session", A::AnyUser, P::ReadPrograms, api_session},
    ApiRoute{V::post, "/api/users", A::Permission, P::ManageUsers, api_create_user},
    ApiRoute{V::get, "/api/users", A::Permission, P::ManageUsers, api_list_users},
    ApiRoute{V::post, "/api/users/{}", A::Permission, P::ManageUsers, api_change_user},
    ApiRoute{V::get, "/api/programs", A::Permission, P::ReadPrograms, api_list_programs},
    ApiRoute{V::post, "/api/programs", A::Permission, P::UploadRevision, api_upload},
    ApiRoute{V::get, "/api/programs/{}", A::Permission, P::ReadPrograms, api_program},
    ApiRoute{V::get, "/api/programs/{}/revisions/{}", A::Permission, P::ReadPrograms, api_revision},
    ApiRoute{V::get, "/api/programs/{}/revisions/{}/text", A::Permission, P::ReadPrograms,
             api_revision_text},
    // The setup sheet made with the program (docs/dnc-server.md, "Setup sheets").
    ApiRoute{V::post, "/api/programs/{}/revisions/{}/sheet", A::Permission, P::UploadRevision,
             api_put_sheet},
    ApiRoute{V::get, "/api/programs/{}/revisions/{}/sheet", A::Permission, P::ReadPrograms,
             api_get_sheet},
    // A link to show the sheet in a frame, which sends no token: signed, it
    // is its own permission for a few minutes (sheet_links.hpp).
    ApiRoute{V::post, "/api/programs/{}/revisions/{}/sheet/link", A::Permission, P::ReadPrograms,
             api_sheet_link},
    ApiRoute{V::get, "/api/programs/{}/revisions/{}/sheet/view", A::Public, P::ReadPrograms,
             api_sheet_view},
    // The viewer's binary tool path (docs/web.md).
    ApiRoute{V::get, "/api/programs/{}/revisions/{}/toolpath", A::Permission, P::ReadPrograms,
             api_toolpath, api_toolpath_later},
    // The figures of each tool, for the page (docs/web.md).
    ApiRoute{V::get, "/api/programs/{}/revisions/{}/tools", A::Permission, P::ReadPrograms,
             api_tool_figures, api_tool_figures_later},
    // The stock the revision leaves, frame by frame, for the viewer (docs/web.md).
    ApiRoute{V::get, "/api/programs/{}/revisions/{}/stock", A::Permission, P::ReadPrograms,
             api_stock, api_stock_later},
    // The 2D drawing, SVG or DXF, as usina draw makes it (docs/web.md, "The drawing").
    ApiRoute{V::get, "/api/programs/{}/revisions/{}/drawing", A::Permission, P::ReadPrograms,
             api_drawing, api_drawing_later},
    // The forms' fields, ranges and defaults (docs/dnc-server.md, "Forms for cycles").
    ApiRoute{V::get, "/api/forms", A::Permission, P::UploadRevision, api_form_specs},
    // A cycle's form made into a program, previewed (docs/dnc-server.md, "Forms for cycles").
    ApiRoute{V::post, "/api/forms/{}/preview", A::Permission, P::UploadRevision, api_form_preview,
             api_form_preview_later},
    // Seed 004's calculators, as `usina calc --format json` answers them (docs/dnc-server.md).
    ApiRoute{V::post, "/api/calc/{}", A::AnyUser, P::ReadPrograms, api_calc},
    // Who may make which move is the state table's (may_change_state).
    ApiRoute{V::post, "/api/programs/{}/revisions/{}/state", A::AnyUser, P::ReadPrograms,
             api_change_state},
    ApiRoute{V::get, "/api/programs/{}/diff", A::Permission, P::ReadPrograms, api_diff},
    ApiRoute{V::get, "/api/machines", A::Permission, P::ReadMachines, api_list_machines},
    ApiRoute{V::get, "/api/machines/{}", A::Permission, P::ReadMachines, api_machine},
    // An admin's machines besides the file's (docs/dnc-server.md, "Machines added from the page").
    ApiRoute{V::post, "/api/machines", A::Permission, P::ManageMachines, api_add_machine},
    ApiRoute{V::post, "/api/machines/{}", A::Permission, P::ManageMachines, api_change_machine},
    ApiRoute{V::post, "/api/machines/{}/retire", A::Permission, P::ManageMachines,
             api_retire_machine},
    ApiRoute{V::get, "/api/machines/{}/utilisation", A::Permission, P::ReadMachines,
             api_utilisation},
    ApiRoute{V::get, "/api/machines/{}/tools", A::Permission, P::ReadMachines, api_tool_life},
    // A tool's count starts again: its insert or cutter was changed (docs/dnc.md).
    ApiRoute{V::post, "/api/machines/{}/tools/{}/reset", A::Permission, P::ResetToolLife,
             api_reset_tool},
    ApiRoute{V::post, "/api/machines/{}/quality", A::Permission, P::RecordQuality,
             api_record_quality},
    ApiRoute{V::get, "/api/machines/{}/quality", A::Permission, P::ReadMachines, api_quality},
    ApiRoute{V::post, "/api/machines/{}/jobs", A::Permission, P::StartJob, api_start_job},
    ApiRoute{V::get, "/api/jobs/{}", A::Permission, P::ReadMachines, api_job},
    ApiRoute{V::post, "/api/jobs/{}/stop", A::Permission, P::StartJob, api_stop_job},
    ApiRoute{V::get, "/api/audit", A::Permission, P::ReadAudit, api_audit},
    // Import and export (docs/dnc.md): the roles table's, as the folder's.
    ApiRoute{V::post, "/api/import", A::Permission, P::ImportPrograms, api_import},
    ApiRoute{V::get, "/api/export", A::Permission, P::ExportReleased, api_export},
    // Without a WebSocket upgrade (the upgrade itself is Api::upgrade).
    ApiRoute{V::get, "/api/events", A::AnyUser, P::ReadMachines, api_events_plain},
};

// The route's {} segments of `segments`, when the pattern matches.
std::optional<std::vector<std::string>> match(std::string_view pattern,
                                              const std::vector<std::string>& segments) {
  auto pat = parse_target(pattern);
  if (!pat || pat->segments.size() != segments.size()) return std::nullopt;
  std::vector<std::string> params;
  for (std::size_t i = 0; i < segments.size(); ++i) {
    if (pat->segments[i] == "{}") {
      params.push_back(segments[i]);
    } else if (pat->segments[i] != segments[i]) {
      return std::nullopt;
    }
  }
  return params;
}

// 401 for a missing, unknown or expired token; 403 for a role that may not.
std::optional<HttpResponse> authorise(ApiCall& call, const ApiRoute& route) {
  if (route.access == A::Public) return std::nullopt;
  const std::string token = bearer_token(call.req);
  if (token.empty()) {
    return error_response(call.req, http::status::unauthorized,
                          "log in first: send the token of POST /api/login as "
                          "\"Authorization: Bearer TOKEN\"");
  }
  auto session = verify_session(call.ctx.store, token);
  if (!session) {
    const bool backend = session.error().kind == StoreErrorKind::Backend;
    return error_response(
        call.req, backend ? http::status::internal_server_error : http::status::unauthorized,
        session.error().message);
  }
  call.session = std::move(*session);
  if (route.access == A::Permission && !role_may(call.role(), route.permission)) {
    return error_response(
        call.req, http::status::forbidden,
        fmt::format("a user with the role {} may not do this", role_name(call.role())));
  }
  return std::nullopt;
}

HttpResponse with_www_authenticate(HttpResponse res) {
  if (res.result() == http::status::unauthorized) res.set(http::field::www_authenticate, "Bearer");
  return res;
}

}  // namespace

std::span<const ApiRoute> api_routes() {
  return kRoutes;
}

HttpResponse Api::handle(const HttpRequest& req, const std::string& origin) {
  stream_.reset();
  auto target = parse_target(std::string_view(req.target().data(), req.target().size()));
  if (!target) {
    return error_response(req, http::status::bad_request,
                          "the path is malformed (names are never paths: no `.`, `..`, empty "
                          "or %-encoded `/` segments)");
  }
  bool path_known = false;
  for (const ApiRoute& route : kRoutes) {
    auto params = match(route.pattern, target->segments);
    if (!params) continue;
    path_known = true;
    if (route.method != req.method()) continue;
    ApiCall call{req, *target, std::move(*params), std::nullopt, origin, ctx_, &stream_};
    if (auto refused = authorise(call, route)) return with_www_authenticate(std::move(*refused));
    return with_www_authenticate(route.handler(call));
  }
  if (path_known) return error_response(req, http::status::method_not_allowed, "no such method");
  return error_response(req, http::status::not_found, "no such route");
}

std::optional<HttpResponse> Api::upgrade(HttpStream& stream, const HttpRequest& req) {
  auto target = parse_target(std::string_view(req.target().data(), req.target().size()));
  if (!target || target->segments != std::vector<std::string>{"api", "events"})
    return error_response(req, http::status::not_found, "no WebSocket here; use /api/events");
  std::string token = bearer_token(req);
  // Browsers cannot set a header on a WebSocket: the token may come as ?token=.
  if (const auto it = target->query.find("token"); token.empty() && it != target->query.end())
    token = it->second;
  if (token.empty())
    return error_response(req, http::status::unauthorized, "log in first: no token given");
  auto session = verify_session(ctx_.store, token);
  if (!session) return error_response(req, http::status::unauthorized, session.error().message);
  auto s = EventSession::over(stream);
  ctx_.events.add(s);
  s->accept(req);
  return std::nullopt;
}

bool Api::handle_later(const HttpRequest& req, const std::string& origin, HttpAnswer& answer) {
  if (ctx_.toolpaths == nullptr) return false;
  auto target = parse_target(std::string_view(req.target().data(), req.target().size()));
  if (!target) return false;
  for (const ApiRoute& route : kRoutes) {
    if (route.later == nullptr || route.method != req.method()) continue;
    auto params = match(route.pattern, target->segments);
    if (!params) continue;
    ApiCall call{req, *target, std::move(*params), std::nullopt, origin, ctx_, nullptr};
    if (auto refused = authorise(call, route)) {
      answer(with_www_authenticate(std::move(*refused)));
      return true;
    }
    route.later(call, std::move(answer));
    return true;
  }
  return false;
}

}  // namespace usina::dnc
