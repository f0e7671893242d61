// The CL text reader's state and statements (cl_text.cpp: the words that
// set things, cl_text_motion.cpp: the motions), private to those two files.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "apt/cl_statement.hpp"
#include "apt/cl_text.hpp"
#include "apt/cldata.hpp"

namespace usina::apt::detail {

inline constexpr int kDrill = 163, kMmpm = 171, kIpm = 73, kOff = 72;

struct Vec {
  double x = 0, y = 0, z = 0;
};

struct PendingCircle {
  Vec center;
  Vec axis;  // unit, right-hand: the arc runs counter-clockwise about it
  std::optional<double> radius;
  core::SourceLoc loc;
};

class ClTextReader {
 public:
  ClTextReader(ClDialect d, core::DiagnosticSink& diags, const ClConsumer& out)
      : dialect_(d), diags_(diags), out_(out) {}

  // Reads one statement and hands on its records; false once reading ends
  // (FINI, or the consumer said stop).
  bool statement(const ClStatement& st);
  // The end of the file: a CIRCLE still waiting for its GOTO is an error.
  void end();

 private:
  // A record longer than CLDATA holds (a PARTNO of pages of text) is
  // refused here: written as CLDATA it would not read back.
  bool add(int cls, int sub, std::vector<ClWord> words, const core::SourceLoc& loc) {
    if (words.size() > kMostCldataWords) {
      return fail(core::Code::ClBadRecord, loc,
                  fmt::format("a record of {} words; a CL record holds at most {} (a text of "
                              "at most {} characters)",
                              words.size(), kMostCldataWords, kMostCldataWords * 6));
    }
    recs_.push_back(ClRecord{cls, sub, std::move(words), loc});
    return true;
  }

  bool fail(core::Code code, const core::SourceLoc& at, std::string why,
            core::Severity s = core::Severity::Error) {
    diags_.report(core::Diagnostic{code, s, at, std::move(why)});
    return false;
  }

  // Each statement's reader adds its records with add() and returns true;
  // false: nothing to hand on (an error, reported, or a statement that
  // writes no record).
  bool dispatch(const ClStatement& st);
  bool post_word(const ClStatement& st, int code);
  bool text(const ClStatement& st, int code, std::string text);
  bool control(const ClStatement& st, int sub);
  bool units(const ClStatement& st);
  bool point(const ClStatement& st, int sub);
  bool godlta(const ClStatement& st);
  bool circle(const ClStatement& st);
  bool arc_to(const ClStatement& st, Vec p, std::optional<Vec> from);
  bool cycle(const ClStatement& st);
  bool circle_left_out(const char* why);
  void flush(const ClStatement& st);

  ClDialect dialect_;
  core::DiagnosticSink& diags_;
  const ClConsumer& out_;
  std::vector<ClRecord> recs_;  // the records of the statement being read
  std::optional<Vec> at_;       // the tool's position, once a motion said
  bool tilted_ = false;         // the last GOTO's tool axis was not +Z
  std::optional<PendingCircle> circle_;
  std::optional<double> feed_;  // the last FEDRAT's, for a cycle that gives none
  int feed_unit_ = kMmpm;
  bool cycle_on_ = false;  // a drilling cycle read from FEDTO is on
  bool stop_ = false;
};

}  // namespace usina::apt::detail
