// Hershey's single-stroke fonts in the .jhf format of the hershey-fonts
// package (public domain; /usr/share/hershey-fonts/*.jhf on Debian).
//
// A .jhf glyph record: columns 1-5 the glyph's Hershey number, 6-8 the count
// of coordinate pairs (the bounds pair included), then that many pairs of
// characters, each coordinate its character's code minus 'R'. The first pair
// is the glyph's left and right bounds; " R" lifts the pen. Y grows downward.
// Records may wrap over several lines. In the ASCII fonts the n-th record is
// the glyph of character 32 + n.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/diagnostic.hpp"
#include "core/vec3.hpp"

namespace usina::cam {

struct HersheyGlyph {
  int left = 0;
  int right = 0;
  std::vector<std::vector<core::Vec2>> strokes;  // font units, Y up
};

struct HersheyFont {
  std::string name;
  std::vector<HersheyGlyph> glyphs;  // glyphs[c - 32] draws character c

  // The glyph of `c`, or null when the font has none for it.
  const HersheyGlyph* glyph(char c) const;
};

// Where the font named `font` is: the name itself when it has a '/' or ends
// in ".jhf", otherwise `dir`/NAME.jhf.
std::string hershey_file(const std::string& font,
                         const std::string& dir = "/usr/share/hershey-fonts");

// The font of a .jhf text; nullopt after E_FONT_UNREADABLE.
std::optional<HersheyFont> parse_hershey(std::string_view text, const std::string& name,
                                         core::DiagnosticSink& diags);

std::optional<HersheyFont> read_hershey(const std::string& file, core::DiagnosticSink& diags);

}  // namespace usina::cam
