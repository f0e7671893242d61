// The IBM APT vocabulary codes (research/apt.md §6.3, from the IBM manual's
// table): post-processor major words are the subclass of their 2000-class
// record, minor words are written as their code (#60 for CLW).
#pragma once

#include <optional>
#include <string_view>

namespace usina::apt {

// The 2000-class subclass of a post-processor word (FEDRAT 1009, END 1).
std::optional<int> post_word_code(std::string_view word);

// The code of a minor word (CLW 60, ON 71).
std::optional<int> minor_word_code(std::string_view word);

// The post-processor word of a 2000-class subclass, "" when it has none.
std::string_view post_word_name(int code);

// The minor word of a code, "" when it has none.
std::string_view minor_word_name(int code);

}  // namespace usina::apt
