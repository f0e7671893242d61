#include "dnc/store_quality.hpp"

#include <charconv>
#include <cmath>
#include <limits>
#include <tuple>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "dnc/store_audit.hpp"
#include "dnc/store_names.hpp"

namespace usina::dnc {
namespace {

constexpr double kMaxValue = 1e9;
constexpr std::size_t kMaxLabelBytes = 200;  // characteristic, unit, part

// A value as its column keeps it: the shortest text that reads back as the
// same double (the store has no column type both back ends read exactly);
// empty for none.
std::string stored(const std::optional<double>& v) {
  return v ? fmt::format("{}", *v) : std::string();
}

std::optional<double> read_value(const std::string& text) {
  if (text.empty()) return std::nullopt;
  double v = 0.0;
  std::from_chars(text.data(), text.data() + text.size(), v);
  return v;
}

StoreResult<void> check_value(const char* what, const std::optional<double>& v) {
  if (!v || (std::isfinite(*v) && std::fabs(*v) <= kMaxValue)) return {};
  return store_error(StoreErrorKind::Invalid,
                     fmt::format("{} must be a finite number within ±1e9", what));
}

StoreResult<void> check_record(const QualityRecord& r) {
  if (r.characteristic.empty())
    return store_error(StoreErrorKind::Invalid, "a quality record names its characteristic");
  for (const auto& [what, text, max] :
       {std::tuple{"characteristic", &r.characteristic, kMaxLabelBytes},
        std::tuple{"unit", &r.unit, kMaxLabelBytes}, std::tuple{"part", &r.part, kMaxLabelBytes},
        std::tuple{"note", &r.note, kMaxReasonBytes}}) {
    if (auto ok = check_text(what, *text, max); !ok) return ok;
  }
  if (!r.program.empty()) {
    if (auto ok = check_name("program", r.program); !ok) return ok;
  }
  for (const auto& [what, v] :
       {std::pair{"measured", std::optional<double>(r.measured)}, std::pair{"nominal", r.nominal},
        std::pair{"min", r.min}, std::pair{"max", r.max}}) {
    if (auto ok = check_value(what, v); !ok) return ok;
  }
  if (r.min && r.max && *r.min > *r.max)
    return store_error(StoreErrorKind::Invalid, "min is above max");
  if (r.job < 0) return store_error(StoreErrorKind::Invalid, "a job number is 0 or more");
  return {};
}

}  // namespace

std::optional<bool> QualityRecord::ok() const {
  if (!min && !max) return std::nullopt;
  return (!min || measured >= *min) && (!max || measured <= *max);
}

StoreResult<QualityRecord> record_quality(Store& store, const Actor& actor, QualityRecord r) {
  if (auto ok = check_record(r); !ok) return tl::unexpected(ok.error());
  r.at_us = store.now_us();
  r.by = actor.user;
  Transaction tx(store.db());
  if (auto b = tx.begin_write(); !b) return tl::unexpected(b.error());
  const std::string measured = stored(r.measured), nominal = stored(r.nominal), min = stored(r.min),
                    max = stored(r.max);
  auto rows = store.db().query(
      "INSERT INTO quality_records (machine, at, by_user, characteristic, measured, nominal, "
      "min_value, max_value, unit, part, program, job, note) "
      "VALUES ($1, $2, $3, $4, $5, $6, $7, $8, $9, $10, $11, $12, $13) RETURNING id",
      {std::string_view(r.machine), r.at_us, std::string_view(r.by),
       std::string_view(r.characteristic), std::string_view(measured), std::string_view(nominal),
       std::string_view(min), std::string_view(max), std::string_view(r.unit),
       std::string_view(r.part), std::string_view(r.program), r.job, std::string_view(r.note)});
  if (!rows) return tl::unexpected(rows.error());
  if (rows->empty()) return store_error(StoreErrorKind::Backend, "the record got no id");
  r.id = rows->front().integer(0);
  nlohmann::json detail = {{"id", r.id}, {"measured", r.measured}};
  if (const auto ok = r.ok()) detail["ok"] = *ok;
  const AuditRecord record{"quality.record", fmt::format("{}/{}", r.machine, r.characteristic),
                           r.note, detail.dump()};
  if (auto a = append_audit(store, actor, record); !a) return tl::unexpected(a.error());
  if (auto c = tx.commit(); !c) return tl::unexpected(c.error());
  return r;
}

StoreResult<std::vector<QualityRecord>> quality_records(Store& store, std::string_view machine,
                                                        std::int64_t before, std::int64_t limit,
                                                        std::string_view characteristic) {
  constexpr std::string_view kColumns =
      "SELECT id, at, by_user, characteristic, measured, nominal, min_value, max_value, unit, "
      "part, program, job, note FROM quality_records WHERE machine = $1 AND id < $2 ";
  const std::int64_t below = before > 0 ? before : std::numeric_limits<std::int64_t>::max();
  // Two statements rather than `$4 = '' OR ...`: PostgreSQL cannot tell the
  // type of a parameter compared only with a literal.
  auto rows =
      characteristic.empty()
          ? store.db().query(fmt::format("{}ORDER BY id DESC LIMIT $3", kColumns),
                             {machine, below, limit})
          : store.db().query(
                fmt::format("{}AND characteristic = $4 ORDER BY id DESC LIMIT $3", kColumns),
                {machine, below, limit, characteristic});
  if (!rows) return tl::unexpected(rows.error());
  std::vector<QualityRecord> out;
  for (const SqlRow& row : *rows) {
    QualityRecord r;
    r.id = row.integer(0);
    r.machine = std::string(machine);
    r.at_us = row.integer(1);
    r.by = row.text(2);
    r.characteristic = row.text(3);
    r.measured = read_value(row.text(4)).value_or(0.0);
    r.nominal = read_value(row.text(5));
    r.min = read_value(row.text(6));
    r.max = read_value(row.text(7));
    r.unit = row.text(8);
    r.part = row.text(9);
    r.program = row.text(10);
    r.job = row.integer(11);
    r.note = row.text(12);
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace usina::dnc
