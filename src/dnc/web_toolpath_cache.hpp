// The viewer's tool-path streams kept in memory (docs/web.md, "The tool-path
// cache"). A revision never changes (its name is the hash of its bytes), so
// the stream of a revision, in a dialect, at a vertex budget is the same
// for ever: computed once, served from here after. The cache is bounded
// twice: by the bytes of the streams it holds and by their count; past
// either bound the stream used longest ago goes first (LRU). A stream
// larger than the byte bound is not kept at all.
#pragma once

#include <cstddef>
#include <cstdint>
#include <list>
#include <memory>
#include <string>
#include <string_view>
#include <unordered_map>

namespace usina::dnc {

using ToolpathStream = std::shared_ptr<const std::string>;

struct ToolpathCacheLimits {
  std::size_t bytes = 64u << 20;  // 64 MiB: 15 streams of the default 200,000 vertices
  std::size_t entries = 256;      // many small programs
};

// The cache's key: a revision's stream depends on its bytes (the hash), the
// dialect they run in and the vertex budget, and on nothing else.
std::string toolpath_key(std::string_view revision, std::string_view dialect,
                         std::uint32_t max_vertices);

// Not thread-safe: the server's event loop owns it.
class ToolpathCache {
 public:
  explicit ToolpathCache(ToolpathCacheLimits limits = {}) : limits_(limits) {}

  // The stream of `key`, marked as used now; nullptr when it is not kept.
  ToolpathStream find(const std::string& key);
  // Keeps `stream` (replacing the one of the same key), then evicts the
  // least recently used until both bounds hold.
  void put(const std::string& key, ToolpathStream stream);

  std::size_t bytes() const { return bytes_; }

  std::size_t size() const { return index_.size(); }

  std::uint64_t evicted() const { return evicted_; }

 private:
  struct Entry {
    std::string key;
    ToolpathStream stream;
  };

  void erase(std::list<Entry>::iterator it);

  ToolpathCacheLimits limits_;
  std::list<Entry> order_;  // most recently used first
  std::unordered_map<std::string, std::list<Entry>::iterator> index_;
  std::size_t bytes_ = 0;
  std::uint64_t evicted_ = 0;
};

}  // namespace usina::dnc
