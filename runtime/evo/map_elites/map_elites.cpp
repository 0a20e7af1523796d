#include "runtime/evo/map_elites/map_elites.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "runtime/evo/limits.hpp"
#include "runtime/evo/map_elites/iso_line_dd.hpp"
#include "runtime/evo/map_elites/selection.hpp"

namespace esc::evo::qd {

namespace {

constexpr std::string_view kFormat = "esc-map-elites";
constexpr std::uint32_t kVersion = 1;

void require(bool ok, const std::string& message) {
  if (!ok) throw std::invalid_argument("MAP-Elites: " + message);
}

}  // namespace

MapElites::MapElites(const MapElitesSettings& settings, std::size_t genome_size, Archive archive)
    : s_(settings), n_(genome_size), archive_(std::move(archive)) {
  require(s_.batch >= 1 && s_.batch <= kMaxMapElitesBatch, "batch must be 1 to 1,000,000");
  require(s_.initial >= 1 && s_.initial <= kMaxMapElitesBatch, "initial must be 1 to 1,000,000");
  require(s_.sigma_iso >= 0.0 && s_.sigma_iso <= kMaxStepSize, "sigma_iso must be in [0, 1000]");
  require(s_.sigma_line >= 0.0 && s_.sigma_line <= kMaxStepSize, "sigma_line must be in [0, 1000]");
  require(std::abs(s_.lower) <= kMaxGeneBound, "lower must lie within +-1e6");
  require(std::abs(s_.upper) <= kMaxGeneBound && s_.lower < s_.upper, "upper must lie within +-1e6, above lower");
  require(n_ >= 1, "genome size must be at least 1");
  for (const std::size_t cell : archive_.filled_cells())
    require(archive_.elite(cell)->genome.size() == n_, "the archive holds a genome of another size");
}

void MapElites::start(std::span<const double> genome) {
  require(genome.size() == n_, "the start genome has " + std::to_string(genome.size()) + " values, not " + std::to_string(n_));
  for (const double v : genome) require(v >= s_.lower && v <= s_.upper, "the start genome lies outside [lower, upper]");
  first_.assign(genome.begin(), genome.end());
}

Genome MapElites::uniform(Rng& rng) const {
  Genome g(n_);
  for (double& v : g) v = rng.uniform(s_.lower, s_.upper);
  return g;
}

std::vector<Genome> MapElites::ask(Rng& rng) {
  std::vector<Genome> out;
  if (archive_.filled() == 0) {
    out.reserve(s_.initial);
    while (out.size() < s_.initial) out.push_back(uniform(rng));
  } else {
    const IsoLineDd op{s_.sigma_iso * (s_.upper - s_.lower), s_.sigma_line, s_.lower, s_.upper};
    out.reserve(s_.batch);
    while (out.size() < s_.batch) {
      const Elite& x = select_uniform(archive_, rng);
      const Elite& y = select_uniform(archive_, rng);
      out.push_back(iso_line_dd(x.genome, y.genome, op, rng));
    }
  }
  if (!first_.empty()) {
    out.front() = std::move(first_);
    first_.clear();
  }
  pending_ = out;
  asked_ = true;
  return out;
}

void MapElites::tell(std::span<const double> fitness, std::span<const std::vector<double>> descriptors) {
  if (!asked_) throw std::logic_error("MAP-Elites: tell without an ask");
  require(fitness.size() == pending_.size() && descriptors.size() == pending_.size(),
          std::to_string(pending_.size()) + " fitness values and descriptors expected");
  for (const auto& d : descriptors)
    require(d.size() == archive_.space().size() && std::all_of(d.begin(), d.end(), [](double v) { return std::isfinite(v); }),
            "every descriptor needs " + std::to_string(archive_.space().size()) + " finite numbers");
  for (std::size_t i = 0; i < pending_.size(); ++i) (void)archive_.insert(std::move(pending_[i]), fitness[i], descriptors[i]);
  pending_.clear();
  asked_ = false;
  ++generation_;
}

void MapElites::write(StateWriter& w) const {
  w.put(std::string(kFormat));
  w.put(kVersion);
  w.put(static_cast<std::uint64_t>(n_));
  w.put(static_cast<std::uint64_t>(s_.batch));
  w.put(static_cast<std::uint64_t>(s_.initial));
  w.put(s_.sigma_iso);
  w.put(s_.sigma_line);
  w.put(s_.lower);
  w.put(s_.upper);
  w.put(generation_);
  w.put(std::span<const double>(first_));
  archive_.write(w);
}

StateBytes MapElites::save() const {
  StateWriter w;
  write(w);
  return std::move(w).take();
}

void MapElites::load(std::span<const std::uint8_t> bytes) {
  StateReader r(bytes);
  const auto fail = [](const std::string& why) { throw std::invalid_argument("MAP-Elites state: " + why); };
  if (r.text() != kFormat) fail("not a MAP-Elites state");
  if (const auto v = r.get<std::uint32_t>(); v != kVersion) fail("format version " + std::to_string(v) + ", expected 1");
  if (const auto n = r.get<std::uint64_t>(); n != n_)
    fail("saved for a genome of " + std::to_string(n) + " values, this one has " + std::to_string(n_));
  if (r.get<std::uint64_t>() != s_.batch) fail("batch differs from the saved one");
  if (r.get<std::uint64_t>() != s_.initial) fail("initial differs from the saved one");
  if (r.get<double>() != s_.sigma_iso) fail("sigma_iso differs from the saved one");
  if (r.get<double>() != s_.sigma_line) fail("sigma_line differs from the saved one");
  if (r.get<double>() != s_.lower) fail("lower differs from the saved one");
  if (r.get<double>() != s_.upper) fail("upper differs from the saved one");
  const auto generation = r.get<std::uint64_t>();
  Genome first = r.doubles();
  if (!first.empty() && (first.size() != n_ || std::any_of(first.begin(), first.end(), [&](double v) {
                           return !(v >= s_.lower && v <= s_.upper);
                         })))
    fail("the start genome does not fit the genome size and box");
  Archive archive = archive_.read_like(r);
  r.finish();
  for (const std::size_t cell : archive.filled_cells())
    if (archive.elite(cell)->genome.size() != n_) fail("an elite has another genome size");
  generation_ = generation;
  first_ = std::move(first);
  archive_ = std::move(archive);
  pending_.clear();
  asked_ = false;
}

double map_elites_memory_bytes(const MapElitesSettings& settings, std::size_t genome_size, std::size_t cells,
                               std::size_t descriptors) {
  const double generation = 2.0 * static_cast<double>(std::max(settings.batch, settings.initial)) *
                            static_cast<double>(genome_size) * sizeof(double);
  return archive_memory_bytes(cells, genome_size, descriptors) + generation;
}

}  // namespace esc::evo::qd
