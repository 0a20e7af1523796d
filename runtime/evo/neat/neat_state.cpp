// Neat's state as bytes: everything the next breeding reads (the population, its fitness,
// the species with their ages and records, the innovation and node counters, the
// threshold, the population's standstill count), then an FNV-1a checksum of all of it, so a
// state garbled anywhere is refused rather than bred from.
#include <algorithm>
#include <cmath>
#include <string>
#include <string_view>

#include "runtime/evo/neat/neat.hpp"
#include "runtime/genome/graph/codec.hpp"

namespace esc::evo {

namespace gg = genome::graph;

namespace {

constexpr std::string_view kFormat = "esc-neat";
constexpr std::uint32_t kVersion = 1;
constexpr std::size_t kChecksumBytes = sizeof(std::uint64_t);

std::uint64_t fnv1a(std::span<const std::uint8_t> bytes) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (const std::uint8_t b : bytes) {
    h ^= b;
    h *= 0x100000001b3ULL;
  }
  return h;
}

// A best fitness: a finite number, or none yet.
bool record(double v) { return std::isfinite(v) || v == kNoRecord; }

[[noreturn]] void fail(const std::string& why) { throw std::invalid_argument("NEAT state: " + why); }

}  // namespace

StateBytes Neat::save() const {
  StateWriter w;
  w.put(std::string(kFormat));
  w.put(kVersion);
  w.put(static_cast<std::uint64_t>(inputs_));
  w.put(static_cast<std::uint64_t>(outputs_));
  w.put(static_cast<std::int32_t>(s_.population));
  w.put(breedings_);
  w.put(static_cast<std::int64_t>(next_innovation_));
  w.put(static_cast<std::int64_t>(next_node_));
  w.put(next_species_);
  w.put(threshold_);
  w.put(highest_);
  w.put(static_cast<std::int32_t>(highest_last_changed_));
  w.put(static_cast<std::uint64_t>(population_.size()));
  for (const gg::Graph& g : population_) w.put(std::span<const double>(gg::encode(g)));
  w.put(std::span<const double>(fitness_));
  w.put(static_cast<std::uint64_t>(species_.size()));
  for (const Species& sp : species_) {
    w.put(sp.id);
    w.put(static_cast<std::int32_t>(sp.age));
    w.put(static_cast<std::int32_t>(sp.last_improved));
    w.put(sp.best_ever);
    w.put(static_cast<std::uint8_t>(sp.novel));
    w.put(static_cast<std::uint64_t>(sp.members.size()));
    for (const std::size_t m : sp.members) w.put(static_cast<std::uint64_t>(m));
  }
  StateBytes bytes = std::move(w).take();
  const std::uint64_t sum = fnv1a(bytes);
  const auto* p = reinterpret_cast<const std::uint8_t*>(&sum);
  bytes.insert(bytes.end(), p, p + kChecksumBytes);
  return bytes;
}

void Neat::load(std::span<const std::uint8_t> state) {
  if (state.size() < kChecksumBytes) fail("truncated");
  const auto body = state.first(state.size() - kChecksumBytes);
  StateReader tail(state.last(kChecksumBytes));
  if (tail.get<std::uint64_t>() != fnv1a(body)) fail("the checksum does not match: the state is damaged");
  StateReader r(body);
  if (r.text() != kFormat) fail("not a NEAT state");
  if (const auto v = r.get<std::uint32_t>(); v != kVersion)
    fail("format version " + std::to_string(v) + ", expected 1");
  if (r.get<std::uint64_t>() != inputs_ || r.get<std::uint64_t>() != outputs_)
    fail("saved for other numbers of inputs or outputs");
  if (r.get<std::int32_t>() != s_.population) fail("saved for another population size");

  Neat next = *this;
  next.breedings_ = r.get<std::int64_t>();
  next.next_innovation_ = r.get<std::int64_t>();
  next.next_node_ = r.get<std::int64_t>();
  next.next_species_ = r.get<std::int64_t>();
  next.threshold_ = r.get<double>();
  next.highest_ = r.get<double>();
  next.highest_last_changed_ = r.get<std::int32_t>();
  if (next.breedings_ < 0 || next.highest_last_changed_ < 0 || !(next.threshold_ > 0.0) ||
      !std::isfinite(next.threshold_) || !record(next.highest_))
    fail("a counter or the threshold is out of range");

  const std::size_t members = r.count(sizeof(std::uint64_t));
  next.population_.assign(members, {});
  for (std::size_t i = 0; i < members; ++i) {
    const std::vector<double> genes = r.doubles();
    if (const std::string why = gg::decode(genes, next.population_[i]); !why.empty())
      fail("member " + std::to_string(i) + ": " + why);
    const gg::Graph& g = next.population_[i];
    if (gg::count_nodes(g, gg::NodeKind::Input) != inputs_ || gg::count_nodes(g, gg::NodeKind::Output) != outputs_)
      fail("member " + std::to_string(i) + " has other numbers of inputs or outputs");
    if (gg::next_innovation(g) > next.next_innovation_ || gg::next_node_id(g) > next.next_node_)
      fail("member " + std::to_string(i) + " has an innovation or node beyond the saved counters");
  }
  next.fitness_ = r.doubles();
  if (!next.fitness_.empty() && next.fitness_.size() != members) fail("fitness values do not match the members");
  for (const double f : next.fitness_)
    if (!std::isfinite(f)) fail("a fitness is not finite");

  const std::size_t species = r.count(1);
  next.species_.assign(species, {});
  std::vector<char> placed(members, 0);
  for (Species& sp : next.species_) {
    sp.id = r.get<std::int64_t>();
    sp.age = r.get<std::int32_t>();
    sp.last_improved = r.get<std::int32_t>();
    sp.best_ever = r.get<double>();
    const auto novel = r.get<std::uint8_t>();
    if (novel > 1) fail("a flag is neither 0 nor 1");
    sp.novel = novel == 1;
    sp.members.resize(r.count(sizeof(std::uint64_t)));
    for (std::size_t& m : sp.members) {
      const auto v = r.get<std::uint64_t>();
      if (v >= members || placed[v] != 0) fail("the species do not partition the population");
      placed[v] = 1;
      m = static_cast<std::size_t>(v);
    }
    if (sp.members.empty() || sp.id <= 0 || sp.id >= next.next_species_ || sp.age < 1 || sp.last_improved < 0 ||
        sp.last_improved > sp.age || !record(sp.best_ever))
      fail("species " + std::to_string(sp.id) + " is out of range");
  }
  if (std::find(placed.begin(), placed.end(), 0) != placed.end()) fail("the species do not partition the population");
  r.finish();
  *this = std::move(next);
}

}  // namespace esc::evo
