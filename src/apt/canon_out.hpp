// CL records as the canon stream (docs/trace.md), so that every back end
// (trace, draw, stats, the posts) reads an APT program.
#pragma once

#include <optional>
#include <vector>

#include "apt/cl.hpp"
#include "canon/sink.hpp"

namespace usina::apt {

// What the canon stream gets for a circle IBM's processor segmented (a
// circle's record, then a motion of several points): the arc itself
// (Arcs: a post writes G2/G3) or the chords as the CL holds them.
enum class Circles : unsigned char { Arcs, Chords };

// `scale`: mm per program unit (1 for a program in mm, 25.4 in inches).
void to_canon(const std::vector<ClRecord>& records, double scale, canon::Sink& sink,
              Circles circles = Circles::Arcs);

// The same, one record at a time (the CL file readers stream their records).
// A circle's record (3000 2) followed by a motion of one point is an arc to
// that point, counter-clockwise about the record's axis; followed by more
// points (IBM's segmented circles) it is an arc about the circle's centre
// from the tool to the motion's last point, the way the points turn (one arc
// a record: a motion of more than 80 points is a few arcs), or with
// Circles::Chords those chords.
class ClToCanon {
 public:
  ClToCanon(double scale, canon::Sink& sink, Circles circles = Circles::Arcs)
      : scale_(scale), sink_(sink), circles_(circles) {}

  void record(const ClRecord& r);

  // A CL file's UNITS statement: the records after it are in this unit.
  void set_scale(double scale) { scale_ = scale; }

 private:
  struct PendingArc {
    canon::Vec3 center;
    canon::Vec3 axis;  // unit
  };

  void emit(canon::OpKind k, const ClRecord& r, canon::Origin o = canon::Origin::Program) {
    sink_.on(canon::Op{std::move(k), r.src, o});
  }

  void post(const ClRecord& r);
  void post_motion_words(const ClRecord& r);
  void surface(const ClRecord& r);
  void motion(const ClRecord& r);
  void move(const canon::Vec3& p, const ClRecord& r);
  void arc(const canon::Vec3& p, const ClRecord& r);
  bool segmented_arc(const ClRecord& r);
  void drill(const canon::Vec3& p, const ClRecord& r);
  void spindle(const ClRecord& r);
  void cycle(const ClRecord& r);

  double scale_;
  canon::Sink& sink_;
  Circles circles_;
  bool rapid_ = false;       // RAPID: the next motion statement traverses
  bool rapid_used_ = false;  // ... and it has begun
  std::optional<double> feed_;
  std::optional<canon::ProgrammedFeed> per_rev_;
  std::optional<double> diameter_;
  canon::Spindle spindle_{};
  // CYCLE/DRILL,depth,IPM,f,clearance[,retract]: each GOTO point drills.
  bool cycle_ = false;
  double depth_ = 0.0;
  double clearance_ = 0.0;
  double retract_ = 0.0;           // where the tool leaves the hole to, above the point
  std::optional<PendingArc> arc_;  // a circle's record, waiting for its motion
  bool segmented_ = false;         // its points so far went out as an arc
  std::optional<canon::Vec3> at_;  // where the tool is, once a motion said
};

}  // namespace usina::apt
