// GOUP and GODOWN in 2.5D: along the tool axis to a horizontal plane, the
// tool at its offset from the drive surface; values worked by hand.
#include "apt_run.hpp"

namespace usina::apt::test {
namespace {

// A 2 mm cutter on the right of L1 (y = 0) going +x: its centre at y = -1;
// GORGT/L1,TO,L2 stops 1 before x = 10: (9,-1,0).
const std::string kStart =
    "L1=LINE/0,0,10,0\nL2=LINE/10,0,10,10\nPL0=PLANE/0,0,1,0\nPL5=PLANE/0,0,1,-5\n"
    "CUTTER/2\nFROM/-5,-5,0\nGO/TO,L1\nTLRGT,GORGT/L1,TO,L2\n";

// The points of the 5000 records, in order.
std::vector<core::Vec3> points(const AptRun& r) {
  std::vector<core::Vec3> out;
  for (const ClRecord& c : r.result.records)
    if (c.cls == cls::kMotion)
      for (std::size_t i = 2; i + 2 < c.words.size(); i += 3)
        out.push_back({c.words[i].real, c.words[i + 1].real, c.words[i + 2].real});
  return out;
}

TEST(AptVertical, GodownToAPlaneThenAlongItAndUp) {
  const AptRun r = run(kStart +
                       "GODOWN/L1,PL5,50\nTLLFT,GOBACK/L1,TO,(LINE/0,0,0,10)\n"
                       "GOUP/L1,ON,(PLANE/0,0,1,9)\nFINI\n");
  EXPECT_FALSE(r.diags.has_errors()) << (r.diags.all().empty() ? "" : r.diags.all()[0].message);
  const std::vector<core::Vec3> p = points(r);
  ASSERT_EQ(p.size(), 6u);
  EXPECT_EQ(p[3], (core::Vec3{9, -1, -5}));  // down to z -5
  EXPECT_EQ(p[4], (core::Vec3{1, -1, -5}));  // back along L1 at the new part surface
  EXPECT_EQ(p[5], (core::Vec3{1, -1, 9}));   // up to z 9
  // The feed after the check surface: a FEDRAT record before the motion.
  bool fedrat = false;
  for (const ClRecord& c : r.result.records)
    fedrat = fedrat || (c.cls == cls::kPost && c.sub == 1009 && c.words[0].real == 50);
  EXPECT_TRUE(fedrat);
}

void expect_error(const std::string& stmt, core::Code code) {
  const AptRun r = run(kStart + stmt + "\nFINI\n");
  EXPECT_TRUE(r.has(code)) << stmt;
  EXPECT_EQ(points(r).size(), 3u) << stmt;  // the motion left out
}

TEST(AptVertical, Errors) {
  using core::Code;
  expect_error("GODOWN/L1,(PLANE/0,0,1,2)", Code::AptNoSolution);             // above the tool
  expect_error("GOUP/L1,PL5", Code::AptNoSolution);                           // below it
  expect_error("GOUP/(LINE/0,5,10,5),(PLANE/0,0,1,2)", Code::AptNoSolution);  // 6 from it, not 1
  expect_error("GODOWN/L1,PAST,PL5", Code::AptNotSupported);
  expect_error("GODOWN/L1,L2", Code::AptNotSupported);
  expect_error("GODOWN/PL5,PL5", Code::AptNotSupported);
  expect_error("GODOWN/L1", Code::AptBadArgument);
  expect_error("GODOWN/L1,TANTO,PL5", Code::AptBadArgument);
}

}  // namespace
}  // namespace usina::apt::test
