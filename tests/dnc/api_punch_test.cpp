// What a control punches, through the server: a program becomes a draft
// revision named after its O number; a remote request is answered with the
// released program, or a response program that says why not.
#include <gtest/gtest.h>

#include "api_control.hpp"

namespace usina::dnc {
namespace {

const std::string kProgram = "G21 G90\nN10 G0 X1 Y1\nN20 M2\n";

TEST(ApiPunch, APunchedProgramBecomesADraftRevisionOfItsONumber) {
  RunningServer s;
  Control control = start_with_control(s);
  const ApiClient c = s.client();
  const std::string oper = c.log_in("oper", test::kPassword);
  punch(s, control, "\x12%\nO4321\nG0 X1\nM30\n%\x14");
  test::Reply got;
  for (int i = 0; i < 600 && got.status != 200; ++i) {
    got = c.get("/api/programs/O4321", oper);
    if (got.status != 200) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  ASSERT_EQ(got.status, 200) << got.body;
  const auto rev = got.json()["revisions"][0];
  EXPECT_EQ(rev["author"], "mill-1");
  EXPECT_EQ(rev["state"], "draft");
  EXPECT_EQ(
      c.get("/api/programs/O4321/revisions/" + rev["revision"].get<std::string>() + "/text", oper)
          .body,
      "O4321\nG0 X1\nM30\n");
}

TEST(ApiPunch, ARemoteRequestGetsTheReleasedProgramOnTheSameLink) {
  RunningServer s;
  Control control = start_with_control(s);
  const ApiClient c = s.client();
  released(c, "O1234", kProgram);
  punch(s, control, "%\nO9999\n(PRG=1234)\n%");
  const std::string wire = "%\nG21 G90\nN10 G0 X1 Y1\nN20 M2\n%";
  EXPECT_EQ(received_once(s, control, wire), wire);
}

TEST(ApiPunch, ARemoteRequestForAProgramNotInTheStoreGetsAResponseSayingSo) {
  RunningServer s;
  Control control = start_with_control(s);
  punch(s, control, "%\nO9999\n(PRG=5555)\n%");
  const std::string got = received_once(s, control, "NOT IN THE STORE");
  EXPECT_NE(got.find("O9999"), std::string::npos) << got;
  EXPECT_NE(got.find("5555 IS NOT IN THE STORE"), std::string::npos) << got;
}

}  // namespace
}  // namespace usina::dnc
