#include "canon/trace_writer.hpp"

#include <stdio.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "canon/op.hpp"

namespace usina::canon {
namespace {

core::SourceLoc at(std::uint32_t line, std::uint32_t col) {
  return {0, line, col, 0, 0};
}

// --- to_jsonl: one op kind each, field names of spec/trace.md ---------------

TEST(TraceJsonl, Traverse) {
  EXPECT_EQ(to_jsonl({Traverse{{1, 2, 3}}, at(4, 2)}),
            R"({"op":"traverse","src":[4,2],"to":[1,2,3]})");
}

TEST(TraceJsonl, FeedWithRate) {
  EXPECT_EQ(to_jsonl({Feed{{1.5, -2, 0}, 100.25}, at(3, 1)}),
            R"({"op":"feed","src":[3,1],"to":[1.5,-2,0],"f":100.25})");
}

TEST(TraceJsonl, FeedWithoutRateWritesNull) {
  // Inverse-time or per-revolution feed: the rate is not in mm/min.
  EXPECT_EQ(to_jsonl({Feed{{0, 0, 1}, std::nullopt}, at(9, 5)}),
            R"({"op":"feed","src":[9,5],"to":[0,0,1],"f":null})");
}

TEST(TraceJsonl, Arc) {
  EXPECT_EQ(to_jsonl({Arc{{10, 0, -1}, {5, 0, 0}, {0, 0, 1}, -2, 300}, at(7, 3)}),
            R"({"op":"arc","src":[7,3],"to":[10,0,-1],"center":[5,0,0],"normal":[0,0,1],)"
            R"("turn":-2,"f":300})");
}

TEST(TraceJsonl, ArcWithoutRateWritesNull) {
  EXPECT_EQ(to_jsonl({Arc{{1, 0, 0}, {0, 0, 0}, {0, 1, 0}, 1, std::nullopt}, at(1, 1)}),
            R"({"op":"arc","src":[1,1],"to":[1,0,0],"center":[0,0,0],"normal":[0,1,0],)"
            R"("turn":1,"f":null})");
}

TEST(TraceJsonl, SplineListsItsPointsEndingAtTo) {
  EXPECT_EQ(to_jsonl({Spline{{2, 0, 0}, {{1, 0.5, 0}, {2, 0, 0}}, 60}, at(4, 1)}),
            R"({"op":"spline","src":[4,1],"to":[2,0,0],"points":[[1,0.5,0],[2,0,0]],"f":60})");
  EXPECT_EQ(to_jsonl({Spline{{2, 0, 0}, {{2, 0, 0}}, std::nullopt}, at(4, 1)}),
            R"({"op":"spline","src":[4,1],"to":[2,0,0],"points":[[2,0,0]],"f":null})");
}

TEST(TraceJsonl, Probe) {
  EXPECT_EQ(to_jsonl({Probe{{0, 0, -5}}, at(2, 1)}), R"({"op":"probe","src":[2,1],"to":[0,0,-5]})");
}

TEST(TraceJsonl, Dwell) {
  EXPECT_EQ(to_jsonl({Dwell{0.5}, at(2, 1)}), R"({"op":"dwell","src":[2,1],"s":0.5})");
}

TEST(TraceJsonl, ToolWithDiameter) {
  EXPECT_EQ(to_jsonl({ToolChange{3, 6.35}, at(5, 1)}),
            R"({"op":"tool","src":[5,1],"tool":3,"diameter":6.35})");
}

TEST(TraceJsonl, ToolWithoutDiameterWritesNull) {
  EXPECT_EQ(to_jsonl({ToolChange{12, std::nullopt}, at(5, 1)}),
            R"({"op":"tool","src":[5,1],"tool":12,"diameter":null})");
}

TEST(TraceJsonl, SpindleEachDirection) {
  EXPECT_EQ(to_jsonl({Spindle{1200, SpindleDir::Cw}, at(1, 1)}),
            R"({"op":"spindle","src":[1,1],"rpm":1200,"dir":"cw"})");
  EXPECT_EQ(to_jsonl({Spindle{800.5, SpindleDir::Ccw}, at(1, 1)}),
            R"({"op":"spindle","src":[1,1],"rpm":800.5,"dir":"ccw"})");
  EXPECT_EQ(to_jsonl({Spindle{1200, SpindleDir::Off}, at(1, 1)}),
            R"({"op":"spindle","src":[1,1],"rpm":1200,"dir":"off"})");
}

TEST(TraceJsonl, CoolantBooleans) {
  EXPECT_EQ(to_jsonl({Coolant{true, false}, at(6, 1)}),
            R"({"op":"coolant","src":[6,1],"mist":true,"flood":false})");
  EXPECT_EQ(to_jsonl({Coolant{false, true}, at(6, 1)}),
            R"({"op":"coolant","src":[6,1],"mist":false,"flood":true})");
}

TEST(TraceJsonl, Hole) {
  EXPECT_EQ(to_jsonl({Hole{{10, 20, 2}, 8.5, 12}, at(8, 1)}),
            R"({"op":"hole","src":[8,1],"at":[10,20,2],"diameter":8.5,"depth":12})");
  // A generator's hole with its own feed rate says it.
  Hole bored{{10, 20, 2}, 10, 12, HoleCycle::Bore};
  bored.f = 9.5;
  EXPECT_EQ(
      to_jsonl({bored, at(8, 1)}),
      R"({"op":"hole","src":[8,1],"at":[10,20,2],"diameter":10,"depth":12,"cycle":"bore","f":9.5})");
}

TEST(TraceJsonl, PocketOutlineWithLineAndArc) {
  Pocket p;
  p.outline.start = {0, 0};
  p.outline.segs.push_back({{10, 0}, std::nullopt, 0});
  p.outline.segs.push_back({{0, 0}, Vec2{5, 0}, -1});
  p.depth = 3;
  EXPECT_EQ(to_jsonl({p, at(2, 1)}),
            R"({"op":"pocket","src":[2,1],"outline":{"start":[0,0],"segs":[{"to":[10,0]},)"
            R"({"to":[0,0],"center":[5,0],"turn":-1}]},"depth":3})");
}

TEST(TraceJsonl, PocketWithNoSegments) {
  Pocket p;
  p.outline.start = {1, 2};
  EXPECT_EQ(to_jsonl({p, at(2, 1)}),
            R"({"op":"pocket","src":[2,1],"outline":{"start":[1,2],"segs":[]},"depth":0})");
}

TEST(TraceJsonl, Comment) {
  EXPECT_EQ(to_jsonl({Comment{"rough pass"}, at(1, 4)}),
            R"({"op":"comment","src":[1,4],"text":"rough pass"})");
}

TEST(TraceJsonl, End) {
  EXPECT_EQ(to_jsonl({ProgramEnd{}, at(12, 1)}), R"({"op":"end","src":[12,1]})");
}

// --- optional fields and number forms --------------------------------------

TEST(TraceJsonl, AbcOnlyWhenARotaryAxisIsNonZero) {
  EXPECT_EQ(to_jsonl({Traverse{{1, 2, 3}, {0, 0, 0}}, at(1, 1)}),
            R"({"op":"traverse","src":[1,1],"to":[1,2,3]})");
  EXPECT_EQ(to_jsonl({Traverse{{1, 2, 3}, {0, 90, 0}}, at(1, 1)}),
            R"({"op":"traverse","src":[1,1],"to":[1,2,3],"abc":[0,90,0]})");
  EXPECT_EQ(to_jsonl({Feed{{0, 0, 0}, 50, {0, 0, -45}}, at(1, 1)}),
            R"({"op":"feed","src":[1,1],"to":[0,0,0],"f":50,"abc":[0,0,-45]})");
  EXPECT_EQ(to_jsonl({Arc{{1, 0, 0}, {0, 0, 0}, {0, 0, 1}, 1, 10, {30, 0, 0}}, at(1, 1)}),
            R"({"op":"arc","src":[1,1],"to":[1,0,0],"center":[0,0,0],"normal":[0,0,1],)"
            R"("turn":1,"f":10,"abc":[30,0,0]})");
  EXPECT_EQ(to_jsonl({Probe{{0, 0, 0}, {1, 0, 0}}, at(1, 1)}),
            R"({"op":"probe","src":[1,1],"to":[0,0,0],"abc":[1,0,0]})");
}

TEST(TraceJsonl, NegativeZeroIsWrittenAsZero) {
  EXPECT_EQ(to_jsonl({Traverse{{-0.0, 0.0, -0.0}}, at(1, 1)}),
            R"({"op":"traverse","src":[1,1],"to":[0,0,0]})");
  EXPECT_EQ(to_jsonl({Feed{{0, 0, 0}, -0.0}, at(1, 1)}),
            R"({"op":"feed","src":[1,1],"to":[0,0,0],"f":0})");
  EXPECT_EQ(to_jsonl({Traverse{{0, 0, 0}, {-0.0, 5, 0}}, at(1, 1)}),
            R"({"op":"traverse","src":[1,1],"to":[0,0,0],"abc":[0,5,0]})");
}

TEST(TraceJsonl, NumbersRoundTrip) {
  const double third = 1.0 / 3.0;
  const double big = 123456789.123456789;
  const double tiny = 1e-7;
  const std::string line = to_jsonl({Traverse{{third, big, tiny}}, at(1, 1)});
  const std::size_t open = line.find("\"to\":[") + 6;
  const char* p = line.c_str() + open;
  char* end = nullptr;
  EXPECT_EQ(std::strtod(p, &end), third);
  ASSERT_EQ(*end, ',');
  EXPECT_EQ(std::strtod(end + 1, &end), big);
  ASSERT_EQ(*end, ',');
  EXPECT_EQ(std::strtod(end + 1, &end), tiny);
  EXPECT_EQ(*end, ']');
}

TEST(TraceJsonl, ShortestFormForSimpleDecimals) {
  EXPECT_EQ(to_jsonl({Dwell{0.1}, at(1, 1)}), R"({"op":"dwell","src":[1,1],"s":0.1})");
  EXPECT_EQ(to_jsonl({Dwell{25.4}, at(1, 1)}), R"({"op":"dwell","src":[1,1],"s":25.4})");
}

// The dwell's number as written: what follows "s":, up to the closing brace.
std::string dwell_text(double s) {
  const std::string line = to_jsonl({Dwell{s}, at(1, 1)});
  const std::size_t from = line.find("\"s\":") + 4;
  return line.substr(from, line.size() - 1 - from);
}

TEST(TraceJsonl, ShortDecimalsAtTheEdgesOfTheirFastPath) {
  EXPECT_EQ(dwell_text(-12.5), "-12.5");
  EXPECT_EQ(dwell_text(-0.000001), "-0.000001");
  EXPECT_EQ(dwell_text(0.000001), "0.000001");
  EXPECT_EQ(dwell_text(999999999.999999), "999999999.999999");
  EXPECT_EQ(dwell_text(-999999999.5), "-999999999.5");
  EXPECT_EQ(dwell_text(100), "100");
  EXPECT_EQ(dwell_text(1e9), "1000000000");   // past the fast path: fmt's shortest form
  EXPECT_EQ(dwell_text(0.0000005), "5e-07");  // not a whole number of millionths
  EXPECT_EQ(dwell_text(0.1 + 0.2), "0.30000000000000004");
}

// Any double, of any size and sign, reads back as itself.
TEST(TraceJsonl, EveryNumberReadsBackAsItself) {
  std::uint64_t state = 0x9E3779B97F4A7C15ULL;
  const auto next = [&state] {
    state ^= state << 13;
    state ^= state >> 7;
    state ^= state << 17;
    return state;
  };
  for (int i = 0; i < 200000; ++i) {
    const std::uint64_t r = next();
    double v = 0.0;
    switch (i % 3) {
    case 0: {  // a short decimal, as programs have
      v = static_cast<double>(static_cast<std::int64_t>(r % 2000000000001ULL) - 1000000000000LL) /
          std::pow(10.0, static_cast<double>(r >> 60));
      break;
    }
    case 1: v = (static_cast<double>(r >> 11) / 9007199254740992.0 - 0.5) * 2e9; break;
    default: std::memcpy(&v, &r, sizeof v);
    }
    if (!std::isfinite(v)) continue;
    const std::string text = dwell_text(v);
    char* end = nullptr;
    ASSERT_EQ(std::strtod(text.c_str(), &end), v) << text;
    ASSERT_EQ(*end, '\0') << text;
  }
}

// Whole numbers are written two digits at a time: every length, both
// signs, and the ends of an int.
TEST(TraceJsonl, WholeNumbersAtEveryLength) {
  std::vector<int> values = {0, std::numeric_limits<int>::max(), std::numeric_limits<int>::min()};
  for (long long p = 1; p <= 1000000000; p *= 10) {
    for (const long long v : {p - 1, p, p + 1, 2 * p - 1})
      values.insert(values.end(), {static_cast<int>(v), static_cast<int>(-v)});
  }
  for (const int v : values) {
    EXPECT_EQ(to_jsonl({ToolChange{v, std::nullopt}, at(1, 1)}),
              R"({"op":"tool","src":[1,1],"tool":)" + std::to_string(v) + R"(,"diameter":null})");
  }
  const core::SourceLoc far{0, 4294967295U, 100, 1, 0};
  EXPECT_EQ(to_jsonl({Dwell{1}, far}), R"({"op":"dwell","src":[4294967295,100],"s":1})");
}

// A line far longer than the room the writer makes at a time (a spline of
// 3,000 points, a long comment) comes out whole, and a number past the fast
// path in the middle of it (written by fmt) too.
TEST(TraceJsonl, LongLinesComeOutWhole) {
  Spline s{{1, 2, 3}, {}, 60};
  std::string points;
  for (int i = 0; i < 3000; ++i) {
    const double x = i == 1500 ? 0.1 + 0.2 : i + 0.5;
    s.points.push_back({x, -(i + 1.0), 0.25});
    points += (i > 0 ? ",[" : "[") +
              (i == 1500 ? std::string("0.30000000000000004") : std::to_string(i) + ".5") + ",-" +
              std::to_string(i + 1) + ",0.25]";
  }
  EXPECT_EQ(to_jsonl({s, at(7, 1)}),
            R"({"op":"spline","src":[7,1],"to":[1,2,3],"points":[)" + points + R"(],"f":60})");
  const std::string text(20000, 'x');
  EXPECT_EQ(to_jsonl({Comment{text}, at(1, 1)}),
            R"({"op":"comment","src":[1,1],"text":")" + text + R"("})");
}

TEST(TraceJsonl, CommentQuotesBackslashesAndControlCharactersEscaped) {
  EXPECT_EQ(to_jsonl({Comment{"say \"hi\" \\ now"}, at(1, 1)}),
            R"({"op":"comment","src":[1,1],"text":"say \"hi\" \\ now"})");
  EXPECT_EQ(to_jsonl({Comment{"a\tb\nc\x01"}, at(1, 1)}),
            R"({"op":"comment","src":[1,1],"text":"a\u0009b\u000ac\u0001"})");
}

TEST(TraceJsonl, CommentUtf8PassesThrough) {
  EXPECT_EQ(to_jsonl({Comment{"usinagem \xC3\xA0 m\xC3\xA3o"}, at(1, 1)}),
            "{\"op\":\"comment\",\"src\":[1,1],\"text\":\"usinagem \xC3\xA0 m\xC3\xA3o\"}");
}

TEST(TraceJsonl, SourceLocationIsLineAndColumnOnly) {
  const core::SourceLoc loc{3, 17, 9, 4, 1234};
  EXPECT_EQ(to_jsonl({ProgramEnd{}, loc}), R"({"op":"end","src":[17,9]})");
}

// --- the writer -------------------------------------------------------------

// Everything a writer puts into a memory stream.
std::string written(TraceFormat format, const std::vector<Op>& ops) {
  char* data = nullptr;
  std::size_t size = 0;
  std::FILE* f = open_memstream(&data, &size);
  EXPECT_NE(f, nullptr);
  if (f == nullptr) return {};
  {
    TraceWriter w(f, format);
    for (const Op& op : ops)
      w.on(op);
    w.finish();
  }
  std::fclose(f);
  std::string out(data, size);
  std::free(data);
  return out;
}

TEST(TraceWriter, JsonlIsOneLinePerOp) {
  const std::string out =
      written(TraceFormat::Jsonl, {{Traverse{{1, 0, 0}}, at(1, 1)}, {ProgramEnd{}, at(2, 1)}});
  EXPECT_EQ(out,
            "{\"op\":\"traverse\",\"src\":[1,1],\"to\":[1,0,0]}\n{\"op\":\"end\",\"src\":[2,1]}\n");
}

TEST(TraceWriter, TextFormIsLineColumnNameAndFourDecimals) {
  const std::string out = written(TraceFormat::Text, {{Feed{{1, 2.5, -3}, 120}, at(12, 3)}});
  EXPECT_EQ(out, "   12:3   feed     X1.0000 Y2.5000 Z-3.0000 F120\n");
}

TEST(TraceWriter, TextFormOfEachKindNamesIt) {
  const std::string out =
      written(TraceFormat::Text, {{Arc{{1, 0, 0}, {0, 0, 0}, {0, 0, 1}, -1, 50}, at(1, 1)},
                                  {Dwell{2}, at(2, 1)},
                                  {ToolChange{4, 10}, at(3, 1)},
                                  {Spindle{900, SpindleDir::Ccw}, at(4, 1)},
                                  {Coolant{true, false}, at(5, 1)},
                                  {Comment{"hello"}, at(6, 1)},
                                  {ProgramEnd{}, at(7, 1)}});
  EXPECT_EQ(
      out,
      "    1:1   arc      X1.0000 Y0.0000 Z0.0000 about (0.0000, 0.0000, 0.0000) turn -1 F50\n"
      "    2:1   dwell    2 s\n"
      "    3:1   tool     T4 diameter 10 mm\n"
      "    4:1   spindle  ccw 900 rpm\n"
      "    5:1   coolant  mist on flood off\n"
      "    6:1   comment  hello\n"
      "    7:1   end     \n");
}

TEST(TraceWriter, LargeOutputIsWrittenCompletelyAndInOrder) {
  std::vector<Op> ops;
  for (int i = 0; i < 5000; ++i) {
    ops.push_back(
        {Feed{{static_cast<double>(i), 0, 0}, 100}, at(static_cast<std::uint32_t>(i + 1), 1)});
  }
  const std::string out = written(TraceFormat::Jsonl, ops);
  std::size_t lines = 0;
  for (const char c : out)
    lines += c == '\n' ? 1 : 0;
  EXPECT_EQ(lines, 5000u);
  EXPECT_NE(out.find("{\"op\":\"feed\",\"src\":[5000,1],\"to\":[4999,0,0],\"f\":100}\n"),
            std::string::npos);
  EXPECT_TRUE(out.starts_with("{\"op\":\"feed\",\"src\":[1,1],\"to\":[0,0,0],\"f\":100}\n"));
}

// --- op names ---------------------------------------------------------------

TEST(OpName, TraceNamesOfEveryKind) {
  EXPECT_STREQ(op_name(Traverse{}), "traverse");
  EXPECT_STREQ(op_name(Feed{}), "feed");
  EXPECT_STREQ(op_name(Arc{}), "arc");
  EXPECT_STREQ(op_name(Spline{}), "spline");
  EXPECT_STREQ(op_name(Probe{}), "probe");
  EXPECT_STREQ(op_name(Dwell{}), "dwell");
  EXPECT_STREQ(op_name(ToolChange{}), "tool");
  EXPECT_STREQ(op_name(Spindle{}), "spindle");
  EXPECT_STREQ(op_name(Coolant{}), "coolant");
  EXPECT_STREQ(op_name(Hole{}), "hole");
  EXPECT_STREQ(op_name(Pocket{}), "pocket");
  EXPECT_STREQ(op_name(Comment{}), "comment");
  EXPECT_STREQ(op_name(ProgramEnd{}), "end");
}

TEST(OpName, OnlyMovesAreMotion) {
  EXPECT_TRUE(is_motion(Traverse{}));
  EXPECT_TRUE(is_motion(Feed{}));
  EXPECT_TRUE(is_motion(Arc{}));
  EXPECT_TRUE(is_motion(Spline{}));
  EXPECT_TRUE(is_motion(Probe{}));
  EXPECT_FALSE(is_motion(Dwell{}));
  EXPECT_FALSE(is_motion(Hole{}));
  EXPECT_FALSE(is_motion(Comment{}));
  EXPECT_FALSE(is_motion(ProgramEnd{}));
}

}  // namespace
}  // namespace usina::canon

namespace usina::canon {
namespace {

std::string write_with_sources(const Op& op, TraceFormat format) {
  core::SourceManager sources;
  sources.add(core::SourceFile::from_string("main.ngc", "G0 X1\n"));
  sources.add(core::SourceFile::from_string("subs/corner.ngc", "G1 X2\n"));
  std::FILE* f = std::tmpfile();
  {
    TraceWriter w(f, format);
    w.set_sources(&sources);
    w.on(op);
  }
  std::rewind(f);
  std::string out(256, '\0');
  out.resize(std::fread(out.data(), 1, out.size(), f));
  std::fclose(f);
  return out;
}

TEST(TraceWriterFile, OpsOfASubroutineFileNameTheFile) {
  Op op{Traverse{{1, 2, 3}, {}}, core::SourceLoc{1, 7, 3, 0, 0}};
  EXPECT_EQ(write_with_sources(op, TraceFormat::Jsonl),
            "{\"op\":\"traverse\",\"src\":[7,3],\"file\":\"subs/corner.ngc\",\"to\":[1,2,3]}\n");
  EXPECT_EQ(write_with_sources(op, TraceFormat::Text).rfind("subs/corner.ngc:", 0), 0u);
}

TEST(TraceWriterFile, OpsOfTheProgramItselfHaveNoFileField) {
  Op op{Traverse{{1, 2, 3}, {}}, core::SourceLoc{0, 7, 3, 0, 0}};
  EXPECT_EQ(write_with_sources(op, TraceFormat::Jsonl),
            "{\"op\":\"traverse\",\"src\":[7,3],\"to\":[1,2,3]}\n");
}

}  // namespace
}  // namespace usina::canon
