// A form's answer is bounded by what it names, not by the body: a body of
// thousands of unknown fields, or a field's name of a megabyte, gives at
// most kMaxFieldErrors entries and names of kMaxFieldName characters.
#include "dnc/form_fields.hpp"

#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "dnc/form_cycles.hpp"

namespace usina::dnc {
namespace {

TEST(FormFieldsBounds, ThousandsOfUnknownFieldsAreAHundredEntriesAndOneMore) {
  nlohmann::json body = {{"radius", 20}, {"depth", 3}, {"stepover", 4}};
  for (int i = 0; i < 5000; ++i)
    body["unknown_" + std::to_string(i)] = i;
  const FormProgram p = form_program("circle_pocket", body);
  EXPECT_TRUE(p.text.empty());
  ASSERT_EQ(p.errors.size(), kMaxFieldErrors + 1);
  EXPECT_EQ(p.errors.back().field, "");
  EXPECT_NE(p.errors.back().message.find("more than 100 fields"), std::string::npos)
      << p.errors.back().message;
}

TEST(FormFieldsBounds, AFieldsNameIsCutInTheAnswer) {
  const std::string name(1'000'000, 'k');
  nlohmann::json body = {{"radius", 20}, {"depth", 3}, {"stepover", 4}, {name, 1}};
  const FormProgram p = form_program("circle_pocket", body);
  ASSERT_FALSE(p.errors.empty());
  for (const FieldError& e : p.errors) {
    EXPECT_LE(e.field.size(), kMaxFieldName + 3) << e.message.substr(0, 100);
    EXPECT_LT(e.message.size(), 300u) << e.message.substr(0, 100);
  }
}

}  // namespace
}  // namespace usina::dnc
