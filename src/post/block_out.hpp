// Blocks as a control reads them: numbers in its format, N words, comments,
// the block end.
#pragma once

#include <ostream>
#include <string>
#include <string_view>

#include "post/control.hpp"

namespace usina::post {

class BlockOut {
 public:
  BlockOut(std::ostream& out, const Control& control, bool line_numbers)
      : out_(out), control_(control), line_numbers_(line_numbers || control.always_line_numbers) {}

  // One block: its N word (if numbered), the words, the block end.
  void block(std::string_view words);

  // A line outside the block structure ("%").
  void raw(std::string_view line);

  // A comment in the control's form, characters it cannot hold removed.
  std::string comment(std::string_view text) const;

  // `v` as the control writes it: its decimals, no trailing zeros, "-0" as "0".
  std::string number(double v) const;

  // `v` rounded to the control's decimals: what a reader will get back.
  double rounded(double v) const;

  const Control& control() const { return control_; }

 private:
  std::ostream& out_;
  const Control& control_;
  bool line_numbers_;
  long next_n_ = 10;
};

}  // namespace usina::post
