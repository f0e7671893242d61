// The layers a drawing of a program has, their names and their colours.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "draw/drawing.hpp"

namespace usina::draw {

inline constexpr std::string_view kContourLayer = "CONTOUR";
inline constexpr std::string_view kRapidLayer = "RAPID";
inline constexpr std::string_view kHolesLayer = "HOLES";
inline constexpr std::string_view kPocketsLayer = "POCKETS";

// "TOOLPATH_T<n>".
std::string toolpath_layer(int tool);

// The tool number of a TOOLPATH_T<n> name.
std::optional<int> tool_of_layer(std::string_view name);

LayerStyle style_of(std::string_view layer_name);

}  // namespace usina::draw
