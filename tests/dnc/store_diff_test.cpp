// The diff algorithm against a slow, sure longest common subsequence, and
// the normalised and plain program diffs.
#include "dnc/store_diff.hpp"

#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "dnc/store_normalise.hpp"
#include "dnc/store_program_diff.hpp"

namespace usina::dnc {
namespace {

using Ids = std::vector<std::uint32_t>;

// b rebuilt from a and the edits: what any correct diff must give.
Ids apply(const Ids& a, const Ids& b, const LineDiff& d) {
  Ids out;
  std::size_t ai = 0;
  std::size_t bi = 0;
  for (const Edit& e : d.edits) {
    EXPECT_EQ(e.a_begin, ai);
    EXPECT_EQ(e.b_begin, bi);
    for (std::size_t k = 0; k < e.count; ++k) {
      if (e.kind == EditKind::Equal) {
        EXPECT_EQ(a[ai + k], b[bi + k]);
        out.push_back(a[ai + k]);
      } else if (e.kind == EditKind::Insert) {
        out.push_back(b[bi + k]);
      }
    }
    if (e.kind != EditKind::Insert) ai += e.count;
    if (e.kind != EditKind::Delete) bi += e.count;
  }
  EXPECT_EQ(ai, a.size());
  EXPECT_EQ(bi, b.size());
  return out;
}

std::size_t lcs(const Ids& a, const Ids& b) {
  std::vector<std::vector<std::size_t>> t(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 1; i <= a.size(); ++i)
    for (std::size_t j = 1; j <= b.size(); ++j)
      t[i][j] = a[i - 1] == b[j - 1] ? t[i - 1][j - 1] + 1 : std::max(t[i - 1][j], t[i][j - 1]);
  return t[a.size()][b.size()];
}

TEST(Diff, RandomPairsAreRebuiltAndMinimal) {
  std::mt19937 rng(13);
  for (int round = 0; round < 400; ++round) {
    std::uniform_int_distribution<int> len(0, 40);
    std::uniform_int_distribution<std::uint32_t> sym(0, 1 + static_cast<std::uint32_t>(round % 9));
    Ids a(static_cast<std::size_t>(len(rng)));
    Ids b(static_cast<std::size_t>(len(rng)));
    for (auto& x : a)
      x = sym(rng);
    for (auto& x : b)
      x = sym(rng);
    const LineDiff d = diff_ids(a, b);
    ASSERT_EQ(apply(a, b, d), b) << "round " << round;
    EXPECT_EQ(a.size() - d.deleted, lcs(a, b)) << "round " << round;
    EXPECT_EQ(b.size() - d.inserted, lcs(a, b)) << "round " << round;
  }
}

TEST(Diff, EmptyAndIdenticalAndDisjoint) {
  EXPECT_TRUE(diff_ids({}, {}).identical());
  const Ids a{1, 2, 3};
  EXPECT_TRUE(diff_ids(a, a).identical());
  const LineDiff d = diff_ids(a, Ids{4, 5});
  EXPECT_EQ(d.deleted, 3u);
  EXPECT_EQ(d.inserted, 2u);
  EXPECT_EQ(diff_ids({}, a).inserted, 3u);
  EXPECT_EQ(diff_ids(a, {}).deleted, 3u);
}

TEST(Diff, AShuffleOfManyLinesStillEndsAndRebuilds) {
  // Past the search bound the split is no longer optimal, but still correct.
  Ids a(20000);
  for (std::uint32_t i = 0; i < a.size(); ++i)
    a[i] = i;
  Ids b = a;
  std::shuffle(b.begin(), b.end(), std::mt19937(5));
  const LineDiff d = diff_ids(a, b);
  EXPECT_EQ(apply(a, b, d), b);
}

TEST(Normalise, RenumberingLineEndsBlankLinesPercentAndLeaderAreIgnored) {
  const std::string a = "%\nO1000\nN10 G0 X0 Y0\nN20 G1 X10 F100\n\nN30 M30\n%\n";
  const std::string b = std::string("\0\0\0", 3) +
                        "%\r\nO1000\r\nN100 G0 X0 Y0;\r\n  \r\nN110G1 X10 F100\r\nM30\r\n%\r\n\x7f";
  EXPECT_TRUE(normalised_diff(a, b).diff.identical());
  EXPECT_FALSE(plain_diff(a, b).diff.identical());
}

TEST(Normalise, BlockDeleteKeepsItsSlashWithoutTheNumber) {
  const auto blocks = normalise_program("/N10 G0 X1\n/ N20 G0 X2\n");
  ASSERT_EQ(blocks.size(), 2u);
  EXPECT_EQ(blocks[0].text, "/G0 X1");
  EXPECT_EQ(blocks[1].text, "/G0 X2");
  EXPECT_EQ(blocks[1].line, 2u);
}

TEST(Normalise, ValuesCommentsAndCaseStillCount) {
  EXPECT_FALSE(normalised_diff("G1 X10\n", "G1 X10.1\n").diff.identical());
  EXPECT_FALSE(normalised_diff("G1 X10 (A)\n", "G1 X10 (B)\n").diff.identical());
  EXPECT_FALSE(normalised_diff("g1 x10\n", "G1 X10\n").diff.identical());
  // An N in the middle of a block is not a sequence number.
  EXPECT_FALSE(normalised_diff("G1 X1 N5\n", "G1 X1 N6\n").diff.identical());
}

TEST(Normalise, RomiHashEndsBlocks) {
  const NormaliseRules romi = normalise_rules("romi");
  const auto blocks = normalise_program("N10 G0 X1#N20 G1 X2 F100#\n", romi);
  ASSERT_EQ(blocks.size(), 2u);
  EXPECT_EQ(blocks[1].text, "G1 X2 F100");
  EXPECT_TRUE(normalised_diff("G0 X1#G1 X2 F100#\n", "G0 X1\nG1 X2 F100\n", romi).diff.identical());
  // In rs274ngc '#' is a parameter: no block end.
  EXPECT_EQ(normalise_program("#1=2 G0 X#1\n", normalise_rules("rs274ngc")).size(), 1u);
}

TEST(UnifiedDiff, HunksCarryLineNumbersAndContext) {
  std::string a;
  std::string b;
  for (int i = 1; i <= 20; ++i) {
    a += "G1 X" + std::to_string(i) + "\n";
    b += (i == 10 ? std::string("G1 X10.5") : "G1 X" + std::to_string(i)) + "\n";
  }
  b += "M30\n";
  const std::string u = unified_diff(plain_diff(a, b), "old", "new", 2);
  EXPECT_EQ(u,
            "--- old\n+++ new\n"
            "@@ -8,5 +8,5 @@\n G1 X8\n G1 X9\n-G1 X10\n+G1 X10.5\n G1 X11\n G1 X12\n"
            "@@ -19,2 +19,3 @@\n G1 X19\n G1 X20\n+M30\n");
  EXPECT_EQ(unified_diff(plain_diff(a, a), "old", "new"), "");
}

TEST(UnifiedDiff, NormalisedHunksPointAtTheProgramsLines) {
  const std::string a = "%\nN10 G0 X0\nN20 G1 X1 F100\nN30 M30\n%\n";
  const std::string b = "%\n\nN5 G0 X0\nN6 G1 X2 F100\nN7 M30\n%\n";
  const std::string u = unified_diff(normalised_diff(a, b), "a", "b", 1);
  EXPECT_EQ(u, "--- a\n+++ b\n@@ -2,3 +3,3 @@\n G0 X0\n-G1 X1 F100\n+G1 X2 F100\n M30\n");
}

}  // namespace
}  // namespace usina::dnc
