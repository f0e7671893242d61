// Answering a remote request (remote_request.hpp) on the machine's link:
// the server's handler decides (the released revision for this machine, or
// why not), and usina sends either the program or a short response program
// whose comment says why the operator gets none. A request that cannot be
// read never reaches the handler: its response says what is wrong with it.
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "dnc/link.hpp"
#include "dnc/program_source.hpp"
#include "dnc/remote_request.hpp"
#include "dnc/transfer_receive.hpp"
#include "dnc/transfer_send.hpp"

namespace usina::dnc {

struct RequestAnswer {
  std::unique_ptr<ProgramSource> program;  // the program to send; null: refused
  std::string refusal;                     // why not (the response program's comment)
};

using AnswerFunction = std::function<void(RequestAnswer)>;
// Provided by the server: looks the program up and answers, now or later
// (the answer may come after a query), exactly once.
using RequestHandler =
    std::function<void(const LinkConfig& machine, const RemoteRequest& request, AnswerFunction)>;

// When `received` is a remote request under the machine's rules, answers it
// on `link` and returns true; `done` gets the report of what was sent.
// False when it is an ordinary punch.
bool answer_remote_request(asio::io_context& io, Link& link, const LinkConfig& machine,
                           const ReceivedProgram& received, const RequestHandler& handler,
                           Sender::DoneHandler done);

}  // namespace usina::dnc
