#include "core/source.hpp"

#include <stdlib.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/files.hpp"

namespace usina::core {
namespace {

using test::TempDir;

TEST(SourceFile, FromStringKeepsNameAndText) {
  auto f = SourceFile::from_string("<stdin>", "G0 X1\n");
  EXPECT_EQ(f->name(), "<stdin>");
  EXPECT_EQ(f->text(), "G0 X1\n");
}

TEST(SourceFile, LineAtStripsLfAndCrLf) {
  auto f = SourceFile::from_string("p", "G0\r\nG1 X1\r\nM2\n");
  EXPECT_EQ(f->line_at(0), "G0");
  EXPECT_EQ(f->line_at(4), "G1 X1");
  EXPECT_EQ(f->line_at(11), "M2");
}

TEST(SourceFile, LineAtLastLineWithoutNewline) {
  auto f = SourceFile::from_string("p", "G0\nM2");
  EXPECT_EQ(f->line_at(3), "M2");
}

TEST(SourceFile, LineAtAnEmptyLineIsEmpty) {
  auto f = SourceFile::from_string("p", "G0\n\r\nM2\n");
  EXPECT_EQ(f->line_at(3), "");
  EXPECT_EQ(f->line_at(5), "M2");
}

TEST(SourceFile, LineAtPastTheEndIsEmptyNotACrash) {
  auto f = SourceFile::from_string("p", "G0\n");
  EXPECT_EQ(f->line_at(3), "");
  EXPECT_EQ(f->line_at(1000), "");
}

TEST(SourceFile, LineAtMidLineGivesTheRestOfThatLine) {
  auto f = SourceFile::from_string("p", "G0 X1\nM2\n");
  EXPECT_EQ(f->line_at(3), "X1");
}

TEST(SourceFile, LoneCarriageReturnInsideALineIsKept) {
  // Only the end of line is stripped; old Mac line ends are not line ends here.
  auto f = SourceFile::from_string("p", "G0\rX1\n");
  EXPECT_EQ(f->line_at(0), "G0\rX1");
}

TEST(SourceFile, OpenMissingFileGivesTheSystemsMessage) {
  std::string error;
  auto f = SourceFile::open("/nonexistent/usina/missing.ngc", error);
  EXPECT_EQ(f, nullptr);
  EXPECT_EQ(error, std::strerror(ENOENT));
}

TEST(SourceFile, OpenDirectoryIsAnError) {
  TempDir dir;
  std::string error;
  auto f = SourceFile::open(dir.path(), error);
  EXPECT_EQ(f, nullptr);
  EXPECT_EQ(error, "is a directory");
}

TEST(SourceFile, OpenReadsTheFileUnchanged) {
  TempDir dir;
  const std::string text = "%\r\nG0 X1 (a)\nM2\n%";
  const std::string p = dir.write("a.ngc", text);
  std::string error;
  auto f = SourceFile::open(p, error);
  ASSERT_NE(f, nullptr) << error;
  EXPECT_EQ(f->name(), p);
  EXPECT_EQ(f->text(), text);
  EXPECT_EQ(f->line_at(3), "G0 X1 (a)");
}

TEST(SourceFile, OpenEmptyFileGivesEmptyText) {
  TempDir dir;
  const std::string p = dir.write("empty.ngc", "");
  std::string error;
  auto f = SourceFile::open(p, error);
  ASSERT_NE(f, nullptr) << error;
  EXPECT_TRUE(f->text().empty());
  EXPECT_EQ(f->line_at(0), "");
}

TEST(SourceFile, TextStaysReadableAfterReleasingPages) {
  TempDir dir;
  // 9 MiB: more than one release chunk.
  std::string text;
  const std::string line = "G1 X1.2345 Y6.7890 Z-0.5 F100\n";
  while (text.size() < (9u << 20))
    text += line;
  text += "M2\n";
  const std::string p = dir.write("big.ngc", text);
  std::string error;
  auto f = SourceFile::open(p, error);
  ASSERT_NE(f, nullptr) << error;
  f->release_before(f->text().size() - 3);
  EXPECT_EQ(f->line_at(0), "G1 X1.2345 Y6.7890 Z-0.5 F100");
  EXPECT_EQ(f->line_at(f->text().size() - 3), "M2");
  EXPECT_EQ(f->text(), text);
}

TEST(SourceFile, ReleaseBeforeOnAStringIsHarmless) {
  auto f = SourceFile::from_string("p", "G0\n");
  f->release_before(100);
  EXPECT_EQ(f->text(), "G0\n");
}

TEST(SourceManager, IdsCountFromZeroAndUnknownIdsAreNull) {
  SourceManager m;
  EXPECT_EQ(m.add(SourceFile::from_string("a", "")), 0u);
  EXPECT_EQ(m.add(SourceFile::from_string("b", "")), 1u);
  EXPECT_EQ(m.size(), 2u);
  ASSERT_NE(m.get(1), nullptr);
  EXPECT_EQ(m.get(1)->name(), "b");
  EXPECT_EQ(m.get(2), nullptr);
  const SourceManager& cm = m;
  EXPECT_EQ(cm.get(0)->name(), "a");
  EXPECT_EQ(cm.get(99), nullptr);
}

}  // namespace
}  // namespace usina::core
