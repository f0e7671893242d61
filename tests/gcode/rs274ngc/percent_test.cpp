// '%' lines in the rs274ngc dialect (docs/rs274ngc.md, "'%' lines"), as
// LinuxCNC 2.9's rs274 reads them: a first '%' opens the program, the next
// closes it; a '%' anywhere else is an error, except a last '%' with nothing
// after it, which usina takes as the end with a warning.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include <gtest/gtest.h>

#include "canon/toolpath.hpp"
#include "core/diagnostic.hpp"
#include "core/source.hpp"
#include "gcode/interp/interpreter.hpp"

namespace usina::gcode {
namespace {

struct Outcome {
  core::SourceManager sources;
  core::DiagnosticList diags;
  canon::Toolpath path;
  bool ok = false;

  // The X of every traverse, in order.
  std::vector<double> xs() const {
    std::vector<double> out;
    for (const canon::Op& op : path.ops())
      if (const auto* t = std::get_if<canon::Traverse>(&op.kind)) out.push_back(t->to.x);
    return out;
  }

  const core::Diagnostic* first(core::Severity s) const {
    for (const core::Diagnostic& d : diags.all())
      if (d.severity == s) return &d;
    return nullptr;
  }
};

std::unique_ptr<Outcome> run(const std::string& text, InterpOptions options = {}) {
  auto out = std::make_unique<Outcome>();
  const std::uint32_t id = out->sources.add(core::SourceFile::from_string("p.ngc", text));
  Interpreter interp(out->sources, std::move(options), out->path, out->diags);
  out->ok = interp.run(id);
  return out;
}

void expect_misplaced(const Outcome& r, std::uint32_t line) {
  EXPECT_FALSE(r.ok);
  const core::Diagnostic* e = r.first(core::Severity::Error);
  ASSERT_NE(e, nullptr);
  EXPECT_EQ(core::code_name(e->code), "E_MISPLACED_PERCENT") << e->message;
  EXPECT_EQ(e->loc.line, line) << e->message;
}

TEST(PercentLines, AFirstPercentOpensTheNextCloses) {
  const auto r = run("%\nG0 X1\n%\nG0 X2\nM2\n");
  EXPECT_TRUE(r->ok);
  EXPECT_EQ(r->xs(), std::vector<double>{1});
  EXPECT_EQ(r->first(core::Severity::Warning), nullptr);
  EXPECT_EQ(run("%\n%\nG0 X1\nM2\n")->xs(), std::vector<double>{});
}

TEST(PercentLines, BlankLinesAndBlanksMayStandBeforeTheOpeningPercent) {
  EXPECT_EQ(run("\n\n\n\n\n%\nG0 X1\n%\n")->xs(), std::vector<double>{1});
  EXPECT_EQ(run("  %\t\nG0 X1\n %\n")->xs(), std::vector<double>{1});
  EXPECT_EQ(run("\xEF\xBB\xBF%\nG0 X1\n%\n")->xs(), std::vector<double>{1});
}

TEST(PercentLines, APercentInTheMiddleIsAnError) {
  // The wild corpus's case: 3 ops instead of 25,000, without a word.
  const auto r = run("G0 X1\n%\nG0 X2\nM2\n");
  expect_misplaced(*r, 2);
  EXPECT_EQ(r->xs(), std::vector<double>{1});
  expect_misplaced(*run("(a comment)\n%\nG0 X1\n%\n"), 2);
  expect_misplaced(*run("G0 X1\nG0 X2\n%\nG0 X3\n"), 3);
  expect_misplaced(*run("G0 X1\n%\n(a comment after it)\n"), 2);
}

TEST(PercentLines, APercentWithMoreOnItsLineIsAnError) {
  expect_misplaced(*run("%(program)\nG0 X1\n%\n"), 1);
  expect_misplaced(*run("%\nG0 X1\n% (end)\n"), 3);
  expect_misplaced(*run("/%\nG0 X1\n%\n"), 1);
}

TEST(PercentLines, ALastPercentNeverOpenedEndsTheProgramWithAWarning) {
  // CAMotics' examples end so; LinuxCNC runs them, then reports an error.
  const auto r = run("G0 X1\nG0 X2\n%\n\n  \n");
  EXPECT_TRUE(r->ok);
  EXPECT_EQ(r->xs(), (std::vector<double>{1, 2}));
  const core::Diagnostic* w = r->first(core::Severity::Warning);
  ASSERT_NE(w, nullptr);
  EXPECT_EQ(core::code_name(w->code), "W_UNOPENED_PERCENT") << w->message;
  EXPECT_EQ(w->loc.line, 3u);
  EXPECT_EQ(r->first(core::Severity::Error), nullptr);
}

TEST(PercentLines, APercentAfterTheProgramEndIsNotRead) {
  const auto r = run("G0 X1\nM2\n%\nG0 X5\n");
  EXPECT_TRUE(r->ok);
  EXPECT_EQ(r->first(core::Severity::Warning), nullptr);
  EXPECT_EQ(r->xs(), std::vector<double>{1});
}

TEST(PercentLines, APercentInASubroutineNotOpenedIsAnError) {
  const std::string sub = "o<s> sub\nG0 X2\n%\nG0 X5\no<s> endsub\n";
  const auto r = run(sub + "G0 X1\no<s> call\nG0 X3\nM2\n");
  expect_misplaced(*r, 3);
  EXPECT_EQ(r->xs(), (std::vector<double>{1, 2}));
}

TEST(PercentLines, APercentInASubroutineFileOfAnOpenedProgramEndsIt) {
  // LinuxCNC ends the whole program there: the '%' flag is the program's,
  // not the file's.
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("usina_percent_test_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "s.ngc") << "%\no<s> sub\nG0 X2\n%\nG0 X5\no<s> endsub\n%\n";
  InterpOptions o;
  o.subroutine_path = {dir.string()};
  const auto opened = run("%\nG0 X1\no<s> call\nG0 X3\n%\n", std::move(o));
  EXPECT_TRUE(opened->ok);
  EXPECT_EQ(opened->xs(), (std::vector<double>{1, 2}));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace usina::gcode
