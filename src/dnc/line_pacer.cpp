#include "dnc/line_pacer.hpp"

#include <algorithm>
#include <cmath>

namespace usina::dnc {
namespace {

constexpr auto kMinWait = std::chrono::microseconds(100);
constexpr auto kPollWait = std::chrono::milliseconds(1);  // no model: look again soon

}  // namespace

LinePacer::LinePacer(double bytes_per_second, std::uint32_t skid)
    : rate_(bytes_per_second), skid_(std::max<std::uint32_t>(skid, 1)) {}

double LinePacer::in_flight(Clock::time_point now, std::optional<std::size_t> queued) const {
  double model = 0.0;
  if (rate_ > 0.0 && wire_empty_at_ > now) {
    model = std::chrono::duration<double>(wire_empty_at_ - now).count() * rate_;
  }
  return std::max(model, static_cast<double>(queued.value_or(0)));
}

std::size_t LinePacer::room(Clock::time_point now, std::optional<std::size_t> queued) const {
  const double flying = std::ceil(in_flight(now, queued) - 1e-9);
  if (flying >= skid_) return 0;
  return static_cast<std::size_t>(skid_ - flying);
}

LinePacer::Clock::time_point LinePacer::ready_at(std::size_t want, Clock::time_point now,
                                                 std::optional<std::size_t> queued) const {
  if (rate_ <= 0.0) return now + kPollWait;
  const double allowed = static_cast<double>(skid_) - static_cast<double>(want);
  const double excess = in_flight(now, queued) - allowed;
  const auto wait = std::chrono::duration_cast<Clock::duration>(
      std::chrono::duration<double>(std::max(excess, 0.0) / rate_));
  return now + std::max<Clock::duration>(wait, kMinWait);
}

void LinePacer::wrote(std::size_t n, Clock::time_point now) {
  if (rate_ <= 0.0) return;
  const auto start = std::max(wire_empty_at_, now);
  wire_empty_at_ = start + std::chrono::duration_cast<Clock::duration>(
                               std::chrono::duration<double>(static_cast<double>(n) / rate_));
}

}  // namespace usina::dnc
