// The part of a post every control shares: a canon sink that writes blocks,
// each modal word only when it changes, through a control's table.
#pragma once

#include <array>
#include <optional>
#include <ostream>
#include <string>

#include "canon/sink.hpp"
#include "core/diagnostic.hpp"
#include "post/block_out.hpp"
#include "post/control.hpp"

namespace usina::post {

class Writer final : public canon::Sink {
 public:
  Writer(std::ostream& out, Control control, const PostOptions& options,
         core::DiagnosticSink& diags);

  void on(const canon::Op& op) override;
  void finish() override;

 private:
  void start();
  void end();
  void traverse(const canon::Traverse& t, const canon::Op& op);
  void feed(const core::Vec3& to, std::optional<double> f, const canon::Abc& abc,
            const canon::Op& op, const canon::ProgrammedFeed& programmed = {});
  void straight(const std::string& g, const core::Vec3& to, std::optional<double> f,
                const canon::Abc& abc, const canon::Op& op,
                const canon::ProgrammedFeed& programmed = {});
  void spline(const canon::Spline& s, const canon::Op& op);
  void arc(const canon::Arc& a, const canon::Op& op);

  // The feed-mode word (G93/G94/G95, when it changes; it leads the block)
  // and the F word (when it must be written).
  struct RateWords {
    std::string mode;
    std::string f;
  };

  void arc_block(const canon::Arc& a, const core::Vec3& to, bool ccw, int turns, int plane,
                 RateWords& rate);
  void hole(const canon::Hole& h, const canon::Op& op);
  void cycle_hole(const canon::Hole& h, std::optional<double> f);
  const std::string& cycle_code(const canon::Hole& h) const;
  std::string cycle_dwell_word(const canon::Hole& h) const;
  void expanded_hole(const canon::Hole& h, std::optional<double> f);
  void expanded_bore_stop(const canon::Hole& h, double clear);
  void dwell(double s);
  void spindle(const canon::Spindle& s);
  void tool_change(const canon::ToolChange& t);
  void coolant(const canon::Coolant& c);

  // Words for the axes that changed ("X1 Z-2"); remembers them as written.
  std::string axis_words(const core::Vec3& to, const canon::Abc& abc, const canon::Op& op);
  void append_axis_words(std::string& words, const core::Vec3& to, const canon::Abc& abc,
                         const canon::Op& op);
  std::string motion_word(const char* g);

  // A move's feed as the canon gives it, with what the post needs to write it
  // another way (the move's length, whether a rotary axis moves).
  struct MoveRate {
    std::optional<double> f;
    canon::ProgrammedFeed programmed;
    double length = 0.0;
    bool rotary = false;
  };

  RateWords rate_words(const MoveRate& m, const canon::Op& op);
  RateWords per_minute(std::optional<double> f, const canon::Op& op);
  RateWords inverse_time(const MoveRate& m, const canon::Op& op);
  RateWords per_revolution(const MoveRate& m, const canon::Op& op);
  std::string feed_mode_word(int mode);
  std::string feed_word(std::optional<double> f, const canon::Op& op);
  bool moves_rotary(const canon::Abc& abc) const;
  std::string code(char letter, int n) const;  // "G1" or "G01"
  std::string machine_word(double v) const;
  void cancel_cycle();
  void unsupported(const canon::Op& op, const std::string& what);
  static void append(std::string& words, const std::string& w);

  Control control_;
  PostOptions options_;
  BlockOut out_;
  core::DiagnosticSink& diags_;
  bool started_ = false;
  bool ended_ = false;
  std::string motion_;                         // the motion G word in force ("" unknown)
  std::array<std::optional<double>, 6> axes_;  // X Y Z A B C as the reader has them
  core::Vec3 pos_;                             // the canon's own position (exact)
  bool pos_known_ = false;
  std::optional<double> feed_;       // F as written
  std::optional<double> last_feed_;  // the last feed rate of any move (for bare holes without one)
  int feed_mode_ = 94;               // G93, G94 or G95 as written
  int plane_ = 17;
  std::optional<long> speed_;
  canon::SpindleDir dir_ = canon::SpindleDir::Off;
  canon::Coolant coolant_;
  // The last spindle word written was M5, the last coolant word M9: the end
  // of the program then writes no second one.
  bool spindle_stop_written_ = false;
  bool coolant_off_written_ = false;
  std::optional<double> cycle_z_, cycle_r_, cycle_q_;
  int retract_mode_ = 98;  // G98 or G99 as written (every header with cycles says G98)
  // The motion codes as this control writes them.
  std::string g0_, g1_, g81_, g83_, g85_, g86_, g89_;
  std::string words_, axes_buf_;  // reused for every straight move
};

}  // namespace usina::post
