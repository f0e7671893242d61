#include "dnc/remote_request.hpp"

#include <gtest/gtest.h>

#include "dnc/tape_code.hpp"

namespace usina::dnc {
namespace {

const RequestRules kRules{9999, 10};

TEST(RemoteRequest, CimcoStyleProgramRequest) {
  const auto r = parse_remote_request("O9999\nN0010 (PRG=1234)\n", kRules);
  ASSERT_TRUE(r && *r);
  EXPECT_EQ((*r)->program, "1234");
  EXPECT_FALSE((*r)->start_block);
}

TEST(RemoteRequest, StartAtBlockLineToolAndOperator) {
  const auto r =
      parse_remote_request("O9999\n(/REQ BRACKET-2 /BL 10020)\n(TO=02 OP=JOHN)\n", kRules);
  ASSERT_TRUE(r && *r) << (r && !*r ? r->error() : "");
  EXPECT_EQ((*r)->program, "BRACKET-2");
  EXPECT_EQ((*r)->start_block, 10020U);
  EXPECT_EQ((*r)->start_tool, 2U);
  EXPECT_EQ((*r)->operator_name, "JOHN");
  const auto l = parse_remote_request("O9999\n(/REQ P1 /LI 120)\n", kRules);
  ASSERT_TRUE(l && *l);
  EXPECT_EQ((*l)->start_line, 120U);
  const auto n = parse_remote_request("O9999\n(/REQ P1 /BL N500)\n", kRules);
  ASSERT_TRUE(n && *n);
  EXPECT_EQ((*n)->start_block, 500U);
}

TEST(RemoteRequest, AnOrdinaryPunchIsNoRequest) {
  EXPECT_FALSE(parse_remote_request("O1000\n(PRG=1234)\nG0 X1\nM30\n", kRules));
  EXPECT_FALSE(parse_remote_request("O1000\nG0 X1\nM30\n", kRules));
  EXPECT_FALSE(parse_remote_request("", kRules));
}

TEST(RemoteRequest, AnyProgramWithARequestWhenTheNumberIsZero) {
  const auto r = parse_remote_request("O1\n(PRG=ABC)\n", RequestRules{0, 10});
  ASSERT_TRUE(r && *r);
  EXPECT_EQ((*r)->program, "ABC");
}

TEST(RemoteRequest, OnlyTheFirstLinesAreRead) {
  EXPECT_FALSE(parse_remote_request("O1\nG0\nG0\n(PRG=ABC)\n", RequestRules{0, 3}));
}

TEST(RemoteRequest, RefusalsSayWhy) {
  const auto none = parse_remote_request("O9999\nM30\n", kRules);
  ASSERT_TRUE(none && !*none);
  EXPECT_NE(none->error().find("names no program"), std::string::npos);
  for (const char* bad : {"O9999\n(PRG=../../etc/passwd)\n", "O9999\n(PRG=.hidden)\n",
                          "O9999\n(PRG=A/B)\n", "O9999\n(PRG=)\n"}) {
    const auto r = parse_remote_request(bad, kRules);
    ASSERT_TRUE(r) << bad;
    EXPECT_FALSE(*r) << bad;
  }
  const auto two = parse_remote_request("O9999\n(PRG=A)\n(PRG=B)\n", kRules);
  ASSERT_TRUE(two && !*two);
  EXPECT_NE(two->error().find("two programs"), std::string::npos);
  const auto block = parse_remote_request("O9999\n(/REQ A /BL X1)\n", kRules);
  ASSERT_TRUE(block && !*block);
}

TEST(RemoteRequest, TheResponseProgramHasOnlyCharactersEveryCodeCanPunch) {
  const std::string p =
      response_program(9999, "program \"1234\" is not released for romi-1 (state: draft) #1=2 [x]");
  EXPECT_TRUE(p.starts_with("O9999\n(USINA PROGRAM  1234  IS NOT RELEASED FOR ROMI-1"));
  EXPECT_TRUE(p.ends_with("M30\n"));
  for (const char c : p) {
    EXPECT_TRUE(encode_char(TapeCode::Eia, static_cast<unsigned char>(c)).has_value()) << c;
  }
}

TEST(RemoteRequest, ValidNames) {
  EXPECT_TRUE(valid_program_name("O1234"));
  EXPECT_TRUE(valid_program_name("part_7.nc"));
  EXPECT_FALSE(valid_program_name(".."));
  EXPECT_FALSE(valid_program_name("a b"));
  EXPECT_FALSE(valid_program_name(std::string(65, 'a')));
}

}  // namespace
}  // namespace usina::dnc
