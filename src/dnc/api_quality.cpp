// Quality records through the API (store_quality.hpp): an operator,
// approver or admin records a measurement of a part made on a machine;
// whoever reads the machines reads them back, newest first, a page at a
// time.
#include <charconv>
#include <limits>
#include <tuple>

#include <fmt/format.h>

#include "dnc/api_json.hpp"
#include "dnc/api_router.hpp"
#include "dnc/store_jobs.hpp"
#include "dnc/store_quality.hpp"
#include "dnc/store_revisions.hpp"

namespace usina::dnc {
namespace {

constexpr std::int64_t kDefaultPage = 100;
constexpr std::int64_t kMaxPage = 1000;
constexpr std::size_t kMaxCharacteristicBytes = 200;  // as a record's (store_quality.cpp)

HttpResponse bad(const ApiCall& c, const std::string& message) {
  return error_response(c.req, http::status::bad_request, message);
}

// The number field `key`: its value, nullopt when absent and not `required`.
tl::expected<std::optional<double>, std::string> number_field(const nlohmann::json& body,
                                                              std::string_view key, bool required) {
  const auto it = body.find(key);
  if (it == body.end() || it->is_null()) {
    if (required) return tl::unexpected(fmt::format("{} is missing", key));
    return std::nullopt;
  }
  if (!it->is_number()) return tl::unexpected(fmt::format("{} must be a number", key));
  return it->get<double>();
}

// The body's fields into a record; a message for the first bad one.
tl::expected<QualityRecord, std::string> read_record(const nlohmann::json& body) {
  QualityRecord r;
  auto measured = number_field(body, "measured", true);
  if (!measured) return tl::unexpected(measured.error());
  r.measured = **measured;
  for (const auto& [key, value] :
       {std::pair{"nominal", &r.nominal}, std::pair{"min", &r.min}, std::pair{"max", &r.max}}) {
    auto v = number_field(body, key, false);
    if (!v) return tl::unexpected(v.error());
    *value = *v;
  }
  for (const auto& [key, value, required] :
       {std::tuple{"characteristic", &r.characteristic, true}, std::tuple{"unit", &r.unit, false},
        std::tuple{"part", &r.part, false}, std::tuple{"program", &r.program, false},
        std::tuple{"note", &r.note, false}}) {
    auto v = string_field(body, key, required);
    if (!v) return tl::unexpected(v.error());
    *value = v->value_or("");
  }
  auto job = count_field(body, "job");
  if (!job) return tl::unexpected(job.error());
  if (*job && **job > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max()))
    return tl::unexpected(std::string("job is no job number"));
  r.job = static_cast<std::int64_t>(job->value_or(0));
  return r;
}

nlohmann::json record_json(const QualityRecord& r) {
  const auto number = [](const std::optional<double>& v) {
    return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
  };
  const auto ok = r.ok();
  return {{"id", r.id},
          {"machine", r.machine},
          {"at_us", r.at_us},
          {"by", r.by},
          {"characteristic", r.characteristic},
          {"measured", r.measured},
          {"nominal", number(r.nominal)},
          {"min", number(r.min)},
          {"max", number(r.max)},
          {"ok", ok ? nlohmann::json(*ok) : nlohmann::json(nullptr)},
          {"unit", r.unit},
          {"part", r.part},
          {"program", r.program.empty() ? nlohmann::json(nullptr) : nlohmann::json(r.program)},
          {"job", r.job == 0 ? nlohmann::json(nullptr) : nlohmann::json(r.job)},
          {"note", r.note}};
}

// The program and the job a record names are the store's, the job this machine's.
std::optional<std::string> unknown_reference(ApiCall& c, const QualityRecord& r) {
  if (!r.program.empty() && !find_program(c.ctx.store, r.program))
    return fmt::format("no program {}", r.program);
  if (r.job != 0) {
    auto job = find_job(c.ctx.store, r.job);
    if (!job) return fmt::format("no job {}", r.job);
    if (job->machine != r.machine)
      return fmt::format("job {} ran on {}, not on {}", r.job, job->machine, r.machine);
  }
  return std::nullopt;
}

std::optional<std::int64_t> query_count(const ApiCall& c, const std::string& key) {
  const auto it = c.target.query.find(key);
  if (it == c.target.query.end()) return 0;
  std::int64_t n = -1;
  const std::string& text = it->second;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), n);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size() || n < 0)
    return std::nullopt;
  return n;
}

}  // namespace

HttpResponse api_record_quality(ApiCall& c) {
  if (c.ctx.machines.find(c.params[0]) == nullptr)
    return error_response(c.req, http::status::not_found,
                          fmt::format("no machine {}", c.params[0]));
  auto body = json_body(c.req);
  if (!body) return bad(c, body.error());
  auto r = read_record(*body);
  if (!r) return bad(c, r.error());
  r->machine = c.params[0];
  if (auto unknown = unknown_reference(c, *r)) return bad(c, *unknown);
  auto recorded = record_quality(c.ctx.store, c.actor(), std::move(*r));
  if (!recorded)
    return error_response(c.req, status_of(recorded.error()), recorded.error().message);
  const nlohmann::json answer = record_json(*recorded);
  c.ctx.events.publish("machine.quality", answer);
  return json_response(c.req, http::status::created, answer);
}

HttpResponse api_quality(ApiCall& c) {
  if (c.ctx.machines.find(c.params[0]) == nullptr)
    return error_response(c.req, http::status::not_found,
                          fmt::format("no machine {}", c.params[0]));
  const auto before = query_count(c, "before");
  const auto limit = query_count(c, "limit");
  if (!before || !limit || *limit > kMaxPage)
    return bad(c, fmt::format("before and limit are whole numbers (limit at most {})", kMaxPage));
  // Only one characteristic's records: its measurements over time.
  std::string_view characteristic;
  if (const auto it = c.target.query.find("characteristic"); it != c.target.query.end())
    characteristic = it->second;
  if (characteristic.size() > kMaxCharacteristicBytes)
    return bad(c, fmt::format("characteristic is at most {} bytes", kMaxCharacteristicBytes));
  // One record more than the page: whether there is a next page at all.
  const std::int64_t page = *limit == 0 ? kDefaultPage : *limit;
  auto records = quality_records(c.ctx.store, c.params[0], *before, page + 1, characteristic);
  if (!records) return error_response(c.req, status_of(records.error()), records.error().message);
  const bool more = static_cast<std::int64_t>(records->size()) > page;
  if (more) records->pop_back();
  nlohmann::json list = nlohmann::json::array();
  for (const QualityRecord& r : *records)
    list.push_back(record_json(r));
  nlohmann::json answer = {{"machine", c.params[0]}, {"records", std::move(list)}};
  // The next page: the records below the last one given; null on the last page.
  answer["next_before"] = more ? nlohmann::json(records->back().id) : nlohmann::json(nullptr);
  return json_response(c.req, http::status::ok, answer);
}

}  // namespace usina::dnc
