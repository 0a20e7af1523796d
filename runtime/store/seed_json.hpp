#pragma once
// A seed's JSON form, used by every JSON file esc writes (settings.json, summary.json,
// run-NN.best.json, the export, the report's data, the stored command-line settings): a
// string of decimal digits, since JSON numbers above 2^53 are rounded by JavaScript and R.
// Reading accepts the string and, for files written before, a JSON number.
#include <cstdint>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "runtime/core/seed_text.hpp"

namespace esc::store {

// A string, so that it goes into json and ordered_json alike.
[[nodiscard]] inline std::string seed_json(std::uint64_t seed) { return seed_text(seed); }

// Throws std::invalid_argument when `j` holds no seed.
template <class Json>
[[nodiscard]] std::uint64_t seed_from_json(const Json& j) {
  if (j.is_number_unsigned()) return j.template get<std::uint64_t>();
  if (j.is_string())
    if (const auto s = parse_seed(j.template get<std::string>())) return *s;
  throw std::invalid_argument("not a seed: " + j.dump());
}

}  // namespace esc::store
