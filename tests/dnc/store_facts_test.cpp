// What the library's search reads of a program's text, in each dialect's
// lexical rules: program numbers, the tools called, the comments.
#include "dnc/store_facts.hpp"

#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace usina::dnc {
namespace {

using Numbers = std::vector<std::string>;
using Tools = std::vector<std::int64_t>;

TEST(ProgramFacts, FanucProgramNumbersHeadBlocksOnATape) {
  const ProgramFacts f = read_facts(
      "%\nO0001 (MAIN PLATE)\nN10 G90 T12 M6\nM98 P1000\nM30\n%\n:1000 N1 (SUB)\nM99\n", "fanuc");
  EXPECT_EQ(f.o_numbers, (Numbers{"o0001", "o1000"}));
  EXPECT_EQ(f.tools, Tools{12});
  EXPECT_EQ(f.comments, "main plate\nsub");
}

TEST(ProgramFacts, FanucCommentsHoldSemicolonsAndPairsAndMacroKeywordsAreNoTools) {
  const ProgramFacts f = read_facts(
      "O2000;(READ WITH (DPI=0); T9 IS NO TOOL)\n#1=5;IF[#1GT3]GOTO10;WHILE[#1LT9]DO1;"
      "#2=ATAN[1]/[2];T0101;END1;M30;",
      "fanuc");
  EXPECT_EQ(f.o_numbers, Numbers{"o2000"});
  EXPECT_EQ(f.tools, Tools{101});  // a lathe's T0101 as written
  EXPECT_EQ(f.comments, "read with (dpi=0); t9 is no tool");
}

TEST(ProgramFacts, Rs274ngcBareONumbersButNoSubroutineLabels) {
  const ProgramFacts f = read_facts(
      "%\nO1234 (FACE)\no100 sub\nT#<tool> M6\no100 endsub\nT3M6 ; roughing\nM6 T 4\n"
      "o<tool_5> call\nT1.5\nT2.0\nM2\n%\n",
      "rs274ngc");
  EXPECT_EQ(f.o_numbers, Numbers{"o1234"});
  EXPECT_EQ(f.tools, (Tools{2, 3, 4}));
  EXPECT_EQ(f.comments, "face\nroughing");
}

TEST(ProgramFacts, RomiOIsAnOffsetAndParenthesisedStatementsAreNoComments) {
  const ProgramFacts f = read_facts(
      "N0042 X10. Y-50 T01 M06;fresa d10#N0044 O01 S1500#(P1 = 20)#(RPT N10,N20,2)#"
      "(P1 is the radius)#(SUB 3)#t5#N0050 T2 (FACEAR)#",
      "romi");
  EXPECT_TRUE(f.o_numbers.empty());
  EXPECT_EQ(f.tools, (Tools{1, 2}));  // a lower-case t is no tool in romi
  EXPECT_EQ(f.comments, "fresa d10\np1 is the radius\nfacear");
}

TEST(ProgramFacts, CommentsAreBoundedAndMadeUtf8) {
  std::string text;
  for (int i = 0; i < 300; ++i)
    text += "(A LONG COMMENT ABOUT THE FIXTURE " + std::to_string(i) + ")\nG0 X1\n";
  const ProgramFacts f = read_facts(text, "rs274ngc");
  EXPECT_LE(f.comments.size(), kMaxCommentBytes);
  EXPECT_GT(f.comments.size(), kMaxCommentBytes - 40);
  EXPECT_EQ(f.comments.find("fixture 299"), std::string::npos);  // past the bound
  const ProgramFacts latin1 = read_facts("(FURA\xc7\xc3O \xe2\x80\x94 \x01OK)\n", "rs274ngc");
  EXPECT_EQ(latin1.comments, "fura??o \xe2\x80\x94  ok");
}

TEST(ProgramFacts, AnUnknownDialectIsReadAsRs274ngc) {
  const ProgramFacts f = read_facts("O7 (X)\nT8 M6\n", "heidenhain");
  EXPECT_EQ(f.o_numbers, Numbers{"o7"});
  EXPECT_EQ(f.tools, Tools{8});
}

}  // namespace
}  // namespace usina::dnc
