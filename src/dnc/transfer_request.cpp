#include "dnc/transfer_request.hpp"

#include <fmt/format.h>

namespace usina::dnc {
namespace {

void send(asio::io_context& io, Link& link, const LinkConfig& machine,
          std::unique_ptr<ProgramSource> program, Sender::DoneHandler done) {
  auto sender =
      std::make_shared<Sender>(io, link, send_options(machine), std::move(program), JobMode::Send);
  sender->start(std::move(done));
}

}  // namespace

bool answer_remote_request(asio::io_context& io, Link& link, const LinkConfig& machine,
                           const ReceivedProgram& received, const RequestHandler& handler,
                           Sender::DoneHandler done) {
  const RequestRules rules{machine.request_program, machine.request_lines};
  auto parsed = parse_remote_request(received.text, rules);
  if (!parsed) return false;
  const std::uint32_t number = machine.request_program != 0 ? machine.request_program : 9999;
  if (!*parsed) {
    send(io, link, machine,
         string_source(response_program(number, "REQUEST REFUSED, " + parsed->error())),
         std::move(done));
    return true;
  }
  handler(machine, **parsed,
          [&io, &link, machine, number, done = std::move(done)](RequestAnswer answer) mutable {
            if (!answer.program) {
              answer.program = string_source(response_program(number, answer.refusal));
            }
            send(io, link, machine, std::move(answer.program), std::move(done));
          });
  return true;
}

}  // namespace usina::dnc
