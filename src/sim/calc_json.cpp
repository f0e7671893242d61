#include "sim/calc_json.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>

#include <fmt/format.h>

namespace usina::sim {
namespace {

using nlohmann::json;

json answer(std::string_view name, json inputs, json results) {
  return {{"calculation", name}, {"inputs", std::move(inputs)}, {"results", std::move(results)}};
}

template <typename T>
json or_null(const std::optional<T>& v) {
  return v ? json(*v) : json(nullptr);
}

// Reads the inputs of one calculation, stopping at the first bad one: a
// value from a page or a script is checked as the command line's flags are.
class Inputs {
 public:
  Inputs(const json& given, std::initializer_list<std::string_view> names) : given_(given) {
    if (!given.is_object()) {
      error_ = "the inputs must be a JSON object of numbers";
      return;
    }
    for (const auto& [key, value] : given.items()) {
      if (std::find(names.begin(), names.end(), key) == names.end()) {
        error_ = fmt::format("unknown input `{}`; this calculation takes {}", key,
                             fmt::join(names, ", "));
        return;
      }
    }
  }

  const std::string& error() const { return error_; }

  bool has(std::string_view key) const {
    const auto it = given_.find(key);
    return given_.is_object() && it != given_.end() && !it->is_null();
  }

  double real(std::string_view key) {
    const json* v = find(key);
    if (v == nullptr) return 0;
    if (!v->is_number() || !std::isfinite(v->get<double>()))
      return fail(key, fmt::format("{} is not a number", v->dump()));
    return v->get<double>();
  }

  std::int64_t whole(std::string_view key) {
    const json* v = find(key);
    if (v == nullptr) return 0;
    // JSON's parser keeps a whole number without a sign as unsigned.
    if (v->is_number_unsigned() &&
        v->get<std::uint64_t>() > std::uint64_t{std::numeric_limits<std::int64_t>::max()})
      return fail(key, fmt::format("{} is too large", v->dump()));
    if (v->is_number_integer()) return v->get<std::int64_t>();
    return fail(key, fmt::format("{} is not a whole number", v->dump()));
  }

  // Text as given, or a whole number of JSON written in decimal.
  std::string numeral(std::string_view key) {
    const json* v = find(key);
    if (v == nullptr) return {};
    if (v->is_string()) return v->get<std::string>();
    if (v->is_number_unsigned()) return std::to_string(v->get<std::uint64_t>());
    if (v->is_number_integer() && v->get<std::int64_t>() >= 0)
      return std::to_string(v->get<std::int64_t>());
    fail(key, fmt::format("{} is neither digits as text (\"1250\") nor a whole number", v->dump()));
    return {};
  }

 private:
  const json* find(std::string_view key) {
    if (!error_.empty()) return nullptr;
    if (!has(key)) {
      error_ = fmt::format("{} is required", key);
      return nullptr;
    }
    return &given_.find(key).value();
  }

  int fail(std::string_view key, const std::string& why) {
    if (error_.empty()) error_ = fmt::format("{}: {}", key, why);
    return 0;
  }

  const json& given_;
  std::string error_;
};

template <typename In, typename Run>
Checked<json> run(const Inputs& read, const In& in, Run calculate) {
  if (!read.error().empty()) return tl::unexpected(read.error());
  auto r = calculate(in);
  if (!r) return tl::unexpected(r.error());
  return calc_json(in, *r);
}

Checked<json> open_loop_from(const json& given) {
  Inputs read(given, {"pitch_mm", "gear_ratio", "steps_per_rev", "distance_mm", "feed_mm_per_min"});
  const OpenLoopInput in{{read.real("pitch_mm"), read.real("gear_ratio")},
                         read.whole("steps_per_rev"),
                         read.real("distance_mm"),
                         read.real("feed_mm_per_min")};
  return run(read, in, open_loop);
}

Checked<json> closed_loop_from(const json& given) {
  Inputs read(given, {"pitch_mm", "gear_ratio", "encoder_slots", "distance_mm", "feed_mm_per_min"});
  const ClosedLoopInput in{{read.real("pitch_mm"), read.real("gear_ratio")},
                           read.whole("encoder_slots"),
                           read.real("distance_mm"),
                           read.real("feed_mm_per_min")};
  return run(read, in, closed_loop);
}

Checked<json> precision_from(const json& given) {
  Inputs read(given, {"pitch_mm", "gear_ratio", "steps_per_rev", "travel_mm", "bits", "sigma_mm"});
  const PrecisionInput in{{read.real("pitch_mm"), read.real("gear_ratio")},
                          read.whole("steps_per_rev"),
                          read.real("travel_mm"),
                          read.whole("bits"),
                          read.real("sigma_mm")};
  return run(read, in, precision);
}

Checked<json> cutting_from(const json& given) {
  Inputs read(given, {"speed_m_per_min", "diameter_mm", "teeth", "chip_load_mm"});
  CuttingInput in{read.real("speed_m_per_min"), read.real("diameter_mm"), std::nullopt,
                  std::nullopt};
  if (read.has("teeth")) in.teeth = read.whole("teeth");
  if (read.has("chip_load_mm")) in.chip_load_mm = read.real("chip_load_mm");
  return run(read, in, cutting);
}

Checked<json> bcd_from(const json& given) {
  Inputs read(given, {"numeral"});
  const std::string numeral = read.numeral("numeral");
  if (!read.error().empty()) return tl::unexpected(read.error());
  auto r = bcd(numeral);
  if (!r) return tl::unexpected(r.error());
  return calc_json(numeral, *r);
}

}  // namespace

json calc_json(const OpenLoopInput& in, const OpenLoop& r) {
  return answer("open_loop",
                {{"pitch_mm", in.drive.pitch_mm},
                 {"gear_ratio", in.drive.gear_ratio},
                 {"steps_per_rev", in.steps_per_rev},
                 {"distance_mm", in.distance_mm},
                 {"feed_mm_per_min", in.feed_mm_per_min}},
                {{"step_angle_deg", r.step_angle_deg},
                 {"screw_angle_deg", r.screw_angle_deg},
                 {"motor_angle_deg", r.motor_angle_deg},
                 {"pulses", r.pulses},
                 {"whole_pulses", r.whole_pulses},
                 {"distance_reached_mm", r.distance_reached_mm},
                 {"screw_rpm", r.screw_rpm},
                 {"motor_rpm", r.motor_rpm},
                 {"pulse_frequency_hz", r.pulse_frequency_hz}});
}

json calc_json(const ClosedLoopInput& in, const ClosedLoop& r) {
  return answer("closed_loop",
                {{"pitch_mm", in.drive.pitch_mm},
                 {"gear_ratio", in.drive.gear_ratio},
                 {"encoder_slots", in.encoder_slots},
                 {"distance_mm", in.distance_mm},
                 {"feed_mm_per_min", in.feed_mm_per_min}},
                {{"slot_angle_deg", r.slot_angle_deg},
                 {"screw_angle_deg", r.screw_angle_deg},
                 {"pulses", r.pulses},
                 {"whole_pulses", r.whole_pulses},
                 {"distance_reached_mm", r.distance_reached_mm},
                 {"pulse_frequency_hz", r.pulse_frequency_hz},
                 {"screw_rpm", r.screw_rpm},
                 {"motor_rpm", r.motor_rpm}});
}

json calc_json(const PrecisionInput& in, const Precision& r) {
  return answer("precision",
                {{"pitch_mm", in.drive.pitch_mm},
                 {"gear_ratio", in.drive.gear_ratio},
                 {"steps_per_rev", in.steps_per_rev},
                 {"travel_mm", in.travel_mm},
                 {"bits", in.bits},
                 {"sigma_mm", in.sigma_mm}},
                {{"cr1_mm", r.cr1_mm},
                 {"cr2_mm", r.cr2_mm},
                 {"control_resolution_mm", r.control_resolution_mm},
                 {"limited_by", r.limited_by_register ? "register" : "mechanics"},
                 {"accuracy_mm", r.accuracy_mm},
                 {"repeatability_mm", r.repeatability_mm}});
}

json calc_json(const CuttingInput& in, const Cutting& r) {
  return answer("cutting",
                {{"speed_m_per_min", in.speed_m_per_min},
                 {"diameter_mm", in.diameter_mm},
                 {"teeth", or_null(in.teeth)},
                 {"chip_load_mm", or_null(in.chip_load_mm)}},
                {{"spindle_rpm", r.spindle_rpm}, {"feed_mm_per_min", or_null(r.feed_mm_per_min)}});
}

json calc_json(std::string_view numeral, const Bcd& r) {
  json digits = json::array();
  for (const BcdDigit& d : r.digits)
    digits.push_back({{"digit", d.digit}, {"bits", d.bits}, {"place_value", d.place_value}});
  return answer("bcd", {{"numeral", numeral}},
                {{"value", r.value}, {"code", r.code}, {"digits", std::move(digits)}});
}

Checked<json> calc_from_json(std::string_view name, const json& inputs) {
  if (name == "open-loop") return open_loop_from(inputs);
  if (name == "closed-loop") return closed_loop_from(inputs);
  if (name == "precision") return precision_from(inputs);
  if (name == "cutting") return cutting_from(inputs);
  if (name == "bcd") return bcd_from(inputs);
  return tl::unexpected(
      fmt::format("no calculator `{}`: open-loop, closed-loop, precision, cutting or bcd", name));
}

}  // namespace usina::sim
