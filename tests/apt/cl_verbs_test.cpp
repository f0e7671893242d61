// CL data on the command line, as a user runs it: usina apt --format cldata
// and iso4343 (-o, the terminal refused), and CL files (NX CLSF, APT CL,
// CLDATA) through check, trace, draw, stats and convert by --from or by
// their extension.
#include "support/files.hpp"
#include "support/usina_process.hpp"

namespace usina::apt::test {
namespace {

using usina::test::quote;
using usina::test::TempDir;

const char* kApt = "PARTNO TEST\nFEDRAT/100\nFROM/0,0,5\nGOTO/10,0,0\nGOTO/10,10,0\nFINI\n";

const char* kClsf =
    "TOOL PATH/OUTLINE,TOOL,D10\nTLDATA/MILL,10.0000,0.0000,50.0000,0.0000,0.0000\n"
    "$$ centerline data\nPAINT/PATH\nLOAD/TOOL,3,ADJUST,3\nSPINDL/RPM,3000,CLW\nRAPID\n"
    "GOTO/0.0000,-10.0000,5.0000,0.0000000,0.0000000,1.0000000\nFEDRAT/MMPM,500.0000\n"
    "GOTO/0.0000,-10.0000,0.0000\n"
    "CIRCLE/0.0000,0.0000,0.0000,0.0000000,0.0000000,1.0000000,10.0000,0.0600,0.5000\n"
    "GOTO/-10.0000,0.0000,0.0000\nEND-OF-PATH\n";

// The ops of a trace without "src" (a record number in CLDATA, a line in APT).
std::string without_src(const std::string& trace) {
  std::string out;
  std::size_t at = 0;
  while (at < trace.size()) {
    std::size_t end = trace.find('\n', at);
    std::string l = trace.substr(at, end - at);
    const std::size_t s = l.find(",\"src\"");
    if (s != std::string::npos) l.erase(s, l.find(']', s) + 1 - s);
    out += l + "\n";
    at = end + 1;
  }
  return out;
}

TEST(AptClVerbs, CldataToAFileIsReadBackByTrace) {
  const TempDir dir;
  const std::string f = dir.write("p.apt", kApt);
  const std::string cl = dir.path("p.cldata");
  const auto w = usina::test::usina("apt " + quote(f) + " --format cldata -o " + quote(cl));
  EXPECT_EQ(w.status, 0) << w.err;
  EXPECT_EQ(usina::test::slurp(cl).substr(0, 4), std::string("\x01\x00\x00\x00", 4));
  const auto want = usina::test::usina("apt " + quote(f) + " --format jsonl");
  const auto got = usina::test::usina("trace " + quote(cl));
  EXPECT_EQ(got.status, 0) << got.err;
  EXPECT_EQ(without_src(got.out), without_src(want.out));
  EXPECT_NE(want.out.find("\"op\":\"feed\",\"src\":[4,1],\"to\":[10,0,0]"), std::string::npos);
}

TEST(AptClVerbs, CldataIsNeverWrittenToATerminal) {
  const TempDir dir;
  const std::string f = dir.write("p.apt", kApt);
  // script(1) gives usina a terminal for its standard output.
  const std::string cmd = "script -qec " +
                          quote(quote(USINA_BINARY) + " apt " + quote(f) + " --format cldata") +
                          " /dev/null";
  const auto r = usina::test::shell(cmd + " 2>/dev/null", dir.write("err", ""));
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_NE(r.out.find("--format cldata is binary; give -o FILE"), std::string::npos) << r.out;
  // A pipe takes it.
  const auto piped = usina::test::usina("apt " + quote(f) + " --format cldata");
  EXPECT_EQ(piped.status, 0);
  EXPECT_GT(piped.out.size(), 100u);
}

TEST(AptClVerbs, Iso4343AndCldataAreNotWrittenWhenTheProgramHasAnError) {
  const TempDir dir;
  const std::string f = dir.write("p.apt", "GOTO/Q\nFINI\n");
  for (const char* format : {"cldata", "iso4343"}) {
    const std::string out = dir.path(std::string("p.") + format);
    const auto r =
        usina::test::usina("apt " + quote(f) + " --format " + format + " -o " + quote(out));
    EXPECT_EQ(r.status, 1) << format;
    EXPECT_FALSE(usina::test::exists(out)) << format;
  }
  const auto text =
      usina::test::usina("apt " + quote(dir.write("q.apt", kApt)) + " --format iso4343");
  EXPECT_EQ(text.out,
            "UNITS/MM\nPARTNO/TEST\nFEDRAT/100\nFROM/0,0,5\nGOTO/10,0,0\nGOTO/10,10,0\nFINI\n");
  const auto self = usina::test::usina("apt " + quote(f) + " --format iso4343 -o " + quote(f));
  EXPECT_EQ(self.status, 2);
}

TEST(AptClVerbs, EveryFormatGoesToTheFileOfO) {
  const TempDir dir;
  const std::string f = dir.write("p.apt", kApt);
  for (const char* format : {"cldump", "jsonl", "iso4343"}) {
    const std::string out = dir.path(std::string("p.") + format);
    const auto to_file =
        usina::test::usina("apt " + quote(f) + " --format " + format + " -o " + quote(out));
    EXPECT_EQ(to_file.status, 0) << to_file.err;
    EXPECT_TRUE(to_file.out.empty());
    EXPECT_EQ(usina::test::slurp(out),
              usina::test::usina("apt " + quote(f) + " --format " + format).out);
  }
  const std::string canon = dir.path("p.json");
  EXPECT_EQ(usina::test::usina("apt " + quote(f) + " --canonical -o " + quote(canon)).status, 0);
  const auto nowhere = usina::test::usina("apt " + quote(f) + " --format cldata -o " +
                                          quote(dir.path("no/such/folder/p.cldata")));
  EXPECT_EQ(nowhere.status, 2);
  EXPECT_NE(nowhere.err.find("usina: error:"), std::string::npos) << nowhere.err;
}

TEST(AptClVerbs, ClsfByItsExtensionThroughConvertCheckStatsAndDraw) {
  const TempDir dir;
  const std::string f = dir.write("part.cls", kClsf);
  const auto nc = usina::test::usina("convert " + quote(f) + " --post grbl");
  EXPECT_EQ(nc.status, 0) << nc.err;
  EXPECT_NE(nc.out.find("G2 X-10 Y0 I0 J10"), std::string::npos) << nc.out;  // NX: +k is CW
  const auto as = usina::test::usina("convert " + quote(dir.write("part.txt", kClsf)) +
                                     " --from clsf --post grbl");
  EXPECT_EQ(as.out, nc.out);
  EXPECT_EQ(usina::test::usina("check " + quote(f)).status, 0);
  const auto stats = usina::test::usina("stats " + quote(f) + " --format json");
  EXPECT_EQ(stats.status, 0) << stats.err;
  EXPECT_NE(stats.out.find("\"arcs\": 1"), std::string::npos) << stats.out;
  const std::string svg = dir.path("part.svg");
  EXPECT_EQ(usina::test::usina("draw " + quote(f) + " -o " + quote(svg)).status, 0);
  EXPECT_NE(usina::test::slurp(svg).find("<svg"), std::string::npos);
}

TEST(AptClVerbs, AptClFromStandardInputAndItsErrorsAtTheirLines) {
  const auto r = usina::test::usina("check --from aptcl -",
                                    "GOTO/0,0,0\nCIRCLE/5,0,0,0,0,1\nGOTO/5,9,0\nGOTO/1\n");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("<stdin>:3:1: error: the arc of CIRCLE/ (line 2) does not fit"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("<stdin>:4:1: error: GOTO/ takes x,y,z"), std::string::npos) << r.err;
}

TEST(AptClVerbs, FromAndDialectMustAgree) {
  const TempDir dir;
  const std::string f = dir.write("p.ngc", "G0 X1\n");
  EXPECT_EQ(usina::test::usina("trace --from fanuc --dialect fanuc " + quote(f)).status, 0);
  const auto r = usina::test::usina("trace --from clsf --dialect fanuc " + quote(f));
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--from clsf and --dialect fanuc disagree"), std::string::npos) << r.err;
  EXPECT_EQ(usina::test::usina("trace --from nonsense " + quote(f)).status, 2);
}

TEST(AptClVerbs, ABrokenCldataFileSaysWhichRecord) {
  const TempDir dir;
  const std::string f = dir.write("p.cldata", std::string("\x01\x00\x00\x00\x09", 5));
  const auto r = usina::test::usina("check " + quote(f));
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("p.cldata:1:1: error: record 1 (byte 0): the file ends inside the "
                       "record's header"),
            std::string::npos)
      << r.err;
}

}  // namespace
}  // namespace usina::apt::test
