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

TEST(ConvertCli, UsageErrors) {
  EXPECT_NE(test::usina("convert x.ngc").status, 0);  // no --post
  EXPECT_NE(test::usina("convert x.ngc --post heidenhain").status, 0);
  const test::Run r = test::usina("convert /nonexistent.ngc --post grbl");
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.err, testing::HasSubstr("usina: error: cannot read"));
}

}  // namespace
}  // namespace usina
