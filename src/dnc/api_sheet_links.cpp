// The setup sheet shown in the page (docs/dnc-server.md, "Setup sheets"):
// a user asks for a short-lived signed link to one sheet, and the page's
// frame opens it without a token. The link is refused (403) when its
// signature does not hold for its program, revision and format, or when it
// has expired.
#include <algorithm>
#include <charconv>

#include <fmt/format.h>

#include "dnc/api_json.hpp"
#include "dnc/api_router.hpp"
#include "dnc/sheet_links.hpp"
#include "dnc/store_sheets.hpp"

namespace usina::dnc {
namespace {

HttpResponse refused(const ApiCall& c, std::string_view why) {
  return error_response(c.req, http::status::forbidden,
                        fmt::format("{}; open the sheet again from its program's page", why));
}

std::string_view query(const ApiCall& c, std::string_view key) {
  const auto it = c.target.query.find(key);
  return it == c.target.query.end() ? std::string_view() : std::string_view(it->second);
}

std::optional<std::int64_t> seconds(std::string_view text) {
  std::int64_t v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || end != text.data() + text.size() || text.empty()) return std::nullopt;
  return v;
}

}  // namespace

// POST .../sheet/link {"format"}: {"url","format","expires_at_us"}; 404
// when the revision has no sheet of that format.
HttpResponse api_sheet_link(ApiCall& c) {
  if (c.ctx.sheet_links == nullptr)
    return error_response(c.req, http::status::not_found, "this server signs no sheet links");
  auto body = json_body(c.req);
  if (!body) return error_response(c.req, http::status::bad_request, body.error());
  auto format = string_field(*body, "format", true);
  if (!format) return error_response(c.req, http::status::bad_request, format.error());
  if (!is_sheet_format(**format))
    return error_response(c.req, http::status::bad_request, R"(format must be "html" or "pdf")");
  auto sheets = list_sheets(c.ctx.store, c.params[0], c.params[1]);
  if (!sheets) return error_response(c.req, status_of(sheets.error()), sheets.error().message);
  const bool there = std::any_of(sheets->begin(), sheets->end(),
                                 [&](const Sheet& s) { return s.format == **format; });
  if (!there) {
    return error_response(
        c.req, http::status::not_found,
        fmt::format("{} revision {} has no {} sheet", c.params[0], c.params[1], **format));
  }
  const std::int64_t expires = c.ctx.store.now_us() / 1'000'000 + kSheetLinkSeconds;
  const std::string sig = c.ctx.sheet_links->sign({c.params[0], c.params[1], **format, expires});
  const std::string url =
      fmt::format("/api/programs/{}/revisions/{}/sheet/view?format={}&expires={}&sig={}",
                  c.params[0], c.params[1], **format, expires, sig);
  return json_response(
      c.req, http::status::ok,
      {{"url", url}, {"format", **format}, {"expires_at_us", expires * 1'000'000}});
}

// GET .../sheet/view?format=F&expires=S&sig=HEX (no token): the sheet as
// GET .../sheet answers it, not kept by the browser.
HttpResponse api_sheet_view(ApiCall& c) {
  const std::string_view format = query(c, "format");
  const std::string_view sig = query(c, "sig");
  const auto expires = seconds(query(c, "expires"));
  if (c.ctx.sheet_links == nullptr || format.empty() || sig.empty() || !expires)
    return refused(c, "this sheet link is incomplete");
  if (!c.ctx.sheet_links->holds({c.params[0], c.params[1], format, *expires}, sig))
    return refused(c,
                   "this sheet link's signature does not hold: it was changed, is another "
                   "sheet's, or was signed before the server restarted");
  if (c.ctx.store.now_us() / 1'000'000 >= *expires)
    return refused(c, "this sheet link has expired");
  HttpResponse res = sheet_answer(c, format);
  res.set(http::field::cache_control, "no-store");
  res.set("Referrer-Policy", "no-referrer");
  return res;
}

}  // namespace usina::dnc
