#include "cam/hershey.hpp"

#include <gtest/gtest.h>

#include "cam/engrave.hpp"
#include "cam_test_util.hpp"

namespace usina::cam {
namespace {

using testing::count_code;

// Two glyphs written by hand in the .jhf layout: a space (bounds only) and
// "!" as rowmans.jhf has it: bounds M W (-5, 5), a stroke (0,-12)-(0,2), pen
// up, a dot stroke of four points. The second record wraps over two lines.
constexpr const char* kTwoGlyphs =
    "  699  1JZ\n"
    "  714  9MWRFRT RRYQZR[SZRY\n";
constexpr const char* kWrapped =
    "  699  1JZ\n"
    "  714  9MWRFRT RRY\n"
    "QZR[SZRY\n";

TEST(Hershey, ParsesBoundsStrokesAndPenUp) {
  core::DiagnosticList d;
  for (const char* text : {kTwoGlyphs, kWrapped}) {
    const auto font = parse_hershey(text, "t", d);
    ASSERT_TRUE(font) << text;
    ASSERT_EQ(font->glyphs.size(), 2u);
    const HersheyGlyph* bang = font->glyph('!');
    ASSERT_TRUE(bang);
    EXPECT_EQ(bang->left, -5);
    EXPECT_EQ(bang->right, 5);
    ASSERT_EQ(bang->strokes.size(), 2u);
    EXPECT_EQ(bang->strokes[0][0], (Vec2{0, 12}));  // Y flipped: up is positive
    EXPECT_EQ(bang->strokes[0][1], (Vec2{0, -2}));
    EXPECT_EQ(bang->strokes[1].size(), 5u);
    EXPECT_EQ(font->glyph('"'), nullptr);
  }
  EXPECT_TRUE(d.all().empty());
}

TEST(Hershey, BrokenFontsAreErrors) {
  core::DiagnosticList d;
  EXPECT_FALSE(parse_hershey("", "empty", d));
  EXPECT_FALSE(parse_hershey("  714  9MWRF\n", "short", d));
  EXPECT_FALSE(parse_hershey("  714  xMWRF\n", "count", d));
  EXPECT_FALSE(read_hershey("/no/such/font.jhf", d));
  EXPECT_EQ(count_code(d, core::Code::FontUnreadable), 4);
  EXPECT_NE(d.all()[1].message.find("short:1:"), std::string::npos);
}

TEST(Hershey, FontNamesAndFiles) {
  EXPECT_EQ(hershey_file("rowmans"), "/usr/share/hershey-fonts/rowmans.jhf");
  EXPECT_EQ(hershey_file("my/font.jhf"), "my/font.jhf");
  EXPECT_EQ(hershey_file("futural", "/tmp"), "/tmp/futural.jhf");
}

TEST(Hershey, InstalledRowmansHasPrintableAscii) {
  core::DiagnosticList d;
  const auto font = read_hershey(hershey_file("rowmans"), d);
  ASSERT_TRUE(font) << "hershey-fonts-data is in scripts/setup.sh";
  EXPECT_EQ(font->glyphs.size(), 96u);  // 32 to 127 (the last one DEL's, never engraved)
  ASSERT_TRUE(font->glyph('~'));
  EXPECT_EQ(font->glyph('A')->strokes.size(), 3u);  // two slants and the bar
}

TEST(Engrave, CapitalHeightIsTheHeightAndLettersAdvance) {
  core::DiagnosticList d;
  const auto font = read_hershey(hershey_file("rowmans"), d);
  ASSERT_TRUE(font);
  EngraveOptions o;
  o.text = "HH";
  o.height = 7;
  o.at = {100, 50};
  std::vector<std::vector<Vec2>> strokes;
  ASSERT_TRUE(layout_text(*font, o, strokes, d));
  ASSERT_EQ(strokes.size(), 6u);  // an H is three strokes
  double lo = 1e9, hi = -1e9;
  for (const auto& s : strokes) {
    for (const Vec2& p : s)
      lo = std::min(lo, p.y), hi = std::max(hi, p.y);
  }
  EXPECT_NEAR(lo, 50, 1e-12);  // on the baseline
  EXPECT_NEAR(hi, 57, 1e-12);
  // The second H is the first moved by the glyph's advance.
  const double advance = strokes[3][0].x - strokes[0][0].x;
  const HersheyGlyph& h = *font->glyph('H');
  EXPECT_NEAR(advance, (h.right - h.left) * 7.0 / 21.0, 1e-12);  // rowmans' H is 21 units
}

TEST(Engrave, StrokesAtTheDepthOneRetractEach) {
  core::DiagnosticList d;
  const auto font = read_hershey(hershey_file("rowmans"), d);
  ASSERT_TRUE(font);
  EngraveOptions o;
  o.text = "L";
  o.depth = 0.3;
  canon::Toolpath tp;
  ASSERT_TRUE(generate_engrave(*font, o, tp, d));
  int plunges = 0;
  for (const auto& f : testing::ops_of<canon::Feed>(tp)) {
    EXPECT_EQ(f.to.z, -0.3);
    plunges += f.f == o.cut.plunge_feed ? 1 : 0;
  }
  EXPECT_EQ(plunges, 2);  // L: the upright and the foot
}

TEST(Engrave, CharacterOutsideTheFontIsAnError) {
  core::DiagnosticList d;
  const auto font = parse_hershey(kTwoGlyphs, "two", d);
  ASSERT_TRUE(font);
  EngraveOptions o;
  o.text = "!A";
  canon::Toolpath tp;
  EXPECT_FALSE(generate_engrave(*font, o, tp, d));
  o.text = "S\xC3\xA3o";
  EXPECT_FALSE(generate_engrave(*font, o, tp, d));
  o.text = "";
  EXPECT_FALSE(generate_engrave(*font, o, tp, d));
  EXPECT_EQ(count_code(d, core::Code::TextNotInFont), 3);
  EXPECT_NE(d.all()[0].message.find("character 2"), std::string::npos);
  EXPECT_EQ(tp.size(), 0u);
}

TEST(Engrave, TextTooLongOrTooFarIsAnError) {
  core::DiagnosticList d;
  const auto font = parse_hershey(kTwoGlyphs, "two", d);
  ASSERT_TRUE(font);
  EngraveOptions o;
  o.text = std::string(20000, '!');
  canon::Toolpath tp;
  EXPECT_FALSE(generate_engrave(*font, o, tp, d));
  o.text = "!!";
  o.at = {1e9, 0};
  EXPECT_FALSE(generate_engrave(*font, o, tp, d));
  EXPECT_EQ(count_code(d, core::Code::GenBadValue), 2);
}

TEST(Engrave, BadHeightOrDepthIsAnError) {
  core::DiagnosticList d;
  const auto font = parse_hershey(kTwoGlyphs, "two", d);
  ASSERT_TRUE(font);
  EngraveOptions o;
  o.text = "!";
  o.height = 0;
  o.depth = -1;
  canon::Toolpath tp;
  EXPECT_FALSE(generate_engrave(*font, o, tp, d));
  EXPECT_EQ(count_code(d, core::Code::GenBadValue), 2);
}

}  // namespace
}  // namespace usina::cam
