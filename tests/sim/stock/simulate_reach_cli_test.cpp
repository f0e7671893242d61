// `usina simulate` with the words above a tool's end, as a user runs it:
// from a tool table's comment and from --tool-shape, the report's tools and
// operations, a holder hit's exit status and line, and the sets refused.
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/files.hpp"
#include "support/usina_process.hpp"

namespace usina::test {
namespace {

// T1 buries its holder (20 mm, 10 above the tip) 15 deep at line 4; T2 cuts a slot.
const char* const kProgram =
    "T1 M6\nG0 X20 Y15 Z2\nG1 Z-5 F100\nG1 Z-15\nG0 Z5\n"
    "T2 M6\nG0 X5 Y5 Z1\nG1 Z-1\nG1 X35\nG0 Z5\nM30\n";

TEST(SimulateReachCli, TheReportListsTheWordsOnlyWhereGivenAndEachOperation) {
  TempDir dir;
  const std::string program = dir.write("p.ngc", kProgram);
  const std::string table = dir.write(
      "tools.tbl", "T1 P1 D6 ;6 mm end mill flutes:8 holder:20 stickout:10 no-plunge:3\n");
  const usina::test::Run r =
      usina("simulate " + quote(program) + " --tool-table " + quote(table) +
            " --stock box:40x30x20 --resolution 0.2 --tool-shape 2=ball/4 -o " +
            quote(dir.path("r.json")));
  EXPECT_EQ(r.status, 1) << r.err;  // the holder hits: an error
  EXPECT_NE(r.err.find("E_HOLDER_HITS_STOCK"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("W_PLUNGE_NOT_CENTRE_CUTTING"), std::string::npos) << r.err;
  const auto j = nlohmann::json::parse(dir.read("r.json"));
  ASSERT_EQ(j["tools"].size(), 2u);
  EXPECT_EQ(j["tools"][0]["flutes_mm"], 8.0);
  EXPECT_EQ(j["tools"][0]["holder_mm"], 20.0);
  EXPECT_EQ(j["tools"][0]["stickout_mm"], 10.0);
  EXPECT_EQ(j["tools"][0]["plunge_ramp_deg"], 3.0);
  for (const char* key : {"flutes_mm", "holder_mm", "stickout_mm", "plunge_ramp_deg"}) {
    EXPECT_FALSE(j["tools"][1].contains(key)) << key;
  }
  bool holder_at_4 = false;
  for (const auto& c : j["checks"]) {
    holder_at_4 |= c["code"] == "E_HOLDER_HITS_STOCK" && c["line"] == 4;
  }
  EXPECT_TRUE(holder_at_4) << j["checks"].dump();
  const auto& ops = j["per_operation"];
  ASSERT_EQ(ops.size(), 2u);
  EXPECT_EQ(ops[0]["tool"], 1);
  EXPECT_EQ(ops[0]["lines"], nlohmann::json::array({1, 5}));
  EXPECT_EQ(ops[1]["tool"], 2);
  EXPECT_EQ(ops[1]["lines"], nlohmann::json::array({6, 10}));
  EXPECT_DOUBLE_EQ(ops[0]["removed_mm3"].get<double>(),
                   j["per_tool"]["1"]["removed_mm3"].get<double>());
  EXPECT_NEAR(ops[0]["removed_mm3"].get<double>() + ops[1]["removed_mm3"].get<double>(),
              j["removed_mm3"].get<double>(), 1e-6);
}

TEST(SimulateReachCli, ToolShapeWordsOverTheTablesAreChecked) {
  TempDir dir;
  const std::string program = dir.write("p.ngc", kProgram);
  const usina::test::Run r = usina("simulate " + quote(program) +
                                   " --stock box:40x30x20 --resolution 0.2 --tool-shape "
                                   "1=flat/6,holder:20,stickout:20 --tool-shape 2=ball/4 -o " +
                                   quote(dir.path("r.json")));
  EXPECT_EQ(r.status, 0) << r.err;  // 20 mm of stick-out clears a 15 mm depth
  EXPECT_EQ(nlohmann::json::parse(dir.read("r.json"))["checks"].size(), 0u);
}

TEST(SimulateReachCli, WordsThatDoNotGoTogetherAreRefusedWithStatus2) {
  TempDir dir;
  const std::string program = dir.write("p.ngc", kProgram);
  const usina::test::Run spec =
      usina("simulate " + quote(program) + " --stock box:40x30x20 --tool-shape 1=flat/6,holder:32");
  EXPECT_EQ(spec.status, 2);
  EXPECT_NE(spec.err.find("a holder needs its stick-out"), std::string::npos) << spec.err;
  const std::string table = dir.write("tools.tbl", "T1 P1 D10 ;ball flutes:3\n");
  const usina::test::Run comment = usina("simulate " + quote(program) + " --tool-table " +
                                         quote(table) + " --stock box:40x30x20");
  EXPECT_EQ(comment.status, 2);
  EXPECT_NE(comment.err.find("tool 1's comment: flutes of 3 mm are shorter than the tool's end"),
            std::string::npos)
      << comment.err;
}

}  // namespace
}  // namespace usina::test
