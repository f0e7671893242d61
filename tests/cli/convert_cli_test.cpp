// usina convert: every test program converted to rs274ngc and traced moves
// as the original does.
#include <filesystem>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "support/usina_process.hpp"

namespace usina {
namespace {

const std::string kPrograms = std::string(USINA_TEST_DIR) + "/programs/rs274ngc";

TEST(ConvertCli, EveryTestProgramKeepsItsMotion) {
  const test::TempDir dir;
  int converted = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kPrograms)) {
    const std::string file = entry.path().string();
    if (entry.path().extension() != ".ngc") continue;
    const test::Run original = test::usina("trace '" + file + "'");
    if (original.status != 0) continue;  // a program that shows an error (bad_arc.ngc)
    const std::string out = dir.path(entry.path().filename().string());
    const test::Run conv = test::usina("convert '" + file + "' --post rs274ngc -o " + out);
    ASSERT_EQ(conv.status, 0) << file << "\n" << conv.err;
    const test::Run again = test::usina("trace " + out);
    ASSERT_EQ(again.status, 0) << file << "\n" << again.err;
    SCOPED_TRACE(file);
    test::expect_same_motion(original.out, again.out, 2e-4);
    ++converted;
  }
  EXPECT_GE(converted, 10);
}

TEST(ConvertCli, ExpandsParametersAndLoopsIntoPlainBlocks) {
  const test::TempDir dir;
  const std::string in = dir.write("param.ngc",
                                   "#1=3\n#2=0\no100 while [#2 LT #1]\nG1 X[#2*10] F100\n"
                                   "#2=[#2+1]\no100 endwhile\nG81 X5 Y5 Z-2 R1\nG80\nM2\n");
  const test::Run r = test::usina("convert " + in + " --post fanuc");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_THAT(r.out, testing::Not(testing::HasSubstr("#")));
  EXPECT_THAT(r.out, testing::Not(testing::HasSubstr("while")));
  EXPECT_THAT(r.out, testing::Not(testing::HasSubstr("G81")));  // the cycle as moves
  EXPECT_THAT(r.out, testing::HasSubstr("G01 X0. Y0. Z0. F100.\nX10.\nX20.\n"));
}

TEST(ConvertCli, AProgramErrorWritesNoFile) {
  const test::TempDir dir;
  const std::string out = dir.path("bad.ngc");
  const test::Run r =
      test::usina("convert '" + kPrograms + "/bad_arc.ngc' --post rs274ngc -o " + out);
  EXPECT_EQ(r.status, 1);
  EXPECT_THAT(r.err, testing::HasSubstr("error"));
  EXPECT_FALSE(test::exists(out));
}

TEST(ConvertCli, WhatThePostCannotWriteIsAnError) {
  const test::TempDir dir;
  const std::string in = dir.write("probe.ngc", "G0 X0 Y0 Z0\nG38.2 Z-5 F10\nM2\n");
  const test::Run r = test::usina("convert " + in + " --post romi");
  EXPECT_EQ(r.status, 1);
  EXPECT_THAT(r.err, testing::HasSubstr(":2:"));  // at the block that probed
  EXPECT_THAT(r.err, testing::HasSubstr("cannot write a probing move [E_UNSUPPORTED]"));
}

// Standard output cannot be taken back: the program waits in a temporary
// file until the run is good. One that cannot be held whole (here a file
// size limit, with SIGXFSZ ignored so the write fails) is an error and
// nothing goes out, not a short program; the same command without the
// limit writes what -o writes.
TEST(ConvertCli, AProgramThatCannotBeHeldWholeIsAnErrorNotAShortProgram) {
  const test::TempDir dir;
  std::string text = "G21 G90 G0 X0 Y0 Z5\nG1 Z0 F300\n";
  for (int i = 0; i < 4000; ++i)
    text += "G1 X" + std::to_string(i % 100) + " Y" + std::to_string(i / 100) + "\n";
  const std::string in = dir.write("long.ngc", text + "M2\n");
  const std::string err = dir.path("err");
  const std::string convert = test::quote(USINA_BINARY) + " convert " + test::quote(in) +
                              " --post fanuc 2>" + test::quote(err);
  const test::Run cut = test::shell("trap '' XFSZ; ulimit -f 8; " + convert, err);
  EXPECT_EQ(cut.status, 2) << cut.err;
  EXPECT_TRUE(cut.out.empty()) << cut.out.size() << " bytes";
  EXPECT_THAT(cut.err, testing::HasSubstr("could not be written or read back"));
  const test::Run whole = test::shell(convert, err);
  EXPECT_EQ(whole.status, 0) << whole.err;
  EXPECT_GT(whole.out.size(), 8u * 1024u);  // past the limit
  const std::string out = dir.path("long.nc");
  ASSERT_EQ(test::usina("convert " + test::quote(in) + " --post fanuc -o " + out).status, 0);
  EXPECT_EQ(whole.out, test::slurp(out));
}

TEST(ConvertCli, UsageErrors) {
  EXPECT_NE(test::usina("convert x.ngc").status, 0);  // no --post
  EXPECT_NE(test::usina("convert x.ngc --post heidenhain").status, 0);
  const test::Run r = test::usina("convert /nonexistent.ngc --post grbl");
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.err, testing::HasSubstr("usina: error: cannot read"));
}

}  // namespace
}  // namespace usina
