// A folder of programs in, the released set out.
#include "dnc/store_import.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "dnc/sha256.hpp"
#include "dnc/store_audit.hpp"
#include "store_fixture.hpp"

namespace usina::dnc {
namespace {

namespace fs = std::filesystem;

constexpr char kProgram[] = "G21 G90\nG0 X0 Y0 Z5\nG1 Z-1 F100\nG1 X10 Y5\nM2\n";

class StoreImport : public test::StoreTest {
 protected:
  std::string shop() { return tmp_.path + "/shop"; }

  void write(const std::string& name, const std::string& text) {
    fs::create_directories(shop());
    std::ofstream(shop() + "/" + name, std::ios::binary) << text;
  }

  static const ImportedFile* find(const ImportReport& r, const std::string& file) {
    for (const ImportedFile& f : r.files)
      if (f.file == file) return &f;
    return nullptr;
  }
};

TEST_P(StoreImport, EachFileBecomesARevisionNamedAfterIt) {
  auto s = open();
  ASSERT_TRUE(s);
  write("O1000.nc", kProgram);
  write("O2000.tap", "%\nO2000\nG90 G0 X1 Y1\nG1 X5 F100\nM30\n%\n");
  write("BROKEN.nc", "G2 X20 Y0 R1\n");
  ImportOptions o;
  o.machine_class = "mill";
  auto r = import_folder(*s, shop(), o, {"root", "import"});
  ASSERT_TRUE(r) << r.error().message;
  EXPECT_EQ(r->imported, 3u);
  EXPECT_EQ(r->skipped, 0u);
  EXPECT_EQ(find(*r, "O1000.nc")->hash, sha256_hex(kProgram));
  EXPECT_EQ(find(*r, "BROKEN.nc")->state, "check-failed");
  EXPECT_EQ(find_program(*s, "O2000").value().dialect, "fanuc");  // guessed
  EXPECT_EQ(find_program(*s, "O1000").value().machine_class, "mill");
  EXPECT_EQ(find_revision(*s, "O1000", sha256_hex(kProgram)).value().reason, "imported: O1000.nc");
  // Importing again changes nothing.
  auto again = import_folder(*s, shop(), o, {"root", "import"});
  ASSERT_TRUE(again);
  EXPECT_EQ(again->unchanged, 3u);
  EXPECT_EQ(again->imported, 0u);
}

TEST_P(StoreImport, BadNamesLinksDuplicatesAndBigFilesAreSkippedWithAReason) {
  StoreOptions opts = options();
  opts.max_program_bytes = 1000;
  auto s = open(opts);
  ASSERT_TRUE(s);
  write("good.nc", kProgram);
  write("good.tap", kProgram);  // the same program name twice
  write("with space.nc", kProgram);
  write("big.nc", std::string(1001, '\n'));
  write(".hidden.nc", kProgram);
  fs::create_directories(shop() + "/sub");
  write("sub/inner.nc", kProgram);
  ASSERT_EQ(::symlink("/etc/passwd", (shop() + "/passwd.nc").c_str()), 0);
  auto r = import_folder(*s, shop(), {}, {"root", "import"});
  ASSERT_TRUE(r) << r.error().message;
  EXPECT_EQ(r->imported, 1u);
  EXPECT_EQ(r->skipped, 4u);
  EXPECT_NE(find(*r, "good.tap")->error.find("already"), std::string::npos);
  EXPECT_NE(find(*r, "with space.nc")->error.find("never a path"), std::string::npos);
  EXPECT_NE(find(*r, "big.nc")->error.find("1001 bytes"), std::string::npos);
  EXPECT_NE(find(*r, "passwd.nc")->error.find("symbolic link"), std::string::npos);
  EXPECT_EQ(find(*r, ".hidden.nc"), nullptr);
  EXPECT_EQ(find(*r, "sub"), nullptr);
  EXPECT_EQ(list_programs(*s).value().size(), 1u);
  EXPECT_FALSE(find_program(*s, "passwd"));
}

TEST_P(StoreImport, AMissingFolderIsAnError) {
  auto s = open();
  ASSERT_TRUE(s);
  auto r = import_folder(*s, tmp_.path + "/nope", {}, {"root", "import"});
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error().kind, StoreErrorKind::Invalid);
}

TEST_P(StoreImport, TheReleasedSetIsExportedWithAChecksumList) {
  auto s = open();
  ASSERT_TRUE(s);
  const std::string v1 = kProgram;
  const std::string v2 = std::string(kProgram) + "(v2)\n";
  for (const auto& [name, text] :
       {std::pair{"A1", v1}, std::pair{"A1", v2}, std::pair{"B2", v1}, std::pair{"C3", v2}}) {
    ASSERT_TRUE(put_revision(*s, {name, "", "rs274ngc", text, "r", nullptr}, {"ana", "t"}));
  }
  const auto release = [&](const char* name, const std::string& text) {
    for (const RevisionState to :
         {RevisionState::Checked, RevisionState::Approved, RevisionState::Released})
      ASSERT_TRUE(change_state(*s, name, sha256_hex(text), to, "", {"boss", "t"}));
  };
  release("A1", v1);
  now_us += 1000;
  release("A1", v2);
  release("B2", v1);  // C3 stays a draft
  const std::string out = tmp_.path + "/released";
  auto r = export_released(*s, out, ".nc", {"ana", "t"});
  ASSERT_TRUE(r) << r.error().message;
  ASSERT_EQ(r->size(), 2u);
  std::stringstream a1;
  a1 << std::ifstream(out + "/A1.nc").rdbuf();
  EXPECT_EQ(a1.str(), v2);
  EXPECT_FALSE(fs::exists(out + "/C3.nc"));
  std::stringstream manifest;
  manifest << std::ifstream(out + "/released.sha256").rdbuf();
  EXPECT_EQ(manifest.str(), sha256_hex(v2) + "  A1.nc\n" + sha256_hex(v1) + "  B2.nc\n");
  EXPECT_EQ(read_audit(*s, 0, 1000).value().back().action, "export.released");
  EXPECT_FALSE(export_released(*s, out, "/../x", {"ana", "t"}));
}

USINA_STORE_BACKENDS(StoreImport);

}  // namespace
}  // namespace usina::dnc
