// The rs274ngc dialect: LinuxCNC's language, run by the interpreter of
// interp/ whose G/M table is interp/codes.cpp (g_group, m_group).
#include "gcode/dialect.hpp"

namespace usina::gcode {
namespace {

class Rs274Runner final : public ProgramRunner {
 public:
  explicit Rs274Runner(RunContext& c) : interp_(c.sources, std::move(c.options), c.sink, c.diags) {}

  void set_parameter(int index, double value) override { interp_.set_parameter(index, value); }

  bool run(std::uint32_t file) override { return interp_.run(file); }

 private:
  Interpreter interp_;
};

std::unique_ptr<ProgramRunner> make(RunContext context) {
  return std::make_unique<Rs274Runner>(context);
}

}  // namespace

const Dialect& rs274ngc_dialect() {
  static const Dialect d{
      "rs274ngc",
      "LinuxCNC's RS274NGC: newline ends a block, ( ) and ; comments, #1 and #<name> "
      "parameters, [ ] expressions, O-word control flow",
      LexicalRules{"\n", "( ) and ; to end of line", "#1..#5602, #<name>", false, false, false},
      {},
      {},
      {},
      &make};
  return d;
}

}  // namespace usina::gcode
