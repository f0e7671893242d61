// `usina simulate`: the times and the removal rate over time, from the
// planner of `usina stats` (docs/simulate.md, "Removal rate").
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/files.hpp"
#include "support/usina_process.hpp"

namespace usina::test {
namespace {

using nlohmann::json;

// A 6 mm end mill slots 2 mm deep along 100 mm at 300 mm/min: 3,600 mm³/min
// at cruise (6 × 2 × 300), then a 4 s dwell and a second, shallower slot.
const char* kSlots =
    "T1 M6\n"
    "G0 X-10 Y10 Z1\n"
    "G1 Z-2 F300\n"
    "G1 X100\n"
    "G0 Z1\n"
    "G4 P4\n"
    "G0 X-10 Y30\n"
    "G1 Z-1\n"
    "G1 X100\n"
    "G0 Z5\n"
    "M30\n";

json simulate(const TempDir& dir, const std::string& extra = "") {
  const usina::test::Run r =
      usina("simulate " + quote(dir.write("slots.ngc", kSlots)) +
            " --stock box:100x40x10 --resolution 0.1 --tool-shape 1=flat/6 -o " +
            quote(dir.path("r.json")) + " " + extra);
  EXPECT_EQ(r.status, 0) << r.err;
  return json::parse(dir.read("r.json"));
}

TEST(SimulateRateCli, TheRateAtCruiseIsWidthTimesDepthTimesFeed) {
  TempDir dir;
  const json j = simulate(dir);
  const json& rate = j["removal_rate"];
  // The first slot cruises at 3,600 mm³/min; the peak is no higher.
  EXPECT_NEAR(rate["peak_mm3_per_min"].get<double>(), 3600.0, 36.0);
  // 100 mm of slot through the stock at 300 mm/min: 20 s each, and the
  // plunges; the mean while cutting sits between the two slots' rates.
  const double mean = rate["mean_cutting_mm3_per_min"].get<double>();
  EXPECT_GT(mean, 1800.0);
  EXPECT_LT(mean, 3600.0);
  EXPECT_NEAR(rate["cutting_s"].get<double>(), 40.0, 2.0);
  // The bins hold the volume removed.
  double mm3 = 0.0;
  for (const json& b : rate["mm3_per_min"])
    mm3 += b.get<double>() * rate["bin_s"].get<double>() / 60.0;
  EXPECT_NEAR(mm3, j["removed_mm3"].get<double>(), 1e-6 * mm3);
}

TEST(SimulateRateCli, TheDwellIsAGapAndTheSecondSlotHalfTheRate) {
  TempDir dir;
  const json j = simulate(dir);
  const json& rate = j["removal_rate"];
  const double bin = rate["bin_s"].get<double>();
  const json& bins = rate["mm3_per_min"];
  // Find the dwell: a run of empty bins at least 3.5 s long after the first cut.
  std::size_t first_cut = 0;
  while (first_cut < bins.size() && bins[first_cut].get<double>() == 0.0)
    ++first_cut;
  std::size_t gap = 0;
  std::size_t longest = 0;
  std::size_t gap_end = 0;
  for (std::size_t i = first_cut; i < bins.size(); ++i) {
    gap = bins[i].get<double>() == 0.0 ? gap + 1 : 0;
    if (gap > longest) {
      longest = gap;
      gap_end = i;
    }
  }
  EXPECT_GE(static_cast<double>(longest) * bin, 3.5);
  // Well into the second slot: 6 × 1 × 300.
  const std::size_t middle = gap_end + static_cast<std::size_t>(12.0 / bin);
  ASSERT_LT(middle, bins.size());
  EXPECT_NEAR(bins[middle].get<double>(), 1800.0, 18.0);
}

TEST(SimulateRateCli, APlungeRemovesItsAreaTimesItsFeed) {
  // A 10 mm end mill down from Z5 to Z-10 at 120 mm/min: 2.5 s in the air,
  // then 78.54 mm² × 120 mm/min = 9,424.8 mm³/min.
  TempDir dir;
  const usina::test::Run r = usina(
      "simulate " + quote(dir.write("plunge.ngc", "T1 M6\nG0 X20 Y20 Z5\nG1 Z-10 F120\nM30\n")) +
      " --stock box:40x40x20 --resolution 0.05 --tool-shape 1=flat/10 -o " +
      quote(dir.path("r.json")));
  ASSERT_EQ(r.status, 0) << r.err;
  const json j = json::parse(dir.read("r.json"));
  const json& rate = j["removal_rate"];
  EXPECT_NEAR(rate["peak_mm3_per_min"].get<double>(), 9424.8, 94.0);
  EXPECT_NEAR(rate["mean_cutting_mm3_per_min"].get<double>(), 9424.8, 0.05 * 9424.8);
  // The air above the stock: nothing in its bins.
  const double bin = rate["bin_s"].get<double>();
  double air = 0.0;
  for (std::size_t i = 0; i < rate["mm3_per_min"].size() && static_cast<double>(i + 1) * bin < 2.0;
       ++i)
    air += rate["mm3_per_min"][i].get<double>();
  EXPECT_EQ(air, 0.0);
}

TEST(SimulateRateCli, TheTimeIsStatsTimeOnTheSameMachine) {
  TempDir dir;
  const json j = simulate(dir);
  const usina::test::Run stats = usina("stats --format json " + quote(dir.path("slots.ngc")));
  ASSERT_EQ(stats.status, 0) << stats.err;
  const json s = json::parse(stats.out);
  EXPECT_NEAR(j["time_s"].get<double>(), s["time"]["total_s"].get<double>(), 1e-9);
  ASSERT_EQ(j["per_operation"].size(), 1u);
  EXPECT_NEAR(j["per_operation"][0]["time_s"].get<double>(), j["time_s"].get<double>(), 1e-9);
  EXPECT_EQ(j["machine"]["profile"], nullptr);
}

TEST(SimulateRateCli, EveryPlannerModelTimesEveryOpAndKeepsTheVolume) {
  // LinuxCNC's model merges and blends moves, Grbl's cuts arcs in chords:
  // the time is still stats' and the bins still hold every mm³.
  TempDir dir;
  const std::string machines = std::string(USINA_TEST_DIR) + "/../examples/machines/";
  const std::string grbl = dir.write(
      "grbl.toml", slurp(machines + "hobby_router.toml") + "\n[planner]\nmodel = \"grbl\"\n");
  const std::string arcs = dir.write("arcs.ngc",
                                     "T1 M6\nG0 X20 Y10 Z1\nG1 Z-1 F100\nG64 P0.05 Q0.05\nF400\n"
                                     "G2 X20 Y30 I0 J10\nG2 X20 Y10 I0 J-10\nG1 X30\nY12\nX40\n"
                                     "Y14\nG0 Z5\nM30\n");
  for (const std::string& profile : {machines + "linuxcnc_sim.toml", grbl}) {
    const usina::test::Run r =
        usina("simulate " + quote(arcs) + " --stock box:50x40x10 --tool-shape 1=flat/6 --machine " +
              quote(profile) + " -o " + quote(dir.path("r.json")));
    ASSERT_EQ(r.status, 0) << r.err;
    const json j = json::parse(dir.read("r.json"));
    const usina::test::Run stats =
        usina("stats --format json --machine " + quote(profile) + " " + quote(arcs));
    ASSERT_EQ(stats.status, 0) << stats.err;
    EXPECT_NEAR(j["time_s"].get<double>(), json::parse(stats.out)["time"]["total_s"].get<double>(),
                1e-9)
        << profile;
    const json& rate = j["removal_rate"];
    double mm3 = 0.0;
    for (const json& b : rate["mm3_per_min"])
      mm3 += b.get<double>() * rate["bin_s"].get<double>() / 60.0;
    EXPECT_GT(j["removed_mm3"].get<double>(), 100.0);
    EXPECT_NEAR(mm3, j["removed_mm3"].get<double>(), 1e-6 * mm3) << profile;
    // The plunge takes 28.27 mm² × 100 mm/min, the slots 6 × 1 × 400 mm³/min at most.
    EXPECT_LE(rate["peak_mm3_per_min"].get<double>(), 2827.4 * 1.01) << profile;
    EXPECT_GE(rate["peak_mm3_per_min"].get<double>(), 2400.0 * 0.9) << profile;
  }
}

TEST(SimulateRateCli, AFasterMachineTakesLessTimeForTheSameVolume) {
  TempDir dir;
  // A router with a 60 s manual tool change and low accelerations.
  const std::string profile =
      std::string(USINA_TEST_DIR) + "/../examples/machines/hobby_router.toml";
  const json slow = simulate(dir, "--machine " + quote(profile));
  const json fast = simulate(dir);
  EXPECT_EQ(slow["machine"]["name"], "hobby router (grbl-like)");
  EXPECT_NEAR(slow["removed_mm3"].get<double>(), fast["removed_mm3"].get<double>(), 1e-9);
  EXPECT_GT(slow["time_s"].get<double>(), fast["time_s"].get<double>() + 50.0);
}

TEST(SimulateRateCli, AMachineProfileThatCannotBeReadIsBadInput) {
  TempDir dir;
  const std::string program = dir.write("slots.ngc", kSlots);
  const usina::test::Run missing =
      usina("simulate " + quote(program) + " --stock box:100x40x10 --machine " +
            quote(dir.path("none.toml")) + " -o " + quote(dir.path("r.json")));
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(missing.err.find("cannot read"), std::string::npos) << missing.err;
  EXPECT_FALSE(exists(dir.path("r.json")));
  const std::string bad = dir.write("bad.toml", "[machine]\nname = 5\n");
  const usina::test::Run wrong =
      usina("simulate " + quote(program) + " --stock box:100x40x10 --machine " + quote(bad) +
            " -o " + quote(dir.path("r.json")));
  EXPECT_EQ(wrong.status, 2);
  EXPECT_NE(wrong.err.find("cannot be used"), std::string::npos) << wrong.err;
  EXPECT_FALSE(exists(dir.path("r.json")));
}

}  // namespace
}  // namespace usina::test

namespace usina::test {
namespace {

const std::string kExamples = std::string(USINA_TEST_DIR) + "/../examples/";

// usina simulate JOB.toml: the job's stock, tools, machine and targets.
TEST(SimulateJobCli, AJobIsSimulatedOnItsStockWithItsToolsAndMachine) {
  TempDir dir;
  const std::string job = kExamples + "jobs/plate.toml";
  const usina::test::Run r = usina("simulate " + quote(job) + " -o " + quote(dir.path("r.json")));
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(dir.read("r.json"));
  EXPECT_EQ(j["stock"]["box"], nlohmann::json::parse("[130.0, 90.0, 10.0]"));
  EXPECT_EQ(j["stock"]["origin"], nlohmann::json::parse("[-5.0, -5.0, 0.0]"));
  EXPECT_EQ(j["machine"]["name"], "small VMC");
  // The two D5 holes through the 10 mm plate: 2 × π 2.5² × 10 and a little
  // of the point's cone beyond the stock's bottom (none: it is below).
  EXPECT_NEAR(j["per_tool"]["6"]["removed_mm3"].get<double>(), 2 * M_PI * 6.25 * 10, 0.01 * 393);
  // The pocket down to Z-4 wherever its 6 mm end mill reaches.
  ASSERT_EQ(j["targets"].size(), 1u);
  EXPECT_EQ(j["targets"][0]["operation"], 2);
  EXPECT_EQ(j["targets"][0]["above_mm2"].get<double>(), 0.0);
  EXPECT_GT(j["targets"][0]["area_mm2"].get<double>(), 1400.0);
  // The same time as the posted program's on the same machine.
  const usina::test::Run posted =
      usina("job " + quote(job) + " --post rs274ngc -o " + quote(dir.path("plate.ngc")));
  ASSERT_EQ(posted.status, 0) << posted.err;
  const usina::test::Run stats =
      usina("stats --format json --machine " + quote(kExamples + "machines/small_vmc.toml") + " " +
            quote(dir.path("plate.ngc")));
  ASSERT_EQ(stats.status, 0) << stats.err;
  EXPECT_NEAR(j["time_s"].get<double>(),
              nlohmann::json::parse(stats.out)["time"]["total_s"].get<double>(), 0.05);
}

TEST(SimulateJobCli, ABoringHeadCutsAtTheDiameterItIsSetTo) {
  // The bearing plate's head T13 (D8-24 in the library) set to D10 bores two
  // D8.5 pilot holes through the 10 mm plate: 2 × π (5² − 4.25²) × 10 mm³.
  // At its smallest diameter, D8, it would cut nothing.
  TempDir dir;
  const usina::test::Run r = usina("simulate " + quote(kExamples + "jobs/bearing_plate.toml") +
                                   " -o " + quote(dir.path("r.json")));
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(dir.read("r.json"));
  EXPECT_NEAR(j["per_tool"]["13"]["removed_mm3"].get<double>(), 2 * M_PI * (25 - 18.0625) * 10,
              0.03 * 436);
}

TEST(SimulateJobCli, APocketCutWithTooSmallATool) {
  // The pocket's path is for its 6 mm end mill; cut with a 3 mm one it
  // leaves ridges between the passes: material above the operation's target.
  TempDir dir;
  const usina::test::Run r = usina("simulate " + quote(kExamples + "jobs/plate.toml") +
                                   " --tool-shape 2=flat/3 -o " + quote(dir.path("r.json")));
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(
      r.err.find("warning[W_MATERIAL_ABOVE_TARGET]: operation 2 (pocket, layer POCKET) (Z-4)"),
      std::string::npos)
      << r.err;
  const nlohmann::json j = nlohmann::json::parse(dir.read("r.json"));
  EXPECT_GT(j["targets"][0]["above_mm2"].get<double>(), 100.0);
}

TEST(SimulateJobCli, ACylinderStockNeedsABoxGiven) {
  TempDir dir;
  std::string job = slurp(kExamples + "jobs/plate.toml");
  const std::string box = "shape = \"box\"\nsize = [130.0, 90.0, 10.0]";
  ASSERT_NE(job.find(box), std::string::npos);
  job.replace(job.find(box), box.size(), "shape = \"cylinder\"\ndiameter = 180.0\nheight = 10.0");
  const std::string corner = "origin = [-5.0, -5.0]";
  ASSERT_NE(job.find(corner), std::string::npos);
  job.replace(job.find(corner), corner.size(), "origin = [60.0, 40.0]");
  for (const char* f : {"machine = \"", "tools = \"", "materials = \"", "drawing = \""}) {
    const std::size_t at = job.find(f);
    ASSERT_NE(at, std::string::npos) << f;
    job.insert(at + std::string(f).size(), kExamples + "jobs/");
  }
  const std::string path = dir.write("round.toml", job);
  const usina::test::Run r = usina("simulate " + quote(path) + " -o " + quote(dir.path("r.json")));
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("the job's stock is a cylinder"), std::string::npos) << r.err;
  EXPECT_FALSE(exists(dir.path("r.json")));
  const usina::test::Run boxed =
      usina("simulate " + quote(path) + " --stock box:180x180x10 --origin -30,-50,0 -o " +
            quote(dir.path("r.json")));
  EXPECT_EQ(boxed.status, 0) << boxed.err;
}

TEST(SimulateJobCli, AJobWithAnErrorIsReportedAtItsLine) {
  TempDir dir;
  std::string job = slurp(kExamples + "jobs/plate.toml");
  job.replace(job.find("depth = 4.0"), 11, "dept = 4.0");
  for (const char* f : {"machine = \"", "tools = \"", "materials = \"", "drawing = \""})
    job.insert(job.find(f) + std::string(f).size(), kExamples + "jobs/");
  const usina::test::Run r =
      usina("simulate " + quote(dir.write("bad.toml", job)) + " -o " + quote(dir.path("r.json")));
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find("bad.toml:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("E_UNKNOWN_JOB_KEY"), std::string::npos) << r.err;
  EXPECT_FALSE(exists(dir.path("r.json")));
  const usina::test::Run missing =
      usina("simulate " + quote(dir.path("none.toml")) + " -o " + quote(dir.path("r.json")));
  EXPECT_EQ(missing.status, 2) << missing.err;
}

}  // namespace
}  // namespace usina::test
