// Who may do what (docs/dnc.md, "Roles"). The store enforces the state graph
// (store_states.hpp); the API layer checks a user's role against this table
// before it asks the store, so both read one table.
//
//   operator    reads programs and machines, starts jobs, enters quality data,
//               resets tool-life counts
//   programmer  + uploads revisions, moves drafts (checked, check-failed,
//               rejected), exports the released set (and resets tool counts)
//   approver    reads, approves or rejects checked revisions, releases
//               approved ones, moves drafts; reads the audit log
//   admin       everything, users, machines and imports included
//
// Four eyes: a revision is approved and released by someone other than its
// author, unless that someone is an admin (a one-person shop has one).
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include <tl/expected.hpp>

#include "dnc/store_states.hpp"

namespace usina::dnc {

enum class Role { Operator, Programmer, Approver, Admin };

std::string_view role_name(Role r);
std::optional<Role> parse_role(std::string_view name);

// What a role may do besides state changes.
enum class Permission {
  ReadPrograms,    // programs, revisions, diffs
  UploadRevision,  // a new revision (a draft)
  ImportPrograms,  // a folder of programs at once
  ExportReleased,  // the released set to a folder
  StartJob,        // send or drip-feed to a machine
  ReadMachines,    // machine states, counts, jobs
  RecordQuality,   // quality records through the API
  ResetToolLife,   // a tool's count starts again (its insert was changed)
  ReadAudit,       // the audit log and its verification
  ManageUsers,     // accounts, roles, passwords
  ManageMachines,  // machines added, changed, retired from the API
};

bool role_may(Role role, Permission p);

// Whether `actor` with `role` may move a revision written by `author` from
// `from` to `to`; the error says why not. The graph itself is checked too,
// so a refusal names the first reason that applies.
tl::expected<void, std::string> may_change_state(Role role, std::string_view actor,
                                                 std::string_view author, RevisionState from,
                                                 RevisionState to);

}  // namespace usina::dnc
