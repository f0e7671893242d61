#include "draw/layer_style.hpp"

#include <array>
#include <charconv>

#include <fmt/format.h>

namespace usina::draw {
namespace {

constexpr std::string_view kToolPrefix = "TOOLPATH_T";

// Tool colours: AutoCAD colour indices that read on LibreCAD's black
// screen, with RGB a little darker so that they read on white paper.
constexpr std::array<LayerStyle, 6> kToolStyles{{
    {1, {220, 0, 0}, false},     // red
    {5, {0, 60, 230}, false},    // blue
    {3, {0, 150, 0}, false},     // green
    {6, {190, 0, 190}, false},   // magenta
    {30, {240, 120, 0}, false},  // orange
    {4, {0, 160, 190}, false},   // cyan
}};

}  // namespace

std::string toolpath_layer(int tool) {
  return fmt::format("{}{}", kToolPrefix, tool);
}

std::optional<int> tool_of_layer(std::string_view name) {
  if (!name.starts_with(kToolPrefix)) return std::nullopt;
  const std::string_view digits = name.substr(kToolPrefix.size());
  int tool = 0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), tool);
  if (ec != std::errc() || end != digits.data() + digits.size() || digits.empty())
    return std::nullopt;
  return tool;
}

LayerStyle style_of(std::string_view layer_name) {
  if (layer_name == kContourLayer) return {7, {0, 0, 0}, false};  // white on screen, black on paper
  if (layer_name == kRapidLayer) return {8, {128, 128, 128}, true};  // grey, dashed
  if (layer_name == kHolesLayer) return {3, {0, 150, 0}, false};     // green
  if (layer_name == kPocketsLayer) return {5, {0, 60, 230}, false};  // blue
  if (const auto tool = tool_of_layer(layer_name)) {
    // T1 takes the first colour; T0 (no tool) and negative numbers wrap too.
    const long n = static_cast<long>(kToolStyles.size());
    const long i = ((static_cast<long>(*tool) - 1) % n + n) % n;
    return kToolStyles[static_cast<std::size_t>(i)];
  }
  return {7, {0, 0, 0}, false};
}

}  // namespace usina::draw
