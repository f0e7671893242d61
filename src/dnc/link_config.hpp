// A machine's link: how its control is wired to usina (the `[[machine]]`
// table of usina-serve.toml, spec/dnc-api.md) — the port, the serial frame,
// the flow control, the tape code and block end, and the limits the drip
// feed keeps. Plain data; machine_config.hpp reads it from TOML and checks
// every value.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace usina::dnc {

enum class Parity : std::uint8_t { None, Even, Odd };
// none | xonxoff | rtscts (the contract) | dtrdsr (a handshake the kernel
// does not do: usina reads DSR before each chunk).
enum class Flow : std::uint8_t { None, XonXoff, RtsCts, DtrDsr };
// research/dnc.md §2.3: ISO 840 (7 bits + even parity on channel 8), EIA
// RS-244 (odd parity on channel 5), or ASCII as it is.
enum class TapeCode : std::uint8_t { Ascii, Iso, Eia };
enum class EndOfBlock : std::uint8_t { Lf, CrLf, Cr, Semicolon, Hash };
// production: released revisions only; tryout: approved ones too.
enum class MachineMode : std::uint8_t { Production, Tryout };

struct LinkConfig {
  std::string name;     // the machine's id in the API
  std::string dialect;  // its programs' dialect (checked by the store)
  std::string port;     // a device or pty path, tcp://host:port, tcp-listen://host:port
  // The defaults are ISO's usual frame: 7 data bits, even parity, 2 stop bits.
  std::uint32_t baud = 9600;
  std::uint8_t data_bits = 7;
  Parity parity = Parity::Even;
  std::uint8_t stop_bits = 2;
  Flow flow = Flow::XonXoff;
  TapeCode code = TapeCode::Iso;
  EndOfBlock eob = EndOfBlock::Lf;
  MachineMode mode = MachineMode::Production;
  // At most this many bytes may still reach the control after its XOFF
  // arrives: the bytes usina keeps in flight (kernel queue, UART, device
  // server) never exceed it.
  std::uint32_t skid = 32;
  std::uint8_t xon = 0x11;               // DC1
  std::uint8_t xoff = 0x13;              // DC3
  std::uint32_t leader = 20;             // NULs before the first `%` (outside the frame)
  std::uint32_t trailer = 20;            // NULs after the last `%`
  bool wait_for_xon = false;             // start only when the control sends its first XON
  double xon_timeout = 600.0;            // seconds under XOFF before the alarm
  double receive_idle = 10.0;            // seconds of silence that end a punch without `%`
  std::uint32_t request_program = 9999;  // the O number of a remote request (0: any)
  std::uint32_t request_lines = 10;      // lines of a punch scanned for a request
};

// The line's speed in bytes a second: one start bit, the data bits, the
// parity bit, the stop bits.
double bytes_per_second(const LinkConfig& c);

std::string_view parity_name(Parity p);
std::string_view flow_name(Flow f);
std::string_view code_name(TapeCode c);
std::string_view eob_name(EndOfBlock e);
std::string_view mode_name(MachineMode m);

std::optional<Parity> parse_parity(std::string_view s);
std::optional<Flow> parse_flow(std::string_view s);
std::optional<TapeCode> parse_code(std::string_view s);
std::optional<EndOfBlock> parse_eob(std::string_view s);
std::optional<MachineMode> parse_mode(std::string_view s);

// The baud rates a UART (and termios) offers from 110 to 115200.
bool standard_baud(std::uint32_t baud);

}  // namespace usina::dnc
