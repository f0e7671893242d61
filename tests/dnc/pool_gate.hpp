// A gate for the tool-path service's pool in the server tests: a run is
// held there (ToolpathService::before_run) until the test releases it, so
// a test sees what the event loop answers meanwhile.
#pragma once

#include <chrono>
#include <condition_variable>
#include <mutex>

namespace usina::test {

// Holds the pool's runs until released (the test's hook, before_run).
class Gate {
 public:
  void enter() {
    std::unique_lock lock(m_);
    ++entered_;
    cv_.notify_all();
    cv_.wait(lock, [&] { return open_; });
  }

  // False after a guard of 60 s (a broken server; no test asserts a time).
  bool wait_entered(int n) {
    std::unique_lock lock(m_);
    return cv_.wait_for(lock, std::chrono::seconds(60), [&] { return entered_ >= n; });
  }

  void release() {
    std::lock_guard lock(m_);
    open_ = true;
    cv_.notify_all();
  }

 private:
  std::mutex m_;
  std::condition_variable cv_;
  int entered_ = 0;
  bool open_ = false;
};

// Opens the gate before the server stops (its pool waits for the held run).
struct ReleaseOnExit {
  Gate& gate;

  ~ReleaseOnExit() { gate.release(); }
};

}  // namespace usina::test
