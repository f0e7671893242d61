#include "dnc/web_toolpath_service.hpp"

#include <exception>

#include <boost/asio/post.hpp>

namespace usina::dnc {

const char* toolpath_from_name(ToolpathFrom from) {
  switch (from) {
  case ToolpathFrom::Cache: return "hit";
  case ToolpathFrom::Computed: return "computed";
  case ToolpathFrom::Joined: return "joined";
  }
  return "computed";
}

// What the loop owns: the cache, the requests waiting for each run.
struct ToolpathService::State {
  explicit State(ToolpathCacheLimits limits) : cache(limits) {}

  ToolpathCache cache;
  std::map<std::string, std::vector<Done>> waiting;  // by key: the runs in progress
  ToolpathCounters counters;

  void finish(const std::string& key, ToolpathStream stream, const std::string& error) {
    if (stream) {
      ++counters.computed;
      cache.put(key, stream);
    } else {
      ++counters.failed;
    }
    auto it = waiting.find(key);
    if (it == waiting.end()) return;
    std::vector<Done> done = std::move(it->second);
    waiting.erase(it);
    for (std::size_t i = 0; i < done.size(); ++i)
      done[i](stream, i == 0 ? ToolpathFrom::Computed : ToolpathFrom::Joined, error);
  }
};

ToolpathService::ToolpathService(boost::asio::io_context& loop, ToolpathServiceConfig config)
    : loop_(loop),
      state_(std::make_shared<State>(config.cache)),
      pool_(config.threads == 0 ? 1 : config.threads) {}

ToolpathService::~ToolpathService() {
  pool_.stop();
  pool_.join();
}

ToolpathStream ToolpathService::cached(const std::string& key) {
  ToolpathStream s = state_->cache.find(key);
  if (s) ++state_->counters.hits;
  return s;
}

void ToolpathService::run(const std::string& key, Work work, Done done) {
  auto& waiting = state_->waiting[key];
  waiting.push_back(std::move(done));
  if (waiting.size() > 1) {
    ++state_->counters.joined;
    return;  // the run in progress answers this one too
  }
  std::weak_ptr<State> back = state_;
  boost::asio::post(pool_, [this, &loop = loop_, back, key, work = std::move(work)] {
    ToolpathStream stream;
    std::string error;
    try {
      if (before_run) before_run();
      stream = std::make_shared<const std::string>(work());
    } catch (const std::exception& e) {  // a run past the memory there is: the server goes on
      error = e.what();
    }
    boost::asio::post(loop, [back, key, stream, error] {
      if (auto state = back.lock()) state->finish(key, stream, error);
    });
  });
}

ToolpathCounters ToolpathService::counters() const {
  return state_->counters;
}

std::size_t ToolpathService::cached_bytes() const {
  return state_->cache.bytes();
}

}  // namespace usina::dnc
