// CL data: the records the processor writes (research/apt.md §6.1, the
// layout of IBM's CLTAPE that ISO 3592 descends from), one model for every
// writer (the record print of the conformance files, binary CLDATA, ISO 4343
// text, the canon stream) and every reader (CLDATA, NX CLSF, APT CL).
#pragma once

#include <string>
#include <vector>

#include "core/diagnostic.hpp"

namespace usina::apt {

struct ClWord {
  enum class Kind : unsigned char { Real, Code, Text };
  Kind kind = Kind::Real;
  double real = 0.0;
  int code = 0;
  std::string text;  // up to 6 characters, as IBM's A6 words

  static ClWord number(double v) { return {Kind::Real, v, 0, {}}; }

  static ClWord vocabulary(int c) { return {Kind::Code, 0.0, c, {}}; }

  static ClWord chars(std::string t) { return {Kind::Text, 0.0, 0, std::move(t)}; }
};

// Record classes and subclasses (README of the conformance files).
namespace cls {
inline constexpr int kSource = 1000;   // subclass: the statement number (ISN)
inline constexpr int kPost = 2000;     // subclass: the major word's code
inline constexpr int kSurface = 3000;  // subclass 2: a circle's canonical form before its points
inline constexpr int kMotion = 5000;   // 3 FROM, 5 GOTO, 6 continuation
inline constexpr int kControl = 6000;  // 4 INTOL, 5 OUTTOL, 6 CUTTER
inline constexpr int kFini = 14000;
}  // namespace cls

struct ClRecord {
  int cls = 0;
  int sub = 0;
  std::vector<ClWord> words;
  core::SourceLoc src;  // the statement that wrote it
};

// A symbol's name as IBM writes it in a record: right-justified in 6.
ClWord symbol_word(const std::string& name);

// Text cut into 6-character words, padded with empty words to `count`.
std::vector<ClWord> text_words(const std::string& text, std::size_t count);

// The record print of ../shared/conformance/apt: "recno class subclass
// nwords data...", one record a line, numbered from `first`.
std::string record_print(const std::vector<ClRecord>& records, std::size_t first = 1);

}  // namespace usina::apt
