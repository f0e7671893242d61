#include "dnc/store_states.hpp"

#include <array>

namespace usina::dnc {
namespace {

using S = RevisionState;

struct StateInfo {
  S state;
  std::string_view name;
  std::string_view leaves;  // what may follow, for a refusal's message
};

constexpr std::array<StateInfo, 6> kStates{{
    {S::Draft, "draft", "a draft becomes checked, check-failed or rejected"},
    {S::Checked, "checked", "a checked revision becomes approved or rejected"},
    {S::Approved, "approved", "an approved revision becomes released or rejected"},
    {S::Released, "released", "a released revision can only be withdrawn (rejected)"},
    {S::Rejected, "rejected", "a rejected revision is final; upload a new revision"},
    {S::CheckFailed, "check-failed", "a revision that failed its check is final; upload a fix"},
}};

struct Edge {
  S from;
  S to;
};

constexpr std::array<Edge, 8> kEdges{{
    {S::Draft, S::Checked},
    {S::Draft, S::CheckFailed},
    {S::Draft, S::Rejected},
    {S::Checked, S::Approved},
    {S::Checked, S::Rejected},
    {S::Approved, S::Released},
    {S::Approved, S::Rejected},
    {S::Released, S::Rejected},
}};

constexpr std::array<S, 6> kAll{S::Draft,    S::Checked,  S::Approved,
                                S::Released, S::Rejected, S::CheckFailed};

}  // namespace

std::string_view state_name(RevisionState s) {
  for (const StateInfo& i : kStates) {
    if (i.state == s) return i.name;
  }
  return "?";
}

std::optional<RevisionState> parse_state(std::string_view name) {
  for (const StateInfo& i : kStates) {
    if (i.name == name) return i.state;
  }
  return std::nullopt;
}

std::span<const RevisionState> all_states() {
  return kAll;
}

bool transition_exists(RevisionState from, RevisionState to) {
  for (const Edge& e : kEdges) {
    if (e.from == from && e.to == to) return true;
  }
  return false;
}

std::string_view why_not(RevisionState from, RevisionState to) {
  if (transition_exists(from, to)) return {};
  for (const StateInfo& i : kStates) {
    if (i.state == from) return i.leaves;
  }
  return "unknown state";
}

bool sendable(RevisionState s, bool tryout) {
  return s == RevisionState::Released || (tryout && s == RevisionState::Approved);
}

}  // namespace usina::dnc
