// A revision's setup sheet over HTTP (docs/dnc-server.md, "Setup sheets"):
// put with the revision as JSON (`text` for HTML, `text_base64` for any
// bytes, as the import takes them), read back as its own bytes.
#include <fmt/format.h>

#include "dnc/api_json.hpp"
#include "dnc/api_router.hpp"
#include "dnc/base64.hpp"
#include "dnc/store_sheets.hpp"

namespace usina::dnc {
namespace {

HttpResponse bad(const ApiCall& c, const std::string& message) {
  return error_response(c.req, http::status::bad_request, message);
}

// `text` or `text_base64`, one of them.
tl::expected<std::string, std::string> sheet_bytes(const nlohmann::json& body) {
  auto text = string_field(body, "text", false);
  if (!text) return tl::unexpected(text.error());
  auto encoded = string_field(body, "text_base64", false);
  if (!encoded) return tl::unexpected(encoded.error());
  if (text->has_value() == encoded->has_value()) {
    return tl::unexpected(std::string(R"(give the sheet as "text" or "text_base64", one of them)"));
  }
  if (text->has_value()) return std::move(**text);
  auto bytes = from_base64(**encoded);
  if (!bytes) return tl::unexpected(std::string("\"text_base64\" is not base64"));
  return std::move(*bytes);
}

tl::expected<SheetUpload, std::string> read_sheet_upload(const ApiCall& c) {
  auto body = json_body(c.req);
  if (!body) return tl::unexpected(body.error());
  auto format = string_field(*body, "format", true);
  if (!format) return tl::unexpected(format.error());
  auto reason = string_field(*body, "reason", false);
  if (!reason) return tl::unexpected(reason.error());
  auto bytes = sheet_bytes(*body);
  if (!bytes) return tl::unexpected(bytes.error());
  return SheetUpload{c.params[0], c.params[1], std::move(**format), std::move(*bytes),
                     reason->value_or("")};
}

}  // namespace

nlohmann::json sheet_json(const Sheet& s) {
  return {{"format", s.format},
          {"sheet", s.hash},
          {"size", s.size},
          {"author", s.author},
          {"created_at_us", s.created_at_us}};
}

HttpResponse api_put_sheet(ApiCall& c) {
  auto up = read_sheet_upload(c);
  if (!up) return bad(c, up.error());
  auto put = put_sheet(c.ctx.store, *up, c.actor());
  if (!put) return error_response(c.req, status_of(put.error()), put.error().message);
  nlohmann::json out = sheet_json(put->sheet);
  out["name"] = up->program;
  out["revision"] = up->revision;
  out["replaced"] = put->replaced ? nlohmann::json(*put->replaced) : nlohmann::json(nullptr);
  out["changed"] = put->changed;
  if (put->changed) {
    c.ctx.events.publish("revision.sheet", {{"name", up->program},
                                            {"revision", up->revision},
                                            {"format", up->format},
                                            {"user", c.actor().user}});
  }
  return json_response(c.req, put->changed ? http::status::created : http::status::ok, out);
}

HttpResponse api_get_sheet(ApiCall& c) {
  std::optional<std::string_view> format;
  if (const auto it = c.target.query.find("format"); it != c.target.query.end())
    format = it->second;
  return sheet_answer(c, format);
}

HttpResponse sheet_answer(ApiCall& c, std::optional<std::string_view> format) {
  auto sheet = read_sheet(c.ctx.store, c.params[0], c.params[1], format);
  if (!sheet) return error_response(c.req, status_of(sheet.error()), sheet.error().message);
  const bool pdf = sheet->first.format == "pdf";
  HttpResponse res{http::status::ok, c.req.version()};
  res.set(http::field::content_type, pdf ? "application/pdf" : "text/html; charset=utf-8");
  res.set("X-Content-Type-Options", "nosniff");
  // A sheet is a programmer's upload: shown in a browser it runs no script
  // and reaches nothing of the server's origin (a sandbox is an origin of
  // its own); its own styles and pictures are inside it.
  if (!pdf) {
    res.set("Content-Security-Policy",
            "sandbox; default-src 'none'; style-src 'unsafe-inline'; img-src data:");
  }
  res.keep_alive(c.req.keep_alive());
  res.body() = std::move(sheet->second);
  res.prepare_payload();
  return res;
}

}  // namespace usina::dnc
