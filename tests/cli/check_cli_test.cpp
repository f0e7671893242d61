// usina check: several files, --format json, --max-errors, --quiet, inputs
// from pipes, and the run options' ranges (issue 11, the command line).
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/usina_process.hpp"

namespace usina::test {
namespace {

constexpr const char* kGood = "G0 X1\nG1 X2 F100\nM2\n";
constexpr const char* kBad = "G0 X1\nG1 X2 Y\nM2\n";

TEST(CheckCli, SeveralFilesEachReportedTheWorstStatusWins) {
  const TempDir dir;
  const std::string good = dir.write("good.ngc", kGood);
  const std::string bad = dir.write("bad.ngc", kBad);
  EXPECT_EQ(usina("check " + quote(good) + " " + quote(good)).status, 0);
  const test::Run r = usina("check " + quote(good) + " " + quote(bad));
  EXPECT_EQ(r.status, 1);
  EXPECT_TRUE(contains(r.err, "bad.ngc:2:8: error")) << r.err;
  EXPECT_EQ(usina("check " + quote(bad) + " " + quote(dir.path("none.ngc"))).status, 2);
}

TEST(CheckCli, JsonListsEachFileAndEachDiagnostic) {
  const TempDir dir;
  const std::string good = dir.write("good.ngc", kGood);
  const std::string bad = dir.write("bad.ngc", kBad);
  const test::Run r = usina("check --format json " + quote(good) + " " + quote(bad));
  EXPECT_EQ(r.status, 1);
  EXPECT_TRUE(r.err.empty()) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j.at("files").size(), 2u);
  EXPECT_EQ(j["files"][0]["status"], 0);
  EXPECT_TRUE(j["files"][0]["diagnostics"].empty());
  const nlohmann::json& d = j["files"][1]["diagnostics"].at(0);
  EXPECT_EQ(d["file"], bad);
  EXPECT_EQ(d["line"], 2);
  EXPECT_EQ(d["column"], 8);
  EXPECT_EQ(d["severity"], "error");
  EXPECT_EQ(d["code"], "E_EXPECTED_EXPRESSION");
  EXPECT_FALSE(d["message"].get<std::string>().empty());
  EXPECT_EQ(j["files"][1]["errors"], 1);
}

TEST(CheckCli, JsonStaysValidWithLatin1InAMessage) {
  const TempDir dir;
  const std::string p = dir.write("p.ngc", "(MSG, caf\xe9)\nG1 X1 Y\nM2\n");
  const test::Run r = usina("check --format json " + quote(p));
  EXPECT_TRUE(nlohmann::json::accept(r.out)) << r.out;
}

// A program of warnings on every line (typographic dashes in romi) says 50
// of them and counts the rest.
TEST(CheckCli, MaxErrorsCapsWhatIsShownAndCountsTheRest) {
  const TempDir dir;
  std::string text;
  for (int i = 0; i < 300; ++i)
    text += "G1 X\xe2\x80\x93" + std::to_string(i) + " F100#\n";
  text += "M30#\n";
  const std::string p = dir.write("w.nc", text);
  const test::Run all = usina("check --dialect romi --max-errors 0 " + quote(p));
  const std::size_t every = count(all.err, "warning:");
  ASSERT_GT(every, 60u) << all.err.substr(0, 400);
  const test::Run capped = usina("check --dialect romi " + quote(p));
  EXPECT_EQ(count(capped.err, "warning:"), 50u);
  EXPECT_TRUE(contains(capped.err,
                       "not shown: 0 more error(s), " + std::to_string(every - 50) + " warning(s)"))
      << capped.err.substr(capped.err.size() - 300);
  const test::Run three = usina("check --dialect romi --max-errors 3 " + quote(p));
  EXPECT_EQ(count(three.err, "warning:"), 3u);
}

TEST(CheckCli, QuietSaysErrorsOnly) {
  const TempDir dir;
  const std::string p = dir.write("w.nc", "%\nO1\nG1 X5 F100\nG1 X2 Y\nM30\n%\n");
  const test::Run loud = usina("check --dialect auto " + quote(p));
  EXPECT_TRUE(contains(loud.err, "warning:")) << loud.err;
  EXPECT_TRUE(contains(loud.err, "N_DIALECT_GUESS")) << loud.err;
  const test::Run quiet = usina("check --dialect auto -q " + quote(p));
  EXPECT_EQ(quiet.status, 1);
  EXPECT_FALSE(contains(quiet.err, "warning:")) << quiet.err;
  EXPECT_FALSE(contains(quiet.err, "note:")) << quiet.err;
  EXPECT_TRUE(contains(quiet.err, "error:")) << quiet.err;
}

TEST(CheckCli, AFiftyMegabyteLineGivesAShortDiagnostic) {
  const TempDir dir;
  const std::string p = dir.write("long.ngc", "G1 X1 (" + std::string(5'000'000, 'c') + ") Y\n");
  const test::Run r = usina("check " + quote(p));
  EXPECT_EQ(r.status, 1);
  EXPECT_LT(r.err.size(), 2000u) << r.err.size();
}

TEST(CheckCli, PipesAndProcessSubstitutionAreInputs) {
  const TempDir dir;
  const std::string p = dir.write("p.ngc", kGood);
  EXPECT_EQ(usina("check -", kGood).status, 0);
  EXPECT_EQ(usina("check /dev/stdin", kGood).status, 0);
  const test::Run piped = usina("trace /dev/fd/3 3< " + quote(p));
  EXPECT_EQ(piped.status, 0) << piped.err;
  const test::Run fifo = usina("check /dev/stdin < /dev/null");
  EXPECT_EQ(fifo.status, 0) << fifo.err;
  // Through a real pipe (sh's `cat |`), not a redirected file.
  const test::Run pipe = usina("--version >/dev/null; (cat " + quote(p) + " | " +
                               quote(USINA_BINARY) + " trace /dev/stdin)");
  EXPECT_EQ(pipe.status, 0) << pipe.err;
  EXPECT_TRUE(contains(pipe.out, "\"to\":[2,0,0]")) << pipe.out;
}

TEST(CheckCli, RunOptionsOutOfRangeAreUsageErrors) {
  const TempDir dir;
  const std::string p = dir.write("p.ngc", kGood);
  for (const std::string& flag : std::vector<std::string>{
           "--max-iterations -5", "--max-iterations 0", "--max-total-iterations -1",
           "--peck-clearance -1", "--peck-clearance inf", "--peck-clearance nan",
           "--max-errors -1"}) {
    const test::Run r = usina("check " + flag + " " + quote(p));
    EXPECT_EQ(r.status, 2) << flag;
    EXPECT_TRUE(contains(r.err, flag.substr(0, flag.find(' ')))) << flag << "\n" << r.err;
  }
}

TEST(CheckCli, OffsetsOutsideFanucAreAnError) {
  const TempDir dir;
  const std::string p = dir.write("p.ngc", kGood);
  const std::string offsets = dir.write("o.toml", "[h]\n1 = 10.0\n");
  const test::Run r = usina("check --offsets " + quote(offsets) + " " + quote(p));
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(contains(r.err, "--offsets is the fanuc dialect's")) << r.err;
}

}  // namespace
}  // namespace usina::test
