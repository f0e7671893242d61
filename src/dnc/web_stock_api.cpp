// GET /api/programs/{name}/revisions/{rev}/stock[?stock=box:WxLxH&origin=X,Y,Z
// &resolution=R&frames=N&tools=T=SHAPE/D;...]: the stock the revision leaves,
// frame by frame, for the viewer (web_stock.hpp), computed on the tool-path
// service's pool and kept in its cache as the tool path is.
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "dnc/api_router.hpp"
#include "dnc/web_stock.hpp"
#include "dnc/web_toolpath_api.hpp"
#include "dnc/web_toolpath_cache.hpp"

namespace usina::dnc {
namespace {

constexpr std::string_view kStockType = "application/octet-stream";

struct Wanted {
  StockSettings settings;
  std::string key;
};

tl::expected<Wanted, HttpResponse> wanted(ApiCall& c) {
  auto settings = read_stock_query(c.target.query, StockLimits{});
  if (!settings) {
    return tl::unexpected(error_response(c.req, static_cast<http::status>(settings.error().status),
                                         settings.error().reason));
  }
  auto named = named_revision(c);
  if (!named) return tl::unexpected(std::move(named.error()));
  Wanted w;
  w.settings = std::move(*settings);
  w.settings.dialect = named->program.dialect;
  w.key = "stock " + toolpath_key(named->revision.hash, w.settings.dialect, 0) + " " +
          stock_settings_key(w.settings);
  return w;
}

RevisionWork stock_work(StockSettings settings) {
  return [settings = std::move(settings)](const std::string& text) {
    return encode_stock(text, settings);
  };
}

// The stock, or the run's refusal: the program's own box is no stock
// (422), the frames passed the answer's bound (413).
HttpResponse respond(const ToolpathReply& r, const std::string& bytes, ToolpathFrom from) {
  if (is_stock_answer(bytes)) return computed_response(r, kStockType, bytes, from);
  HttpRequest req;
  req.version(r.version);
  req.keep_alive(r.keep_alive);
  const auto why = nlohmann::json::parse(bytes, nullptr, false);
  if (!why.is_object()) return error_response(req, http::status::unprocessable_entity, bytes);
  return error_response(req, static_cast<http::status>(why.value("status", 422u)),
                        why.value("error", bytes));
}

}  // namespace

// Without the service (an Api made without one): computed here, on the loop.
HttpResponse api_stock(ApiCall& c) {
  auto w = wanted(c);
  if (!w) return std::move(w.error());
  return answer_now(c, respond, stock_work(w->settings));
}

void api_stock_later(ApiCall& c, HttpAnswer answer) {
  auto w = wanted(c);
  if (!w) return answer(std::move(w.error()));
  answer_later(c, std::move(answer), w->key, respond, stock_work(std::move(w->settings)));
}

}  // namespace usina::dnc
