// The statements that write CL records: post-processor words, tolerances
// and cutter, point-to-point motion (FROM, GOTO, GODLTA), END and FINI. A
// statement's records are kept only when the whole statement is correct.
#pragma once

#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "apt/cl.hpp"
#include "apt/contour.hpp"
#include "apt/lexer.hpp"
#include "apt/processor.hpp"
#include "core/vec3.hpp"

namespace usina::apt {

class StatementRunner {
 public:
  StatementRunner(core::DiagnosticSink& diags, AptResult& out) : diags_(diags), out_(out) {}

  // The statement of words `t` from `i` on: "W, W, MAJOR/args" or "W".
  void words(const std::vector<Token>& t, std::size_t i, int isn, const core::SourceLoc& loc);
  // A text word (PARTNO, PPRINT, INSERT, REMARK) and its text.
  void text(const std::string& word, const std::string& text, int isn, const core::SourceLoc& loc);

  // The end of the program (or FINI): a motion still waiting for its
  // implicit check surface is an error.
  void end_of_program();

  bool finished() const { return finished_; }

  SymbolTable& symbols() { return symbols_; }

  double zsurf() const { return zsurf_; }

  std::size_t& pattern_points() { return pattern_points_; }

 private:
  bool fail(const core::SourceLoc& at, core::Code code, std::string message);
  bool major(const Token& word, const std::vector<Arg>& args);
  bool motion(const Token& word, const std::vector<Arg>& args);
  bool godlta(const Token& word, const std::vector<Arg>& args);
  bool goto_pattern(const Token& word, const std::vector<Arg>& args);
  void write_run(const ClWord& name, const std::vector<core::Vec3>& points);
  bool control(const Token& word, const std::vector<Arg>& args);
  bool post(const Token& word, int code, const std::vector<Arg>& args);
  bool modifiers(const std::vector<Token>& mods, const Token& major);
  void commit(int isn, const core::SourceLoc& loc);
  void add(int cls, int sub, std::vector<ClWord> words);

  // Contouring (statements_contour.cpp).
  struct Drive {
    Token word;
    Turn turn = Turn::Forward;
    Arg ds;
    std::optional<Arg> cs;
    Stop stop = Stop::To;
    int nth = 1;
    std::optional<double> feed;
    int side = 0;  // the tool side when the statement was read
  };

  // A motion with no check surface waits for the next statement's drive
  // surface (IBM's implicit check surface), with its records so far.
  struct Deferred {
    Drive drive;
    std::vector<ClRecord> records;
    int isn = 0;
    core::SourceLoc loc;
  };

  bool contour(const Token& word, const std::vector<Arg>& args);
  bool modal(const std::string& word, const std::vector<Arg>& args, const core::SourceLoc& at);
  bool direction(const std::string& word, const std::vector<Arg>& args, const core::SourceLoc& at);
  bool startup(const Token& word, const std::vector<Arg>& args);
  bool vertical(const Token& word, const std::vector<Arg>& args);  // GOUP, GODOWN
  std::optional<Drive> read_drive(const Token& word, const std::vector<Arg>& args);
  bool run_drive(const Drive& d);
  bool known_start(const Token& word);
  void resolve_deferred(const Token& next, const std::vector<Arg>& args);
  void write_points(const Arg& ds, const std::vector<Vec2>& points, double z);
  void turned(core::Vec3 to);

  std::optional<Deferred> deferred_;
  bool defer_now_ = false;  // the statement just read became deferred_
  int side_ = 0;            // +1 TLLFT, -1 TLRGT, 0 TLON
  double cutter_radius_ = 0.0;
  double intol_ = 0.0;  // IBM's defaults: INTOL 0, OUTTOL .0005
  double outtol_ = 0.0005;
  double ps_z_ = 0.0;               // the part surface, a horizontal plane (the XY plane at first)
  bool nops_ = false;               // NOPS: the next GO/ keeps the tool's z
  std::optional<Vec2> fwd_;         // the sense of direction: the last motion's, unit
  std::size_t arc_points_ = 0;      // the points written on circles so far
  std::size_t pattern_points_ = 0;  // the points the patterns defined hold
  std::size_t visited_ = 0;         // the patterns' points GOTO/pattern went through

  core::DiagnosticSink& diags_;
  AptResult& out_;
  SymbolTable symbols_;
  std::vector<ClRecord> pending_;  // the records of the statement being read
  bool writes_ = false;            // whether the statement has a 1000 record
  int isn_ = 0;                    // the statement's number
  core::Vec3 at_{};                // the tool end's position
  int lost_at_ = 0;  // the line of a motion not run, after which at_ is unknown (0: known)
  double zsurf_ = 0.0;
  bool finished_ = false;
};

}  // namespace usina::apt
