// Drawings usina cannot read, given to `gen from-dxf`, `gen pocket --dxf` and
// `gen profile --dxf`: each ends with exit status 2 and a message that names
// the file (and the line), never a hang (issue 11, "Time and size"). Every
// command runs under `timeout`, so a regression fails instead of hanging ctest.
#include <cstdio>
#include <string>

#include <gtest/gtest.h>
#include <sys/wait.h>

#include "support/usina_process.hpp"

namespace {

using usina::test::contains;
using usina::test::quote;
using Result = usina::test::Run;
using usina::test::TempDir;

// Seconds a command may take; a hang ends with status 124 (timeout's).
constexpr int kTimeLimit = 30;

// `usina <args>` as usina_process.hpp's usina() runs it, under timeout(1);
// `input` is standard input, through a pipe when `piped`.
Result usina_within(const std::string& args, const std::string& input = "", bool piped = false) {
  const TempDir io;
  const std::string in = io.write("stdin", input);
  const std::string err = io.path("stderr");
  const std::string run = "timeout -k 5 " + std::to_string(kTimeLimit) + " " + quote(USINA_BINARY) +
                          " " + args + " 2>" + quote(err);
  const std::string cmd = piped ? "cat " + quote(in) + " | " + run : run + " <" + quote(in);
  return usina::test::shell(cmd, err);
}

const char* const kVerbs[] = {
    "gen from-dxf {} --depth 1",
    "gen pocket --dxf {} --depth 1 --stepover 1 --tool-diameter 2",
    "gen profile --dxf {} --side outside --depth 1 --tool-diameter 2",
};

std::string command(const char* verb, const std::string& drawing, const std::string& output) {
  std::string c = verb;
  c.replace(c.find("{}"), 2, quote(drawing));
  return c + " --post rs274ngc -o " + quote(output);
}

std::string entities(const std::string& body) {
  return "0\nSECTION\n2\nENTITIES\n" + body + "0\nENDSEC\n0\nEOF\n";
}

// A closed 20 × 10 rectangle on layer `layer` (line 8 of the file).
std::string rectangle(const std::string& layer) {
  return entities("0\nLWPOLYLINE\n8\n" + layer +
                  "\n90\n4\n70\n1\n10\n0\n20\n0\n10\n20\n20\n0\n10\n20\n20\n10\n10\n0\n20\n10\n");
}

class DxfInput : public ::testing::Test {
 protected:
  // Every verb on `drawing` fails with status 2, `code` and `part` on
  // standard error, and writes no program.
  void refused(const std::string& drawing, const std::string& code, const std::string& part) {
    for (const char* verb : kVerbs) {
      const std::string out = dir_.path("out.ngc");
      const Result r = usina_within(command(verb, drawing, out));
      EXPECT_EQ(r.status, 2) << verb << "\n" << r.err;
      EXPECT_TRUE(contains(r.err, code)) << verb << "\n" << r.err;
      EXPECT_TRUE(contains(r.err, part)) << verb << "\n" << r.err;
      EXPECT_FALSE(usina::test::exists(out)) << verb << " wrote a program";
    }
  }

  // Every verb reads `drawing` and writes a program.
  void accepted(const std::string& drawing) {
    for (const char* verb : kVerbs) {
      const std::string out = dir_.path("ok.ngc");
      const Result r = usina_within(command(verb, drawing, out));
      EXPECT_EQ(r.status, 0) << verb << "\n" << r.err;
      EXPECT_TRUE(contains(usina::test::slurp(out), "G1")) << verb;
    }
  }

  const TempDir dir_;
};

TEST_F(DxfInput, LineOf1024CharactersIsAnErrorNotAHang) {
  const std::string f = dir_.write("long.dxf", rectangle(std::string(1024, 'L')));
  refused(f, "E_DXF_MALFORMED", "long.dxf:8: a value of 1024 characters");
}

TEST_F(DxfInput, LineOf1023CharactersIsRead) {
  accepted(dir_.write("long.dxf", rectangle(std::string(1023, 'L'))));
}

TEST_F(DxfInput, FolderIsUnreadable) {
  refused(dir_.path(), "E_DXF_UNREADABLE", "a folder, not a drawing");
}

TEST_F(DxfInput, RandomBytesAreRefusedNotAHang) {
  // Twelve files of random bytes as the issue tried (3 of its 12 hung).
  unsigned state = 2024;
  for (int file = 0; file < 12; ++file) {
    std::string bytes;
    for (int i = 0; i < 4000 * (file + 1); ++i) {
      state = state * 1103515245u + 12345u;
      bytes.push_back(static_cast<char>(state >> 23));
    }
    const std::string f = dir_.write("random.dxf", bytes);
    const Result r = usina_within(command(kVerbs[0], f, dir_.path("out.ngc")));
    EXPECT_EQ(r.status, 2) << file << "\n" << r.err;
    EXPECT_TRUE(contains(r.err, "random.dxf")) << r.err;
    EXPECT_TRUE(contains(r.err, "E_DXF_UNREADABLE") || contains(r.err, "E_DXF_MALFORMED")) << r.err;
  }
}

TEST_F(DxfInput, EndlessInputIsTooBig) {
  refused("/dev/zero", "E_DXF_UNREADABLE", "larger than 64 MiB");
}

TEST_F(DxfInput, CutShortDrawingIsRefused) {
  const std::string whole = rectangle("CUT");
  const std::string f = dir_.write("cut.dxf", whole.substr(0, whole.size() - 20));
  refused(f, "E_DXF_MALFORMED", "cut.dxf:");
}

TEST_F(DxfInput, CountBeyondTheVerticesIsRefused) {
  std::string text = rectangle("CUT");
  text.replace(text.find("90\n4\n"), 5, "90\n1073741825\n");
  refused(dir_.write("count.dxf", text), "E_DXF_MALFORMED",
          "count.dxf:5: the LWPOLYLINE declares 1073741825 vertices (group 90) but lists 4");
}

TEST_F(DxfInput, DrawingOnStandardInputIsRead) {
  // `cat part.dxf | usina gen from-dxf /dev/stdin`: a pipe is read to its end.
  const std::string out = dir_.path("out.ngc");
  const Result r = usina_within(command(kVerbs[0], "/dev/stdin", out), rectangle("CUT"), true);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(contains(usina::test::slurp(out), "G1"));
}

}  // namespace
