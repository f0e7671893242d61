// The library page on both back ends: filters by class, dialect, newest
// state and released revision, a part of the name in any case (with LIKE's
// own characters taken literally), the count on every page, paging.
#include "dnc/store_library.hpp"

#include <string>
#include <vector>

#include <gtest/gtest.h>

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

USINA_STORE_BACKENDS(StoreLibrary);

}  // namespace
}  // namespace usina::dnc
