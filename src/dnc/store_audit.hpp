// The audit log: append-only, each entry holding the hash of the one before,
// so that rewriting, removing or reordering an entry breaks the chain from
// there on. The database refuses UPDATE and DELETE (triggers); the chain
// catches whoever drops the triggers or edits the file. Cutting entries off
// the end leaves a valid shorter chain: compare the head hash with one kept
// elsewhere (verify_audit's `expected_head`) to catch that too.
//
// An entry's hash is SHA-256 over its fields, each preceded by its length
// (so no two different entries hash alike by moving a separator):
//   seq, at, actor, action, subject, reason, origin, detail, prev_hash.
// The first entry's prev_hash is 64 zeros.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "dnc/store.hpp"

namespace usina::dnc {

struct AuditRecord {
  std::string action;   // "revision.upload", "revision.state", "user.create", "login.failed"...
  std::string subject;  // "O1000@<hash>", a user name
  std::string reason;
  std::string detail;  // JSON
};

struct AuditEntry {
  std::int64_t seq = 0;
  std::int64_t at_us = 0;
  std::string actor;
  std::string action;
  std::string subject;
  std::string reason;
  std::string origin;
  std::string detail;
  std::string prev_hash;
  std::string hash;
};

// Appends inside the caller's write transaction (the change and its entry
// commit together, or neither does).
StoreResult<AuditEntry> append_audit(Store& store, const Actor& actor, const AuditRecord& record);

// Entries with seq > `after`, oldest first, at most `limit`.
StoreResult<std::vector<AuditEntry>> read_audit(Store& store, std::int64_t after,
                                                std::size_t limit);

struct AuditVerdict {
  bool ok = true;
  std::int64_t entries = 0;
  std::string head;            // the last entry's hash (64 zeros when empty)
  std::int64_t first_bad = 0;  // seq of the first entry that fails, 0 when none
  std::string problem;         // what is wrong there
};

// Walks the whole chain. With `expected_head`, also fails when the chain no
// longer contains that hash (entries were cut off the end).
StoreResult<AuditVerdict> verify_audit(Store& store,
                                       const std::optional<std::string>& expected_head = {});

// The hash an entry must carry.
std::string audit_hash(const AuditEntry& e);

}  // namespace usina::dnc
