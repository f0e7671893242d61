// The "linuxcnc" planner model against LinuxCNC's own planner: every program
// of tests/programs/timing/ was run once by LinuxCNC 2.9 (its README says
// how); `usina stats --format json` on machine.toml must give the motion time
// LinuxCNC took within 2 % (reference.tsv; a program listed there with a
// wider bound says why in its last column).
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/usina_process.hpp"

namespace usina::test {
namespace {

const std::string kDir = std::string(USINA_TEST_DIR) + "/programs/timing";

struct Reference {
  std::string program;
  double motion_s = 0.0;
  double bound_pct = 2.0;
  std::string why;
};

std::vector<Reference> references() {
  std::vector<Reference> out;
  std::ifstream in(kDir + "/reference.tsv");
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    Reference r;
    std::string motion, version, bound;
    std::getline(fields, r.program, '\t');
    std::getline(fields, motion, '\t');
    std::getline(fields, version, '\t');
    std::getline(fields, bound, '\t');
    std::getline(fields, r.why);
    r.motion_s = std::stod(motion);
    if (!bound.empty()) r.bound_pct = std::stod(bound);
    out.push_back(r);
  }
  return out;
}

nlohmann::json stats(const std::string& program) {
  const Run r =
      usina(fmt::format("stats {} --machine {} --format json", quote(kDir + "/" + program + ".ngc"),
                        quote(kDir + "/machine.toml")));
  EXPECT_EQ(r.status, 0) << program << ": " << r.err;
  return nlohmann::json::parse(r.out, nullptr, false);
}

// stats --format json: time.motion_s (cutting and rapid), time.total_s
// (with dwells), and the model, textbook without a profile.
TEST(LinuxcncTiming, TheJsonGivesMotionAndTotalTimeAndTheModel) {
  const TempDir dir;
  const std::string program = dir.write("p.ngc", "G1 X10 F600\nG4 P2\nG0 X0\nM2\n");
  const usina::test::Run r = usina(fmt::format("stats {} --format json", quote(program)));
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["planner"]["model"], "textbook");
  const nlohmann::json& t = j["time"];
  EXPECT_DOUBLE_EQ(t["motion_s"].get<double>(),
                   t["cutting_s"].get<double>() + t["rapid_s"].get<double>());
  EXPECT_NEAR(t["total_s"].get<double>() - t["motion_s"].get<double>(), 2.0, 1e-9);  // the dwell
  EXPECT_EQ(stats("a_line_rapid_g64")["planner"]["model"], "linuxcnc");
}

TEST(LinuxcncTiming, TheReferenceSetHasThirtyProgramsOrMore) {
  EXPECT_GE(references().size(), 30u);
}

TEST(LinuxcncTiming, EveryStoredTimeIsMetWithinItsBound) {
  int wide = 0;
  for (const Reference& ref : references()) {
    const nlohmann::json j = stats(ref.program);
    ASSERT_TRUE(j.is_object()) << ref.program;
    EXPECT_EQ(j["planner"]["model"], "linuxcnc");
    const double motion = j["time"]["motion_s"].get<double>();
    const double off = 100.0 * (motion - ref.motion_s) / ref.motion_s;
    EXPECT_LE(std::abs(off), ref.bound_pct)
        << ref.program << ": usina " << motion << " s, LinuxCNC " << ref.motion_s << " s ("
        << fmt::format("{:+.2f}", off) << " %)";
    if (ref.bound_pct > 2.0) {
      ++wide;
      EXPECT_FALSE(ref.why.empty()) << ref.program << " needs a reason for its wider bound";
    }
  }
  // Most of the set meets 2 %: a wider bound is the exception, with its reason.
  EXPECT_LE(wide, 5);
}

// The five programs of issue 18's table, each within 2 % (as measured here: the
// dense-CAM program is our own, 10.773 s against the table's 10.768; they are in the
// reference set too; here by name, so a regression names the rule).
TEST(LinuxcncTiming, TheIssueTableIsWithinTwoPercent) {
  const struct {
    const char* program;
    double linuxcnc_s;
  } table[] = {{"a_line_rapid_g64", 12.930},
               {"b_square_g61", 10.224},
               {"b_square_g64", 7.931},
               {"c_circle_r20_f3000", 4.685},
               {"d_cam_1000x0_5_p0_01", 10.773}};

  for (const auto& row : table) {
    const double motion = stats(row.program)["time"]["motion_s"].get<double>();
    EXPECT_NEAR(motion, row.linuxcnc_s, 0.02 * row.linuxcnc_s) << row.program;
  }
}

}  // namespace
}  // namespace usina::test
