// Program text in a trace: every JSONL line stays valid JSON whatever bytes
// a comment holds (issue 11: a Latin-1 "(café)" made the trace invalid), and
// the text form never sends a control character to a terminal.
#include <stdio.h>

#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "canon/op.hpp"
#include "canon/trace_writer.hpp"

namespace usina::canon {
namespace {

std::string text_of_comment(const std::string& text) {
  const nlohmann::json j = nlohmann::json::parse(to_jsonl({Comment{text}, {0, 1, 1, 0, 0}}));
  return j.at("text").get<std::string>();
}

TEST(TraceText, Latin1BytesAreReadAsLatin1) {
  EXPECT_EQ(text_of_comment("caf\xe9"), "caf\xc3\xa9");  // é
  EXPECT_EQ(text_of_comment("FURA\xc7\xc3O"), "FURA\xc3\x87\xc3\x83O");
}

TEST(TraceText, ValidUtf8IsKept) {
  EXPECT_EQ(text_of_comment("caf\xc3\xa9 \xe2\x82\xac"), "caf\xc3\xa9 \xe2\x82\xac");
}

TEST(TraceText, ControlCharactersAreEscaped) {
  const std::string line = to_jsonl({Comment{"a\x1b[2J\x7f"}, {0, 1, 1, 0, 0}});
  EXPECT_EQ(line.find('\x1b'), std::string::npos) << line;
  EXPECT_EQ(text_of_comment("a\x1b[2J\x7f"), "a\x1b[2J\x7f");
}

TEST(TraceText, EveryByteGivesValidJson) {
  for (int b = 0; b < 256; ++b) {
    const std::string text = {'x', static_cast<char>(b), 'y'};
    EXPECT_NO_THROW(text_of_comment(text)) << b;
  }
  // Sequences cut short or overlong, surrogates.
  for (const std::string text : {"\xe2\x82", "\xc0\xaf", "\xed\xa0\x80", "\xf4\x90\x80\x80"})
    EXPECT_NO_THROW(text_of_comment(text)) << text;
}

TEST(TraceText, TheTextFormatEscapesControls) {
  char* buf = nullptr;
  std::size_t len = 0;
  FILE* mem = open_memstream(&buf, &len);
  {
    TraceWriter w(mem, TraceFormat::Text);
    w.on({Comment{"x\x1b[2Jy"}, {0, 1, 1, 0, 0}});
    w.finish();
  }
  std::fclose(mem);
  const std::string out(buf, len);
  std::free(buf);
  EXPECT_EQ(out.find('\x1b'), std::string::npos) << out;
  EXPECT_NE(out.find("x\\x1b[2Jy"), std::string::npos) << out;
}

}  // namespace
}  // namespace usina::canon
