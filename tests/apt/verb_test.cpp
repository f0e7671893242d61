// usina apt, run as a user runs it: formats, --canonical, exit status.
#include "support/files.hpp"
#include "support/usina_process.hpp"

namespace usina::apt::test {
namespace {

using usina::test::quote;
using usina::test::TempDir;

TEST(AptVerb, CanonicalPrintsEachDefinitionAsAJsonLine) {
  const TempDir dir;
  const std::string f = dir.write("p.apt", "P1=POINT/1,2\nL1=LINE/P1,(POINT/1,5)\nFINI\n");
  const auto r = usina::test::usina("apt " + quote(f) + " --canonical");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out,
            "{\"name\":\"P1\",\"type\":\"POINT\",\"canon\":[1,2,0]}\n"
            "{\"name\":\"L1\",\"type\":\"LINE\",\"canon\":[1,0,0,1]}\n");
}

TEST(AptVerb, ErrorsGiveStatus1WithEveryErrorAtItsLine) {
  const TempDir dir;
  const std::string f = dir.write("p.apt", "A=1/0\nGOTO/Q\nL1=LINE/XAXIS\nGOFWD/L1\nFINI\n");
  const auto r = usina::test::usina("apt " + quote(f));
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("p.apt:1:4: error: division by zero [E_APT_ARITHMETIC]"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("p.apt:2:6: error"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("p.apt:4:1: error: GOFWD has no check surface"), std::string::npos) << r.err;
}

TEST(AptVerb, JsonlIsTheCanonTrace) {
  const TempDir dir;
  const std::string f = dir.write("p.apt", "FEDRAT/10\nFROM/0,0,0\nGOTO/1,0,0\nFINI\n");
  const auto r = usina::test::usina("apt " + quote(f) + " --format jsonl --units inch");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find(R"("op":"feed","src":[3,1],"to":[25.4,0,0],"f":254)"), std::string::npos)
      << r.out;
}

TEST(AptVerb, MissingFileIsStatus2) {
  EXPECT_EQ(usina::test::usina("apt /nonexistent/p.apt").status, 2);
}

}  // namespace
}  // namespace usina::apt::test
