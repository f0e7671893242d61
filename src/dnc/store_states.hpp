// A revision's life (docs/dnc.md, "States"):
//
//   draft ──► checked ──► approved ──► released
//     │          │           │            │
//     ├──► check-failed      ▼            ▼
//     └────────────────► rejected ◄───────┘ (withdrawn)
//
// A revision is born a draft with its check results; when the check found an
// error the store moves it to check-failed at once. checked needs a clean
// check. rejected and check-failed are final: a fix is a new revision (new
// bytes, new address). Only released revisions go to production machines;
// a machine in try-out mode also takes approved ones.
#pragma once

#include <optional>
#include <span>
#include <string_view>

namespace usina::dnc {

enum class RevisionState { Draft, Checked, Approved, Released, Rejected, CheckFailed };

// "draft", "checked", "approved", "released", "rejected", "check-failed".
std::string_view state_name(RevisionState s);
std::optional<RevisionState> parse_state(std::string_view name);
std::span<const RevisionState> all_states();

// An edge of the graph above.
bool transition_exists(RevisionState from, RevisionState to);

// Why `from` → `to` is not an edge, for a message ("a released revision can
// only be withdrawn (rejected)"); empty when it is one.
std::string_view why_not(RevisionState from, RevisionState to);

// What a machine may be sent: released ones; in try-out, approved ones too.
bool sendable(RevisionState s, bool tryout);

}  // namespace usina::dnc
