// The runner of the grbl dialect: the program read once, line by line, as
// Grbl reads a stream; each line checked by Grbl's rules, run by the
// RS274NGC interpreter, its moves checked from the position, and passed on
// (grbl/dialect.cpp says why).
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "gcode/dialect.hpp"

namespace usina::gcode {

const Dialect& grbl_dialect();

namespace grbl {

class Runner final : public ProgramRunner {
 public:
  Runner(const Dialect& d, RunContext context) : dialect_(d), c_(std::move(context)) {}

  void set_parameter(int index, double value) override { params_.emplace_back(index, value); }

  bool run(std::uint32_t file) override;

  std::optional<RunModes> modes() const override { return modes_; }

 private:
  const Dialect& dialect_;
  RunContext c_;
  std::vector<std::pair<int, double>> params_;
  std::optional<RunModes> modes_;  // after run()
};

}  // namespace grbl
}  // namespace usina::gcode
