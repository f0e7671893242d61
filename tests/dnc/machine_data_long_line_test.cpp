// A line a control punches while idle is matched against the machine's data
// patterns by std::regex, which recursed once a character: "PART COUNT "
// and 200,000 digits overflowed the server's stack (found with fuzz_config's
// long patterns). A line longer than kMaxDataLineLength is no DPRNT line and
// is not matched; the lines around it still are.
#include <string>

#include <gtest/gtest.h>

#include "api_control.hpp"

namespace usina::dnc {
namespace {

TEST(MachineDataLongLine, ALineOfTwoHundredThousandDigitsIsNotMatchedAndTheServerGoesOn) {
  RunningServer s;
  Control control = start_punching_mill(s);
  const ApiClient c = s.client();
  const std::string oper = c.log_in("oper", test::kPassword);
  const auto idle = [](const nlohmann::json& m) { return m.value("state", "") == "idle"; };
  ASSERT_TRUE(idle(machine_when(c, oper, idle)));
  punch(s, control, "PART COUNT " + std::string(200000, '1') + "\nPART COUNT 7\n");
  const auto m =
      machine_when(c, oper, [](const nlohmann::json& j) { return j.value("part_count", 0) == 1; });
  EXPECT_EQ(m["part_count"], 1);
  EXPECT_EQ(m["control_part_count"], 7);
}

}  // namespace
}  // namespace usina::dnc
