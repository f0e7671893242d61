#include "cam/engrave.hpp"

#include <algorithm>
#include <limits>

#include <fmt/format.h>

namespace usina::cam {
namespace {

struct Span {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
};

Span y_span(const HersheyGlyph& g) {
  Span s;
  for (const auto& stroke : g.strokes) {
    for (const Vec2& p : stroke)
      s.lo = std::min(s.lo, p.y), s.hi = std::max(s.hi, p.y);
  }
  return s;
}

// The font's capital height and baseline in font units: those of its "H",
// or of all its glyphs together when it has no "H" (a symbol font).
Span cap_span(const HersheyFont& font) {
  if (const HersheyGlyph* h = font.glyph('H'); h != nullptr && !h->strokes.empty())
    return y_span(*h);
  Span all;
  for (const HersheyGlyph& g : font.glyphs) {
    const Span s = y_span(g);
    all.lo = std::min(all.lo, s.lo), all.hi = std::max(all.hi, s.hi);
  }
  return all;
}

}  // namespace

bool layout_text(const HersheyFont& font, const EngraveOptions& o,
                 std::vector<std::vector<Vec2>>& strokes, core::DiagnosticSink& diags) {
  if (!check_range("the text height (--height)", o.height, kLength, diags)) return false;
  if (o.text.empty()) return fail(diags, core::Code::TextNotInFont, "the text is empty");
  if (o.text.find_first_not_of(' ') == std::string::npos) {
    return fail(diags, core::Code::GenBadValue,
                "the text is only spaces: there is nothing to engrave");
  }
  if (o.text.size() > static_cast<std::size_t>(kMaxPasses)) {
    return fail(diags, core::Code::GenBadValue,
                fmt::format("the text has {} characters, more than {}", o.text.size(), kMaxPasses));
  }
  if (!check_point("the text's start", o.at, diags)) return false;
  if (!check_point("the text's end",
                   o.at + Vec2{o.height * static_cast<double>(o.text.size()) * 2, o.height},
                   diags)) {
    return false;
  }
  for (std::size_t i = 0; i < o.text.size(); ++i) {
    const char c = o.text[i];
    if (c < ' ' || c > '~' || font.glyph(c) == nullptr) {
      return fail(diags, core::Code::TextNotInFont,
                  fmt::format("character {} of the text (byte 0x{:02X}) has no glyph in font {}; "
                              "the fonts draw printable ASCII, from space to '~'",
                              i + 1, static_cast<unsigned char>(c), font.name));
    }
  }
  const Span cap = cap_span(font);
  if (!(cap.hi > cap.lo)) {
    return fail(diags, core::Code::FontUnreadable,
                fmt::format("font {} has no strokes to size the text by", font.name));
  }
  const double scale = o.height / (cap.hi - cap.lo);
  double cursor = o.at.x;
  for (const char c : o.text) {
    const HersheyGlyph& g = *font.glyph(c);
    for (const auto& stroke : g.strokes) {
      std::vector<Vec2> out;
      out.reserve(stroke.size());
      for (const Vec2& p : stroke) {
        out.push_back({cursor + (p.x - g.left) * scale, o.at.y + (p.y - cap.lo) * scale});
      }
      strokes.push_back(std::move(out));
    }
    cursor += (g.right - g.left) * scale;
  }
  return true;
}

bool generate_engrave(const HersheyFont& font, const EngraveOptions& o, canon::Sink& sink,
                      core::DiagnosticSink& diags) {
  bool ok = check_cutting(o.cut, diags);
  ok = check_range("the depth (--depth)", o.depth, kLength, diags) && ok;
  ok = check_range("the text height (--height)", o.height, kLength, diags) && ok;
  std::vector<std::vector<Vec2>> strokes;
  if (!ok || !layout_text(font, o, strokes, diags)) return false;
  double moves = 10;
  for (const auto& stroke : strokes)
    moves += static_cast<double>(stroke.size()) + 2;
  if (!check_work("the engraving", moves, o.cut.max_moves, "engrave less text at a time", diags)) {
    return false;
  }
  ProgramWriter w(sink, o.cut);
  // The text itself stays out of the comment: a parenthesis in it would end
  // a G-code comment early.
  w.begin(fmt::format("usina gen engrave: {} characters, {:g} mm high", o.text.size(), o.height));
  for (const auto& stroke : strokes) {
    w.rapid_over(stroke.front());
    w.plunge(-o.depth);
    for (std::size_t i = 1; i < stroke.size(); ++i)
      w.feed({stroke[i].x, stroke[i].y, -o.depth});
  }
  w.end();
  return true;
}

}  // namespace usina::cam
