// Issue 11, files and the command line: no verb destroys a file, a failed
// write is exit 2 with its reason, usage errors are exit 2 (docs/cli.md).
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>

#include "support/usina_process.hpp"

namespace usina::test {
namespace {

constexpr const char* kProgram = "G0 X1 Y1\nG1 X20 F300\nM2\n";

bool has_dev_full() {
  struct stat st {};

  return ::stat("/dev/full", &st) == 0 && S_ISCHR(st.st_mode);
}

TEST(OutputCli, ConvertOntoItsOwnInputIsRefusedBeforeAnythingIsWritten) {
  const TempDir dir;
  const std::string p = dir.write("s.ngc", kProgram);
  const test::Run r = usina("convert " + quote(p) + " --post fanuc -o " + quote(p));
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(contains(r.err, "also an input")) << r.err;
  EXPECT_EQ(slurp(p), kProgram);
}

TEST(OutputCli, GenOntoItsOwnDrawingIsRefused) {
  const TempDir dir;
  const std::string dxf = dir.write(
      "sq.dxf",
      "0\nSECTION\n2\nENTITIES\n0\nLINE\n8\n0\n10\n0\n20\n0\n11\n10\n21\n0\n0\nENDSEC\n0\nEOF\n");
  const std::string before = slurp(dxf);
  for (const std::string& verb : std::vector<std::string>{"from-dxf --depth 1", "profile --depth 1",
                                                          "pocket --depth 1 --stepover 2"}) {
    const test::Run r =
        usina("gen " + verb + " --dxf " + quote(dxf) + " --post rs274ngc -o " + quote(dxf));
    EXPECT_EQ(r.status, 2) << verb << "\n" << r.err;
    EXPECT_TRUE(contains(r.err, "also an input")) << verb << "\n" << r.err;
    EXPECT_EQ(slurp(dxf), before) << verb;
  }
}

TEST(OutputCli, SaveVarsOntoTheProgramIsRefusedButOntoTheVarFileIsAllowed) {
  const TempDir dir;
  const std::string p = dir.write("p.ngc", "#5161=1\nM2\n");
  const test::Run bad = usina("check " + quote(p) + " --save-vars " + quote(p));
  EXPECT_EQ(bad.status, 2);
  EXPECT_EQ(slurp(p), "#5161=1\nM2\n");
  const std::string vars = dir.write("p.var", "5161 0\n");
  const test::Run good =
      usina("check " + quote(p) + " --var-file " + quote(vars) + " --save-vars " + quote(vars));
  EXPECT_EQ(good.status, 0) << good.err;
  EXPECT_TRUE(contains(slurp(vars), "5161")) << slurp(vars);
}

TEST(OutputCli, DrawOntoTheProgramIsRefused) {
  const TempDir dir;
  const std::string p = dir.write("p.svg", kProgram);  // a program under a drawing's name
  const test::Run r = usina("draw " + quote(p) + " -o " + quote(p));
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(slurp(p), kProgram);
}

// As root, `-o /dev/null` used to replace the device node with a file; a
// node of our own stands in for it, so a failure cannot harm the machine.
TEST(OutputCli, ADeviceIsWrittenNotReplaced) {
  const TempDir dir;
  const std::string p = dir.write("p.ngc", kProgram);
  const std::string dev = dir.path("null");
  if (::mknod(dev.c_str(), S_IFCHR | 0666, makedev(1, 3)) != 0)
    GTEST_SKIP() << "mknod: " << std::strerror(errno);
  for (const std::string& args :
       std::vector<std::string>{"draw " + quote(p) + " --format svg -o " + quote(dev),
                                "convert " + quote(p) + " --post grbl -o " + quote(dev)}) {
    const test::Run r = usina(args);
    EXPECT_EQ(r.status, 0) << args << "\n" << r.err;

    struct stat st {};

    ASSERT_EQ(::lstat(dev.c_str(), &st), 0);
    EXPECT_TRUE(S_ISCHR(st.st_mode)) << args;
  }
}

TEST(OutputCli, AFifoIsWrittenNotReplaced) {
  const TempDir dir;
  const std::string p = dir.write("p.ngc", kProgram);
  const std::string fifo = dir.path("fifo");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const test::Run r = usina("convert " + quote(p) + " --post grbl -o " + quote(fifo) + " & cat " +
                            quote(fifo) + "; wait $!");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "G1 X20")) << r.out;

  struct stat st {};

  ASSERT_EQ(::lstat(fifo.c_str(), &st), 0);
  EXPECT_TRUE(S_ISFIFO(st.st_mode));
}

TEST(OutputCli, AFullStandardOutputIsExit2WithTheReason) {
  if (!has_dev_full()) GTEST_SKIP() << "no /dev/full";
  const TempDir dir;
  const std::string p = dir.write("p.ngc", kProgram);
  for (const std::string& args : std::vector<std::string>{
           "trace " + quote(p), "trace --format text " + quote(p), "stats " + quote(p),
           "stats --format json " + quote(p), "convert " + quote(p) + " --post fanuc",
           "calc bcd 1250", "draw " + quote(p) + " --format svg -o -",
           "gen drill --at 10,10 --depth 3 --post grbl"}) {
    const test::Run r = usina(args + " >/dev/full");
    EXPECT_EQ(r.status, 2) << args << "\n" << r.err;
    EXPECT_TRUE(contains(r.err, "cannot write standard output: No space left on device"))
        << args << "\n"
        << r.err;
  }
}

TEST(OutputCli, AFullDeviceAsTheOutputIsExit2) {
  if (!has_dev_full()) GTEST_SKIP() << "no /dev/full";
  const TempDir dir;
  const std::string p = dir.write("p.ngc", kProgram);
  for (const std::string& args :
       std::vector<std::string>{"draw " + quote(p) + " --format png -o /dev/full",
                                "convert " + quote(p) + " --post fanuc -o /dev/full"}) {
    const test::Run r = usina(args);
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_TRUE(contains(r.err, "cannot write /dev/full: No space left on device")) << args << "\n"
                                                                                    << r.err;
  }
}

TEST(OutputCli, AMissingFolderIsNamedWithTheReason) {
  const TempDir dir;
  const std::string p = dir.write("p.ngc", kProgram);
  const test::Run r = usina("draw " + quote(p) + " -o " + quote(dir.path("nodir/x.png")));
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(contains(r.err, dir.path("nodir/x.png") + ": No such file or directory")) << r.err;
}

TEST(OutputCli, AFailedConvertLeavesTheOldFileAndNoTemporary) {
  const TempDir dir;
  const std::string p = dir.write("bad.ngc", "G1 X10\nM2\n");  // no feed rate
  const std::string out = dir.write("out.ngc", "the old program\n");
  const test::Run r = usina("convert " + quote(p) + " --post fanuc -o " + quote(out));
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_EQ(slurp(out), "the old program\n");
  std::size_t files = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir.path()))
    ++files;
  EXPECT_EQ(files, 2u);
}

// `usina ARGS` with TMPDIR set to `tmpdir`.
test::Run usina_with_tmpdir(const std::string& tmpdir, const std::string& args) {
  const TempDir io;
  const std::string err = io.path("stderr");
  return shell("TMPDIR=" + quote(tmpdir) + " " + quote(USINA_BINARY) + " " + args +
                   " </dev/null 2>" + quote(err),
               err);
}

// What goes to standard output only when the run is good waits in an
// unnamed file in $TMPDIR (core/held_output.hpp): with a TMPDIR it can be
// made in the output is whole; with one it cannot, the run is exit 2 with
// the folder and the reason, and nothing reaches standard output.
TEST(OutputCli, HeldOutputWaitsInTmpdirAndABadTmpdirIsExit2WithTheReason) {
  const TempDir dir;
  const std::string p = dir.write("p.ngc", kProgram);
  const std::string not_a_folder = dir.write("file", "");
  const std::string held = dir.path("held");
  std::filesystem::create_directory(held);

  struct Case {
    std::string args;
    std::string expected;  // in the output when the run is good
    std::string what;      // the message's words for what is held
  };

  const std::vector<Case> cases{
      {"convert " + quote(p) + " --post fanuc", "X20.", "the program"},
      {"gen drill --at 10,10 --depth 3 --post grbl", "X10", "the program"},
      {"trace --format cldata " + quote(p), "", "the CL data"}};
  for (const Case& c : cases) {
    const test::Run good = usina_with_tmpdir(held, c.args);
    EXPECT_EQ(good.status, 0) << c.args << "\n" << good.err;
    EXPECT_FALSE(good.out.empty()) << c.args;
    EXPECT_TRUE(contains(good.out, c.expected)) << c.args << "\n" << good.out;
    EXPECT_TRUE(std::filesystem::is_empty(held)) << c.args;  // unnamed: nothing left behind
    for (const auto& [tmpdir, reason] : std::vector<std::pair<std::string, std::string>>{
             {dir.path("none"), "No such file or directory"}, {not_a_folder, "Not a directory"}}) {
      const test::Run bad = usina_with_tmpdir(tmpdir, c.args);
      EXPECT_EQ(bad.status, 2) << c.args << "\n" << bad.err;
      EXPECT_EQ(bad.out, "") << c.args;
      EXPECT_TRUE(contains(
          bad.err, "no temporary file to hold " + c.what + " in (" + tmpdir + "): " + reason))
          << c.args << "\n"
          << bad.err;
    }
  }
}

TEST(Cli, UsageErrorsExit2AndSayWhat) {
  struct Case {
    std::string args;
    std::string says;
  };

  for (const Case& c : std::vector<Case>{
           {"", "no verb given"},
           {"--bogus", "--bogus"},
           {"frob", "no verb 'frob'"},
           {"check", "check: file is required"},
           {"check --dialect klingon x.ngc", "--dialect"},
           {"calc bcd --number 3", "calc bcd:"},
           {"help frob", "no verb 'frob'"},
       }) {
    const test::Run r = usina(c.args);
    EXPECT_EQ(r.status, 2) << c.args;
    EXPECT_TRUE(contains(r.err, c.says)) << c.args << "\n" << r.err;
  }
}

TEST(Cli, HelpAndVersionExit0) {
  const test::Run help = usina("help");
  EXPECT_EQ(help.status, 0);
  EXPECT_TRUE(contains(help.out, "Exit status")) << help.out;
  const test::Run verb = usina("help draw");
  EXPECT_EQ(verb.status, 0);
  EXPECT_TRUE(contains(verb.out, "--view")) << verb.out;
  EXPECT_EQ(usina("--version").status, 0);
  EXPECT_EQ(usina("check --help").status, 0);
}

TEST(Cli, ConvertFromAndDialectMustAgree) {
  const TempDir dir;
  const std::string p = dir.write("p.ngc", kProgram);
  const test::Run clash = usina("convert " + quote(p) + " --from fanuc --dialect grbl --post grbl");
  EXPECT_EQ(clash.status, 2);
  EXPECT_TRUE(contains(clash.err, "disagree")) << clash.err;
  EXPECT_EQ(usina("convert " + quote(p) + " --from grbl --dialect grbl --post grbl").status, 0);
  EXPECT_EQ(usina("convert " + quote(p) + " --from grbl --post grbl").status, 0);
}

}  // namespace
}  // namespace usina::test
