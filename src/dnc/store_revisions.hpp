// Programs and their revisions. A program (name, machine class, dialect) is
// created by its first revision. A revision is the SHA-256 of its bytes: the
// same bytes uploaded again are the same revision (nothing new is written),
// and nothing of a revision changes but its state, along the graph of
// store_states.hpp, each change an audit entry.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "dnc/store.hpp"
#include "dnc/store_check.hpp"
#include "dnc/store_program_diff.hpp"
#include "dnc/store_states.hpp"

namespace usina::dnc {

struct Program {
  std::string name;
  std::string machine_class;
  std::string dialect;
  std::int64_t created_at_us = 0;
};

struct Revision {
  std::string program;
  std::string hash;  // SHA-256 hex of the bytes: the revision's address
  std::int64_t size = 0;
  std::string author;
  std::int64_t created_at_us = 0;
  std::string reason;
  std::string dialect;
  RevisionState state = RevisionState::Draft;
  std::int64_t state_at_us = 0;
  std::uint64_t check_blocking = 0;  // errors + moves past travel
  std::string checks_json;           // CheckResults::to_json()
};

struct Upload {
  std::string name;
  std::string machine_class;  // empty: the program's (a new program: "default")
  std::string dialect;        // empty: the program's, or guessed from the text
  std::string text;
  std::string reason;
  const sim::MachineProfile* profile = nullptr;  // the machine class's; nullptr: generic
};

struct PutResult {
  Revision revision;
  bool created = false;  // false: these bytes were that program's revision already
};

// Checks the program, then stores it as a draft (check-failed at once when
// the check fails), with its audit entries, in one transaction.
StoreResult<PutResult> put_revision(Store& store, const Upload& upload, const Actor& actor);

StoreResult<Program> find_program(Store& store, std::string_view name);
StoreResult<std::vector<Program>> list_programs(Store& store);

struct RevisionQuery {
  std::string program;                 // empty: every program
  std::optional<RevisionState> state;  // only these
  std::size_t limit = 1000;
  std::size_t offset = 0;
};

// Newest first.
StoreResult<std::vector<Revision>> list_revisions(Store& store, const RevisionQuery& q);
StoreResult<Revision> find_revision(Store& store, std::string_view program, std::string_view hash);
// The revision's bytes, verified against its hash.
StoreResult<std::string> revision_bytes(Store& store, std::string_view program,
                                        std::string_view hash);

// Moves a revision along the graph; refuses a move that is not an edge, to
// checked with a failed check and to check-failed with a clean one. Roles
// are the caller's to check (store_roles.hpp).
StoreResult<Revision> change_state(Store& store, std::string_view program, std::string_view hash,
                                   RevisionState to, std::string_view reason, const Actor& actor);

// The revision released last, nullopt when none is.
StoreResult<std::optional<Revision>> released_revision(Store& store, std::string_view program);

// The diff of two revisions of a program (both read verified), normalised
// by the rules of the newer one's dialect, or plain.
StoreResult<ProgramDiff> diff_revisions(Store& store, std::string_view program,
                                        std::string_view from, std::string_view to,
                                        bool normalised);

}  // namespace usina::dnc
