// `usina trace --save-vars FILE`: the persistent variables written at the
// end of the run, also after an error, for the dialects that keep them.
#include <string>

#include <gtest/gtest.h>

#include "support/usina_process.hpp"

namespace {

using usina::test::slurp;
using usina::test::TempDir;
using usina::test::usina;

TEST(CliSaveVars, FanucWritesTheCommonVariablesItSet) {
  const TempDir dir;
  const std::string prog =
      dir.write("sv_fanuc.nc", "%\nO0001\n#500 = 1.5\n#501 = #500 + 1\nM30\n%\n");
  const std::string vars = dir.path("sv_fanuc.var");
  const auto r = usina("trace --dialect fanuc --save-vars " + vars + " " + prog);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(slurp(vars), "500\t1.500000\n501\t2.500000\n");
  // Read back: the next run starts from them and adds to them.
  const auto again = usina("trace --dialect fanuc --var-file " + vars + " --save-vars " + vars +
                           " " + dir.write("sv_fanuc2.nc", "#502 = #501 * 2\nM30\n"));
  EXPECT_EQ(again.status, 0) << again.err;
  EXPECT_EQ(slurp(vars), "500\t1.500000\n501\t2.500000\n502\t5.000000\n");
}

TEST(CliSaveVars, WrittenAlsoAfterAnError) {
  const TempDir dir;
  const std::string prog = dir.write("sv_alarm.nc", "#600 = 6\n#3000 = 1 (STOP)\n#601 = 1\nM30\n");
  const std::string vars = dir.path("sv_alarm.var");
  const auto r = usina("trace --dialect fanuc --save-vars " + vars + " " + prog);
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("E_MACRO_ALARM"), std::string::npos) << r.err;
  EXPECT_EQ(slurp(vars), "600\t6.000000\n");  // set before the alarm; #601 never ran
}

TEST(CliSaveVars, Rs274ngcWritesLinuxCncsParameters) {
  const TempDir dir;
  const std::string prog = dir.write("sv_lcnc.ngc", "G10 L2 P1 X7\nM2\n");
  const std::string vars = dir.path("sv_lcnc.var");
  const auto r = usina("trace --save-vars " + vars + " " + prog);
  EXPECT_EQ(r.status, 0) << r.err;
  const std::string text = slurp(vars);
  EXPECT_NE(text.find("5161\t0.000000\n"), std::string::npos) << text;
  EXPECT_NE(text.find("5220\t1.000000\n"), std::string::npos) << text;
  EXPECT_NE(text.find("5221\t7.000000\n"), std::string::npos) << text;
  EXPECT_NE(text.find("5390\t0.000000\n"), std::string::npos) << text;
}

TEST(CliSaveVars, DialectsWithoutVariablesAndUnwritableFiles) {
  const TempDir dir;
  const std::string prog = dir.write("sv_grbl.nc", "G0 X1\n");
  const auto grbl =
      usina("trace --dialect grbl --save-vars " + dir.path("sv_grbl.var") + " " + prog);
  EXPECT_EQ(grbl.status, 2);
  EXPECT_NE(grbl.err.find("keeps no variables"), std::string::npos) << grbl.err;
  const auto bad = usina("trace --dialect fanuc --save-vars /nonexistent-dir/x.var " + prog);
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("cannot write /nonexistent-dir/x.var"), std::string::npos) << bad.err;
}

}  // namespace
