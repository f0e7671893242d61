// The revision state graph and the role table, every pair tried.
#include "dnc/store_states.hpp"

#include <set>
#include <utility>

#include <gtest/gtest.h>

#include "dnc/store_roles.hpp"

namespace usina::dnc {
namespace {

using S = RevisionState;

// docs/dnc.md's graph, written out again so that a change to the code's
// table fails here until the doc and this agree.
const std::set<std::pair<S, S>> kEdges = {
    {S::Draft, S::Checked},     {S::Draft, S::CheckFailed}, {S::Draft, S::Rejected},
    {S::Checked, S::Approved},  {S::Checked, S::Rejected},  {S::Approved, S::Released},
    {S::Approved, S::Rejected}, {S::Released, S::Rejected},
};

TEST(RevisionStates, EveryPairIsAnEdgeExactlyWhenTheGraphSaysSo) {
  int edges = 0;
  for (const S from : all_states()) {
    for (const S to : all_states()) {
      const bool expected = kEdges.count({from, to}) != 0;
      EXPECT_EQ(transition_exists(from, to), expected)
          << state_name(from) << " -> " << state_name(to);
      EXPECT_EQ(why_not(from, to).empty(), expected);
      edges += expected ? 1 : 0;
    }
  }
  EXPECT_EQ(edges, 8);
}

TEST(RevisionStates, RejectedAndCheckFailedAreFinal) {
  for (const S to : all_states()) {
    EXPECT_FALSE(transition_exists(S::Rejected, to));
    EXPECT_FALSE(transition_exists(S::CheckFailed, to));
  }
}

TEST(RevisionStates, NamesRoundTrip) {
  for (const S s : all_states())
    EXPECT_EQ(parse_state(state_name(s)), s);
  EXPECT_EQ(parse_state("check-failed"), S::CheckFailed);
  EXPECT_FALSE(parse_state("Released").has_value());
  EXPECT_FALSE(parse_state("").has_value());
}

TEST(RevisionStates, ProductionTakesReleasedTryoutTakesApprovedToo) {
  for (const S s : all_states()) {
    EXPECT_EQ(sendable(s, false), s == S::Released) << state_name(s);
    EXPECT_EQ(sendable(s, true), s == S::Released || s == S::Approved) << state_name(s);
  }
}

// Who may make each edge (docs/dnc.md, "Roles").
struct RoleRow {
  S from;
  S to;
  bool op, prog, appr, admin;
};

const RoleRow kRoleTable[] = {
    {S::Draft, S::Checked, false, true, true, true},
    {S::Draft, S::CheckFailed, false, true, true, true},
    {S::Draft, S::Rejected, false, true, true, true},
    {S::Checked, S::Approved, false, false, true, true},
    {S::Checked, S::Rejected, false, false, true, true},
    {S::Approved, S::Released, false, false, true, true},
    {S::Approved, S::Rejected, false, false, true, true},
    {S::Released, S::Rejected, false, false, true, true},
};

TEST(Roles, EachEdgeIsForTheRolesOfTheTable) {
  for (const RoleRow& row : kRoleTable) {
    const bool allowed[] = {row.op, row.prog, row.appr, row.admin};
    for (int r = 0; r < 4; ++r) {
      const auto role = static_cast<Role>(r);
      const auto may = may_change_state(role, "someone", "author", row.from, row.to);
      EXPECT_EQ(may.has_value(), allowed[r])
          << role_name(role) << ": " << state_name(row.from) << " -> " << state_name(row.to)
          << (may ? "" : ": " + may.error());
    }
  }
}

TEST(Roles, NoRoleMakesAMoveThatIsNotAnEdge) {
  for (const S from : all_states()) {
    for (const S to : all_states()) {
      if (transition_exists(from, to)) continue;
      for (int r = 0; r < 4; ++r) {
        const auto may = may_change_state(static_cast<Role>(r), "a", "b", from, to);
        ASSERT_FALSE(may.has_value());
        EXPECT_NE(may.error().find("not allowed"), std::string::npos) << may.error();
      }
    }
  }
}

TEST(Roles, AnApproverMayNotApproveOrReleaseTheirOwnRevision) {
  EXPECT_FALSE(may_change_state(Role::Approver, "ana", "ana", S::Checked, S::Approved));
  EXPECT_FALSE(may_change_state(Role::Approver, "ana", "ana", S::Approved, S::Released));
  EXPECT_TRUE(may_change_state(Role::Approver, "ana", "bruno", S::Checked, S::Approved));
  // Rejecting one's own revision is always allowed; an admin is exempt.
  EXPECT_TRUE(may_change_state(Role::Approver, "ana", "ana", S::Checked, S::Rejected));
  EXPECT_TRUE(may_change_state(Role::Admin, "root", "root", S::Checked, S::Approved));
  const auto may = may_change_state(Role::Approver, "ana", "ana", S::Checked, S::Approved);
  ASSERT_FALSE(may);
  EXPECT_NE(may.error().find("four eyes"), std::string::npos) << may.error();
}

TEST(Roles, PermissionsOfTheTable) {
  EXPECT_TRUE(role_may(Role::Operator, Permission::ReadPrograms));
  EXPECT_TRUE(role_may(Role::Operator, Permission::StartJob));
  EXPECT_FALSE(role_may(Role::Operator, Permission::UploadRevision));
  EXPECT_FALSE(role_may(Role::Operator, Permission::ReadAudit));
  EXPECT_TRUE(role_may(Role::Programmer, Permission::UploadRevision));
  EXPECT_FALSE(role_may(Role::Programmer, Permission::ManageUsers));
  EXPECT_FALSE(role_may(Role::Approver, Permission::UploadRevision));
  EXPECT_TRUE(role_may(Role::Approver, Permission::ReadAudit));
  EXPECT_FALSE(role_may(Role::Approver, Permission::ImportPrograms));
  EXPECT_TRUE(role_may(Role::Operator, Permission::ResetToolLife));
  EXPECT_TRUE(role_may(Role::Programmer, Permission::ResetToolLife));
  EXPECT_FALSE(role_may(Role::Approver, Permission::ResetToolLife));
  for (const Permission p :
       {Permission::ReadPrograms, Permission::UploadRevision, Permission::ImportPrograms,
        Permission::ExportReleased, Permission::StartJob, Permission::ReadMachines,
        Permission::RecordQuality, Permission::ResetToolLife, Permission::ReadAudit,
        Permission::ManageUsers})
    EXPECT_TRUE(role_may(Role::Admin, p));
}

TEST(Roles, NamesRoundTrip) {
  for (int r = 0; r < 4; ++r)
    EXPECT_EQ(parse_role(role_name(static_cast<Role>(r))), static_cast<Role>(r));
  EXPECT_FALSE(parse_role("root").has_value());
}

}  // namespace
}  // namespace usina::dnc
