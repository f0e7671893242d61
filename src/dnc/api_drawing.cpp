// GET /api/programs/{name}/revisions/{rev}/drawing[?view=part|toolpath&format=svg|dxf]:
// the revision's 2D drawing (web_drawing.hpp), computed on the tool-path
// service's pool and kept in its cache as the tool path is. A drawing that
// is not whole (the run stopped on an error, or moves were left out past
// the bound) is still 200, and says why in X-Drawing-Complete and
// X-Drawing-Note; nothing to draw is 422.
#include <fmt/format.h>

#include "dnc/api_router.hpp"
#include "dnc/web_drawing.hpp"
#include "dnc/web_toolpath_api.hpp"
#include "dnc/web_toolpath_cache.hpp"

namespace usina::dnc {
namespace {

struct Wanted {
  DrawingSettings settings;
  std::string key;
  std::string file_name;  // of the download: NAME-REV12.svg
};

// `key` of the query: one of `names` (the first when absent), else nothing.
std::optional<std::string> choice(const Target& target, std::string_view key,
                                  std::initializer_list<std::string_view> names) {
  const auto it = target.query.find(key);
  if (it == target.query.end()) return std::string(*names.begin());
  for (std::string_view n : names)
    if (it->second == n) return it->second;
  return std::nullopt;
}

tl::expected<Wanted, HttpResponse> wanted(ApiCall& c) {
  const auto view = choice(c.target, "view", {"part", "toolpath"});
  const auto format = choice(c.target, "format", {"svg", "dxf"});
  if (!view || !format) {
    return tl::unexpected(error_response(
        c.req, http::status::bad_request,
        !view ? "view must be part (the contour, holes, pockets) or toolpath (every move by tool)"
              : "format must be svg or dxf"));
  }
  auto named = named_revision(c);
  if (!named) return tl::unexpected(std::move(named.error()));
  Wanted w;
  w.settings.dialect = named->program.dialect;
  w.settings.view = *view == "toolpath" ? draw::View::Toolpath : draw::View::Part;
  w.settings.format = *format == "dxf" ? DrawingFormat::Dxf : DrawingFormat::Svg;
  // A drawing has no times: the machine class's profile changes nothing in it.
  w.key = fmt::format("drawing {} {} {}", *view, *format,
                      toolpath_key(named->revision.hash, named->program.dialect, 0));
  w.file_name =
      fmt::format("{}-{}.{}", named->program.name, named->revision.hash.substr(0, 12), *format);
  return w;
}

// The note as a header's value: %-encoded, so that any message stays one
// line of ASCII (the page decodes it with decodeURIComponent).
std::string header_text(std::string_view s) {
  std::string out;
  for (const char ch : s) {
    const auto u = static_cast<unsigned char>(ch);
    if (u >= 0x20 && u < 0x7f && ch != '%') {
      out += ch;
    } else {
      out += fmt::format("%{:02X}", u);
    }
  }
  return out;
}

Respond respond_with(const Wanted& w) {
  const bool svg = w.settings.format == DrawingFormat::Svg;
  const std::string type = svg ? "image/svg+xml" : "image/vnd.dxf";
  const std::string disposition =
      fmt::format("{}; filename=\"{}\"", svg ? "inline" : "attachment", w.file_name);
  return [type, disposition](const ToolpathReply& r, const std::string& bytes, ToolpathFrom from) {
    HttpRequest req;
    req.version(r.version);
    req.keep_alive(r.keep_alive);
    auto answer = decode_drawing_answer(bytes);
    if (!answer) return run_failed(r, "the drawing's answer is malformed");
    if (answer->status != 200)
      return error_response(req, static_cast<http::status>(answer->status), answer->note);
    HttpResponse res = computed_response(r, type, answer->body, from);
    res.set(http::field::content_disposition, disposition);
    // The SVG is made here from numbers and layer names; nothing in it runs.
    res.set("Content-Security-Policy", "default-src 'none'");
    res.set("X-Drawing-Complete", answer->complete ? "true" : "false");
    if (!answer->note.empty()) res.set("X-Drawing-Note", header_text(answer->note));
    return res;
  };
}

RevisionWork drawing_work(DrawingSettings settings) {
  return [settings = std::move(settings)](const std::string& text) {
    return encode_drawing_answer(program_drawing(text, settings));
  };
}

}  // namespace

// Without the service (an Api made without one): computed here, on the loop.
HttpResponse api_drawing(ApiCall& c) {
  auto w = wanted(c);
  if (!w) return std::move(w.error());
  return answer_now(c, respond_with(*w), drawing_work(w->settings));
}

void api_drawing_later(ApiCall& c, HttpAnswer answer) {
  auto w = wanted(c);
  if (!w) return answer(std::move(w.error()));
  answer_later(c, std::move(answer), w->key, respond_with(*w), drawing_work(w->settings));
}

}  // namespace usina::dnc
