// A blob read piece by piece (BlobPieces, the export's reader) on both back
// ends: the pieces are the bytes, damage shows at the last piece, a wrong
// length at the start, the store's connection stays free between pieces,
// and a PostgreSQL value stored compressed (before schema version 8) reads
// the same.
#include "dnc/store_blobs.hpp"

#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "dnc/sha256.hpp"
#include "store_fixture.hpp"

namespace usina::dnc {
namespace {

class StoreBlobPieces : public test::StoreTest {};

constexpr std::size_t kPiece = 4096;

// 10.5 pieces of a program that compresses well (as G-code does).
std::string program_text() {
  std::string text = "G21 G90\n";
  while (text.size() < 10 * kPiece + kPiece / 2)
    text += "G1 X10.5 Y20.25 F500\nG1 X0 Y0\n";
  return text;
}

// Stores `bytes` under their hash in a transaction of their own.
std::string store_blob(Store& s, const std::string& bytes) {
  const std::string hash = sha256_hex(std::string_view(bytes));
  Transaction tx(s.db());
  EXPECT_TRUE(tx.begin_write());
  EXPECT_TRUE(put_blob(s, hash, bytes));
  EXPECT_TRUE(tx.commit());
  return hash;
}

// Every piece until the end or the first error; the error's kind, if any.
struct Drained {
  std::string bytes;
  std::vector<std::size_t> sizes;
  std::optional<StoreErrorKind> error;
};

Drained drain(BlobPieces& b) {
  Drained d;
  for (;;) {
    auto piece = b.next();
    if (!piece) {
      d.error = piece.error().kind;
      return d;
    }
    if (piece->empty()) return d;
    d.sizes.push_back(piece->size());
    d.bytes += *piece;
  }
}

TEST_P(StoreBlobPieces, ALargeBlobComesOutInPiecesThatAreItsBytes) {
  auto s = open();
  ASSERT_TRUE(s);
  const std::string text = program_text();
  const std::string hash = store_blob(*s, text);
  auto b = BlobPieces::open(*s, hash, kPiece);
  ASSERT_TRUE(b) << b.error().message;
  EXPECT_EQ(b->size(), text.size());
  const Drained d = drain(*b);
  EXPECT_FALSE(d.error);
  EXPECT_EQ(d.bytes, text);
  ASSERT_EQ(d.sizes.size(), 11u);
  EXPECT_EQ(d.sizes.front(), kPiece);
  EXPECT_EQ(d.sizes.back(), text.size() - 10 * kPiece);
}

TEST_P(StoreBlobPieces, TheStoresConnectionWritesBetweenPieces) {
  auto s = open();
  ASSERT_TRUE(s);
  const std::string text = program_text();
  const std::string hash = store_blob(*s, text);
  auto b = BlobPieces::open(*s, hash, kPiece);
  ASSERT_TRUE(b) << b.error().message;
  std::string got = b->next().value_or("");
  // Another request's write on the store's connection while the export is half-way.
  const std::string other = store_blob(*s, "G0 X1\nM2\n");
  auto read = read_blob(*s, other);
  ASSERT_TRUE(read) << read.error().message;
  const Drained rest = drain(*b);
  EXPECT_FALSE(rest.error);
  EXPECT_EQ(got + rest.bytes, text);
}

TEST_P(StoreBlobPieces, BytesChangedInTheDatabaseAreRefusedAtTheLastPiece) {
  auto s = open();
  ASSERT_TRUE(s);
  const std::string text = program_text();
  const std::string hash = store_blob(*s, text);
  auto db = raw();
  ASSERT_TRUE(db);
  drop_trigger(*db, "blobs_no_update", "blobs");
  std::string changed = text;
  changed[5 * kPiece] = 'X';  // the same length: only the hash can tell
  ASSERT_TRUE(db->query("UPDATE blobs SET bytes = $1 WHERE hash = $2",
                        {SqlBlob{changed}, std::string_view(hash)}));
  auto b = BlobPieces::open(*s, hash, kPiece);
  ASSERT_TRUE(b) << b.error().message;
  const Drained d = drain(*b);
  ASSERT_TRUE(d.error);
  EXPECT_EQ(*d.error, StoreErrorKind::Damaged);
  EXPECT_EQ(d.bytes.size(), 10 * kPiece);  // all but the last piece
  EXPECT_EQ(d.bytes, changed.substr(0, 10 * kPiece));
}

TEST_P(StoreBlobPieces, ALengthThatIsNotTheRecordedOneIsRefusedBeforeAnyPiece) {
  auto s = open();
  ASSERT_TRUE(s);
  const std::string text = program_text();
  const std::string hash = store_blob(*s, text);
  auto db = raw();
  ASSERT_TRUE(db);
  drop_trigger(*db, "blobs_no_update", "blobs");
  ASSERT_TRUE(
      db->query("UPDATE blobs SET bytes = $1 WHERE hash = $2",
                {SqlBlob{std::string_view(text).substr(0, 3 * kPiece)}, std::string_view(hash)}));
  auto b = BlobPieces::open(*s, hash, kPiece);
  ASSERT_FALSE(b);
  EXPECT_EQ(b.error().kind, StoreErrorKind::Damaged);
  const std::string says = fmt::format("{} bytes (recorded {})", 3 * kPiece, text.size());
  EXPECT_NE(b.error().message.find(says), std::string::npos) << b.error().message;
}

TEST_P(StoreBlobPieces, ASmallBlobIsOnePieceVerifiedAndAMissingOneIsNotFound) {
  auto s = open();
  ASSERT_TRUE(s);
  const std::string hash = store_blob(*s, "G0 X1\nM2\n");
  auto b = BlobPieces::open(*s, hash, kPiece);
  ASSERT_TRUE(b) << b.error().message;
  const Drained d = drain(*b);
  EXPECT_EQ(d.bytes, "G0 X1\nM2\n");
  EXPECT_EQ(d.sizes.size(), 1u);
  const std::string empty = store_blob(*s, "");
  auto e = BlobPieces::open(*s, empty, kPiece);
  ASSERT_TRUE(e) << e.error().message;
  EXPECT_EQ(drain(*e).sizes.size(), 0u);
  auto missing = BlobPieces::open(*s, sha256_hex(std::string_view("nothing")), kPiece);
  ASSERT_FALSE(missing);
  EXPECT_EQ(missing.error().kind, StoreErrorKind::NotFound);
}

// Blobs stored before schema version 8 are compressed by PostgreSQL (the
// default storage); they are read in larger slices, and still right.
TEST_P(StoreBlobPieces, ABlobStoredCompressedReadsTheSame) {
  auto s = open();
  ASSERT_TRUE(s);
  auto db = raw();
  ASSERT_TRUE(db);
  if (GetParam() == Backend::Postgres) {
    ASSERT_TRUE(db->script("ALTER TABLE blobs ALTER COLUMN bytes SET STORAGE EXTENDED"));
  }
  std::string text;
  while (text.size() < (1u << 20))
    text += "G1 X10.5 Y20.25 F500\nG1 X0 Y0\n";
  const std::string hash = store_blob(*s, text);
  if (GetParam() == Backend::Postgres) {
    auto sizes = db->query("SELECT pg_column_size(bytes), octet_length(bytes) FROM blobs", {});
    ASSERT_TRUE(sizes && !sizes->empty());
    EXPECT_LT(sizes->front().integer(0), sizes->front().integer(1));  // compressed
  }
  auto b = BlobPieces::open(*s, hash, kPiece);
  ASSERT_TRUE(b) << b.error().message;
  const Drained d = drain(*b);
  EXPECT_FALSE(d.error);
  EXPECT_EQ(d.bytes, text);
  EXPECT_EQ(d.sizes.size(), text.size() / kPiece + (text.size() % kPiece != 0 ? 1 : 0));
}

// Schema version 8 stores PostgreSQL's new blobs uncompressed, so a slice
// reads only its own chunks.
TEST_P(StoreBlobPieces, NewBlobsAreStoredUncompressedOnPostgresql) {
  if (GetParam() != Backend::Postgres) GTEST_SKIP() << "PostgreSQL's storage only";
  auto s = open();
  ASSERT_TRUE(s);
  std::string text;
  while (text.size() < (1u << 20))
    text += "G1 X10.5 Y20.25 F500\nG1 X0 Y0\n";
  store_blob(*s, text);
  auto sizes = s->db().query("SELECT pg_column_size(bytes), octet_length(bytes) FROM blobs", {});
  ASSERT_TRUE(sizes && !sizes->empty());
  EXPECT_EQ(sizes->front().integer(0), sizes->front().integer(1));
}

USINA_STORE_BACKENDS(StoreBlobPieces);

}  // namespace
}  // namespace usina::dnc
