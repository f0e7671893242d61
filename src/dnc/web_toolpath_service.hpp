// The tool-path route's work off the event loop (docs/web.md, "The
// tool-path cache"). Running a program of a million blocks through the
// interpreter takes seconds; on the server's one event loop that would
// pause every other client. So the loop hands the revision's bytes to a
// small thread pool (a fixed number of threads, not one per request) and
// goes on serving; the encoded stream comes back to the loop, goes into the
// cache (web_toolpath_cache.hpp), and answers every request that asked for
// it meanwhile (one computation however many ask at once).
//
// Everything here but the computation itself runs on the loop: the cache
// and the waiting requests need no lock.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <boost/asio/io_context.hpp>
#include <boost/asio/thread_pool.hpp>

#include "dnc/web_toolpath.hpp"
#include "dnc/web_toolpath_cache.hpp"

namespace usina::dnc {

// Where a stream came from (the route's `X-Toolpath-Cache` header).
enum class ToolpathFrom { Cache, Computed, Joined };

const char* toolpath_from_name(ToolpathFrom from);

// What an answer computed later needs of its request, which is gone by then.
struct ToolpathReply {
  unsigned version = 11;
  bool keep_alive = true;
};

struct ToolpathServiceConfig {
  // Two: a small program is not queued behind one big one, and at most two
  // runs hold their vertices at once (a run holds up to 20,000,000).
  unsigned threads = 2;
  ToolpathCacheLimits cache;
};

struct ToolpathCounters {
  std::uint64_t hits = 0;      // answered from the cache
  std::uint64_t computed = 0;  // runs finished on the pool
  std::uint64_t joined = 0;    // requests that waited for a run another one started
  std::uint64_t failed = 0;    // runs that threw (out of memory): answered 500, not kept
};

class ToolpathService {
 public:
  // The answer's bytes, computed on the pool (it may throw: then `error`).
  using Work = std::function<std::string()>;
  // On the loop: the bytes, or nullptr and why not.
  using Done = std::function<void(ToolpathStream, ToolpathFrom, const std::string& error)>;

  ToolpathService(boost::asio::io_context& loop, ToolpathServiceConfig config = {});
  // Drops the queued runs and waits for the ones running to end.
  ~ToolpathService();

  ToolpathService(const ToolpathService&) = delete;
  ToolpathService& operator=(const ToolpathService&) = delete;

  // On the loop: the kept stream of `key`, nullptr when there is none.
  ToolpathStream cached(const std::string& key);
  // On the loop: runs `work` on the pool (or joins the run of `key` in
  // progress: its bytes depend on `key` alone); `done` runs on the loop
  // with the bytes.
  void run(const std::string& key, Work work, Done done);

  // On the loop.
  ToolpathCounters counters() const;
  std::size_t cached_bytes() const;

  // Runs on the pool's thread before each run (the tests hold a run there
  // to see the loop answer meanwhile, or throw as a run out of memory
  // would). Set it before the first request.
  std::function<void()> before_run;

 private:
  struct State;

  boost::asio::io_context& loop_;
  std::shared_ptr<State> state_;  // the runs' way back: gone once this is
  boost::asio::thread_pool pool_;
};

}  // namespace usina::dnc
