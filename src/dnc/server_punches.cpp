// What the machines punch: a program becomes a draft revision (with the
// diff against the released one a click away); a remote request is answered
// from the store, the answer recorded as a job of its own.
#include <fmt/format.h>

#include "dnc/program_source.hpp"
#include "dnc/resume.hpp"
#include "dnc/server_machines.hpp"
#include "dnc/store_revisions.hpp"

namespace usina::dnc {
namespace {

// The store's name for a requested program: `O1234` for 1234, as punches
// are named; a name that is not a number stays as it is.
std::vector<std::string> candidate_names(const std::string& asked) {
  const bool digits = !asked.empty() && asked.find_first_not_of("0123456789") == std::string::npos;
  if (digits) return {"O" + asked, asked};
  return {asked};
}

// /BL is a block's N word, /LI a line of the file, TO= a tool.
std::optional<gcode::ResumeStart> requested_start(const RemoteRequest& r) {
  using K = gcode::ResumeStart::Kind;
  if (r.start_tool) return gcode::ResumeStart{K::Tool, static_cast<long>(*r.start_tool)};
  if (r.start_block) return gcode::ResumeStart{K::NWord, static_cast<long>(*r.start_block)};
  if (r.start_line) return gcode::ResumeStart{K::Line, static_cast<long>(*r.start_line)};
  return std::nullopt;
}

}  // namespace

void Machines::on_punch(MachineRuntime& m, const ReceivedProgram& r) {
  const std::string& machine = m.config.link.name;
  if (!r.good() || r.name.empty()) {
    const std::string why = !r.good() ? r.reason : "the punch has no O number to name it";
    events_.publish("punch.refused", {{"machine", machine}, {"reason", why}, {"rows", r.rows}});
    return;
  }
  Upload up;
  up.name = r.name;
  up.machine_class = m.config.machine_class;
  up.dialect = m.config.link.dialect;
  up.text = r.text;
  up.reason = fmt::format("punched by machine {}", machine);
  if (profiles_ != nullptr) {
    if (auto it = profiles_->find(up.machine_class); it != profiles_->end())
      up.profile = &it->second;
  }
  auto put = put_revision(store_, up, Actor{machine, "machine " + machine});
  if (!put) {
    events_.publish("punch.refused",
                    {{"machine", machine}, {"program", r.name}, {"reason", put.error().message}});
    return;
  }
  events_.publish("revision.created", {{"name", r.name},
                                       {"revision", put->revision.hash},
                                       {"state", state_name(put->revision.state)},
                                       {"machine", machine},
                                       {"created", put->created}});
}

void Machines::on_request(MachineRuntime& m, const RemoteRequest& r, const AnswerFunction& answer) {
  for (const std::string& name : candidate_names(r.program)) {
    auto program = find_program(store_, name);
    if (!program) continue;
    auto released = released_revision(store_, name);
    if (!released || !*released) {
      answer(RequestAnswer{nullptr, fmt::format("PROGRAM {} IS NOT RELEASED", r.program)});
      return;
    }
    const JobOrder order{name, (*released)->hash, JobMode::Send, nullptr};
    if (auto ok = may_take(m, order); !ok) {
      answer(RequestAnswer{nullptr, fmt::format("PROGRAM {} IS NOT FOR THIS MACHINE", r.program)});
      return;
    }
    auto bytes = revision_bytes(store_, name, order.revision);
    if (!bytes) {
      answer(RequestAnswer{nullptr, fmt::format("PROGRAM {} CANNOT BE READ", r.program)});
      return;
    }
    if (auto start = requested_start(r)) {
      auto text = resume_program(*bytes, program->dialect, *start);
      if (!text) {
        answer(
            RequestAnswer{nullptr, fmt::format("NO RESTART OF {}: {}", r.program, text.error())});
        return;
      }
      *bytes = std::move(*text);
    }
    JobRecord job;
    job.machine = m.config.link.name;
    job.program = name;
    job.revision = order.revision;
    job.mode = "send";
    job.state = "running";
    job.actor = m.config.link.name;
    const std::string by = r.operator_name.empty() ? "the control" : r.operator_name;
    if (auto made = create_job(store_, job, Actor{m.config.link.name, "remote request by " + by}))
      job = *made;
    job.started_at_us = store_.now_us();
    m.answering = job;
    publish_job(job);
    answer(RequestAnswer{string_source(std::move(*bytes)), {}});
    return;
  }
  answer(RequestAnswer{nullptr, fmt::format("PROGRAM {} IS NOT IN THE STORE", r.program)});
}

void Machines::on_request_answered(MachineRuntime& m, const JobReport& r) {
  if (!m.answering) return;  // a refusal: no job
  JobRecord job = *m.answering;
  m.answering.reset();
  apply_report(job, r);
  job.bytes_total = r.bytes_sent;
  job.ended_at_us = store_.now_us();
  save(job, Actor{m.config.link.name, "server"});
  publish_job(job);
}

}  // namespace usina::dnc
