// A layer's entities in drawing order, in flat memory whatever their number
// (issue 19: the 10,000,000-block spiral held 28 MB of entities until the
// writers ran, because a picture's scale needs the bounds of all of them).
// The newest are held in memory, for the drawing lengthens its last line;
// once they pass `hold_bytes`, or all the drawing's lists together pass the
// SpillFile's limit, all but the last go in a compact binary form to the
// drawing's unnamed temporary file (spill_file.hpp), and the writers read
// them back in order. Where no temporary file can be made or written (a
// full or read-only folder) the entities stay in memory: the same drawing,
// only bigger.
#pragma once

#include <cstddef>
#include <cstdint>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

#include "draw/entity.hpp"
#include "draw/spill_file.hpp"

namespace usina::draw {

class EntityList {
 public:
  // Some 1,100 lines held in memory a layer before they go to the file: a
  // program with a hundred tools, a layer each in the toolpath view, holds
  // 6.4 MB.
  static constexpr std::size_t kHoldBytes = std::size_t{64} << 10;

  // Past the drawing's limit, a list spills when it holds this much or more:
  // a write a hundred lines or so, however many layers share the file.
  static constexpr std::size_t kLeastSpill = std::size_t{4} << 10;

  // A list of its own file (in `folder`; empty, $TMPDIR or /tmp).
  explicit EntityList(std::size_t hold_bytes = kHoldBytes, std::string folder = {});
  // A list of the drawing's file, which outlives it.
  EntityList(std::size_t hold_bytes, SpillFile& file);
  EntityList(EntityList&& other) noexcept;
  EntityList& operator=(EntityList&& other) noexcept;
  EntityList(const EntityList&) = delete;
  EntityList& operator=(const EntityList&) = delete;
  ~EntityList();

  std::size_t size() const { return spilled_ + held_.size(); }

  bool empty() const { return size() == 0; }

  void push_back(Entity e);

  // The last entity, always in memory (the drawing lengthens a line).
  // The list must not be empty.
  Entity& back() { return held_.back(); }

  const Entity& back() const { return held_.back(); }

  // How many entities are in the temporary file.
  std::size_t spilled() const { return spilled_; }

  class Cursor;
  // The entities in order, read back from the file first. A cursor reads
  // the list as it was when it began; the list must not grow meanwhile.
  // When the file cannot be read back (an I/O error of the temporary
  // folder's disk) the cursor ends there and read_error() says why.
  Cursor begin() const;

  std::default_sentinel_t end() const { return {}; }

  // Every entity, in a vector: for small lists (tests).
  std::vector<Entity> to_vector() const;

  // Why the last cursor begun ended before the last entity; empty when it
  // did not.
  const std::string& read_error() const { return read_error_; }

 private:
  // Entities in the file, written at one go.
  struct Chunk {
    std::uint64_t offset = 0;
    std::uint64_t bytes = 0;
  };

  void spill();
  void let_go_of_held();

  std::size_t hold_bytes_;
  // Not a shared_ptr: its atomic count would keep these lists out of the
  // raster module (a shared object built from position-dependent code).
  std::unique_ptr<SpillFile> own_file_;
  SpillFile* file_;
  std::vector<Chunk> chunks_;
  std::size_t spilled_ = 0;
  std::vector<Entity> held_;
  std::size_t held_bytes_ = 0;
  mutable std::string read_error_;
};

// An input iterator over an EntityList.
class EntityList::Cursor {
 public:
  using value_type = Entity;
  using difference_type = std::ptrdiff_t;

  const Entity& operator*() const {
    return where_ == Where::File ? decoded_ : list_->held_[held_index_ - 1];
  }

  const Entity* operator->() const { return &**this; }

  Cursor& operator++() {
    next();
    return *this;
  }

  void operator++(int) { next(); }

  bool operator==(std::default_sentinel_t) const { return where_ == Where::Done; }

 private:
  friend class EntityList;
  explicit Cursor(const EntityList& list);

  void next();
  void fail(int error);
  // Each 0, or the errno of why the file could not be read back.
  int decode_next();
  int decode_polyline(bool closed);
  // At least `n` unread bytes in the buffer, read from the file.
  int fill(std::size_t n);
  double number();

  const EntityList* list_;
  std::size_t next_chunk_ = 0;
  std::uint64_t offset_ = 0;     // the next byte of the file to read
  std::uint64_t chunk_end_ = 0;  // where the chunk being read ends
  std::vector<char> buffer_;
  std::size_t at_ = 0;          // the next unread byte of the buffer
  std::size_t in_file_;         // entities still to read from the file
  std::size_t held_index_ = 0;  // the next held entity, after the file's
  Entity decoded_;
  // Where the current entity is: decoded from the file, held, or none left
  // (not a pointer, so that a copy of the cursor reads its own).
  enum class Where { File, Held, Done } where_ = Where::Done;
};

}  // namespace usina::draw
