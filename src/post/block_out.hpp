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
  BlockOut(std::ostream& out, const Control& control, bool line_numbers);

  ~BlockOut() { flush(); }

  BlockOut(const BlockOut&) = delete;
  BlockOut& operator=(const BlockOut&) = delete;

  // Hands the buffered blocks to the stream.
  void flush();

  // One block: its N word (if numbered), the words, the block end.
  void block(std::string_view words);

  // A line outside the block structure ("%").
  void raw(std::string_view line);

  // A comment in the control's form, characters it cannot hold removed.
  std::string comment(std::string_view text) const;

  // `v` as the control writes it: its decimals, no trailing zeros, "-0" as "0".
  std::string number(double v) const;

  // `letter` and number(v) appended to `words`, a space first unless empty.
  void append_word(std::string& words, char letter, double v) const;

  // The same for a value rounded() already.
  void append_rounded(std::string& words, char letter, double r) const;

  // `v` rounded to the control's decimals: what a reader will get back.
  double rounded(double v) const;

  const Control& control() const { return control_; }

 private:
  std::ostream& out_;
  const Control& control_;
  bool line_numbers_;
  double scale_;        // 10^decimals
  std::string buffer_;  // blocks not yet handed to out_ (a stream write a block is slow)
  long next_n_ = 10;
};

}  // namespace usina::post
