#include "draw/entity_list.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <utility>

#include <fmt/format.h>

namespace usina::draw {
namespace {

// The file's form, for this process only (native byte order): a tag byte,
// then the entity's numbers as doubles; a polyline's point count before
// its points.
enum Tag : char { kLine, kArcCcw, kArcCw, kCircle, kOpenPolyline, kClosedPolyline };

constexpr std::size_t kReadPiece = std::size_t{64} << 10;

// What an entity takes in memory, for the hold.
std::size_t bytes_of(const Entity& e) {
  const auto* p = std::get_if<Polyline>(&e);
  return sizeof(Entity) + (p != nullptr ? p->points.size() * sizeof(Vec2) : 0);
}

class Encoder {
 public:
  explicit Encoder(std::vector<char>& out) : out_(out) {}

  void operator()(const Line& l) {
    tag(kLine);
    put(l.from);
    put(l.to);
  }

  void operator()(const Arc& a) {
    tag(a.ccw ? kArcCcw : kArcCw);
    put(a.center);
    put(a.radius);
    put(a.start_angle);
    put(a.end_angle);
  }

  void operator()(const Circle& c) {
    tag(kCircle);
    put(c.center);
    put(c.radius);
  }

  void operator()(const Polyline& p) {
    tag(p.closed ? kClosedPolyline : kOpenPolyline);
    const auto n = static_cast<std::uint64_t>(p.points.size());
    append(&n, sizeof n);
    for (const Vec2& v : p.points)
      put(v);
  }

 private:
  void tag(Tag t) { out_.push_back(t); }

  void put(double d) { append(&d, sizeof d); }

  void put(Vec2 v) {
    put(v.x);
    put(v.y);
  }

  void append(const void* data, std::size_t n) {
    const auto* bytes = static_cast<const char*>(data);
    out_.insert(out_.end(), bytes, bytes + n);
  }

  std::vector<char>& out_;
};

}  // namespace

EntityList::EntityList(std::size_t hold_bytes, std::string folder)
    : hold_bytes_(hold_bytes),
      own_file_(std::make_unique<SpillFile>(std::move(folder))),
      file_(own_file_.get()) {
  file_->hold_limit = hold_bytes;
}

EntityList::EntityList(std::size_t hold_bytes, SpillFile& file)
    : hold_bytes_(hold_bytes), file_(&file) {}

EntityList::EntityList(EntityList&& other) noexcept
    : hold_bytes_(other.hold_bytes_),
      own_file_(std::move(other.own_file_)),
      file_(std::exchange(other.file_, nullptr)),
      chunks_(std::move(other.chunks_)),
      spilled_(std::exchange(other.spilled_, 0)),
      held_(std::move(other.held_)),
      held_bytes_(std::exchange(other.held_bytes_, 0)),
      read_error_(std::move(other.read_error_)) {}

EntityList& EntityList::operator=(EntityList&& other) noexcept {
  if (this == &other) return *this;
  let_go_of_held();
  hold_bytes_ = other.hold_bytes_;
  own_file_ = std::move(other.own_file_);
  file_ = std::exchange(other.file_, nullptr);
  chunks_ = std::move(other.chunks_);
  spilled_ = std::exchange(other.spilled_, 0);
  held_ = std::move(other.held_);
  held_bytes_ = std::exchange(other.held_bytes_, 0);
  read_error_ = std::move(other.read_error_);
  return *this;
}

EntityList::~EntityList() {
  let_go_of_held();
}

// The drawing's count of held bytes no longer counts this list's.
void EntityList::let_go_of_held() {
  if (file_ != nullptr) file_->held -= held_bytes_;
  held_bytes_ = 0;
}

void EntityList::push_back(Entity e) {
  const std::size_t bytes = bytes_of(e);
  held_bytes_ += bytes;
  file_->held += bytes;
  held_.push_back(std::move(e));
  if (held_.size() > 1 && !file_->failed() &&
      (held_bytes_ > hold_bytes_ ||
       (file_->held > file_->hold_limit && held_bytes_ >= kLeastSpill)))
    spill();
}

// All held entities but the last go to the file, as one chunk. Nothing is
// dropped from memory until it is written; a file that cannot be made or
// written is not tried again: the rest of the drawing stays in memory.
void EntityList::spill() {
  std::vector<char> bytes;
  bytes.reserve(held_bytes_);
  Encoder encode(bytes);
  for (std::size_t i = 0; i + 1 < held_.size(); ++i)
    std::visit(encode, held_[i]);
  const auto offset = file_->append(bytes);
  if (!offset) return;
  chunks_.push_back({*offset, bytes.size()});
  spilled_ += held_.size() - 1;
  held_.erase(held_.begin(), held_.end() - 1);
  const std::size_t left = bytes_of(held_.back());
  file_->held -= held_bytes_ - left;
  held_bytes_ = left;
}

EntityList::Cursor EntityList::begin() const {
  return Cursor(*this);
}

std::vector<Entity> EntityList::to_vector() const {
  std::vector<Entity> out;
  out.reserve(size());
  for (const Entity& e : *this)
    out.push_back(e);
  return out;
}

EntityList::Cursor::Cursor(const EntityList& list) : list_(&list), in_file_(list.spilled_) {
  list.read_error_.clear();
  next();
}

void EntityList::Cursor::next() {
  if (in_file_ > 0) {
    --in_file_;
    where_ = Where::File;
    if (const int error = decode_next(); error != 0) fail(error);
  } else if (held_index_ < list_->held_.size()) {
    ++held_index_;
    where_ = Where::Held;
  } else {
    where_ = Where::Done;
  }
}

// The list keeps the reason, for a range-for hides its cursor; the writers
// ask Drawing::read_error() when they are done.
void EntityList::Cursor::fail(int error) {
  list_->read_error_ = fmt::format(
      "the drawing's entities could not be read back from their temporary file in {}: {}",
      list_->file_->folder(), std::strerror(error));
  in_file_ = 0;
  held_index_ = list_->held_.size();
  where_ = Where::Done;
}

// 0, or the errno of why the next entity could not be read; a tag or a
// count the list never wrote is EIO (the file was changed from outside).
int EntityList::Cursor::decode_next() {
  if (at_ == buffer_.size() && offset_ == chunk_end_) {  // the next chunk
    if (next_chunk_ == list_->chunks_.size()) return EIO;
    const Chunk& c = list_->chunks_[next_chunk_++];
    offset_ = c.offset;
    chunk_end_ = c.offset + c.bytes;
  }
  if (const int error = fill(1); error != 0) return error;
  const char tag = buffer_[at_++];
  switch (tag) {
  case kLine:
    if (const int error = fill(4 * sizeof(double)); error != 0) return error;
    decoded_ = Line{{number(), number()}, {number(), number()}};
    return 0;
  case kArcCcw:
  case kArcCw:
    if (const int error = fill(5 * sizeof(double)); error != 0) return error;
    decoded_ = Arc{{number(), number()}, number(), number(), number(), tag == kArcCcw};
    return 0;
  case kCircle:
    if (const int error = fill(3 * sizeof(double)); error != 0) return error;
    decoded_ = Circle{{number(), number()}, number()};
    return 0;
  case kOpenPolyline:
  case kClosedPolyline: return decode_polyline(tag == kClosedPolyline);
  default: return EIO;
  }
}

int EntityList::Cursor::decode_polyline(bool closed) {
  std::uint64_t n = 0;
  if (const int error = fill(sizeof n); error != 0) return error;
  std::memcpy(&n, buffer_.data() + at_, sizeof n);
  at_ += sizeof n;
  if (n > (chunk_end_ - offset_ + (buffer_.size() - at_)) / sizeof(Vec2)) return EIO;
  if (const int error = fill(static_cast<std::size_t>(n) * sizeof(Vec2)); error != 0) return error;
  Polyline p{std::vector<Vec2>(static_cast<std::size_t>(n)), closed};
  for (Vec2& v : p.points)
    v = {number(), number()};
  decoded_ = std::move(p);
  return 0;
}

double EntityList::Cursor::number() {
  double d = 0.0;
  std::memcpy(&d, buffer_.data() + at_, sizeof d);
  at_ += sizeof d;
  return d;
}

// Keeps the unread bytes, then reads pieces of the chunk after them until
// `n` are there: 0, or the errno of a failed read (EIO when the chunk ends
// before: an entity never spans two).
int EntityList::Cursor::fill(std::size_t n) {
  const std::size_t have = buffer_.size() - at_;
  if (have >= n) return 0;
  const std::uint64_t left = chunk_end_ - offset_;
  if (left < n - have) return EIO;
  const auto want =
      static_cast<std::size_t>(std::min<std::uint64_t>(left, std::max(kReadPiece, n - have)));
  buffer_.erase(buffer_.begin(), buffer_.begin() + static_cast<std::ptrdiff_t>(at_));
  at_ = 0;
  buffer_.resize(have + want);
  if (const int error = list_->file_->read(buffer_.data() + have, want, offset_); error != 0)
    return error;
  offset_ += want;
  return 0;
}

}  // namespace usina::draw
