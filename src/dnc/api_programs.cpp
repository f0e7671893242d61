// Programs and revisions: upload (checked by the store in the program's
// dialect), read, move along the state graph by role, diff.
#include <fmt/format.h>

#include "dnc/api_json.hpp"
#include "dnc/api_router.hpp"
#include "dnc/store_revisions.hpp"

namespace usina::dnc {
namespace {

HttpResponse store_failure(const ApiCall& c, const StoreError& e) {
  return error_response(c.req, status_of(e), e.message);
}

HttpResponse bad(const ApiCall& c, const std::string& message) {
  return error_response(c.req, http::status::bad_request, message);
}

tl::expected<Upload, std::string> read_upload(const HttpRequest& req) {
  auto body = json_body(req);
  if (!body) return tl::unexpected(body.error());
  Upload up;
  const std::pair<std::string_view, std::string*> fields[] = {{"name", &up.name},
                                                              {"machine_class", &up.machine_class},
                                                              {"dialect", &up.dialect},
                                                              {"text", &up.text},
                                                              {"reason", &up.reason}};
  for (const auto& [key, into] : fields) {
    auto v = string_field(*body, key, key == "name" || key == "text");
    if (!v) return tl::unexpected(v.error());
    if (*v) *into = std::move(**v);
  }
  return up;
}

// The profile of the upload's machine class (or its program's): the
// check then finds moves past that machine's travel.
const sim::MachineProfile* profile_for(const ApiCall& c, const Upload& up) {
  std::string machine_class = up.machine_class;
  if (machine_class.empty()) {
    if (auto p = find_program(c.ctx.store, up.name)) machine_class = p->machine_class;
  }
  const auto it = c.ctx.profiles.find(machine_class);
  return it == c.ctx.profiles.end() ? nullptr : &it->second;
}

}  // namespace

HttpResponse api_upload(ApiCall& c) {
  auto up = read_upload(c.req);
  if (!up) return bad(c, up.error());
  up->profile = profile_for(c, *up);
  auto put = put_revision(c.ctx.store, *up, c.actor());
  if (!put) return store_failure(c, put.error());
  nlohmann::json out = revision_json(put->revision);
  out["name"] = up->name;
  out["created"] = put->created;
  if (put->created) {
    c.ctx.events.publish("revision.created", {{"name", up->name},
                                              {"revision", put->revision.hash},
                                              {"state", state_name(put->revision.state)},
                                              {"user", c.actor().user}});
  }
  return json_response(c.req, put->created ? http::status::created : http::status::ok, out);
}

HttpResponse api_program(ApiCall& c) {
  const std::string& name = c.params[0];
  auto program = find_program(c.ctx.store, name);
  if (!program) return store_failure(c, program.error());
  auto revisions = list_revisions(c.ctx.store, RevisionQuery{name, std::nullopt, 1000, 0});
  if (!revisions) return store_failure(c, revisions.error());
  auto released = released_revision(c.ctx.store, name);
  if (!released) return store_failure(c, released.error());
  nlohmann::json list = nlohmann::json::array();
  for (const Revision& r : *revisions)
    list.push_back(revision_json(r));
  return json_response(
      c.req, http::status::ok,
      {{"name", program->name},
       {"machine_class", program->machine_class},
       {"dialect", program->dialect},
       {"created_at_us", program->created_at_us},
       {"released", *released ? nlohmann::json((*released)->hash) : nlohmann::json(nullptr)},
       {"revisions", std::move(list)}});
}

HttpResponse api_revision(ApiCall& c) {
  auto r = find_revision(c.ctx.store, c.params[0], c.params[1]);
  if (!r) return store_failure(c, r.error());
  auto sheets = list_sheets(c.ctx.store, r->program, r->hash);
  if (!sheets) return store_failure(c, sheets.error());
  nlohmann::json out = revision_json(*r);
  out["name"] = r->program;
  out["sheets"] = nlohmann::json::array();
  for (const Sheet& s : *sheets)
    out["sheets"].push_back(sheet_json(s));
  return json_response(c.req, http::status::ok, out);
}

HttpResponse api_revision_text(ApiCall& c) {
  auto bytes = revision_bytes(c.ctx.store, c.params[0], c.params[1]);
  if (!bytes) return store_failure(c, bytes.error());
  HttpResponse res{http::status::ok, c.req.version()};
  res.set(http::field::content_type, "text/plain; charset=utf-8");
  res.keep_alive(c.req.keep_alive());
  res.body() = std::move(*bytes);
  res.prepare_payload();
  return res;
}

HttpResponse api_change_state(ApiCall& c) {
  auto body = json_body(c.req);
  if (!body) return bad(c, body.error());
  auto state = string_field(*body, "state", true);
  if (!state) return bad(c, state.error());
  auto reason = string_field(*body, "reason", false);
  if (!reason) return bad(c, reason.error());
  const auto to = parse_state(**state);
  if (!to) {
    return bad(c, fmt::format("no state \"{}\"; the states are draft, checked, approved, "
                              "released, rejected, check-failed",
                              **state));
  }
  auto rev = find_revision(c.ctx.store, c.params[0], c.params[1]);
  if (!rev) return store_failure(c, rev.error());
  if (!transition_exists(rev->state, *to)) {
    return error_response(c.req, http::status::conflict,
                          fmt::format("{} -> {}: {}", state_name(rev->state), state_name(*to),
                                      why_not(rev->state, *to)));
  }
  if (auto may = may_change_state(c.role(), c.actor().user, rev->author, rev->state, *to); !may)
    return error_response(c.req, http::status::forbidden, may.error());
  auto moved =
      change_state(c.ctx.store, c.params[0], c.params[1], *to, reason->value_or(""), c.actor());
  if (!moved) return store_failure(c, moved.error());
  c.ctx.events.publish("revision.state", {{"name", moved->program},
                                          {"revision", moved->hash},
                                          {"state", state_name(*to)},
                                          {"user", c.actor().user}});
  nlohmann::json out = revision_json(*moved);
  out["name"] = moved->program;
  return json_response(c.req, http::status::ok, out);
}

HttpResponse api_diff(ApiCall& c) {
  const auto& q = c.target.query;
  const auto from = q.find("from");
  const auto to = q.find("to");
  if (from == q.end() || to == q.end())
    return bad(c,
               "give both revisions: ?from=REV&to=REV (and normalised=1 for the normalised diff)");
  const auto norm = q.find("normalised");
  const bool normalised = norm != q.end() && (norm->second == "1" || norm->second == "true");
  auto d = diff_revisions(c.ctx.store, c.params[0], from->second, to->second, normalised);
  if (!d) return store_failure(c, d.error());
  return json_response(c.req, http::status::ok,
                       {{"name", c.params[0]},
                        {"from", from->second},
                        {"to", to->second},
                        {"normalised", normalised},
                        {"identical", d->diff.identical()},
                        {"deleted", d->diff.deleted},
                        {"inserted", d->diff.inserted},
                        {"diff", unified_diff(*d, from->second, to->second)}});
}

}  // namespace usina::dnc
