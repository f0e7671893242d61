#include "dnc/link_serial.hpp"

#include <fcntl.h>
#include <termios.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <optional>
#include <utility>

#include <boost/asio/posix/stream_descriptor.hpp>
#include <boost/asio/write.hpp>
#include <fmt/format.h>
#include <sys/ioctl.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>

namespace usina::dnc {
namespace {

std::optional<speed_t> speed_of(std::uint32_t baud) {
  static constexpr std::array<std::pair<std::uint32_t, speed_t>, 15> kSpeeds{{
      {110, B110},
      {134, B134},
      {150, B150},
      {200, B200},
      {300, B300},
      {600, B600},
      {1200, B1200},
      {1800, B1800},
      {2400, B2400},
      {4800, B4800},
      {9600, B9600},
      {19200, B19200},
      {38400, B38400},
      {57600, B57600},
      {115200, B115200},
  }};
  for (const auto& [b, s] : kSpeeds) {
    if (b == baud) return s;
  }
  return std::nullopt;
}

// Linux's pty keeps no output queue: its TIOCOUTQ is 0 whatever waits on
// the other side, so asking it (a system call before every chunk) says
// nothing. Unix 98 pty slaves and masters, and BSD ptys, by device major.
bool is_pty(int fd) {
  struct stat st {};

  if (::fstat(fd, &st) != 0 || !S_ISCHR(st.st_mode)) return false;
  const unsigned major_number = major(st.st_rdev);
  const unsigned minor_number = minor(st.st_rdev);
  constexpr unsigned kBsdMaster = 2, kBsdSlave = 3, kTtyAux = 5, kPtmx = 2;
  constexpr unsigned kUnix98Master = 128, kUnix98Slave = 136, kUnix98Count = 8;
  return major_number == kBsdMaster || major_number == kBsdSlave ||
         (major_number == kTtyAux && minor_number == kPtmx) ||
         (major_number >= kUnix98Master && major_number < kUnix98Slave + kUnix98Count);
}

class DescriptorLink final : public Link {
 public:
  DescriptorLink(asio::io_context& io, int fd, std::string name, bool dsr_flow)
      : stream_(io, fd), fd_(fd), name_(std::move(name)), dsr_flow_(dsr_flow) {
    // asio makes the descriptor non-blocking at its first asynchronous
    // operation; try_write must never block the loop before that either.
    const int flags = ::fcntl(fd_, F_GETFL);
    if (flags >= 0 && (flags & O_NONBLOCK) == 0) (void)::fcntl(fd_, F_SETFL, flags | O_NONBLOCK);
    counts_output_ = !is_pty(fd_);
  }

  void async_read_some(std::span<std::uint8_t> buffer, IoHandler handler) override {
    stream_.async_read_some(asio::buffer(buffer.data(), buffer.size()), std::move(handler));
  }

  void async_write(std::span<const std::uint8_t> bytes, IoHandler handler) override {
    asio::async_write(stream_, asio::buffer(bytes.data(), bytes.size()), std::move(handler));
  }

  std::optional<std::size_t> try_write(std::span<const std::uint8_t> bytes,
                                       ErrorCode& ec) override {
    ec.clear();
    if (!stream_.is_open()) {
      ec = asio::error::bad_descriptor;
      return std::nullopt;
    }
    for (;;) {
      const ssize_t n = ::write(fd_, bytes.data(), bytes.size());
      if (n >= 0) return static_cast<std::size_t>(n);
      if (errno == EINTR) continue;
      if (errno == EAGAIN || errno == EWOULDBLOCK) return 0;
      ec = ErrorCode(errno, boost::system::system_category());
      return std::nullopt;
    }
  }

  void cancel() override {
    ErrorCode ignored;
    stream_.cancel(ignored);
  }

  void close() override {
    ErrorCode ignored;
    stream_.close(ignored);
  }

  std::optional<std::size_t> output_queue() const override {
    int n = 0;
    if (!counts_output_ || !stream_.is_open() || ::ioctl(fd_, TIOCOUTQ, &n) != 0 || n < 0) {
      return std::nullopt;
    }
    return static_cast<std::size_t>(n);
  }

  bool peer_ready() const override {
    if (!dsr_flow_) return true;
    int lines = 0;
    if (::ioctl(fd_, TIOCMGET, &lines) != 0) return true;  // no modem lines (a pty)
    return (lines & TIOCM_DSR) != 0;
  }

  std::string describe() const override { return name_; }

 private:
  asio::posix::stream_descriptor stream_;
  int fd_;
  std::string name_;
  bool dsr_flow_;
  bool counts_output_ = true;  // TIOCOUTQ tells something (not on a pty)
};

std::string errno_text(const char* what, const std::string& path) {
  return fmt::format("{} {}: {}", what, path, std::strerror(errno));
}

}  // namespace

tl::expected<termios, std::string> serial_frame(termios t, const LinkConfig& config) {
  // A rate the port has no constant for is refused, never replaced by another.
  const auto speed = speed_of(config.baud);
  if (!speed) return tl::make_unexpected(fmt::format("no serial rate of {} baud", config.baud));
  // Raw: no kernel flow control (IXON would eat the control's XOFF and hide
  // it from usina), no CR/LF translation, no echo, no signals.
  t.c_iflag &= ~static_cast<tcflag_t>(IGNBRK | BRKINT | PARMRK | ISTRIP | INLCR | IGNCR | ICRNL |
                                      IXON | IXOFF | IXANY | INPCK);
  t.c_oflag &= ~static_cast<tcflag_t>(OPOST);
  t.c_lflag &= ~static_cast<tcflag_t>(ECHO | ECHONL | ICANON | ISIG | IEXTEN);
  t.c_cflag &= ~static_cast<tcflag_t>(CSIZE | PARENB | PARODD | CSTOPB | CRTSCTS);
  t.c_cflag |= static_cast<tcflag_t>(CLOCAL | CREAD | (config.data_bits == 7 ? CS7 : CS8));
  if (config.parity != Parity::None) {
    t.c_cflag |= PARENB;
    t.c_iflag |= INPCK;  // a row with a parity error reads as NUL (a tape feed)
  }
  if (config.parity == Parity::Odd) t.c_cflag |= PARODD;
  if (config.stop_bits == 2) t.c_cflag |= CSTOPB;
  if (config.flow == Flow::RtsCts) t.c_cflag |= CRTSCTS;
  t.c_cc[VMIN] = 1;
  t.c_cc[VTIME] = 0;
  ::cfsetispeed(&t, *speed);
  ::cfsetospeed(&t, *speed);
  return t;
}

tl::expected<void, std::string> configure_tty(int fd, const LinkConfig& config) {
  termios now{};
  if (::tcgetattr(fd, &now) != 0) {
    return tl::make_unexpected(fmt::format("not a serial port or pty ({})", std::strerror(errno)));
  }
  const auto frame = serial_frame(now, config);
  if (!frame) return tl::make_unexpected(frame.error());
  if (::tcsetattr(fd, TCSANOW, &*frame) != 0) {
    return tl::make_unexpected(fmt::format("cannot set the frame ({})", std::strerror(errno)));
  }
  // Controls without handshake still want DTR and RTS high (research/dnc.md
  // §2.1); a pty has no modem lines, so the error is not one.
  if (config.flow != Flow::RtsCts) {
    int lines = TIOCM_DTR | TIOCM_RTS;
    (void)::ioctl(fd, TIOCMBIS, &lines);
  }
  return {};
}

tl::expected<std::unique_ptr<Link>, std::string> open_serial_link(asio::io_context& io,
                                                                  const std::string& path,
                                                                  const LinkConfig& config) {
  const int fd = ::open(path.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return tl::make_unexpected(errno_text("cannot open", path));
  if (auto ok = configure_tty(fd, config); !ok) {
    ::close(fd);
    return tl::make_unexpected(fmt::format("{}: {}", path, ok.error()));
  }
  return descriptor_link(io, fd, path, config.flow == Flow::DtrDsr);
}

std::unique_ptr<Link> descriptor_link(asio::io_context& io, int fd, std::string name,
                                      bool dsr_flow) {
  return std::make_unique<DescriptorLink>(io, fd, std::move(name), dsr_flow);
}

tl::expected<PtyPair, std::string> open_pty_pair(asio::io_context& io) {
  const int master = ::posix_openpt(O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (master < 0) return tl::make_unexpected(errno_text("cannot open", "a pty"));
  std::array<char, 128> name{};
  if (::grantpt(master) != 0 || ::unlockpt(master) != 0 ||
      ::ptsname_r(master, name.data(), name.size()) != 0) {
    ::close(master);
    return tl::make_unexpected(errno_text("cannot unlock", "a pty"));
  }
  termios t{};
  if (::tcgetattr(master, &t) == 0) {
    ::cfmakeraw(&t);
    (void)::tcsetattr(master, TCSANOW, &t);
  }
  PtyPair pair;
  pair.slave_path = name.data();
  pair.master = descriptor_link(io, master, "pty master " + pair.slave_path);
  return pair;
}

}  // namespace usina::dnc
