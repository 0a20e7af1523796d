#pragma once
// Text placed in HTML or SVG (the report page, the replay picture) with the characters that
// markup reserves escaped.
#include <string>
#include <string_view>

namespace esc::report {

[[nodiscard]] std::string escape_markup(std::string_view text);

}  // namespace esc::report
