#include "dnc/store_db.hpp"

#include <charconv>

namespace usina::dnc {

const std::string& SqlRow::text(std::size_t i) const {
  static const std::string kEmpty;
  const auto& c = columns.at(i);
  return c ? *c : kEmpty;
}

std::int64_t SqlRow::integer(std::size_t i) const {
  const std::string& s = text(i);
  std::int64_t v = 0;
  std::from_chars(s.data(), s.data() + s.size(), v);
  return v;
}

}  // namespace usina::dnc
