#include "dnc/store_audit.hpp"

#include <fmt/format.h>

#include "dnc/sha256.hpp"

namespace usina::dnc {
namespace {

const std::string kZeroHash(64, '0');
constexpr std::size_t kPage = 5000;  // entries read at a time while verifying

constexpr std::string_view kColumns =
    "seq, at, actor, action, subject, reason, origin, detail, prev_hash, hash";

AuditEntry entry_of(const SqlRow& r) {
  return {r.integer(0), r.integer(1), r.text(2), r.text(3), r.text(4),
          r.text(5),    r.text(6),    r.text(7), r.text(8), r.text(9)};
}

void field(Sha256& h, std::string_view s) {
  h.add(std::to_string(s.size())).add(":").add(s);
}

// What is wrong with `e` coming after an entry with `prev_seq` and `prev_hash`.
std::string problem_of(const AuditEntry& e, std::int64_t prev_seq, const std::string& prev_hash) {
  if (e.seq != prev_seq + 1) {
    return fmt::format("entry {} follows entry {}: {} entries are missing", e.seq, prev_seq,
                       e.seq - prev_seq - 1);
  }
  if (e.prev_hash != prev_hash) {
    return fmt::format("entry {} points back to {}, but the entry before it hashes to {}", e.seq,
                       e.prev_hash, prev_hash);
  }
  if (const std::string h = audit_hash(e); h != e.hash)
    return fmt::format("entry {} was altered: its fields hash to {}, it says {}", e.seq, h, e.hash);
  return {};
}

}  // namespace

std::string audit_hash(const AuditEntry& e) {
  Sha256 h;
  field(h, std::to_string(e.seq));
  field(h, std::to_string(e.at_us));
  for (const std::string* s :
       {&e.actor, &e.action, &e.subject, &e.reason, &e.origin, &e.detail, &e.prev_hash})
    field(h, *s);
  return h.hex();
}

StoreResult<AuditEntry> append_audit(Store& store, const Actor& actor, const AuditRecord& record) {
  auto last = store.db().query("SELECT seq, hash FROM audit ORDER BY seq DESC LIMIT 1");
  if (!last) return tl::unexpected(last.error());
  AuditEntry e;
  e.seq = last->empty() ? 1 : last->front().integer(0) + 1;
  e.prev_hash = last->empty() ? kZeroHash : last->front().text(1);
  e.at_us = store.now_us();
  e.actor = actor.user;
  e.origin = actor.origin;
  e.action = record.action;
  e.subject = record.subject;
  e.reason = record.reason;
  e.detail = record.detail;
  e.hash = audit_hash(e);
  auto put = store.db().query(
      "INSERT INTO audit (seq, at, actor, action, subject, reason, origin, detail, prev_hash, "
      "hash) VALUES ($1, $2, $3, $4, $5, $6, $7, $8, $9, $10)",
      {e.seq, e.at_us, std::string_view(e.actor), std::string_view(e.action),
       std::string_view(e.subject), std::string_view(e.reason), std::string_view(e.origin),
       std::string_view(e.detail), std::string_view(e.prev_hash), std::string_view(e.hash)});
  if (!put) return tl::unexpected(put.error());
  return e;
}

StoreResult<std::vector<AuditEntry>> read_audit(Store& store, std::int64_t after,
                                                std::size_t limit) {
  auto rows = store.db().query(
      fmt::format("SELECT {} FROM audit WHERE seq > $1 ORDER BY seq LIMIT $2", kColumns),
      {after, static_cast<std::int64_t>(limit)});
  if (!rows) return tl::unexpected(rows.error());
  std::vector<AuditEntry> out;
  out.reserve(rows->size());
  for (const SqlRow& r : *rows)
    out.push_back(entry_of(r));
  return out;
}

StoreResult<AuditVerdict> verify_audit(Store& store,
                                       const std::optional<std::string>& expected_head) {
  Transaction tx(store.db());
  if (auto b = tx.begin_read(); !b) return tl::unexpected(b.error());
  AuditVerdict v;
  v.head = kZeroHash;
  std::int64_t prev_seq = 0;
  bool head_seen = !expected_head || *expected_head == kZeroHash;
  for (;;) {
    auto page = read_audit(store, prev_seq, kPage);
    if (!page) return tl::unexpected(page.error());
    for (const AuditEntry& e : *page) {
      if (std::string p = problem_of(e, prev_seq, v.head); !p.empty()) {
        v.ok = false;
        v.first_bad = e.seq;
        v.problem = std::move(p);
        return v;
      }
      head_seen = head_seen || e.hash == *expected_head;
      prev_seq = e.seq;
      v.head = e.hash;
      ++v.entries;
    }
    if (page->size() < kPage) break;
  }
  if (!head_seen) {
    v.ok = false;
    v.problem = fmt::format(
        "the chain of {} entries no longer holds the head {} kept elsewhere: "
        "entries were cut off its end",
        v.entries, *expected_head);
  }
  return v;
}

}  // namespace usina::dnc
