// Issue 11: a tool table line `T1 P1 D-6` was accepted (holes got diameter
// -6). Every real word is within a range: the diameter from 0 to 1000 mm,
// offsets within ±10 m, angles within ±360°; NaN and infinity are refused.
#include <memory>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/diagnostic.hpp"
#include "core/source.hpp"
#include "gcode/tool_table.hpp"

namespace usina::gcode {
namespace {

struct Read {
  std::unique_ptr<core::SourceFile> file;
  core::DiagnosticList diags;
  std::optional<ToolTable> table;
};

std::unique_ptr<Read> read(const std::string& text, double mm_per_unit = 1.0) {
  auto r = std::make_unique<Read>();
  r->file = core::SourceFile::from_string("tools.tbl", text);
  r->table = read_tool_table(*r->file, 1, mm_per_unit, r->diags);
  return r;
}

TEST(ToolTableLimits, ANegativeDiameterIsAnErrorAndTheToolIsNotRead) {
  const auto r = read("T1 P1 D-6\nT2 P2 D6\n");
  ASSERT_TRUE(r->table);
  EXPECT_EQ(r->table->find(1), nullptr);
  ASSERT_NE(r->table->find(2), nullptr);
  ASSERT_EQ(r->diags.all().size(), 1u);
  const core::Diagnostic& d = r->diags.all().front();
  EXPECT_EQ(d.code, core::Code::BadToolTable);
  EXPECT_EQ(d.severity, core::Severity::Error);
  EXPECT_EQ(d.loc.line, 1u);
  EXPECT_EQ(d.loc.col, 8u);  // at the value
  EXPECT_EQ(d.message,
            "diameter D-6 is out of range; it must be from 0 to 1000 mm (a diameter is not "
            "negative)");
}

TEST(ToolTableLimits, EveryWordOutOfItsRangeIsAnError) {
  for (const char* word :
       {"D1001", "D-0.001", "X10001", "Y-1e300", "Z1e300", "U2e4", "V-2e4", "W10000.5", "A361",
        "B-400", "C1e9", "I720", "J-361", "Dnan", "Zinf", "X-inf", "Q10", "T-1", "P-1"}) {
    SCOPED_TRACE(word);
    const auto r = read(std::string("T1 P1 ") + (word[0] == 'T' || word[0] == 'P' ? "" : word) +
                        "\n" + (word[0] == 'T' ? std::string(word) + " P3\n" : "") +
                        (word[0] == 'P' ? std::string("T4 ") + word + "\n" : ""));
    EXPECT_EQ(r->diags.error_count(), 1);
  }
}

TEST(ToolTableLimits, TheRangeIsInTheTablesUnits) {
  // An inch machine: 1000 mm is 39.37 inches.
  EXPECT_EQ(read("T1 P1 D40\n", 25.4)->diags.error_count(), 1);
  const auto r = read("T1 P1 D39\n", 25.4);
  EXPECT_EQ(r->diags.error_count(), 0);
  EXPECT_DOUBLE_EQ(r->table->find(1)->diameter, 39 * 25.4);
  EXPECT_THAT(read("T1 P1 D40\n", 25.4)->diags.all().front().message,
              testing::HasSubstr("from 0 to 39.3701 machine units"));
}

TEST(ToolTableLimits, EveryValueWithinItsRangeIsRead) {
  const auto r = read("T1 P1 X-10000 Y10000 Z9999.9 A-360 B360 C0 U1 V-1 W0 D0 I-360 J360 Q9\n");
  EXPECT_TRUE(r->diags.all().empty());
  ASSERT_TRUE(r->table && r->table->find(1));
  EXPECT_EQ(r->table->find(1)->offset.x, -10000.0);
  EXPECT_EQ(r->table->find(1)->diameter, 0.0);  // 0: the diameter is not known
}

}  // namespace
}  // namespace usina::gcode
