// The canon stream as CL records (cl.hpp): what lets `usina trace PROG
// --format cldata|iso4343|cldump` write the CL data of a G-code program, the
// reverse of canon_out.hpp. Each op becomes a CL statement, preceded by a
// source record (1000) that numbers it by the op's line, so that ClToCanon
// reads the records back into the same moves (docs/apt.md, "CL data of a
// G-code program", says what the CL cannot hold and how it is written).
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include "apt/cl.hpp"
#include "canon/sink.hpp"

namespace usina::apt {

class CanonToCl final : public canon::Sink {
 public:
  // Takes the records written so far, when given: a program of millions of
  // moves is written in parts (some kChunk records, each ending between two
  // ops) and never held whole.
  using Flush = std::function<void(std::vector<ClRecord>&&)>;
  static constexpr std::size_t kChunk = 4096;

  explicit CanonToCl(Flush flush = {}) : flush_(std::move(flush)) {}

  void on(const canon::Op& op) override;

  // Writes what is held, closes an open cycle, then FINI; once (front ends
  // may call it more than once).
  void finish() override;

  // The records not yet flushed (all of them without a Flush).
  const std::vector<ClRecord>& records() const { return records_; }

 private:
  // A drilled hole whose moves are still coming: its moves are held until
  // they show whether it is a plain drilling (CYCLE/DRILL) or not.
  struct PendingHole {
    canon::Hole hole;
    core::SourceLoc src;
    std::vector<canon::Op> held;
    std::optional<canon::Op> approach;  // the traverse down over it, taken back
  };

  void write(const canon::Op& op);
  void statement(const core::SourceLoc& src);
  void add(int cls, int sub, std::vector<ClWord> words, const core::SourceLoc& src);
  void goto_point(const canon::Vec3& p, const core::SourceLoc& src);
  void traverse(const canon::Vec3& p, const core::SourceLoc& src);
  void feed_to(const canon::Feed& f, const core::SourceLoc& src);
  void arc(const canon::Arc& a, const core::SourceLoc& src);
  void arc_piece(const canon::Vec3& to, const canon::Vec3& center, const canon::Vec3& axis,
                 const core::SourceLoc& src);
  void feed_rate(std::optional<double> f, const canon::ProgrammedFeed& p, double length,
                 const core::SourceLoc& src);
  void spindle(const canon::Spindle& s, const core::SourceLoc& src);
  void coolant(const canon::Coolant& c, const core::SourceLoc& src);
  void tool(const canon::ToolChange& t, const core::SourceLoc& src);
  void text(int code, const std::string& t, const core::SourceLoc& src);
  void machine_code(const canon::MachineCode& m, const core::SourceLoc& src);
  void cycle_off(const core::SourceLoc& src);

  void hole(const canon::Op& op);
  void hold(const canon::Op& op);
  bool drilled(const PendingHole& h) const;
  void write_drilled(const PendingHole& h);
  void release();

  void flush();

  Flush flush_;
  std::vector<ClRecord> records_;
  std::optional<canon::Vec3> at_;  // where the tool is
  std::optional<double> feed_;     // the CL's feed rate (mm/min) ...
  bool per_rev_ = false;           // ... or per revolution

  // The open CYCLE/DRILL: depth, feed; RAPID GOTOs keep it open.
  struct Cycle {
    double depth;
    double feed;
    double clearance;  // the approach's height above the hole's top
    double retract;    // and where the tool leaves to
  };

  std::optional<Cycle> cycle_;
  std::optional<PendingHole> pending_;

  // The last op written, when it was a traverse: where its records begin
  // and where the tool was before it (a hole takes it back).
  struct LastTraverse {
    std::size_t first;
    std::optional<canon::Vec3> from;
    canon::Op op;
  };

  std::optional<LastTraverse> last_traverse_;
  bool finished_ = false;
};

// The records of a whole stream (tests).
std::vector<ClRecord> canon_to_cl(const std::vector<canon::Op>& ops);

}  // namespace usina::apt
