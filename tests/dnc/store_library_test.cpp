// The library page on both back ends: filters by class, dialect, newest
// state and released revision, a part of the name in any case (with LIKE's
// own characters taken literally), the count on every page, paging; the
// search of the newest revision's comments, program numbers and tools, and
// the facts of a store's revisions made when it comes to schema version 6.
#include "dnc/store_library.hpp"

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "dnc/store_schema.hpp"
#include "store_fixture.hpp"

namespace usina::dnc {
namespace {

using S = RevisionState;

constexpr char kProgram[] = "G21 G90\nG0 X0 Y0 Z5\nG1 Z-1 F100\nG1 X10 Y5\nM2\n";

class StoreLibrary : public test::StoreTest {
 protected:
  // A revision of `name` (its text differs by `n`), moved along to `to`.
  Revision put(Store& s, const std::string& name, const std::string& machine_class,
               const std::string& dialect, int n, S to) {
    const std::string text = "(" + std::to_string(n) + ")\n" + kProgram;
    auto r = put_revision(s, {name, machine_class, dialect, text, "t", nullptr}, {"ana", "t"});
    if (!r) ADD_FAILURE() << name << ": " << r.error().message;
    Revision v = r->revision;
    std::vector<S> path;
    if (to == S::Checked) path = {S::Checked};
    if (to == S::Released) path = {S::Checked, S::Approved, S::Released};
    if (to == S::Rejected) path = {S::Rejected};
    for (const S next : path) {
      auto moved = change_state(s, v.program, v.hash, next, "t", {"boss", "t"});
      EXPECT_TRUE(moved) << (moved ? "" : moved.error().message);
      v = *moved;
    }
    return v;
  }

  // The names of a page.
  static std::vector<std::string> names(const LibraryPage& page) {
    std::vector<std::string> out;
    for (const LibraryEntry& e : page.programs)
      out.push_back(e.program.name);
    return out;
  }

  // Five programs: two mill classes, two dialects, every kind of newest state.
  void fill(Store& s) {
    put(s, "O1000", "mill", "rs274ngc", 1, S::Released);
    released_then_draft = put(s, "O1000", "mill", "rs274ngc", 2, S::Draft).hash;
    put(s, "O2000", "mill", "fanuc", 3, S::Checked);
    put(s, "LATHE_10", "lathe", "fanuc", 4, S::Rejected);
    put(s, "Plate_50", "mill", "rs274ngc", 5, S::Released);
    put(s, "PlateX5", "mill", "rs274ngc", 6, S::Draft);
  }

  std::string released_then_draft;

  // A revision of `name` with this text, a draft.
  void put_text(Store& s, const std::string& name, const std::string& dialect,
                const std::string& text) {
    auto r = put_revision(s, {name, "mill", dialect, text, "t", nullptr}, {"ana", "t"});
    ASSERT_TRUE(r) << name << ": " << r.error().message;
  }

  // Three programs with comments, program numbers and tools; PLATE's newest
  // revision no longer has its first one's comment and tool.
  void fill_texts(Store& s) {
    put_text(s, "BRACKET", "fanuc", "%\nO4711 (BRACKET FOR PUMP)\nT5 M6\nG0 X0 Y0\nM30\n%\n");
    put_text(s, "FLANGE", "rs274ngc", "(Flange, 6 holes; 100%)\nT12 M6\nG0 X0\nM2\n");
    put_text(s, "PLATE", "rs274ngc", "(old fixture)\nT7 M6\nG0 X0\nM2\n");
    put_text(s, "PLATE", "rs274ngc", "(new clamp)\nT8 M6\nG0 X0\nM2\n");
  }

  std::vector<std::string> text_search(Store& s, const std::string& text,
                                       std::optional<std::int64_t> tool = std::nullopt) {
    LibraryQuery q;
    q.text = text;
    q.tool = tool;
    auto page = library_page(s, q);
    EXPECT_TRUE(page) << page.error().message;
    if (page) {
      EXPECT_EQ(page->total, static_cast<std::int64_t>(page->programs.size()));
    }
    return page ? names(*page) : std::vector<std::string>{};
  }
};

TEST_P(StoreLibrary, EveryProgramWithItsNewestAndReleasedRevision) {
  auto s = open();
  ASSERT_TRUE(s);
  fill(*s);
  auto page = library_page(*s, {});
  ASSERT_TRUE(page) << page.error().message;
  EXPECT_EQ(page->total, 5);
  ASSERT_EQ(names(*page),
            (std::vector<std::string>{"LATHE_10", "O1000", "O2000", "PlateX5", "Plate_50"}));
  const LibraryEntry& o1000 = page->programs[1];
  EXPECT_EQ(o1000.revisions, 2);
  EXPECT_EQ(o1000.newest_revision, released_then_draft);
  EXPECT_EQ(o1000.newest_state, "draft");
  EXPECT_FALSE(o1000.released_revision.empty());
  EXPECT_NE(o1000.released_revision, o1000.newest_revision);
  EXPECT_TRUE(page->programs[2].released_revision.empty());
}

TEST_P(StoreLibrary, FiltersByClassDialectStateAndReleased) {
  auto s = open();
  ASSERT_TRUE(s);
  fill(*s);
  LibraryQuery q;
  q.machine_class = "lathe";
  EXPECT_EQ(names(library_page(*s, q).value()), std::vector<std::string>{"LATHE_10"});
  q = {};
  q.dialect = "fanuc";
  EXPECT_EQ(names(library_page(*s, q).value()), (std::vector<std::string>{"LATHE_10", "O2000"}));
  q = {};
  q.state = S::Draft;  // the newest revision's state: O1000's released one is older
  EXPECT_EQ(names(library_page(*s, q).value()), (std::vector<std::string>{"O1000", "PlateX5"}));
  q = {};
  q.released_only = true;
  EXPECT_EQ(names(library_page(*s, q).value()), (std::vector<std::string>{"O1000", "Plate_50"}));
  q.machine_class = "lathe";
  const LibraryPage none = library_page(*s, q).value();
  EXPECT_TRUE(none.programs.empty());
  EXPECT_EQ(none.total, 0);
}

TEST_P(StoreLibrary, ANamePartInAnyCaseWithLikesCharactersTakenLiterally) {
  auto s = open();
  ASSERT_TRUE(s);
  fill(*s);
  LibraryQuery q;
  q.name_part = "plate";
  EXPECT_EQ(names(library_page(*s, q).value()), (std::vector<std::string>{"PlateX5", "Plate_50"}));
  q.name_part = "e_5";  // _ is a character here, not "any one": no PlateX5
  EXPECT_EQ(names(library_page(*s, q).value()), std::vector<std::string>{"Plate_50"});
  q.name_part = "5%0";  // % is a character, not "anything": no Plate_50
  EXPECT_TRUE(library_page(*s, q).value().programs.empty());
  q.name_part = "5!";  // the escape character itself
  EXPECT_TRUE(library_page(*s, q).value().programs.empty());
  q.name_part = "ATHE_1";
  EXPECT_EQ(names(library_page(*s, q).value()), std::vector<std::string>{"LATHE_10"});
}

TEST_P(StoreLibrary, PagesShareTheirCount) {
  auto s = open();
  ASSERT_TRUE(s);
  fill(*s);
  LibraryQuery q;
  q.limit = 2;
  std::vector<std::string> all;
  for (q.offset = 0; q.offset < 6; q.offset += 2) {
    const LibraryPage page = library_page(*s, q).value();
    EXPECT_EQ(page.total, 5);
    EXPECT_LE(page.programs.size(), 2u);
    for (const std::string& n : names(page))
      all.push_back(n);
  }
  EXPECT_EQ(all, (std::vector<std::string>{"LATHE_10", "O1000", "O2000", "PlateX5", "Plate_50"}));
}

TEST_P(StoreLibrary, TextFindsACommentAProgramNumberOrANameInAnyCase) {
  auto s = open();
  ASSERT_TRUE(s);
  fill_texts(*s);
  using Names = std::vector<std::string>;
  EXPECT_EQ(text_search(*s, "pump"), Names{"BRACKET"});
  EXPECT_EQ(text_search(*s, "For Pump"), Names{"BRACKET"});
  EXPECT_EQ(text_search(*s, "O4711"), Names{"BRACKET"});
  EXPECT_EQ(text_search(*s, "o47"), Names{"BRACKET"});
  EXPECT_EQ(text_search(*s, "6 holes"), Names{"FLANGE"});
  EXPECT_EQ(text_search(*s, "ACKE"), Names{"BRACKET"});  // the name
  EXPECT_EQ(text_search(*s, "100%"), Names{"FLANGE"});   // % is a character
  EXPECT_EQ(text_search(*s, "1_0"), Names{});            // _ too
  EXPECT_EQ(text_search(*s, "new clamp"), Names{"PLATE"});
  EXPECT_EQ(text_search(*s, "old fixture"), Names{});  // only the newest revision's
  EXPECT_EQ(text_search(*s, "T5"), Names{});           // a tool is no comment
}

TEST_P(StoreLibrary, ToolFindsTheProgramsWhoseNewestRevisionCallsIt) {
  auto s = open();
  ASSERT_TRUE(s);
  fill_texts(*s);
  using Names = std::vector<std::string>;
  EXPECT_EQ(text_search(*s, "", 5), Names{"BRACKET"});
  EXPECT_EQ(text_search(*s, "", 12), Names{"FLANGE"});
  EXPECT_EQ(text_search(*s, "", 8), Names{"PLATE"});
  EXPECT_EQ(text_search(*s, "", 7), Names{});  // PLATE's older revision
  EXPECT_EQ(text_search(*s, "", 0), Names{});
  EXPECT_EQ(text_search(*s, "clamp", 8), Names{"PLATE"});
  EXPECT_EQ(text_search(*s, "flange", 8), Names{});  // both must hold
  LibraryQuery q;
  q.tool = 12;
  q.dialect = "fanuc";
  EXPECT_TRUE(library_page(*s, q).value().programs.empty());
}

TEST_P(StoreLibrary, AStoreOfAnOlderSchemaGetsItsRevisionsFactsWhenOpened) {
  {
    auto s = open();
    ASSERT_TRUE(s);
    fill_texts(*s);
  }
  {
    auto db = raw();
    ASSERT_TRUE(db);
    // The store as version 5 left it: no facts, no tools.
    ASSERT_TRUE(db->script(
        "DROP TABLE revision_tools; DROP TABLE revision_facts; "
        "DROP INDEX programs_by_class; DROP TABLE tool_resets; DROP TABLE revision_sheets; "
        "DROP TABLE quality_records; DROP TABLE machines; "
        "DELETE FROM schema_version WHERE version >= 6"));
  }
  auto s = open();
  ASSERT_TRUE(s);
  auto version = raw()->query("SELECT MAX(version) FROM schema_version");
  ASSERT_TRUE(version);
  EXPECT_EQ(version->front().integer(0), current_schema_version());
  using Names = std::vector<std::string>;
  EXPECT_EQ(text_search(*s, "pump"), Names{"BRACKET"});
  EXPECT_EQ(text_search(*s, "o4711"), Names{"BRACKET"});
  EXPECT_EQ(text_search(*s, "", 8), Names{"PLATE"});
  EXPECT_EQ(text_search(*s, "", 7), Names{});
  auto facts = raw()->query("SELECT COUNT(*) FROM revision_facts");
  ASSERT_TRUE(facts);
  EXPECT_EQ(facts->front().integer(0), 4);  // every revision, PLATE's older one too
}

TEST_P(StoreLibrary, TheMachineClassesOfTheLibrary) {
  auto s = open();
  ASSERT_TRUE(s);
  fill(*s);
  EXPECT_EQ(library_machine_classes(*s).value(), (std::vector<std::string>{"lathe", "mill"}));
}

USINA_STORE_BACKENDS(StoreLibrary);

}  // namespace
}  // namespace usina::dnc
