#include "dnc/web_toolpath_cache.hpp"

#include <fmt/format.h>

namespace usina::dnc {

std::string toolpath_key(std::string_view revision, std::string_view dialect,
                         std::uint32_t max_vertices) {
  // A hash and a dialect name never hold a space.
  return fmt::format("{} {} {}", revision, dialect, max_vertices);
}

ToolpathStream ToolpathCache::find(const std::string& key) {
  const auto it = index_.find(key);
  if (it == index_.end()) return nullptr;
  order_.splice(order_.begin(), order_, it->second);
  return it->second->stream;
}

void ToolpathCache::put(const std::string& key, ToolpathStream stream) {
  if (const auto it = index_.find(key); it != index_.end()) erase(it->second);
  if (!stream || stream->size() > limits_.bytes || limits_.entries == 0) return;
  order_.push_front(Entry{key, std::move(stream)});
  index_.emplace(key, order_.begin());
  bytes_ += order_.front().stream->size();
  while (bytes_ > limits_.bytes || index_.size() > limits_.entries) {
    erase(std::prev(order_.end()));
    ++evicted_;
  }
}

void ToolpathCache::erase(std::list<Entry>::iterator it) {
  bytes_ -= it->stream->size();
  index_.erase(it->key);
  order_.erase(it);
}

}  // namespace usina::dnc
