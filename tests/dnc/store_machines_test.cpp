// The machines an admin adds through the API, as the store keeps them on
// SQLite and PostgreSQL: added once per name, changed and retired while in
// service only, each change an audit entry in its transaction.
#include "dnc/store_machines.hpp"

#include <gtest/gtest.h>

#include "dnc/store_audit.hpp"
#include "store_fixture.hpp"

namespace usina::dnc {
namespace {

class StoreMachines : public test::StoreTest {};

const Actor kBoss{"boss", "test"};

TEST_P(StoreMachines, AddedChangedAndRetiredEachWithItsAuditEntry) {
  auto store = open();
  ASSERT_TRUE(store);
  ASSERT_TRUE(add_machine(*store, kBoss, "mill-2", R"({"name":"mill-2"})", "new mill"));
  now_us += 1'000'000;
  auto changed = change_machine(*store, kBoss, "mill-2", R"({"name":"mill-2","baud":4800})",
                                R"({"baud":{"from":9600,"to":4800}})", "slower cable");
  ASSERT_TRUE(changed) << changed.error().message;
  EXPECT_GT(changed->changed_at_us, changed->created_at_us);
  ASSERT_TRUE(retire_machine(*store, kBoss, "mill-2", "sold"));
  auto all = stored_machines(*store);
  ASSERT_TRUE(all);
  ASSERT_EQ(all->size(), 1U);
  EXPECT_EQ(all->front().settings, R"({"name":"mill-2","baud":4800})");
  EXPECT_EQ(all->front().created_by, "boss");
  EXPECT_EQ(all->front().retired_by, "boss");
  EXPECT_EQ(all->front().retire_reason, "sold");
  EXPECT_NE(all->front().retired_at_us, 0);
  auto audit = read_audit(*store, 0, 100);
  ASSERT_TRUE(audit);
  std::vector<std::string> actions;
  for (const AuditEntry& e : *audit) {
    if (e.subject == "mill-2") actions.push_back(e.action + ":" + e.reason);
  }
  EXPECT_EQ(actions,
            (std::vector<std::string>{"machine.add:new mill", "machine.change:slower cable",
                                      "machine.retire:sold"}));
  EXPECT_EQ(audit->back().detail, "{}");
}

TEST_P(StoreMachines, ANameIsTakenOnceAndARetiredMachineChangesNoMore) {
  auto store = open();
  ASSERT_TRUE(store);
  ASSERT_TRUE(add_machine(*store, kBoss, "lathe-1", "{}", ""));
  auto again = add_machine(*store, kBoss, "lathe-1", "{}", "");
  ASSERT_FALSE(again);
  EXPECT_EQ(again.error().kind, StoreErrorKind::Conflict);
  ASSERT_TRUE(retire_machine(*store, kBoss, "lathe-1", "scrapped"));
  auto after = add_machine(*store, kBoss, "lathe-1", "{}", "");
  ASSERT_FALSE(after);
  EXPECT_NE(after.error().message.find("retired"), std::string::npos) << after.error().message;
  auto change = change_machine(*store, kBoss, "lathe-1", "{}", "{}", "");
  ASSERT_FALSE(change);
  EXPECT_EQ(change.error().kind, StoreErrorKind::Refused);
  EXPECT_EQ(retire_machine(*store, kBoss, "lathe-1", "twice").error().kind,
            StoreErrorKind::Refused);
  EXPECT_EQ(retire_machine(*store, kBoss, "nothing", "x").error().kind, StoreErrorKind::NotFound);
  EXPECT_EQ(add_machine(*store, kBoss, "../x", "{}", "").error().kind, StoreErrorKind::Invalid);
  EXPECT_EQ(add_machine(*store, kBoss, "m", "{}", std::string(3000, 'r')).error().kind,
            StoreErrorKind::TooLarge);
}

USINA_STORE_BACKENDS(StoreMachines);

}  // namespace
}  // namespace usina::dnc
