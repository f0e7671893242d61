// The rs274ngc dialect: LinuxCNC's language, run by the interpreter of
// interp/ reading LinuxCNC's G/M table (rs274ngc/codes.cpp).
#include "gcode/dialect.hpp"

#include <set>

namespace usina::gcode {
namespace {

// What LinuxCNC does where the interpreter serves other controls otherwise.
constexpr DialectRules kLinuxcnc{.start_motion = 800,
                                 .reselect_reloads_work_offsets = false,
                                 .g74_takes_l = false,
                                 .min_arc_radius_mm = 0.00005 * 25.4,
                                 .max_call_nesting = 9};

class Rs274Runner final : public ProgramRunner {
 public:
  explicit Rs274Runner(RunContext& c)
      : interp_(c.sources, std::move(c.options), c.sink, c.diags, nullptr, kLinuxcnc) {}

  void set_parameter(int index, double value) override {
    interp_.set_parameter(index, value);
    from_file_.insert(index);
  }

  bool run(std::uint32_t file) override { return interp_.run(file); }

  std::optional<RunModes> modes() const override { return run_modes(interp_.state()); }

  // LinuxCNC's save_parameters(): its required parameters (homes, G92, the
  // selected system, the nine work systems) and every number the parameter
  // file it started from held.
  std::optional<std::vector<VarFileEntry>> persistent_variables() const override {
    std::set<int> numbers = from_file_;
    for (int base : {5160, 5180}) {
      for (int a = 1; a <= 9; ++a)
        numbers.insert(base + a);
    }
    for (int n = 5210; n <= 5220; ++n)
      numbers.insert(n);
    for (int system = 1; system <= 9; ++system) {
      for (int k = 1; k <= 10; ++k)
        numbers.insert(5200 + 20 * system + k);
    }
    std::vector<VarFileEntry> out;
    for (int n : numbers) {
      if (n >= kMinVarFileParameter && n <= kMaxVarFileParameter)
        out.push_back({n, interp_.parameters().get(n)});
    }
    return out;
  }

 private:
  Interpreter interp_;
  std::set<int> from_file_;
};

std::unique_ptr<ProgramRunner> make(RunContext context) {
  return std::make_unique<Rs274Runner>(context);
}

}  // namespace

const Dialect& rs274ngc_dialect() {
  static const Dialect d{"rs274ngc", LexicalRules{"\n", false}, linuxcnc_codes(), {}, {}, &make};
  return d;
}

const InterpCodes& rs274ngc_code_table() {
  static const InterpCodes table = interp_code_table("rs274ngc", rs274ngc_dialect().codes);
  return table;
}

}  // namespace usina::gcode
