// One machine's end of usina: its link, listening while idle, one transfer
// at a time. While idle it reads the link: the first bytes of a punch start
// a receive; a punch that is a remote request is answered through the
// server's handler, any other goes to `punched` (the store makes it a draft
// revision). A job (send or drip) takes the link while it runs. A lost link
// makes the station offline and it opens the port again after
// `reopen_after` — a job it interrupted is never restarted.
#pragma once

#include <array>
#include <chrono>
#include <functional>
#include <memory>
#include <string>

#include <boost/asio/steady_timer.hpp>

#include "dnc/link.hpp"
#include "dnc/transfer_receive.hpp"
#include "dnc/transfer_request.hpp"
#include "dnc/transfer_send.hpp"

namespace usina::dnc {

enum class StationState : std::uint8_t { Offline, Idle, Receiving, Sending };

std::string_view station_state_name(StationState s);

struct StationEvents {
  std::function<void(StationState)> state;
  std::function<void(const ReceivedProgram&)> punched;
  RequestHandler request;
  std::function<void(const JobReport&)> request_answered;
  std::function<void(const std::string&)> link_error;  // why the port did not open
};

class Station : public std::enable_shared_from_this<Station> {
 public:
  Station(asio::io_context& io, LinkConfig config, StationEvents events,
          std::chrono::duration<double> reopen_after = std::chrono::seconds(10));

  // Opens the machine's port (or takes `link`, already open) and listens.
  void start();
  void start(std::unique_ptr<Link> link);
  void shutdown();

  // Starts a job if the station is idle; false (and why) otherwise.
  bool submit(std::unique_ptr<ProgramSource> program, JobMode mode, Sender::DoneHandler done,
              std::string* why);
  // The operator's stop of the running job (it ends interrupted).
  void stop_job();

  StationState state() const { return state_; }

  const LinkConfig& config() const { return config_; }

  // The running job's progress; nothing when none runs.
  const JobReport* job() const { return sender_ ? &sender_->report() : nullptr; }

 private:
  void open();
  void set_state(StationState s);
  void listen();
  void on_punch_start(std::size_t n);
  void on_received(const ReceivedProgram& received);
  void lost();
  void to_idle();

  asio::io_context& io_;
  LinkConfig config_;
  StationEvents events_;
  std::chrono::duration<double> reopen_after_;
  asio::steady_timer reopen_;
  std::unique_ptr<Link> link_;
  std::shared_ptr<Sender> sender_;
  std::shared_ptr<Receiver> receiver_;
  std::array<std::uint8_t, 256> in_{};
  StationState state_ = StationState::Offline;
  std::uint64_t listen_generation_ = 0;  // an idle read from before a job is stale
  bool shut_ = false;
};

}  // namespace usina::dnc
