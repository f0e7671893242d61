// The limits of one run as a user meets them (issue 11, "Time and size"):
// the operation budget on every verb that runs a program, no progress line
// when standard error is not a terminal, a runaway loop drawn once, and the
// block-length limit.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/usina_process.hpp"

namespace {

using usina::test::contains;
using usina::test::count;
using usina::test::lines;
using usina::test::quote;
using usina::test::TempDir;
using usina::test::usina;
using Result = usina::test::Run;

// Issue 11's four-line runaway loop.
const std::string kRunaway = "o1 while [1]\nG0 X1\nG0 X0\no1 endwhile\nM30\n";

TEST(RunLimitsCli, TraceStopsAtTheOperationBudget) {
  const TempDir s;
  const std::string p = s.write("loop.ngc", kRunaway);
  const Result r = usina("trace --max-ops 10 " + quote(p));
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_EQ(lines(r.out).size(), 10u);
  EXPECT_EQ(count(r.err, "[E_TOO_MANY_OPERATIONS]"), 1u) << r.err;
  EXPECT_TRUE(contains(r.err, "loop.ngc:2:1: error:")) << r.err;  // the block of op 11
}

TEST(RunLimitsCli, EveryVerbThatRunsAProgramTakesMaxOps) {
  const TempDir s;
  const std::string p = quote(s.write("loop.ngc", kRunaway));
  const std::vector<std::string> verbs = {"check", "trace", "stats",
                                          "draw -o " + quote(s.path("x.svg")),
                                          "convert --post fanuc -o " + quote(s.path("x.nc"))};
  for (const std::string& verb : verbs) {
    SCOPED_TRACE(verb);
    const Result r = usina(verb + " --max-ops 100 " + p);
    EXPECT_EQ(r.status, 1) << r.err;
    EXPECT_EQ(count(r.err, "[E_TOO_MANY_OPERATIONS]"), 1u) << r.err;
  }
}

TEST(RunLimitsCli, MaxOpsBelowOneIsAUsageError) {
  const TempDir s;
  const std::string p = s.write("a.ngc", "G0 X1\nM30\n");
  const Result r = usina("check --max-ops 0 " + quote(p));
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.status, 1);
  EXPECT_TRUE(contains(r.err, "--max-ops")) << r.err;
}

TEST(RunLimitsCli, NoProgressLineWhenStandardErrorIsNotATerminal) {
  // Long enough (some two million ops, a second or more) that a terminal
  // would see the progress line; standard error here is a file.
  const TempDir s;
  const std::string p = s.write("loop.ngc", kRunaway);
  const Result r = usina("check --max-iterations 1000000 " + quote(p));
  EXPECT_EQ(r.status, 1);
  EXPECT_TRUE(contains(r.err, "[E_TOO_MANY_ITERATIONS]")) << r.err;
  EXPECT_FALSE(contains(r.err, "\r")) << r.err;
  EXPECT_FALSE(contains(r.err, "operations of at most")) << r.err;
}

TEST(RunLimitsCli, DrawOfARunawayLoopDrawsItsPathOnce) {
  const TempDir s;
  const std::string p = s.write("loop.ngc", kRunaway);
  const Result r = usina("draw --view toolpath --max-iterations 100000 " + quote(p) + " -o " +
                         quote(s.path("x.svg")));
  EXPECT_EQ(r.status, 1) << r.err;  // the loop's iteration limit
  const std::string svg = s.read("x.svg");
  EXPECT_EQ(count(svg, "<line "), 1u) << svg.substr(0, 2000);
}

TEST(RunLimitsCli, AnOverLongBlockIsItsOwnError) {
  const TempDir s;
  const std::string p = s.write("long.ngc", "G0 X1 (" + std::string(5000, 'A') + ")\nM30\n");
  for (const char* dialect : {"rs274ngc", "fanuc", "romi", "grbl"}) {
    SCOPED_TRACE(dialect);
    const Result r = usina(std::string("check --dialect ") + dialect + " " + quote(p));
    EXPECT_EQ(r.status, 1) << r.err;
    EXPECT_TRUE(contains(r.err, "[E_BLOCK_TOO_LONG]")) << r.err.substr(0, 500);
    EXPECT_FALSE(contains(r.err, "[E_EXPECTED_EXPRESSION]"));
  }
}

}  // namespace
