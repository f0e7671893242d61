#include "draw/entity_list.hpp"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <utility>

#include <fmt/format.h>

#include "core/temporary_file.hpp"

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

// Writes all of `bytes` at `offset`; false, errno set, when it could not.
bool write_all(int fd, const std::vector<char>& bytes, std::uint64_t offset) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n =
        ::pwrite(fd, bytes.data() + done, bytes.size() - done, static_cast<off_t>(offset + done));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<std::size_t>(n);
  }
  return true;
}

}  // namespace

EntityList::EntityList(std::size_t hold_bytes, std::string folder)
    : hold_bytes_(hold_bytes), folder_(std::move(folder)) {}

EntityList::EntityList(EntityList&& other) noexcept
    : hold_bytes_(other.hold_bytes_),
      folder_(std::move(other.folder_)),
      fd_(std::exchange(other.fd_, -1)),
      spill_failed_(other.spill_failed_),
      file_bytes_(std::exchange(other.file_bytes_, 0)),
      spilled_(std::exchange(other.spilled_, 0)),
      held_(std::move(other.held_)),
      held_bytes_(std::exchange(other.held_bytes_, 0)),
      read_error_(std::move(other.read_error_)) {}

EntityList& EntityList::operator=(EntityList&& other) noexcept {
  if (this == &other) return *this;
  close_file();
  hold_bytes_ = other.hold_bytes_;
  folder_ = std::move(other.folder_);
  fd_ = std::exchange(other.fd_, -1);
  spill_failed_ = other.spill_failed_;
  file_bytes_ = std::exchange(other.file_bytes_, 0);
  spilled_ = std::exchange(other.spilled_, 0);
  held_ = std::move(other.held_);
  held_bytes_ = std::exchange(other.held_bytes_, 0);
  read_error_ = std::move(other.read_error_);
  return *this;
}

EntityList::~EntityList() {
  close_file();
}

void EntityList::close_file() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
}

void EntityList::push_back(Entity e) {
  held_bytes_ += bytes_of(e);
  held_.push_back(std::move(e));
  if (held_bytes_ > hold_bytes_ && held_.size() > 1 && !spill_failed_) spill();
}

// All held entities but the last go to the file. Nothing is dropped from
// memory until it is written; a file that cannot be made or written is
// not tried again (spill_failed_): the rest of the drawing stays in memory.
void EntityList::spill() {
  if (fd_ < 0) fd_ = core::open_unnamed_file(folder_.empty() ? core::temporary_folder() : folder_);
  std::vector<char> bytes;
  bytes.reserve(held_bytes_);
  Encoder encode(bytes);
  for (std::size_t i = 0; i + 1 < held_.size(); ++i)
    std::visit(encode, held_[i]);
  if (fd_ < 0 || !write_all(fd_, bytes, file_bytes_)) {
    spill_failed_ = true;
    return;
  }
  file_bytes_ += bytes.size();
  spilled_ += held_.size() - 1;
  held_.erase(held_.begin(), held_.end() - 1);
  held_bytes_ = bytes_of(held_.back());
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

EntityList::Cursor::Cursor(const EntityList& list)
    : list_(&list), file_end_(list.file_bytes_), in_file_(list.spilled_) {
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
      list_->folder_.empty() ? core::temporary_folder() : list_->folder_, std::strerror(error));
  in_file_ = 0;
  held_index_ = list_->held_.size();
  where_ = Where::Done;
}

// 0, or the errno of why the next entity could not be read; a tag or a
// count the list never wrote is EIO (the file was changed from outside).
int EntityList::Cursor::decode_next() {
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
  if (n > (file_end_ - offset_ + (buffer_.size() - at_)) / sizeof(Vec2)) return EIO;
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

// Keeps the unread bytes, then reads pieces of the file after them until
// `n` are there: 0, or the errno of a failed read (EIO when the file ends
// before, cut short from outside).
int EntityList::Cursor::fill(std::size_t n) {
  std::size_t have = buffer_.size() - at_;
  if (have >= n) return 0;
  buffer_.erase(buffer_.begin(), buffer_.begin() + static_cast<std::ptrdiff_t>(at_));
  at_ = 0;
  while (have < n) {
    const std::uint64_t left = file_end_ - offset_;
    if (left == 0) return EIO;
    const std::size_t want =
        static_cast<std::size_t>(std::min<std::uint64_t>(left, std::max(kReadPiece, n - have)));
    buffer_.resize(have + want);
    const ssize_t got =
        ::pread(list_->fd_, buffer_.data() + have, want, static_cast<off_t>(offset_));
    buffer_.resize(have + static_cast<std::size_t>(std::max<ssize_t>(got, 0)));
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) return errno;
    if (got == 0) return EIO;
    have += static_cast<std::size_t>(got);
    offset_ += static_cast<std::uint64_t>(got);
  }
  return 0;
}

}  // namespace usina::draw
