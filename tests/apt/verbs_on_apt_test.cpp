// check, draw, stats and trace take an APT program (a file named *.apt):
// the APT processor's canon stream on the road of every verb.
#include <nlohmann/json.hpp>

#include "support/files.hpp"
#include "support/usina_process.hpp"

namespace usina::apt::test {
namespace {

using usina::test::quote;
using usina::test::TempDir;

// FROM (0,0,0), GO/TO,L1 to (-1,-5)... a 2 mm cutter up x = -1 past y = 5
// to (-1,6): two feeds of 4 and 11 mm at 300 mm/min.
constexpr const char* kContour =
    "L1=LINE/0,0,0,10\nL2=LINE/0,5,10,5\nCUTTER/2\nFEDRAT/300\nFROM/-5,-5,0\n"
    "GO/TO,L1\nTLLFT,GOLFT/L1,PAST,L2\nEND\nFINI\n";

TEST(AptVerbs, CheckReportsAnAptProgramsErrors) {
  const TempDir dir;
  const auto ok = usina::test::usina("check " + quote(dir.write("ok.apt", kContour)));
  EXPECT_EQ(ok.status, 0) << ok.err;
  const auto bad = usina::test::usina("check " + quote(dir.write("bad.APT", "GOTO/Q\nFINI\n")));
  EXPECT_EQ(bad.status, 1);
  EXPECT_NE(bad.err.find("bad.APT:1:6: error"), std::string::npos) << bad.err;
  EXPECT_NE(bad.err.find("E_APT_UNDEFINED_SYMBOL"), std::string::npos) << bad.err;
}

TEST(AptVerbs, StatsMeasuresAnAptProgram) {
  const TempDir dir;
  const auto r = usina::test::usina("stats --format json " + quote(dir.write("p.apt", kContour)));
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["counts"]["feeds"], 2);
  EXPECT_NEAR(j["distance"]["cutting_mm"].get<double>(), 4.0 + 11.0, 1e-9);
  EXPECT_EQ(j["feed_mm_per_min"]["max"], 300.0);
}

TEST(AptVerbs, TraceAndDrawTakeAnAptProgram) {
  const TempDir dir;
  const std::string f = dir.write("p.apt", kContour);
  const auto t = usina::test::usina("trace " + quote(f));
  ASSERT_EQ(t.status, 0) << t.err;
  EXPECT_NE(t.out.find(R"("to":[-1,6,0])"), std::string::npos) << t.out;
  const auto d = usina::test::usina("draw " + quote(f) + " -o " + quote(dir.path("p.svg")));
  ASSERT_EQ(d.status, 0) << d.err;
  EXPECT_NE(dir.read("p.svg").find("<svg"), std::string::npos);
}

TEST(AptVerbs, MachineUnitsInchScalesAnAptProgram) {
  const TempDir dir;
  const std::string f = dir.write("p.apt", "FEDRAT/10\nFROM/0,0,0\nGOTO/1,0,0\nFINI\n");
  const auto r = usina::test::usina("trace --machine-units inch " + quote(f));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find(R"("to":[25.4,0,0],"f":254)"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace usina::apt::test
