#include "apt/vocabulary.hpp"

namespace usina::apt {
namespace {

using vocabulary_detail::Entry;
using vocabulary_detail::kMinorWords;
using vocabulary_detail::kPostWords;

template <std::size_t N>
std::optional<int> find(const Entry (&table)[N], std::string_view word) {
  for (const Entry& e : table)
    if (e.word == word) return e.code;
  return std::nullopt;
}

}  // namespace

std::optional<int> post_word_code(std::string_view word) {
  return find(kPostWords, word);
}

std::optional<int> minor_word_code(std::string_view word) {
  // Selectors and words of the 2.5D subset whose codes the table above does
  // not give are minor words too; they never reach a CL record.
  return find(kMinorWords, word);
}

std::string_view post_word_name(int code) {
  for (const Entry& e : kPostWords)
    if (e.code == code) return e.word;
  return "";
}

std::string_view minor_word_name(int code) {
  for (const Entry& e : kMinorWords)
    if (e.code == code) return e.word;
  return "";
}

}  // namespace usina::apt
