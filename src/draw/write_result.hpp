// What a drawing writer returns: nothing, or why the file could not be written.
#pragma once

#include <string>

#include <tl/expected.hpp>

namespace usina::draw {

using WriteResult = tl::expected<void, std::string>;

}  // namespace usina::draw
