#pragma once
// The types of strongly typed GP. Every primitive has a result type and argument types,
// and every operator keeps trees well typed: a subtree only ever replaces a subtree of
// the same type.
#include <array>
#include <cstdint>
#include <string_view>

namespace esc::genome::tree {

enum class Type : std::uint8_t {
  Number,    // a double
  Bool,      // a double that is 0 or 1 (comparisons, and/or/not, true/false, collision)
  Action,    // one action of a list (index) with its Number parameters
  Behavior,  // one behavior of a list (index)
  Wheels,    // two wheel commands, wheels(left, right)
};

inline constexpr std::size_t kTypeCount = 5;
inline constexpr std::array kAllTypes = {Type::Number, Type::Bool, Type::Action, Type::Behavior,
                                         Type::Wheels};

[[nodiscard]] constexpr std::size_t index_of(Type t) noexcept { return static_cast<std::size_t>(t); }

[[nodiscard]] constexpr std::string_view name_of(Type t) noexcept {
  switch (t) {
    case Type::Number: return "Number";
    case Type::Bool: return "Bool";
    case Type::Action: return "Action";
    case Type::Behavior: return "Behavior";
    case Type::Wheels: return "Wheels";
  }
  return "?";
}

}  // namespace esc::genome::tree
