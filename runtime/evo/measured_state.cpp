#include "runtime/evo/measured_state.hpp"

#include <stdexcept>
#include <string>

namespace esc::evo {

namespace {

constexpr std::uint32_t kVersion = 1;

}  // namespace

void put_measured(StateWriter& w, std::span<const Measured> measured) {
  w.put(static_cast<std::uint64_t>(measured.size()));
  for (const Measured& m : measured) {
    w.put(m.generation);
    w.put(m.candidate);
  }
}

std::vector<Measured> get_measured(StateReader& r) {
  std::vector<Measured> out(r.count(sizeof(std::int64_t) + sizeof(std::uint64_t)));
  for (Measured& m : out) {
    m.generation = r.get<std::int64_t>();
    m.candidate = r.get<std::uint64_t>();
    if (m.generation < -1) throw std::invalid_argument("optimizer state: a member measured in a negative generation");
  }
  return out;
}

StateBytes save_with_measured(std::string_view tag, const StateBytes& core, std::span<const Measured> measured) {
  StateWriter w;
  w.put(std::string(tag));
  w.put(kVersion);
  w.put(std::span<const std::uint8_t>(core));
  put_measured(w, measured);
  return std::move(w).take();
}

CoreAndMeasured read_with_measured(std::string_view tag, std::span<const std::uint8_t> bytes) {
  StateReader r(bytes);
  if (r.text() != tag) return {StateBytes(bytes.begin(), bytes.end()), std::nullopt};
  if (const auto v = r.get<std::uint32_t>(); v != kVersion)
    throw std::invalid_argument(std::string(tag) + " state: format version " + std::to_string(v) + ", expected 1");
  const std::string core = r.text();
  std::vector<Measured> measured = get_measured(r);
  r.finish();
  return {StateBytes(core.begin(), core.end()), std::move(measured)};
}

std::vector<Measured> measured_for(std::optional<std::vector<Measured>> stored, std::size_t count,
                                   const std::string& what, const std::string& members) {
  if (!stored) return std::vector<Measured>(count);
  if (stored->size() != count)
    throw std::invalid_argument(what + " state: " + std::to_string(stored->size()) + " origins for " +
                                std::to_string(count) + " " + members);
  return std::move(*stored);
}

}  // namespace esc::evo
