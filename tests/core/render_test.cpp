// core::render and core::printable: a diagnostic shows at most a window of
// its line, and nothing from a program reaches a terminal unescaped.
#include <fcntl.h>
#include <unistd.h>

#include <string>

#include <gtest/gtest.h>

#include "core/source.hpp"
#include "core/text.hpp"

namespace usina::core {
namespace {

std::string render_at(const std::string& text, std::uint32_t col, std::uint32_t length = 1) {
  SourceManager sources;
  const std::uint32_t id = sources.add(SourceFile::from_string("p.ngc", text));
  Diagnostic d{Code::UnknownWord, Severity::Error, {id, 1, col, length, 0}, "bad"};
  return render(d, sources);
}

TEST(Printable, ControlCharactersAndBadBytesAreEscaped) {
  EXPECT_EQ(printable("a\x1b[2Jb"), "a\\x1b[2Jb");
  EXPECT_EQ(printable("caf\xe9"), "caf\\xe9");
  EXPECT_EQ(printable("caf\xc3\xa9"), "caf\xc3\xa9");  // valid UTF-8 stays
  EXPECT_EQ(printable("tab\there"), "tab\\there");
  EXPECT_EQ(printable(std::string("nul\0x", 5)), "nul\\x00x");
  EXPECT_EQ(printable("\xc2\x9b"), "\\xc2\\x9b");           // C1 CSI
  EXPECT_EQ(printable("\xed\xa0\x80"), "\\xed\\xa0\\x80");  // a surrogate
  EXPECT_EQ(printable("\xc0\xaf"), "\\xc0\\xaf");           // an overlong '/'
}

TEST(Utf8, SequencesAreMeasured) {
  EXPECT_EQ(utf8_sequence_at("a", 0), 1u);
  EXPECT_EQ(utf8_sequence_at("\xc3\xa9", 0), 2u);
  EXPECT_EQ(utf8_sequence_at("\xe2\x82\xac", 0), 3u);
  EXPECT_EQ(utf8_sequence_at("\xf0\x9f\x94\xa7", 0), 4u);
  EXPECT_EQ(utf8_sequence_at("\xe2\x82", 0), 0u);          // cut short
  EXPECT_EQ(utf8_sequence_at("\xf4\x90\x80\x80", 0), 0u);  // past U+10FFFF
}

TEST(Render, TheMessageAndTheLineAreEscaped) {
  SourceManager sources;
  const std::uint32_t id = sources.add(SourceFile::from_string("p\x1b.ngc", "G1 (\x1b[2J) Q1\n"));
  Diagnostic d{Code::UnknownWord, Severity::Error, {id, 1, 11, 2, 0}, "word \x1b[31m"};
  const std::string r = render(d, sources);
  EXPECT_EQ(r.find('\x1b'), std::string::npos) << r;
  EXPECT_EQ(r,
            "p\\x1b.ngc:1:11: error: word \\x1b[31m [E_UNKNOWN_WORD]\n"
            "  G1 (\\x1b[2J) Q1\n"
            "               ^~\n");  // under Q: the escape is 4 columns wide
}

TEST(Render, ACaretAfterMultiByteCharactersStaysUnderItsWord) {
  // "(é)" is 4 bytes and 3 columns: the caret counts columns.
  EXPECT_EQ(render_at("(\xc3\xa9) Q1\n", 6, 2),
            "p.ngc:1:6: error: bad [E_UNKNOWN_WORD]\n"
            "  (\xc3\xa9) Q1\n"
            "      ^~\n");
}

TEST(Render, ALongLineShowsAWindowAroundTheError) {
  const std::string line = std::string(100000, 'X') + "Q1" + std::string(100000, 'Y');
  const std::string r = render_at(line, 100001, 2);
  EXPECT_LT(r.size(), 600u) << r.size();
  EXPECT_NE(r.find("...XXX"), std::string::npos);
  EXPECT_NE(r.find("YYY...\n"), std::string::npos);
  // The caret stands under Q.
  const std::size_t text = r.find("  ...");
  const std::size_t q = r.find('Q', text) - text;
  const std::size_t caret_line = r.find('\n', text) + 1;
  EXPECT_EQ(r.find('^', caret_line) - caret_line, q) << r;
}

TEST(Render, ALongLineErrorAtItsStartOrEnd) {
  const std::string line(50000, 'X');
  EXPECT_LT(render_at(line, 1).size(), 600u);
  const std::string end = render_at(line, 50001);
  EXPECT_LT(end.size(), 600u);
  EXPECT_NE(end.find("...XXX"), std::string::npos) << end;
}

TEST(SourceFile, APipeIsReadWhole) {
  int fds[2];
  ASSERT_EQ(::pipe(fds), 0);
  ASSERT_EQ(::write(fds[1], "G0 X1\n", 6), 6);
  ::close(fds[1]);
  std::string why;
  auto f = SourceFile::open_descriptor(fds[0], "<pipe>", why, 1024);
  ::close(fds[0]);
  ASSERT_NE(f, nullptr) << why;
  EXPECT_EQ(f->text(), "G0 X1\n");
}

TEST(SourceFile, AnEndlessDeviceIsCutAtItsBound) {
  std::string why;
  auto f = SourceFile::open("/dev/zero", why, 1 << 20);
  EXPECT_EQ(f, nullptr);
  EXPECT_NE(why.find("larger than 1 MiB"), std::string::npos) << why;
}

TEST(SourceFile, WithoutABoundOnlyRegularFilesAreRead) {
  std::string why;
  EXPECT_EQ(SourceFile::open("/dev/zero", why), nullptr);
  EXPECT_EQ(why, "not a regular file");
}

TEST(SourceFile, AFifoNobodyWritesDoesNotHang) {
  char name[] = "/tmp/usina_fifo_XXXXXX";
  ASSERT_NE(::mkdtemp(name), nullptr);
  const std::string fifo = std::string(name) + "/f";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::string why;
  EXPECT_EQ(SourceFile::open(fifo, why), nullptr);  // a subroutine file that is a FIFO
  auto f = SourceFile::open(fifo, why, 1024);       // a program given as a FIFO: empty
  ASSERT_NE(f, nullptr) << why;
  EXPECT_EQ(f->text(), "");
  ::unlink(fifo.c_str());
  ::rmdir(name);
}

}  // namespace
}  // namespace usina::core
