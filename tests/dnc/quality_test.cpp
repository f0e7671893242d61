// Quality records: stored append-only with their audit entry on SQLite and
// PostgreSQL, and POST/GET /api/machines/{m}/quality over HTTP with their
// roles, checks and pages.
#include <gtest/gtest.h>

#include "api_control.hpp"
#include "dnc/store_audit.hpp"
#include "dnc/store_quality.hpp"
#include "store_fixture.hpp"

namespace usina::dnc {
namespace {

class QualityOnBothStores : public test::StoreTest {};

QualityRecord bore(double measured) {
  QualityRecord r;
  r.machine = "m1";
  r.characteristic = "bore A diameter";
  r.measured = measured;
  r.nominal = 20.0;
  r.min = 20.0;
  r.max = 20.021;  // H7
  r.unit = "mm";
  r.part = "SN-0042";
  return r;
}

TEST_P(QualityOnBothStores, ARecordComesBackExactlyWithItsVerdictNewestFirst) {
  auto store = open();
  ASSERT_TRUE(store);
  const Actor inspector{"ines", "10.0.0.9"};
  auto first = record_quality(*store, inspector, bore(20.012));
  ASSERT_TRUE(first) << first.error().message;
  auto second = record_quality(*store, inspector, bore(20.0215));
  ASSERT_TRUE(second);
  QualityRecord plain;  // a measurement with no limits
  plain.machine = "m1";
  plain.characteristic = "roughness Ra";
  plain.measured = 0.8;
  ASSERT_TRUE(record_quality(*store, inspector, plain));
  QualityRecord other = bore(20.0);
  other.machine = "m2";
  ASSERT_TRUE(record_quality(*store, inspector, other));

  auto page = quality_records(*store, "m1", 0, 100);
  ASSERT_TRUE(page) << page.error().message;
  ASSERT_EQ(page->size(), 3u);
  EXPECT_EQ((*page)[0].characteristic, "roughness Ra");
  EXPECT_FALSE((*page)[0].ok().has_value());
  EXPECT_FALSE((*page)[0].min.has_value());
  EXPECT_EQ((*page)[1].measured, 20.0215);  // the same double back
  EXPECT_EQ((*page)[1].ok(), false);
  EXPECT_EQ((*page)[2].measured, 20.012);
  EXPECT_EQ((*page)[2].max, 20.021);
  EXPECT_EQ((*page)[2].ok(), true);
  EXPECT_EQ((*page)[2].by, "ines");
  EXPECT_EQ((*page)[2].part, "SN-0042");
  // The next page: below the last record given.
  auto next = quality_records(*store, "m1", (*page)[1].id, 100);
  ASSERT_TRUE(next);
  ASSERT_EQ(next->size(), 1u);
  EXPECT_EQ((*next)[0].id, first->id);
  // One characteristic's records, and their next page.
  auto bores = quality_records(*store, "m1", 0, 1, "bore A diameter");
  ASSERT_TRUE(bores) << bores.error().message;
  ASSERT_EQ(bores->size(), 1u);
  EXPECT_EQ((*bores)[0].id, second->id);
  auto older = quality_records(*store, "m1", second->id, 100, "bore A diameter");
  ASSERT_TRUE(older);
  ASSERT_EQ(older->size(), 1u);
  EXPECT_EQ((*older)[0].id, first->id);
  EXPECT_TRUE(quality_records(*store, "m1", 0, 100, "bore B")->empty());
  auto entries = read_audit(*store, 0, 100);
  ASSERT_TRUE(entries);
  ASSERT_EQ(entries->size(), 4u);
  EXPECT_EQ(entries->front().action, "quality.record");
  EXPECT_EQ(entries->front().subject, "m1/bore A diameter");
  EXPECT_EQ(entries->front().origin, "10.0.0.9");
}

TEST_P(QualityOnBothStores, ABadRecordWritesNothingAndNoRecordIsChangedOrDeleted) {
  auto store = open();
  ASSERT_TRUE(store);
  const Actor a{"ines", ""};
  QualityRecord r = bore(20.01);
  r.characteristic = "";
  EXPECT_EQ(record_quality(*store, a, r).error().kind, StoreErrorKind::Invalid);
  r = bore(1e10);
  EXPECT_EQ(record_quality(*store, a, r).error().kind, StoreErrorKind::Invalid);
  r = bore(std::numeric_limits<double>::quiet_NaN());
  EXPECT_EQ(record_quality(*store, a, r).error().kind, StoreErrorKind::Invalid);
  r = bore(20.01);
  r.min = 21.0;  // above max
  EXPECT_EQ(record_quality(*store, a, r).error().kind, StoreErrorKind::Invalid);
  r = bore(20.01);
  r.program = "../etc/passwd";
  EXPECT_EQ(record_quality(*store, a, r).error().kind, StoreErrorKind::Invalid);
  r = bore(20.01);
  r.note = std::string("a\0b", 3);
  EXPECT_EQ(record_quality(*store, a, r).error().kind, StoreErrorKind::Invalid);
  auto none = quality_records(*store, "m1", 0, 100);
  ASSERT_TRUE(none);
  EXPECT_TRUE(none->empty());
  EXPECT_TRUE(read_audit(*store, 0, 100)->empty());

  ASSERT_TRUE(record_quality(*store, a, bore(20.01)));
  auto db = raw();
  ASSERT_TRUE(db);
  EXPECT_FALSE(db->script("UPDATE quality_records SET measured = '20.0'"));
  EXPECT_FALSE(db->script("DELETE FROM quality_records"));
  EXPECT_EQ(quality_records(*store, "m1", 0, 100)->front().measured, 20.01);
}

USINA_STORE_BACKENDS(QualityOnBothStores);

TEST(ApiQuality, AnOperatorRecordsAndAReaderPagesNewestFirst) {
  RunningServer s;
  Control control = start_with_control(s);
  const ApiClient c = s.client();
  const std::string oper = c.log_in("oper", usina::test::kPassword);
  const std::string base = "/api/machines/mill-1/quality";
  const auto made = c.post(base,
                           {{"characteristic", "bore A diameter"},
                            {"measured", 20.025},
                            {"nominal", 20},
                            {"min", 20},
                            {"max", 20.021},
                            {"unit", "mm"},
                            {"part", "SN-7"},
                            {"note", "reworked"}},
                           oper);
  ASSERT_EQ(made.status, 201) << made.body;
  EXPECT_EQ(made.json()["ok"], false);
  EXPECT_EQ(made.json()["by"], "oper");
  EXPECT_EQ(made.json()["measured"], 20.025);
  ASSERT_EQ(c.post(base, {{"characteristic", "depth"}, {"measured", 5.0}}, oper).status, 201);
  const auto page = c.get(base + "?limit=1", oper);
  ASSERT_EQ(page.status, 200) << page.body;
  ASSERT_EQ(page.json()["records"].size(), 1u);
  EXPECT_EQ(page.json()["records"][0]["characteristic"], "depth");
  EXPECT_TRUE(page.json()["records"][0]["ok"].is_null());
  const auto next = c.get(
      base + "?before=" + std::to_string(page.json()["next_before"].get<std::int64_t>()), oper);
  ASSERT_EQ(next.json()["records"].size(), 1u);
  EXPECT_EQ(next.json()["records"][0]["note"], "reworked");
  EXPECT_TRUE(next.json()["next_before"].is_null());  // the last page says so
  // A page that holds exactly what is left is the last one too.
  const auto whole = c.get(base + "?limit=2", oper).json();
  EXPECT_EQ(whole["records"].size(), 2u);
  EXPECT_TRUE(whole["next_before"].is_null()) << whole.dump();
  // One characteristic (the name %-escaped in the query), and one too long.
  const auto bore = c.get(base + "?characteristic=bore%20A%20diameter", oper);
  ASSERT_EQ(bore.status, 200) << bore.body;
  ASSERT_EQ(bore.json()["records"].size(), 1u);
  EXPECT_EQ(bore.json()["records"][0]["measured"], 20.025);
  EXPECT_EQ(c.get(base + "?characteristic=" + std::string(201, 'x'), oper).status, 400);
}

TEST(ApiQuality, BadBodiesAre400AnUnknownMachine404) {
  RunningServer s;
  Control control = start_with_control(s);
  const ApiClient c = s.client();
  const std::string oper = c.log_in("oper", usina::test::kPassword);
  const std::string base = "/api/machines/mill-1/quality";
  const nlohmann::json bad[] = {
      {{"measured", 1.0}},                            // no characteristic
      {{"characteristic", "d"}},                      // nothing measured
      {{"characteristic", "d"}, {"measured", "20"}},  // a string
      {{"characteristic", "d"}, {"measured", 1.0}, {"min", 2.0}, {"max", 1.0}},
      {{"characteristic", "d"}, {"measured", 1.0}, {"program", "NOPE"}},  // no such program
      {{"characteristic", "d"}, {"measured", 1.0}, {"job", 999}},         // no such job
      {{"characteristic", "d"}, {"measured", 1.0}, {"job", -1}}};
  for (const auto& body : bad)
    EXPECT_EQ(c.post(base, body, oper).status, 400) << body.dump();
  EXPECT_EQ(c.call(usina::test::bhttp::verb::post, base, "{", oper).status, 400);
  EXPECT_EQ(c.get(base + "?limit=5000", oper).status, 400);
  EXPECT_EQ(c.get(base + "?before=x", oper).status, 400);
  EXPECT_EQ(c.post("/api/machines/nope/quality", {{"characteristic", "d"}, {"measured", 1.0}}, oper)
                .status,
            404);
  EXPECT_TRUE(c.get(base, oper).json()["records"].empty());
}

}  // namespace
}  // namespace usina::dnc
