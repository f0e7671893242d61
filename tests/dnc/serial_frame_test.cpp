// The termios a machine's frame becomes (dnc/link_serial.hpp): every rate,
// data bits, parity, stop bits and flow control of the configuration reach
// the port's flags, in raw mode, without a device to open.
#include <termios.h>

#include <gtest/gtest.h>

#include "dnc/link_config.hpp"
#include "dnc/link_serial.hpp"

namespace usina::dnc {
namespace {

// A port as a previous program may have left it: cooked, with every flag
// serial_frame must clear.
termios cooked() {
  termios t{};
  t.c_iflag = IXON | IXOFF | IXANY | ICRNL | INLCR | IGNCR | ISTRIP | BRKINT | INPCK;
  t.c_oflag = OPOST;
  t.c_lflag = ECHO | ICANON | ISIG | IEXTEN;
  t.c_cflag = CS8 | PARENB | PARODD | CSTOPB | CRTSCTS;
  return t;
}

bool has(tcflag_t flags, tcflag_t bits) {
  return (flags & bits) == bits;
}

TEST(SerialFrame, EveryStandardRateIsItsConstant) {
  const std::pair<std::uint32_t, speed_t> rates[] = {
      {110, B110},   {134, B134},     {150, B150},     {200, B200},     {300, B300},
      {600, B600},   {1200, B1200},   {1800, B1800},   {2400, B2400},   {4800, B4800},
      {9600, B9600}, {19200, B19200}, {38400, B38400}, {57600, B57600}, {115200, B115200}};
  for (const auto& [baud, constant] : rates) {
    LinkConfig c;
    c.baud = baud;
    ASSERT_TRUE(standard_baud(baud)) << baud;
    const auto t = serial_frame(cooked(), c);
    ASSERT_TRUE(t) << baud << ": " << t.error();
    EXPECT_EQ(cfgetospeed(&*t), constant) << baud;
    EXPECT_EQ(cfgetispeed(&*t), constant) << baud;
  }
}

TEST(SerialFrame, ARateWithNoConstantIsRefusedNotReplaced) {
  LinkConfig c;
  c.baud = 250000;
  const auto t = serial_frame(cooked(), c);
  ASSERT_FALSE(t);
  EXPECT_EQ(t.error(), "no serial rate of 250000 baud");
}

TEST(SerialFrame, IsoSevenEvenTwoIsRawWithParityChecked) {
  const LinkConfig iso;  // the defaults: 7 data bits, even parity, 2 stop bits, XON/XOFF
  const auto t = serial_frame(cooked(), iso);
  ASSERT_TRUE(t);
  EXPECT_EQ(t->c_cflag & CSIZE, static_cast<tcflag_t>(CS7));
  EXPECT_TRUE(has(t->c_cflag, PARENB | CSTOPB | CLOCAL | CREAD));
  EXPECT_FALSE(has(t->c_cflag, PARODD));
  EXPECT_FALSE(has(t->c_cflag, CRTSCTS));
  EXPECT_TRUE(has(t->c_iflag, INPCK));
  // XON/XOFF is usina's, in user space: the kernel's is off.
  EXPECT_EQ(t->c_iflag & (IXON | IXOFF | IXANY | ICRNL | INLCR | IGNCR | ISTRIP | BRKINT), 0u);
  EXPECT_EQ(t->c_oflag & OPOST, 0u);
  EXPECT_EQ(t->c_lflag & (ECHO | ICANON | ISIG | IEXTEN), 0u);
  EXPECT_EQ(t->c_cc[VMIN], 1);
  EXPECT_EQ(t->c_cc[VTIME], 0);
}

TEST(SerialFrame, EightNoneOneWithRtsCtsAndSevenOdd) {
  LinkConfig c;
  c.data_bits = 8;
  c.parity = Parity::None;
  c.stop_bits = 1;
  c.flow = Flow::RtsCts;
  auto t = serial_frame(cooked(), c);
  ASSERT_TRUE(t);
  EXPECT_EQ(t->c_cflag & CSIZE, static_cast<tcflag_t>(CS8));
  EXPECT_EQ(t->c_cflag & (PARENB | PARODD | CSTOPB), 0u);
  EXPECT_EQ(t->c_iflag & INPCK, 0u);  // no parity, none checked
  EXPECT_TRUE(has(t->c_cflag, CRTSCTS));
  c = LinkConfig{};
  c.parity = Parity::Odd;  // EIA RS-244's
  c.flow = Flow::DtrDsr;   // polled by usina: no kernel handshake
  t = serial_frame(cooked(), c);
  ASSERT_TRUE(t);
  EXPECT_TRUE(has(t->c_cflag, PARENB | PARODD));
  EXPECT_FALSE(has(t->c_cflag, CRTSCTS));
}

}  // namespace
}  // namespace usina::dnc
