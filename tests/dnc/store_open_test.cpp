// Opening a store: the schema's version, SQLite's WAL, a newer schema refused.
#include <algorithm>

#include <gtest/gtest.h>

#include "dnc/store_check.hpp"
#include "dnc/store_schema.hpp"
#include "store_fixture.hpp"

namespace usina::dnc {
namespace {

class StoreOpen : public test::StoreTest {};

TEST_P(StoreOpen, AFreshStoreHasTheCurrentSchemaAndOpensAgain) {
  ASSERT_TRUE(open());
  auto rows = raw()->query("SELECT MAX(version) FROM schema_version").value();
  EXPECT_EQ(rows[0].integer(0), current_schema_version());
  ASSERT_TRUE(open());
  EXPECT_EQ(raw()->query("SELECT COUNT(*) FROM schema_version").value()[0].integer(0),
            current_schema_version());
}

TEST_P(StoreOpen, AStoreFromANewerUsinaIsRefused) {
  ASSERT_TRUE(open());
  ASSERT_TRUE(raw()->query("INSERT INTO schema_version (version) VALUES (999)"));
  auto s = Store::open(where(), options());
  ASSERT_FALSE(s);
  EXPECT_EQ(s.error().kind, StoreErrorKind::Conflict);
  EXPECT_NE(s.error().message.find("999"), std::string::npos) << s.error().message;
}

TEST_P(StoreOpen, SqliteRunsInWalMode) {
  if (GetParam() != Backend::Sqlite) GTEST_SKIP() << "SQLite only";
  ASSERT_TRUE(open());
  EXPECT_EQ(raw()->query("PRAGMA journal_mode").value()[0].text(0), "wal");
}

USINA_STORE_BACKENDS(StoreOpen);

TEST(StoreOpenErrors, AnUnreachableServerIsABackendError) {
  auto s = Store::open("postgresql://usina@127.0.0.1:1/none?connect_timeout=2");
  ASSERT_FALSE(s);
  EXPECT_EQ(s.error().kind, StoreErrorKind::Backend);
  EXPECT_NE(s.error().message.find("postgresql"), std::string::npos) << s.error().message;
}

TEST(StoreOpenErrors, AFileWhereTheFolderShouldBeIsRefused) {
  auto s = Store::open("/dev/null");
  ASSERT_FALSE(s);
  EXPECT_EQ(s.error().kind, StoreErrorKind::Invalid);
}

TEST(CheckResults, JsonRoundTrip) {
  const CheckResults r = check_program("G21 G90\nG0 X1 Y2 Z3\nG1 X4 F100\nG2 X9 R1\nM2\n", {});
  EXPECT_GT(r.errors, 0u);
  const auto error = std::find_if(r.diagnostics.begin(), r.diagnostics.end(),
                                  [](const CheckDiagnostic& d) { return d.severity == "error"; });
  ASSERT_NE(error, r.diagnostics.end());
  EXPECT_EQ(error->line, 4u) << error->message;
  const auto back = CheckResults::from_json(r.to_json());
  ASSERT_TRUE(back);
  EXPECT_EQ(back->to_json(), r.to_json());
  EXPECT_FALSE(CheckResults::from_json("{\"bounds\": {\"min\": [\"x\"]}}"));
  EXPECT_FALSE(CheckResults::from_json("not json"));
}

TEST(CheckResults, AnUnknownDialectIsAnError) {
  const CheckResults r = check_program("G0 X1\n", {"heidenhain", nullptr});
  EXPECT_EQ(r.errors, 1u);
  EXPECT_FALSE(r.complete);
}

}  // namespace
}  // namespace usina::dnc
