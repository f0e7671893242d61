#include "dnc/machine_config.hpp"

#include <string>

#include <gtest/gtest.h>

namespace usina::dnc {
namespace {

// spec/dnc-api.md's example, as written there.
constexpr std::string_view kContract = R"(
[[machine]]
name = "romi-1"            # the machine's id in the API
dialect = "romi"           # the dialect its programs are checked in
port = "/dev/ttyS0"        # a serial device or pty path, or "tcp://host:port"
baud = 9600
data_bits = 7              # 7 or 8
parity = "even"            # none | even | odd
stop_bits = 2
flow = "xonxoff"           # none | xonxoff | rtscts
code = "iso"               # ascii | iso | eia
eob = "lf"                 # lf | crlf | cr | semicolon | hash
mode = "production"        # production (released only) | tryout (approved too)
skid = 32                  # at most this many bytes written after an XOFF arrives (default 32)
)";

struct Read {
  std::optional<std::vector<LinkConfig>> machines;
  core::DiagnosticList diags;
};

Read read(std::string_view text) {
  Read r;
  r.machines = read_machine_links(text, 0, r.diags);
  return r;
}

std::string messages(const core::DiagnosticList& d) {
  std::string s;
  for (const auto& x : d.all())
    s += x.message + "\n";
  return s;
}

TEST(MachineConfig, TheContractsExampleReads) {
  const Read r = read(kContract);
  ASSERT_TRUE(r.machines) << messages(r.diags);
  ASSERT_EQ(r.machines->size(), 1U);
  const LinkConfig& c = r.machines->front();
  EXPECT_EQ(c.name, "romi-1");
  EXPECT_EQ(c.dialect, "romi");
  EXPECT_EQ(c.port, "/dev/ttyS0");
  EXPECT_EQ(c.baud, 9600U);
  EXPECT_EQ(c.data_bits, 7);
  EXPECT_EQ(c.parity, Parity::Even);
  EXPECT_EQ(c.stop_bits, 2);
  EXPECT_EQ(c.flow, Flow::XonXoff);
  EXPECT_EQ(c.code, TapeCode::Iso);
  EXPECT_EQ(c.eob, EndOfBlock::Lf);
  EXPECT_EQ(c.mode, MachineMode::Production);
  EXPECT_EQ(c.skid, 32U);
  EXPECT_TRUE(r.diags.all().empty());
}

TEST(MachineConfig, SkidDefaultsTo32) {
  const Read r = read("[[machine]]\nname = \"a\"\nport = \"tcp://10.0.0.5:4001\"\n");
  ASSERT_TRUE(r.machines) << messages(r.diags);
  EXPECT_EQ(r.machines->front().skid, 32U);
}

TEST(MachineConfig, AnUnknownKeyIsAWarningWithTheNearestName) {
  const Read r = read("[[machine]]\nname = \"a\"\nport = \"/dev/ttyS1\"\nbuad = 4800\n");
  ASSERT_TRUE(r.machines);
  ASSERT_EQ(r.diags.all().size(), 1U);
  const core::Diagnostic& d = r.diags.all()[0];
  EXPECT_EQ(d.code, core::Code::UnknownDncKey);
  EXPECT_EQ(d.severity, core::Severity::Warning);
  EXPECT_EQ(d.loc.line, 4U);
  EXPECT_NE(d.message.find("did you mean `baud`?"), std::string::npos) << d.message;
}

TEST(MachineConfig, EveryBadValueIsAnErrorAtItsLine) {
  const std::vector<std::pair<std::string, std::string>> cases{
      {"baud = 12345", "no UART rate"},
      {"baud = 230400", "from 110 to 115200"},
      {"data_bits = 9", "from 7 to 8"},
      {"parity = \"mark\"", "none, even, odd"},
      {"stop_bits = 3", "from 1 to 2"},
      {"flow = \"hardware\"", "none, xonxoff, rtscts"},
      {"code = \"ebcdic\"", "ascii, iso, eia"},
      {"eob = \"lfcr\"", "lf, crlf, cr, semicolon, hash"},
      {"mode = \"test\"", "production, tryout"},
      {"skid = 0", "from 1 to 65536"},
      {"skid = 1.5", "whole number"},
      {"xon_timeout = -1", "seconds"},
      {"wait_for_xon = 1", "true or false"},
      {"port = 5", "must be a string"},
  };
  for (const auto& [line, says] : cases) {
    const std::string text =
        "[[machine]]\nname = \"m\"\n" +
        std::string(line.starts_with("port") ? "" : "port = \"/dev/ttyS0\"\n") + line + "\n";
    const Read r = read(text);
    EXPECT_FALSE(r.machines) << line;
    ASSERT_FALSE(r.diags.all().empty()) << line;
    EXPECT_EQ(r.diags.all()[0].code, core::Code::DncConfig) << line;
    EXPECT_NE(messages(r.diags).find(says), std::string::npos) << line << ": " << messages(r.diags);
  }
}

TEST(MachineConfig, PortsAreCheckedAsTheyWillBeOpened) {
  for (const char* bad : {"ttyS0", "tcp://host", "tcp://:4001", "tcp://h:0", "tcp://h:70000",
                          "tcp-listen://0.0.0.0:x"}) {
    const Read r = read(std::string("[[machine]]\nname = \"m\"\nport = \"") + bad + "\"\n");
    EXPECT_FALSE(r.machines) << bad;
  }
  for (const char* good :
       {"/dev/ttyUSB0", "tcp://10.0.0.20:4001", "tcp://[::1]:4001", "tcp-listen://0.0.0.0:4001"}) {
    const Read r = read(std::string("[[machine]]\nname = \"m\"\nport = \"") + good + "\"\n");
    EXPECT_TRUE(r.machines) << good << ": " << messages(r.diags);
  }
}

TEST(MachineConfig, EiaNeedsEightBitsWithoutParity) {
  const Read r = read("[[machine]]\nname = \"m\"\nport = \"/dev/ttyS0\"\ncode = \"eia\"\n");
  EXPECT_FALSE(r.machines);
  EXPECT_NE(messages(r.diags).find("data_bits = 8"), std::string::npos);
  const Read ok = read(
      "[[machine]]\nname = \"m\"\nport = \"/dev/ttyS0\"\ncode = \"eia\"\ndata_bits = 8\n"
      "parity = \"none\"\neob = \"cr\"\n");
  EXPECT_TRUE(ok.machines) << messages(ok.diags);
}

TEST(MachineConfig, NamesAreRequiredUniqueAndSafe) {
  EXPECT_FALSE(read("[[machine]]\nport = \"/dev/ttyS0\"\n").machines);
  EXPECT_FALSE(read("[[machine]]\nname = \"../etc\"\nport = \"/dev/ttyS0\"\n").machines);
  EXPECT_FALSE(read("[[machine]]\nname = \"a\"\nport = \"/dev/ttyS0\"\n"
                    "[[machine]]\nname = \"a\"\nport = \"/dev/ttyS1\"\n")
                   .machines);
}

TEST(MachineConfig, NotTomlIsAnError) {
  const Read r = read("[[machine]\nname = ");
  EXPECT_FALSE(r.machines);
  EXPECT_EQ(r.diags.all()[0].code, core::Code::DncConfig);
}

TEST(MachineConfig, OtherTablesAreNotRead) {
  const Read r = read("[server]\nlisten = \"127.0.0.1:8080\"\n");
  ASSERT_TRUE(r.machines);
  EXPECT_TRUE(r.machines->empty());
  EXPECT_TRUE(r.diags.all().empty());
}

TEST(MachineConfig, LineRate) {
  LinkConfig c;
  c.baud = 115200;
  c.data_bits = 8;
  c.parity = Parity::None;
  c.stop_bits = 1;
  EXPECT_DOUBLE_EQ(bytes_per_second(c), 11520.0);
  c.data_bits = 7;
  c.parity = Parity::Even;
  c.stop_bits = 2;
  EXPECT_DOUBLE_EQ(bytes_per_second(c), 115200.0 / 11.0);
}

}  // namespace
}  // namespace usina::dnc
