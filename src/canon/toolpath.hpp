// A retained stream of ops, for consumers that need random access.
#pragma once

#include <vector>

#include "canon/sink.hpp"

namespace usina::canon {

struct Bounds {
  Vec3 min;
  Vec3 max;
  bool empty = true;

  void add(const Vec3& p);
};

class Toolpath final : public Sink {
 public:
  void on(const Op& op) override;

  const std::vector<Op>& ops() const { return ops_; }

  // Bounding box of every motion end point.
  const Bounds& bounds() const { return bounds_; }

  std::size_t size() const { return ops_.size(); }

 private:
  std::vector<Op> ops_;
  Bounds bounds_;
};

}  // namespace usina::canon
