// RS274NGC parameters: numbered #1..#5602 and named #<name> (local to a
// subroutine call) or #<_name> (global). Read-only predefined names
// (#<_x>, #<_metric>...) are answered by the interpreter, not stored here.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

namespace usina::gcode {

inline constexpr int kMaxParameter = 5602;

// A named parameter's canonical spelling: lower case, blanks removed.
std::string normalise_name(std::string_view raw);

class Parameters {
 public:
  static bool in_range(int index) { return index >= 1 && index <= kMaxParameter; }

  double get(int index) const { return numbered_[static_cast<std::size_t>(index)]; }

  void set(int index, double value) {
    if (journal_ != nullptr) journal_->emplace_back(index, get(index));
    numbered_[static_cast<std::size_t>(index)] = value;
  }

  // Every write of a numbered parameter from now on is appended to
  // `journal` as (index, value before), so a refused block's writes can be
  // put back (Interpreter::roll_back); nullptr stops the recording.
  void record_writes(std::vector<std::pair<int, double>>* journal) { journal_ = journal; }

  // Locals first (innermost call), then globals; nullopt when not defined.
  std::optional<double> named(std::string_view name) const;
  void set_named(const std::string& name, double value);

  // A subroutine call: a new scope of local names; #1..#30 saved and restored.
  void push_scope();
  void pop_scope();

  std::size_t depth() const { return locals_.size(); }

 private:
  using Scope = std::unordered_map<std::string, double>;
  std::array<double, kMaxParameter + 1> numbered_{};
  Scope globals_;
  std::vector<Scope> locals_{Scope{}};
  std::vector<std::array<double, 30>> saved_locals_;
  std::vector<std::pair<int, double>>* journal_ = nullptr;
};

}  // namespace usina::gcode
