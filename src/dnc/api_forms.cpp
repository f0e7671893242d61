// GET /api/forms: every cycle's fields with their ranges and defaults, as
// the server reads them (form_specs), so the page checks a field as the
// user types by the server's own ranges.
// POST /api/forms/{cycle}/preview: a cycle's form made into a program for
// one control (form_cycles.hpp), checked in its dialect as an upload is
// (store_check.hpp), with its tool path in the viewer's stream
// (web_toolpath.hpp). Computed on the tool-path service's pool and kept in
// its cache under the body's hash, so the event loop goes on serving and a
// form sent again (the page previews as the user types) is answered at once.
#include <fmt/format.h>
#include <tl/expected.hpp>

#include "dnc/api_json.hpp"
#include "dnc/api_router.hpp"
#include "dnc/base64.hpp"
#include "dnc/form_cycles.hpp"
#include "dnc/sha256.hpp"
#include "dnc/store_check.hpp"
#include "dnc/web_toolpath.hpp"
#include "dnc/web_toolpath_api.hpp"
#include "dnc/web_toolpath_service.hpp"

namespace usina::dnc {
namespace {

using nlohmann::json;

struct PreviewRequest {
  std::string cycle;
  json body;
  const sim::MachineProfile* profile = nullptr;  // the machine class's, when it has one
  std::string key;                               // in the tool-path cache
};

std::string cycle_list() {
  std::string s;
  for (std::string_view c : form_cycles())
    s += (s.empty() ? "" : ", ") + std::string(c);
  return s;
}

tl::expected<PreviewRequest, HttpResponse> preview_request(ApiCall& c) {
  const std::string& cycle = c.params[0];
  if (!is_form_cycle(cycle)) {
    return tl::unexpected(
        error_response(c.req, http::status::not_found,
                       fmt::format("no cycle \"{}\"; the cycles are {}", cycle, cycle_list())));
  }
  auto body = json_body(c.req);
  if (!body) return tl::unexpected(error_response(c.req, http::status::bad_request, body.error()));
  auto machine_class = string_field(*body, "machine_class", false);
  if (!machine_class) {
    return tl::unexpected(error_response(c.req, http::status::bad_request, machine_class.error()));
  }
  PreviewRequest r{cycle, std::move(*body), nullptr, ""};
  if (*machine_class) {
    const auto it = c.ctx.profiles.find(**machine_class);
    if (it != c.ctx.profiles.end()) r.profile = &it->second;
  }
  // The body's bytes as sent (a drawing may be megabytes: not written again).
  r.key = "form:" + cycle + ":" + sha256_hex(c.req.body());
  return r;
}

json errors_json(const std::vector<FieldError>& errors) {
  json list = json::array();
  for (const FieldError& e : errors)
    list.push_back({{"field", e.field}, {"message", e.message}, {"code", e.code}});
  return {{"error", errors.empty() ? "" : errors.front().message}, {"errors", std::move(list)}};
}

json diagnostics_json(const FormProgram& p, const CheckResults& check) {
  json list = json::array();
  for (const core::Diagnostic& d : p.notes) {
    list.push_back({{"code", core::code_name(d.code)},
                    {"severity", core::severity_name(d.severity)},
                    {"line", d.loc.line},
                    {"column", d.loc.col},
                    {"message", d.message}});
  }
  for (const CheckDiagnostic& d : check.diagnostics) {
    list.push_back({{"code", d.code},
                    {"severity", d.severity},
                    {"line", d.line},
                    {"column", d.column},
                    {"message", d.message}});
  }
  return list;
}

// The answer's status and body as one string, "STATUS\n" then the JSON:
// what the pool computes and the cache keeps is bytes.
std::string preview_work(const PreviewRequest& r) {
  const FormProgram p = form_program(r.cycle, r.body);
  if (!p.errors.empty()) return "400\n" + errors_json(p.errors).dump();
  CheckSettings settings;
  settings.dialect = p.dialect;
  settings.profile = r.profile;
  const CheckResults check = check_program(p.text, settings);
  ToolpathSettings path;
  path.dialect = p.dialect;
  if (r.profile != nullptr) path.profile = *r.profile;
  const std::string stream = encode_toolpath(program_toolpath(p.text, path));
  const json out = {{"cycle", r.cycle},
                    {"dialect", p.dialect},
                    {"text", p.text},
                    {"bytes", p.text.size()},
                    {"diagnostics", diagnostics_json(p, check)},
                    {"checks", json::parse(check.to_json())},
                    {"check_ok", check.blocking() == 0},
                    {"toolpath", to_base64(stream)}};
  return "200\n" + out.dump(-1, ' ', false, json::error_handler_t::replace);
}

HttpResponse preview_response(const ToolpathReply& reply, const std::string& computed) {
  const std::size_t nl = computed.find('\n');
  const bool ok = computed.starts_with("200");
  HttpResponse res{ok ? http::status::ok : http::status::bad_request, reply.version};
  res.set(http::field::server, "usina");
  res.set(http::field::content_type, "application/json");
  res.set(http::field::cache_control, "no-store");
  res.keep_alive(reply.keep_alive);
  res.body() = computed.substr(nl == std::string::npos ? computed.size() : nl + 1);
  res.prepare_payload();
  return res;
}

}  // namespace

// Without the service (an Api made without one): computed here, on the loop.
HttpResponse api_form_specs(ApiCall& c) {
  // The same for every call: made once.
  static const nlohmann::json kSpecs = form_specs();
  return json_response(c.req, http::status::ok, kSpecs);
}

HttpResponse api_form_preview(ApiCall& c) {
  auto r = preview_request(c);
  if (!r) return std::move(r.error());
  return preview_response({c.req.version(), c.req.keep_alive()}, preview_work(*r));
}

void api_form_preview_later(ApiCall& c, HttpAnswer answer) {
  auto r = preview_request(c);
  if (!r) return answer(std::move(r.error()));
  const ToolpathReply reply{c.req.version(), c.req.keep_alive()};
  ToolpathService& service = *c.ctx.toolpaths;
  if (ToolpathStream kept = service.cached(r->key)) {
    answer(preview_response(reply, *kept));
    return;
  }
  const std::string key = r->key;
  service.run(
      key, [r = std::move(*r)] { return preview_work(r); },
      [reply, answer = std::move(answer)](ToolpathStream s, ToolpathFrom,
                                          const std::string& error) {
        answer(s ? preview_response(reply, *s) : run_failed(reply, error));
      });
}

}  // namespace usina::dnc
