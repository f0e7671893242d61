// The DXF reader on input dxflib cannot take: every input ends, with paths or
// with a diagnostic naming the file and the line (issue 11, "Time and size").
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "cam/dxf_groups.hpp"
#include "cam/dxf_import.hpp"

namespace usina::cam {
namespace {

struct Read {
  std::optional<std::vector<Path>> paths;
  core::DiagnosticList diags;

  bool has(core::Code code) const {
    return std::ranges::any_of(diags.all(), [&](const auto& d) { return d.code == code; });
  }

  // The messages, one a line, for failure output and for searching.
  std::string text() const {
    std::string out;
    for (const auto& d : diags.all())
      out += std::string(core::code_name(d.code)) + ": " + d.message + "\n";
    return out;
  }

  bool says(const std::string& part) const { return text().find(part) != std::string::npos; }
};

Read read(const std::string& text, const DxfOptions& options = {}) {
  Read r;
  std::istringstream in(text);
  r.paths = read_dxf(in, "t.dxf", options, r.diags);
  return r;
}

Read read_file(const std::string& file) {
  Read r;
  r.paths = read_dxf(file, {}, r.diags);
  return r;
}

std::string pairs(std::initializer_list<std::pair<int, std::string>> groups) {
  std::string out;
  for (const auto& [code, value] : groups)
    out += std::to_string(code) + "\n" + value + "\n";
  return out;
}

std::string entities(const std::string& body) {
  return "0\nSECTION\n2\nENTITIES\n" + body + "0\nENDSEC\n0\nEOF\n";
}

const std::string kLine =
    pairs({{0, "LINE"}, {8, "CUT"}, {10, "0"}, {20, "0"}, {11, "10"}, {21, "5"}});

// A line whose layer name (line 8 of the file) is `length` characters.
std::string long_layer_line(std::size_t length) {
  return entities(pairs(
      {{0, "LINE"}, {8, std::string(length, 'A')}, {10, "0"}, {20, "0"}, {11, "1"}, {21, "1"}}));
}

// A scratch file removed at the end of the test.
class ScratchFile {
 public:
  explicit ScratchFile(const std::string& bytes)
      : path_((std::filesystem::temp_directory_path() /
               ("usina_dxf_reader_" + std::to_string(::getpid()) + "_" + std::to_string(++made_)))
                  .string()) {
    std::ofstream(path_, std::ios::binary) << bytes;
  }

  ~ScratchFile() {
    std::error_code ec;
    std::filesystem::remove(path_, ec);
  }

  const std::string& path() const { return path_; }

 private:
  static inline int made_ = 0;
  std::string path_;
};

// --- lines dxflib's reader never finished ------------------------------------

TEST(DxfReader, LineOf1024CharactersIsAnErrorNamingTheLine) {
  const Read r = read(long_layer_line(1024));
  EXPECT_FALSE(r.paths);
  EXPECT_TRUE(r.has(core::Code::DxfMalformed)) << r.text();
  EXPECT_TRUE(r.says("t.dxf:8:")) << r.text();
  EXPECT_TRUE(r.says("1024 characters")) << r.text();
}

TEST(DxfReader, LineOf1023CharactersIsRead) {
  const Read r = read(long_layer_line(kMaxDxfLineLength));
  ASSERT_TRUE(r.paths) << r.text();
  EXPECT_EQ(r.paths->size(), 1u);
}

TEST(DxfReader, MegabyteLineIsAnErrorNotAHang) {
  const Read r = read(long_layer_line(1 << 20));
  EXPECT_FALSE(r.paths);
  EXPECT_TRUE(r.has(core::Code::DxfMalformed)) << r.text();
}

TEST(DxfReader, LongCommentIsSkipped) {
  const Read r = read(pairs({{999, std::string(100'000, 'c')}}) + entities(kLine));
  ASSERT_TRUE(r.paths) << r.text();
  EXPECT_EQ(r.paths->size(), 1u);
}

TEST(DxfReader, BytesWithoutLineEndsAreAnErrorNotAHang) {
  std::string junk;
  unsigned state = 12345;
  for (int i = 0; i < 20'000; ++i) {
    state = state * 1103515245u + 12345u;
    const auto c = static_cast<char>(state >> 24);
    junk.push_back(c == '\n' || c == '\r' || c == '\0' ? 'x' : c);
  }
  const Read r = read(junk);
  EXPECT_FALSE(r.paths);
  EXPECT_TRUE(r.has(core::Code::DxfMalformed)) << r.text();
  EXPECT_TRUE(r.says("t.dxf:1:")) << r.text();
  EXPECT_FALSE(r.says("\x1b")) << "a control character reached the message";
}

// --- what is not a drawing file ------------------------------------------------

TEST(DxfReader, FolderIsUnreadable) {
  const Read r = read_file(std::filesystem::temp_directory_path().string());
  EXPECT_FALSE(r.paths);
  EXPECT_TRUE(r.has(core::Code::DxfUnreadable)) << r.text();
  EXPECT_TRUE(r.says("a folder")) << r.text();
}

TEST(DxfReader, EndlessDeviceIsTooBig) {
  if (!std::filesystem::is_character_file("/dev/zero")) GTEST_SKIP() << "/dev/zero is no device";
  const Read r = read_file("/dev/zero");
  EXPECT_FALSE(r.paths);
  EXPECT_TRUE(r.has(core::Code::DxfUnreadable)) << r.text();
  EXPECT_TRUE(r.says("larger than 64 MiB")) << r.text();
}

TEST(DxfReader, EmptyFileIsUnreadable) {
  const ScratchFile f("");
  const Read r = read_file(f.path());
  EXPECT_FALSE(r.paths);
  EXPECT_TRUE(r.has(core::Code::DxfUnreadable)) << r.text();
  EXPECT_TRUE(r.says("empty")) << r.text();
}

TEST(DxfReader, MissingFileSaysWhy) {
  const Read r = read_file("/no/such/drawing.dxf");
  EXPECT_TRUE(r.has(core::Code::DxfUnreadable));
  EXPECT_TRUE(r.says("No such file")) << r.text();
}

TEST(DxfReader, RegularFileIsRead) {
  const ScratchFile f(entities(kLine));
  const Read r = read_file(f.path());
  ASSERT_TRUE(r.paths) << r.text();
  EXPECT_EQ(r.paths->size(), 1u);
}

TEST(DxfReader, NulByteIsNotText) {
  const Read r = read(std::string("0\nSECTION\n2\nENT\0ITIES\n", 22));
  EXPECT_FALSE(r.paths);
  EXPECT_TRUE(r.has(core::Code::DxfUnreadable)) << r.text();
  EXPECT_TRUE(r.says("t.dxf:4: a NUL byte")) << r.text();
}

TEST(DxfReader, BinaryDxfIsNamed) {
  const Read r = read(std::string("AutoCAD Binary DXF\r\n\x1a\0", 22));
  EXPECT_TRUE(r.has(core::Code::DxfUnreadable));
  EXPECT_TRUE(r.says("binary DXF")) << r.text();
}

// --- lines that are not groups -------------------------------------------------

TEST(DxfReader, FileWithoutEofIsCutShort) {
  const Read r = read("0\nSECTION\n2\nENTITIES\n" + kLine);
  EXPECT_FALSE(r.paths);
  EXPECT_TRUE(r.has(core::Code::DxfMalformed));
  EXPECT_TRUE(r.says("cut short")) << r.text();
}

TEST(DxfReader, CodeWithoutValueIsCutShort) {
  const Read r = read("0\nSECTION\n2\n");
  EXPECT_TRUE(r.says("t.dxf:3: group 2 has no value line")) << r.text();
}

TEST(DxfReader, CodeThatIsNoNumberNamesTheLine) {
  const Read r = read(entities(kLine + "abc\nx\n"));
  EXPECT_TRUE(r.has(core::Code::DxfMalformed));
  EXPECT_TRUE(r.says("t.dxf:17: \"abc\" is not a group code")) << r.text();
}

TEST(DxfReader, HeaderVariableWithoutDollarIsMalformed) {
  // dxflib would read the variable "LINE" as a line.
  const Read r =
      read(pairs({{0, "SECTION"}, {2, "HEADER"}, {9, "LINE"}, {10, "5"}, {0, "ENDSEC"}}) +
           entities(kLine));
  EXPECT_TRUE(r.has(core::Code::DxfMalformed));
  EXPECT_TRUE(r.says("t.dxf:6: a header variable named \"LINE\"")) << r.text();
}

TEST(DxfReader, ShortDxflibCommentIsNotACrash) {
  // dxflib reads its version from a "dxflib" comment with substr(7), which
  // throws on these six letters; comments no longer reach it.
  const Read r = read(pairs({{999, "dxflib"}}) + entities(kLine));
  ASSERT_TRUE(r.paths) << r.text();
}

TEST(DxfReader, LineEndsOfEveryKindAndAByteOrderMark) {
  const std::string lf = entities(kLine);
  std::string crlf;
  std::string cr;
  for (const char c : lf) {
    crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
    cr += c == '\n' ? '\r' : c;
  }
  for (const std::string& text : {lf, crlf, cr, "\xEF\xBB\xBF" + lf, "  " + lf}) {
    const Read r = read(text);
    ASSERT_TRUE(r.paths) << r.text();
    EXPECT_EQ(r.paths->size(), 1u);
  }
}

// --- counts dxflib sizes its arrays by ----------------------------------------

std::string lwpolyline(const std::string& count, int vertices) {
  std::string out = pairs({{0, "LWPOLYLINE"}, {8, "0"}});
  if (!count.empty()) out += pairs({{90, count}});
  for (int i = 0; i < vertices; ++i)
    out += pairs({{10, std::to_string(i)}, {20, std::to_string(i % 2)}});
  return out;
}

TEST(DxfReader, VertexCountThatIsNotTheVerticesIsMalformed) {
  // dxflib allocated 4 × count doubles: 2,000,000,000 asks for 64 GB, and
  // 1,073,741,825 overflows int to 4 doubles written 1,073,741,825 times.
  for (const char* count : {"3", "1", "2000000000", "1073741825"}) {
    const Read r = read(entities(lwpolyline(count, 2)));
    EXPECT_FALSE(r.paths) << count;
    EXPECT_TRUE(r.has(core::Code::DxfMalformed)) << count << "\n" << r.text();
    EXPECT_TRUE(r.says("t.dxf:5: the LWPOLYLINE declares " + std::string(count) + " vertices"))
        << r.text();
  }
  for (const char* count : {"-1", "4x", "", "99999999999999999999"}) {
    const Read r = read(entities(pairs({{0, "LWPOLYLINE"}, {8, "0"}, {90, count}})));
    EXPECT_TRUE(r.says("t.dxf:9: the LWPOLYLINE's count of vertices (group 90) is")) << r.text();
  }
  const Read ok = read(entities(lwpolyline("2", 2)));
  ASSERT_TRUE(ok.paths) << ok.text();
}

TEST(DxfReader, VertexCountAfterTheVerticesIsMalformed) {
  const Read r = read(entities(lwpolyline("", 2) + pairs({{90, "2"}})));
  EXPECT_TRUE(r.says("comes after 2 of them")) << r.text();
}

TEST(DxfReader, SecondVertexCountIsMalformed) {
  const Read r = read(entities(lwpolyline("0", 0) + pairs({{90, "0"}})));
  EXPECT_TRUE(r.says("a second group 90")) << r.text();
}

TEST(DxfReader, BulgeBeforeTheFirstVertexIsMalformed) {
  // dxflib writes it before its vertex array.
  const Read r = read(entities(pairs({{0, "LWPOLYLINE"}, {8, "0"}, {90, "2"}, {42, "1"}}) +
                               pairs({{10, "0"}, {20, "0"}, {10, "5"}, {20, "0"}})));
  EXPECT_FALSE(r.paths);
  EXPECT_TRUE(r.says("t.dxf:11: the LWPOLYLINE has a group 42 before its first group 10"))
      << r.text();
}

TEST(DxfReader, PolylineWithoutCountHasNoVerticesOfTheOneBefore) {
  // dxflib kept the previous LWPOLYLINE's vertices for one that declares none.
  const Read r = read(entities(lwpolyline("3", 3) + lwpolyline("", 0)));
  ASSERT_TRUE(r.paths) << r.text();
  EXPECT_EQ(r.paths->size(), 1u);
  EXPECT_TRUE(r.says("0 vertex")) << r.text();
}

std::string spline(const std::string& counts, int knots, int points, int weights, int fit) {
  std::string out = pairs({{0, "SPLINE"}, {8, "0"}, {70, "8"}, {71, "1"}}) + counts;
  for (int i = 0; i < knots; ++i)
    out += pairs({{40, std::to_string(i < 2 ? 0 : i >= knots - 2 ? knots - 3 : i - 1)}});
  for (int i = 0; i < weights; ++i)
    out += pairs({{41, "1"}});
  for (int i = 0; i < points; ++i)
    out += pairs({{10, std::to_string(i)}, {20, std::to_string(i % 2)}, {30, "0"}});
  for (int i = 0; i < fit; ++i)
    out += pairs({{11, std::to_string(i)}, {21, "0"}, {31, "0"}});
  return out;
}

TEST(DxfReader, SplineCountsMatchTheirItems) {
  const std::string good = pairs({{72, "5"}, {73, "3"}, {74, "0"}});
  const Read ok = read(entities(spline(good, 5, 3, 0, 0)));
  ASSERT_TRUE(ok.paths) << ok.text();
  EXPECT_FALSE(ok.diags.has_errors());
  const Read weighted = read(entities(spline(good, 5, 3, 3, 0)));
  ASSERT_TRUE(weighted.paths) << weighted.text();

  EXPECT_TRUE(
      read(entities(spline(good, 4, 3, 0, 0))).says("declares 5 knots (group 72) but lists 4"));
  EXPECT_TRUE(read(entities(spline(good, 5, 4, 0, 0))).says("declares 3 control points"));
  EXPECT_TRUE(read(entities(spline(good, 5, 3, 2, 0))).says("declares 3 weights"));
  EXPECT_TRUE(read(entities(spline(good, 5, 3, 0, 1))).says("declares 0 fit points"));
  EXPECT_TRUE(read(entities(spline(pairs({{72, "5"}, {73, "1431655766"}}), 5, 3, 0, 0)))
                  .has(core::Code::DxfMalformed));
}

TEST(DxfReader, SplineItemsBeforeTheirCountAreMalformed) {
  const Read r =
      read(entities(spline("", 0, 0, 1, 0) + pairs({{72, "0"}, {73, "1"}, {10, "0"}, {20, "0"}})));
  EXPECT_TRUE(r.says("count of weights (group 73) comes after 1 of them")) << r.text();
}

TEST(DxfReader, SplineWithoutCountsHasNoPointsOfTheOneBefore) {
  const std::string good = pairs({{72, "5"}, {73, "3"}, {74, "0"}});
  const Read r = read(entities(spline(good, 5, 3, 0, 0) + spline("", 0, 0, 0, 0)));
  ASSERT_TRUE(r.paths) << r.text();
  EXPECT_EQ(r.paths->size(), 1u);
  EXPECT_TRUE(r.says("neither control points nor fit points")) << r.text();
}

TEST(DxfReader, LeaderVertexCountIsChecked) {
  const Read r = read(entities(
      pairs({{0, "LEADER"}, {8, "0"}, {76, "100000000"}, {10, "0"}, {20, "0"}, {30, "0"}}) +
      kLine));
  EXPECT_TRUE(r.says("the LEADER declares 100000000 vertices (group 76) but lists 1")) << r.text();
}

// --- splines whose approximation would not end in reasonable time ------------

std::string zigzag_spline(int points, int degree, double amplitude, const std::string& weight) {
  const int knots = points + degree + 1;
  std::string out = pairs({{0, "SPLINE"},
                           {8, "0"},
                           {70, "8"},
                           {71, std::to_string(degree)},
                           {72, std::to_string(knots)},
                           {73, std::to_string(points)},
                           {74, "0"}});
  for (int i = 0; i < knots; ++i) {
    const int k = i <= degree ? 0 : i >= points ? points - degree : i - degree;
    out += pairs({{40, std::to_string(k)}});
  }
  for (int i = 0; i < points; ++i)
    out += pairs({{41, i % 2 != 0 ? weight : "1"}});
  for (int i = 0; i < points; ++i) {
    out += pairs({{10, std::to_string(i)},
                  {20, std::to_string(i % 2 != 0 ? amplitude : -amplitude)},
                  {30, "0"}});
  }
  return out;
}

TEST(DxfReader, SplineTooLargeToApproximateIsLeftOut) {
  // 20,000 control points of degree 3 took 13 s (Bézier decomposition).
  const Read r = read(entities(zigzag_spline(20'000, 3, 10, "1") + kLine));
  ASSERT_TRUE(r.paths) << r.text();
  EXPECT_EQ(r.paths->size(), 1u);
  EXPECT_TRUE(r.says("SPLINE of degree 3 with 20000 control points is too large")) << r.text();
}

TEST(DxfReader, SplineWorkIsBoundedForTheWholeDrawing) {
  const std::string big = zigzag_spline(2'000, 3, 10, "1");
  const Read one = read(entities(big));
  ASSERT_TRUE(one.paths) << one.text();
  const Read two = read(entities(big + big));
  ASSERT_TRUE(two.paths) << two.text();
  EXPECT_EQ(two.paths->size(), 1u);
  EXPECT_TRUE(two.says("too large")) << two.text();
}

TEST(DxfReader, SplineControlPointsOutOfRangeOrWeightsFarApartAreLeftOut) {
  const Read far = read(entities(zigzag_spline(8, 3, 1e6, "1") + kLine));
  EXPECT_TRUE(far.says("a control point is not a number or beyond")) << far.text();
  const Read weights = read(entities(zigzag_spline(8, 3, 10, "1e7") + kLine));
  EXPECT_TRUE(weights.says("weights from 1 to 1e+07")) << weights.text();
  EXPECT_EQ(weights.paths->size(), 1u);
}

TEST(DxfReader, SplineToleranceFollowsItsExtent) {
  // 200 m across: chords within 0.2 mm (1e-6 of the extent), not 0.1 µm
  // (about 120 segments; 3,950 with the 0.1 µm floor alone).
  DxfOptions fine;
  fine.spline_tolerance = 1e-9;
  const Read r = read(entities(zigzag_spline(40, 3, 100'000, "1")), fine);
  ASSERT_TRUE(r.paths) << r.text();
  EXPECT_LT((*r.paths)[0].segs.size(), 1000u);
}

}  // namespace
}  // namespace usina::cam
