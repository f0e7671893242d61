#include "dnc/store_roles.hpp"

#include <array>
#include <cstdint>

#include <fmt/format.h>

namespace usina::dnc {
namespace {

using S = RevisionState;

constexpr std::uint8_t bit(Role r) {
  return static_cast<std::uint8_t>(1u << static_cast<int>(r));
}

constexpr std::uint8_t kOperator = bit(Role::Operator);
constexpr std::uint8_t kProgrammer = bit(Role::Programmer);
constexpr std::uint8_t kApprover = bit(Role::Approver);
constexpr std::uint8_t kAdmin = bit(Role::Admin);
constexpr std::uint8_t kEveryone = kOperator | kProgrammer | kApprover | kAdmin;

struct Grant {
  Permission what;
  std::uint8_t roles;
};

constexpr std::array<Grant, 11> kGrants{{
    {Permission::ReadPrograms, kEveryone},
    {Permission::UploadRevision, kProgrammer | kAdmin},
    {Permission::ImportPrograms, kAdmin},
    {Permission::ExportReleased, kProgrammer | kApprover | kAdmin},
    {Permission::StartJob, kOperator | kProgrammer | kAdmin},
    {Permission::ReadMachines, kEveryone},
    {Permission::RecordQuality, kOperator | kApprover | kAdmin},
    // Those who run the machines change the inserts: as StartJob.
    {Permission::ResetToolLife, kOperator | kProgrammer | kAdmin},
    {Permission::ReadAudit, kApprover | kAdmin},
    {Permission::ManageUsers, kAdmin},
    {Permission::ManageMachines, kAdmin},
}};

struct StateGrant {
  S from;
  S to;
  std::uint8_t roles;
  bool four_eyes;  // not by the revision's author (admins excepted)
};

constexpr std::array<StateGrant, 8> kStateGrants{{
    {S::Draft, S::Checked, kProgrammer | kApprover | kAdmin, false},
    {S::Draft, S::CheckFailed, kProgrammer | kApprover | kAdmin, false},
    {S::Draft, S::Rejected, kProgrammer | kApprover | kAdmin, false},
    {S::Checked, S::Approved, kApprover | kAdmin, true},
    {S::Checked, S::Rejected, kApprover | kAdmin, false},
    {S::Approved, S::Released, kApprover | kAdmin, true},
    {S::Approved, S::Rejected, kApprover | kAdmin, false},
    {S::Released, S::Rejected, kApprover | kAdmin, false},
}};

constexpr std::array<std::string_view, 4> kRoleNames{"operator", "programmer", "approver", "admin"};

std::string roles_text(std::uint8_t roles) {
  std::string out;
  for (std::size_t i = 0; i < kRoleNames.size(); ++i) {
    if ((roles & (1u << i)) == 0) continue;
    if (!out.empty()) out += ", ";
    out += kRoleNames[i];
  }
  return out;
}

}  // namespace

std::string_view role_name(Role r) {
  return kRoleNames.at(static_cast<std::size_t>(r));
}

std::optional<Role> parse_role(std::string_view name) {
  for (std::size_t i = 0; i < kRoleNames.size(); ++i) {
    if (kRoleNames[i] == name) return static_cast<Role>(i);
  }
  return std::nullopt;
}

bool role_may(Role role, Permission p) {
  for (const Grant& g : kGrants) {
    if (g.what == p) return (g.roles & bit(role)) != 0;
  }
  return false;
}

tl::expected<void, std::string> may_change_state(Role role, std::string_view actor,
                                                 std::string_view author, RevisionState from,
                                                 RevisionState to) {
  if (!transition_exists(from, to)) {
    return tl::unexpected(fmt::format("{} → {} is not allowed: {}", state_name(from),
                                      state_name(to), why_not(from, to)));
  }
  for (const StateGrant& g : kStateGrants) {
    if (g.from != from || g.to != to) continue;
    if ((g.roles & bit(role)) == 0) {
      return tl::unexpected(fmt::format("{} → {} is for {}; {} is {}", state_name(from),
                                        state_name(to), roles_text(g.roles), actor,
                                        role_name(role)));
    }
    if (g.four_eyes && role != Role::Admin && actor == author) {
      return tl::unexpected(
          fmt::format("{} wrote this revision; {} → {} needs someone else (four eyes)", actor,
                      state_name(from), state_name(to)));
    }
    return {};
  }
  return tl::unexpected(
      fmt::format("{} → {} has no role that may do it", state_name(from), state_name(to)));
}

}  // namespace usina::dnc
