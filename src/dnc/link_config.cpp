#include "dnc/link_config.hpp"

#include <algorithm>
#include <array>
#include <utility>

namespace usina::dnc {
namespace {

template <typename E, std::size_t N>
std::optional<E> find_value(const std::array<std::pair<std::string_view, E>, N>& table,
                            std::string_view s) {
  for (const auto& [name, value] : table) {
    if (name == s) return value;
  }
  return std::nullopt;
}

template <typename E, std::size_t N>
std::string_view find_name(const std::array<std::pair<std::string_view, E>, N>& table, E v) {
  for (const auto& [name, value] : table) {
    if (value == v) return name;
  }
  return "?";
}

constexpr std::array<std::pair<std::string_view, Parity>, 3> kParity{
    {{"none", Parity::None}, {"even", Parity::Even}, {"odd", Parity::Odd}}};
constexpr std::array<std::pair<std::string_view, Flow>, 4> kFlow{{{"none", Flow::None},
                                                                  {"xonxoff", Flow::XonXoff},
                                                                  {"rtscts", Flow::RtsCts},
                                                                  {"dtrdsr", Flow::DtrDsr}}};
constexpr std::array<std::pair<std::string_view, TapeCode>, 3> kCode{
    {{"ascii", TapeCode::Ascii}, {"iso", TapeCode::Iso}, {"eia", TapeCode::Eia}}};
constexpr std::array<std::pair<std::string_view, EndOfBlock>, 5> kEob{
    {{"lf", EndOfBlock::Lf},
     {"crlf", EndOfBlock::CrLf},
     {"cr", EndOfBlock::Cr},
     {"semicolon", EndOfBlock::Semicolon},
     {"hash", EndOfBlock::Hash}}};
constexpr std::array<std::pair<std::string_view, MachineMode>, 2> kMode{
    {{"production", MachineMode::Production}, {"tryout", MachineMode::Tryout}}};

// termios's B110 ... B115200 (POSIX plus Linux's B57600 and B115200).
constexpr std::array<std::uint32_t, 15> kBauds{110,  150,   300,   600,   1200,   1800, 2400, 4800,
                                               9600, 19200, 38400, 57600, 115200, 200,  134};

}  // namespace

double bytes_per_second(const LinkConfig& c) {
  const unsigned bits =
      1U + c.data_bits + (c.parity == Parity::None ? 0U : 1U) + static_cast<unsigned>(c.stop_bits);
  return static_cast<double>(c.baud) / bits;
}

std::string_view parity_name(Parity p) {
  return find_name(kParity, p);
}

std::string_view flow_name(Flow f) {
  return find_name(kFlow, f);
}

std::string_view code_name(TapeCode c) {
  return find_name(kCode, c);
}

std::string_view eob_name(EndOfBlock e) {
  return find_name(kEob, e);
}

std::string_view mode_name(MachineMode m) {
  return find_name(kMode, m);
}

std::optional<Parity> parse_parity(std::string_view s) {
  return find_value(kParity, s);
}

std::optional<Flow> parse_flow(std::string_view s) {
  return find_value(kFlow, s);
}

std::optional<TapeCode> parse_code(std::string_view s) {
  return find_value(kCode, s);
}

std::optional<EndOfBlock> parse_eob(std::string_view s) {
  return find_value(kEob, s);
}

std::optional<MachineMode> parse_mode(std::string_view s) {
  return find_value(kMode, s);
}

bool standard_baud(std::uint32_t baud) {
  return std::find(kBauds.begin(), kBauds.end(), baud) != kBauds.end();
}

}  // namespace usina::dnc
