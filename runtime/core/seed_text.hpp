#pragma once
// Seeds as text. A seed is any 64-bit unsigned integer; read through a double it would be
// rounded above 2^53 (9007199254740993 became ...992) and a `-1` would wrap to 2^64 - 1, so
// every seed a person writes (a script's `seed N`, `--seed`, `--set seed=`) is read here,
// digit by digit. Written out (JSON, CSV) a seed is its decimal text, which every reader
// keeps exactly; JSON numbers above 2^53 are rounded by JavaScript and R.
#include <charconv>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace esc {

// The seed written in `text` (decimal digits only, at most 2^64 - 1); nullopt for anything
// else: a sign, a point, an exponent, spaces, a value out of range.
[[nodiscard]] inline std::optional<std::uint64_t> parse_seed(std::string_view text) noexcept {
  if (text.empty() || text.front() < '0' || text.front() > '9') return std::nullopt;
  std::uint64_t v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return v;
}

[[nodiscard]] inline std::string seed_text(std::uint64_t seed) { return std::to_string(seed); }

// What a seed may be, for messages.
inline constexpr std::string_view kSeedRange = "a whole number from 0 to 18446744073709551615 (2^64 - 1)";

}  // namespace esc
