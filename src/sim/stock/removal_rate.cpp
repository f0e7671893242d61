#include "sim/stock/removal_rate.hpp"

#include <algorithm>
#include <cmath>

namespace usina::sim::stock {

double RemovalTimeline::Pending::mm3() const {
  double sum = 0.0;
  for (const double v : parts)
    sum += v;
  return sum;
}

void RemovalTimeline::cut(std::uint64_t op, double mm3, double f0, double f1) {
  if (!(mm3 > 0.0) || !std::isfinite(mm3)) return;
  if (pending_.empty() || pending_.back().op != op) {
    if (pending_.size() >= kMaxPending) merge_oldest();
    pending_.push_back({op, {}});
  }
  std::array<double, kParts>& parts = pending_.back().parts;
  const double n = static_cast<double>(kParts);
  f0 = std::clamp(f0, 0.0, 1.0);
  f1 = std::clamp(f1, f0, 1.0);
  if (!(f1 - f0 > 1e-12)) {
    parts[std::min(static_cast<std::size_t>(f0 * n), kParts - 1)] += mm3;
    return;
  }
  // Evenly over [f0, f1]: each part its overlap's share.
  for (std::size_t k = static_cast<std::size_t>(f0 * n); k < kParts; ++k) {
    const double lo = std::max(f0, static_cast<double>(k) / n);
    const double hi = std::min(f1, static_cast<double>(k + 1) / n);
    if (lo >= f1) break;
    if (hi > lo) parts[k] += mm3 * (hi - lo) / (f1 - f0);
  }
}

void RemovalTimeline::operation_begins(std::uint64_t op) {
  operation_first_op_.push_back(op);
  // What ran before the first operation (a spindle start) is the first's.
  operation_s_.push_back(operation_s_.empty() ? before_operations_s_ : 0.0);
}

void RemovalTimeline::timed(std::uint64_t op, double seconds) {
  if (!(seconds >= 0.0) || !std::isfinite(seconds)) return;
  // The planner tells the ops in order; a piece of an op already closed
  // (never expected) is counted with the one being timed.
  if (op > current_op_) {
    close();
    current_op_ = op;
    current_start_ = clock_;
  }
  clock_ += seconds;
  grow_to(clock_);
  if (operation_s_.empty()) {
    before_operations_s_ += seconds;
  } else {
    operation_s_[operation_of(current_op_)] += seconds;
  }
}

void RemovalTimeline::finish() {
  close();
  // Volume of ops the planner never timed: at the end, where it was cut.
  double left = 0.0;
  for (const Pending& p : pending_)
    left += p.mm3();
  pending_.clear();
  if (left > 0.0) spread(left, clock_, clock_);
}

// The oldest op's volume goes with the next one's, evenly over its stretches.
void RemovalTimeline::merge_oldest() {
  const double mm3 = pending_.front().mm3();
  pending_.pop_front();
  for (double& part : pending_.front().parts)
    part += mm3 / static_cast<double>(kParts);
}

std::size_t RemovalTimeline::peak_bin() const {
  if (bins_.empty()) return 0;
  return static_cast<std::size_t>(std::max_element(bins_.begin(), bins_.end()) - bins_.begin());
}

// The ops up to the one being timed are done: their volume goes on the time
// from its start to now.
void RemovalTimeline::close() {
  const double t0 = current_start_;
  const double d = clock_ - t0;
  const double n = static_cast<double>(kParts);
  // The cutting time: the parts of the op that cut, or all of its time when
  // ops the planner told with it cut.
  double cutting = 0.0;
  while (!pending_.empty() && pending_.front().op <= current_op_) {
    const Pending& p = pending_.front();
    if (p.op < current_op_) {
      spread(p.mm3(), t0, clock_);  // an op the planner told with this one
      cutting = d;
    } else {
      for (std::size_t k = 0; k < kParts; ++k) {
        if (!(p.parts[k] > 0.0)) continue;
        spread(p.parts[k], t0 + d * static_cast<double>(k) / n,
               t0 + d * static_cast<double>(k + 1) / n);
        cutting = std::min(d, cutting + d / n);
      }
    }
    pending_.pop_front();
  }
  cutting_s_ += cutting;
}

void RemovalTimeline::spread(double mm3, double t0, double t1) {
  grow_to(t1);
  const auto bin_at = [this](double t) {
    return std::min(static_cast<std::size_t>(t / bin_s_), kBins - 1);
  };
  const std::size_t first = bin_at(t0);
  const std::size_t last = bin_at(t1);
  if (first == last || !(t1 > t0)) {
    add_to_bin(first, mm3);
    return;
  }
  const double per_s = mm3 / (t1 - t0);
  for (std::size_t i = first; i <= last; ++i) {
    const double lo = std::max(t0, static_cast<double>(i) * bin_s_);
    const double hi = std::min(t1, static_cast<double>(i + 1) * bin_s_);
    if (hi > lo) add_to_bin(i, per_s * (hi - lo));
  }
}

void RemovalTimeline::add_to_bin(std::size_t bin, double mm3) {
  if (bins_.size() <= bin) bins_.resize(bin + 1, 0.0);
  bins_[bin] += mm3;
}

// Merges neighbouring bins until `t` falls in the last of kBins.
void RemovalTimeline::grow_to(double t) {
  while (t >= static_cast<double>(kBins) * bin_s_) {
    std::vector<double> wider((bins_.size() + 1) / 2, 0.0);
    for (std::size_t i = 0; i < bins_.size(); ++i)
      wider[i / 2] += bins_[i];
    bins_ = std::move(wider);
    bin_s_ *= 2.0;
  }
}

std::size_t RemovalTimeline::operation_of(std::uint64_t op) const {
  const auto after = std::upper_bound(operation_first_op_.begin(), operation_first_op_.end(), op);
  return after == operation_first_op_.begin()
             ? 0
             : static_cast<std::size_t>(after - operation_first_op_.begin()) - 1;
}

}  // namespace usina::sim::stock
