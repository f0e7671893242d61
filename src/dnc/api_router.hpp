// usina's HTTP API (docs/dnc-server.md; the routes of spec/dnc-api.md and
// more). Every request is matched to a route first (404 for no route, 405
// for a route without that method), then its token checked (401), then the
// user's role (403, store_roles.hpp), and only then its names looked up
// (404) and its body read (400 with a message, 413 past the limits).
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "dnc/api_events.hpp"
#include "dnc/api_http.hpp"
#include "dnc/http_listener.hpp"
#include "dnc/server_machines.hpp"
#include "dnc/store.hpp"
#include "dnc/store_roles.hpp"
#include "dnc/store_users.hpp"

namespace usina::dnc {

class ToolpathService;  // web_toolpath_service.hpp
class SheetLinks;       // sheet_links.hpp
using HttpAnswer = HttpHandlers::Answer;

struct ApiContext {
  Store& store;
  Machines& machines;
  EventHub& events;
  const std::map<std::string, sim::MachineProfile>& profiles;  // by machine class
  ToolpathService* toolpaths = nullptr;  // the tool-path route's pool and cache; none: on the loop
  const SheetLinks* sheet_links = nullptr;  // the sheets' signed links; none: refused
};

// One request on its way through a handler.
struct ApiCall {
  const HttpRequest& req;
  Target target;
  std::vector<std::string> params;  // the route's {name} segments, in order
  std::optional<Session> session;   // the caller (every route but login)
  std::string origin;
  ApiContext& ctx;
  // Where a handler puts a body that streams after its answer's head (the
  // answer then has none of its own); null when the caller cannot stream.
  std::optional<StreamedBody>* stream = nullptr;

  Actor actor() const { return Actor{session ? session->user.name : "", origin}; }

  Role role() const { return session ? session->user.role : Role::Operator; }
};

using ApiHandler = HttpResponse (*)(ApiCall&);
// A route whose work is done off the loop: it answers later, once.
using ApiLaterHandler = void (*)(ApiCall&, HttpAnswer);

enum class Access { Public, AnyUser, Permission };

struct ApiRoute {
  http::verb method;
  std::string_view pattern;  // "/api/programs/{}/revisions/{}/state"
  Access access;
  Permission permission;  // when access is Permission
  ApiHandler handler;
  ApiLaterHandler later = nullptr;  // the server's road (Api::handle_later); `handler` in tests
};

// Every route, for the router and the tests that walk them.
std::span<const ApiRoute> api_routes();

class Api {
 public:
  explicit Api(ApiContext ctx) : ctx_(ctx) {}

  // The routes whose work is done off the loop (the tool path, the tools'
  // figures): true when `req` is one, and `answer` is called later (HttpHandlers::later).
  bool handle_later(const HttpRequest& req, const std::string& origin, HttpAnswer& answer);
  HttpResponse handle(const HttpRequest& req, const std::string& origin);

  // The streamed body of the answer handle() just gave (HttpHandlers::take_stream).
  std::optional<StreamedBody> take_stream() { return std::exchange(stream_, std::nullopt); }

  // `GET /api/events`: takes the stream (WS or WSS) for the events, or refuses.
  std::optional<HttpResponse> upgrade(HttpStream& stream, const HttpRequest& req);

 private:
  ApiContext ctx_;
  std::optional<StreamedBody> stream_;
};

// The handlers, by topic (api_auth.cpp, api_programs.cpp, api_machines.cpp, api_audit.cpp).
HttpResponse api_login(ApiCall& c);
HttpResponse api_logout(ApiCall& c);
HttpResponse api_session(ApiCall& c);
HttpResponse api_create_user(ApiCall& c);
HttpResponse api_list_users(ApiCall& c);
HttpResponse api_change_user(ApiCall& c);
HttpResponse api_list_programs(ApiCall& c);
HttpResponse api_upload(ApiCall& c);
HttpResponse api_program(ApiCall& c);
HttpResponse api_revision(ApiCall& c);
HttpResponse api_revision_text(ApiCall& c);
HttpResponse api_put_sheet(ApiCall& c);   // api_sheets.cpp
HttpResponse api_get_sheet(ApiCall& c);   // api_sheets.cpp
HttpResponse api_sheet_link(ApiCall& c);  // api_sheet_links.cpp
HttpResponse api_sheet_view(ApiCall& c);
// The sheet's bytes as GET .../sheet answers them (api_sheets.cpp).
HttpResponse sheet_answer(ApiCall& c, std::optional<std::string_view> format);
HttpResponse api_toolpath(ApiCall& c);  // web_toolpath_api.cpp
void api_toolpath_later(ApiCall& c, HttpAnswer answer);
HttpResponse api_tool_figures(ApiCall& c);  // web_toolpath_tools.cpp
void api_tool_figures_later(ApiCall& c, HttpAnswer answer);
HttpResponse api_stock(ApiCall& c);  // web_stock_api.cpp
void api_stock_later(ApiCall& c, HttpAnswer answer);
HttpResponse api_drawing(ApiCall& c);  // api_drawing.cpp
void api_drawing_later(ApiCall& c, HttpAnswer answer);
HttpResponse api_form_specs(ApiCall& c);    // api_forms.cpp
HttpResponse api_form_preview(ApiCall& c);  // api_forms.cpp
void api_form_preview_later(ApiCall& c, HttpAnswer answer);
HttpResponse api_calc(ApiCall& c);  // api_calc.cpp
HttpResponse api_change_state(ApiCall& c);
HttpResponse api_diff(ApiCall& c);
HttpResponse api_list_machines(ApiCall& c);
HttpResponse api_machine(ApiCall& c);
HttpResponse api_add_machine(ApiCall& c);  // api_machine_admin.cpp
HttpResponse api_change_machine(ApiCall& c);
HttpResponse api_retire_machine(ApiCall& c);
// A machine as GET /api/machines/{machine} answers (api_machines.cpp), and
// the retired ones of the store (api_machine_admin.cpp).
nlohmann::json machine_json(ApiCall& c, MachineRuntime& m);
StoreResult<nlohmann::json> retired_machines(ApiCall& c);
HttpResponse api_utilisation(ApiCall& c);  // api_utilisation.cpp
HttpResponse api_tool_life(ApiCall& c);
HttpResponse api_reset_tool(ApiCall& c);
HttpResponse api_record_quality(ApiCall& c);  // api_quality.cpp
HttpResponse api_quality(ApiCall& c);
HttpResponse api_start_job(ApiCall& c);
HttpResponse api_job(ApiCall& c);
HttpResponse api_stop_job(ApiCall& c);
HttpResponse api_audit(ApiCall& c);
HttpResponse api_import(ApiCall& c);  // api_transfer.cpp
HttpResponse api_export(ApiCall& c);
HttpResponse api_events_plain(ApiCall& c);

}  // namespace usina::dnc
