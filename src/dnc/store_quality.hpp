// Quality records (schema version 10; seed 004 table 7.3's data back from
// the machines): a measurement of a part made on a machine, entered by an
// operator or inspector through the API, with the limits it must fall
// within. A record is evidence: the table is append-only (triggers refuse
// UPDATE and DELETE), and each record is an audit entry (`quality.record`)
// written in the same transaction.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "dnc/store.hpp"

namespace usina::dnc {

struct QualityRecord {
  std::int64_t id = 0;  // the store's; 0 before it is recorded
  std::string machine;
  std::int64_t at_us = 0;
  std::string by;              // the user
  std::string characteristic;  // "bore A diameter", "flatness of face 2"
  double measured = 0.0;
  std::optional<double> nominal;
  std::optional<double> min;  // the lowest value that passes
  std::optional<double> max;  // the highest
  std::string unit;           // "mm", "um", "in", "deg", "Ra", ... free text
  std::string part;           // a serial or part number, may be empty
  std::string program;        // the program that made it, may be empty
  std::int64_t job = 0;       // the job that made it, 0 when not given
  std::string note;

  // Within its limits; nullopt when it has none (a plain measurement).
  std::optional<bool> ok() const;
};

// Records `r` (its id, time and user are the store's), with its audit
// entry. Invalid: a characteristic that is empty or not free text, a value
// that is not finite or beyond ±1e9, min above max, a program name that is
// not a name, a job below 0, texts past their sizes (store_names.hpp).
StoreResult<QualityRecord> record_quality(Store& store, const Actor& actor, QualityRecord r);

// The machine's records, newest first: at most `limit`, those with an id
// below `before` when it is not 0 (the next page); only those of
// `characteristic` when it is not empty.
StoreResult<std::vector<QualityRecord>> quality_records(Store& store, std::string_view machine,
                                                        std::int64_t before, std::int64_t limit,
                                                        std::string_view characteristic = {});

}  // namespace usina::dnc
