// The start-up split of issue 19 (docs/performance.md, "Start-up"): the
// usina executable depends on no library of the server or of cairo; the
// server is usina-serve and the PNG/PDF writers usina-raster.so, both found
// beside usina only, and a missing or foreign helper is an error naming it.
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "support/usina_process.hpp"

namespace {

using usina::test::contains;
using usina::test::quote;
using usina::test::TempDir;
using Result = usina::test::Run;
namespace fs = std::filesystem;

const std::string kBuild = fs::path(USINA_BINARY).parent_path().string();
const std::string kProgram = "G21 G90\nG0 X0 Y0 Z5\nG1 Z-1 F100\nG1 X10\nG1 Y10\nG0 Z5\nM2\n";

// The NEEDED entries of an ELF file's dynamic section, as readelf -d lists them.
std::set<std::string> needed(const std::string& file) {
  const TempDir io;
  const Result r = usina::test::shell("readelf -d " + quote(file), io.path("err"));
  EXPECT_EQ(r.status, 0) << r.err;
  std::set<std::string> names;
  const std::string mark = "Shared library: [";
  for (const std::string& line : usina::test::lines(r.out)) {
    const auto at = line.find(mark);
    if (at == std::string::npos) continue;
    const auto from = at + mark.size();
    names.insert(line.substr(from, line.find(']', from) - from));
  }
  return names;
}

bool needs(const std::set<std::string>& names, const std::string& prefix) {
  for (const std::string& name : names)
    if (name.starts_with(prefix)) return true;
  return false;
}

// The file of a shared library this process has loaded ("" when none).
std::string loaded_library(const std::string& name) {
  std::ifstream maps("/proc/self/maps");
  std::string line;
  while (std::getline(maps, line)) {
    const auto at = line.find('/');
    if (at != std::string::npos && contains(line.substr(line.rfind('/')), name))
      return line.substr(at);
  }
  return "";
}

// `usina <args>` run from a copy of the executable alone in `dir`, so its
// helpers are not beside it (or are what the test put there).
Result lone_usina(const TempDir& dir, const std::string& args) {
  const std::string copy = dir.path("usina");
  if (!usina::test::exists(copy)) fs::copy_file(USINA_BINARY, copy);
  return usina::test::shell(quote(copy) + " " + args + " </dev/null 2>" + quote(dir.path("err")),
                            dir.path("err"));
}

TEST(Startup, TheCliNeedsNoServerOrCairoLibrary) {
  const auto names = needed(USINA_BINARY);
  ASSERT_TRUE(needs(names, "libc.so")) << "readelf -d listed no libc: the check reads nothing";
  for (const char* lib :
       {"libpq", "libssl", "libcrypto", "libsqlite3", "libsodium", "libmosquitto", "libboost",
        "libcairo", "libpixman", "libfontconfig", "libfreetype", "libX11", "libxcb", "libpng"})
    EXPECT_FALSE(needs(names, lib)) << "usina needs " << lib;
}

TEST(Startup, TheHelpersNeedWhatTheCliDoesNot) {
  EXPECT_TRUE(needs(needed(kBuild + "/usina-serve"), "libpqxx"));
  EXPECT_TRUE(needs(needed(kBuild + "/usina-raster.so"), "libcairo"));
}

TEST(Startup, ServeRunsTheServerExecutable) {
  const Result help = usina::test::usina("serve --help");
  EXPECT_EQ(help.status, 0) << help.err;
  EXPECT_TRUE(contains(help.out, "Usage: usina serve")) << help.out;
  const Result verb_help = usina::test::usina("help serve");
  EXPECT_EQ(verb_help.status, 0) << verb_help.err;
  EXPECT_EQ(verb_help.out, help.out);
  const Result bad = usina::test::usina("serve --no-such-flag");
  EXPECT_EQ(bad.status, 2);
  EXPECT_TRUE(bad.out.empty()) << bad.out;
  EXPECT_TRUE(contains(bad.err, "usina: error: serve: ")) << bad.err;
  EXPECT_TRUE(contains(bad.err, "--no-such-flag")) << bad.err;
  EXPECT_TRUE(contains(bad.err, "(usina serve --help)")) << bad.err;
}

TEST(Startup, ServeWithoutItsExecutableSaysWhichFileIsMissing) {
  const TempDir dir;
  const Result r = lone_usina(dir, "serve --help");
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_TRUE(contains(r.err, dir.path("usina-serve"))) << r.err;
  EXPECT_TRUE(contains(r.err, "No such file")) << r.err;
  // Not found elsewhere either: the build's server is on no path the copy looks in.
  const Result help = lone_usina(dir, "help serve");
  EXPECT_EQ(help.status, 2);
  EXPECT_TRUE(contains(help.err, dir.path("usina-serve"))) << help.err;
}

TEST(Startup, ThePicturesWithoutTheModuleAreAnErrorBeforeTheRun) {
  const TempDir dir;
  const std::string program = dir.write("p.ngc", kProgram);
  for (const char* out : {"p.png", "p.pdf"}) {
    const Result r = lone_usina(dir, "draw " + quote(program) + " -o " + quote(dir.path(out)));
    EXPECT_EQ(r.status, 2) << out;
    EXPECT_TRUE(contains(r.err, "usina: error: draw: cannot load " + dir.path("usina-raster.so")))
        << r.err;
    EXPECT_FALSE(usina::test::exists(dir.path(out))) << out;
  }
  const Result sim = lone_usina(
      dir, "simulate " + quote(program) + " --stock box:20x20x5 -o " + quote(dir.path("s.png")));
  EXPECT_EQ(sim.status, 2);
  EXPECT_TRUE(contains(sim.err, "simulate: cannot load " + dir.path("usina-raster.so"))) << sim.err;
  EXPECT_TRUE(sim.out.empty()) << "the run went ahead: " << sim.out;
  // A PDF setup sheet needs the module; an HTML one does not.
  const std::string job = "job " +
                          quote(std::string(USINA_TEST_DIR) + "/../examples/jobs/plate.toml") +
                          " --post fanuc -o " + quote(dir.path("j.nc")) + " --sheet ";
  const Result pdf = lone_usina(dir, job + quote(dir.path("j.pdf")));
  EXPECT_EQ(pdf.status, 2);
  EXPECT_TRUE(contains(pdf.err, "cannot load " + dir.path("usina-raster.so"))) << pdf.err;
  EXPECT_FALSE(usina::test::exists(dir.path("j.nc")));  // said before the job ran
  EXPECT_FALSE(usina::test::exists(dir.path("j.pdf")));
  EXPECT_EQ(lone_usina(dir, job + quote(dir.path("j.html"))).status, 0);
  // The verbs that need no helper work without them.
  const Result svg = lone_usina(dir, "draw " + quote(program) + " -o " + quote(dir.path("p.svg")));
  EXPECT_EQ(svg.status, 0) << svg.err;
  EXPECT_EQ(lone_usina(dir, "check " + quote(program)).status, 0);
}

TEST(Startup, AFileThatIsNotTheModuleIsRefused) {
  const TempDir dir;
  const std::string program = dir.write("p.ngc", kProgram);
  const std::string png = "draw " + quote(program) + " -o " + quote(dir.path("p.png"));
  dir.write("usina-raster.so", "not a shared object\n");
  const Result junk = lone_usina(dir, png);
  EXPECT_EQ(junk.status, 2);
  EXPECT_TRUE(contains(junk.err, "cannot load " + dir.path("usina-raster.so") + ", ")) << junk.err;
  // A real shared object without the module's entry: the C maths library
  // this test runs with.
  const std::string other_library = loaded_library("libm.so");
  ASSERT_FALSE(other_library.empty());
  fs::remove(dir.path("usina-raster.so"));
  fs::copy_file(other_library, dir.path("usina-raster.so"));
  const Result foreign = lone_usina(dir, png);
  EXPECT_EQ(foreign.status, 2);
  EXPECT_TRUE(contains(foreign.err, "it is not the module of this usina")) << foreign.err;
  EXPECT_FALSE(usina::test::exists(dir.path("p.png")));
}

TEST(Startup, TheModuleBesideTheCopyIsTheOneUsed) {
  const TempDir dir;
  const std::string program = dir.write("p.ngc", kProgram);
  fs::copy_file(kBuild + "/usina-raster.so", dir.path("usina-raster.so"));
  const Result r = lone_usina(dir, "draw " + quote(program) + " -o " + quote(dir.path("p.png")));
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(dir.read("p.png").substr(1, 3), "PNG");
}

}  // namespace
