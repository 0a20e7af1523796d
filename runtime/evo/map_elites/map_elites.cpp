#include "runtime/evo/map_elites/map_elites.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "runtime/genome/vector/box.hpp"
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

MapElitesGenomes iso_line_dd_genomes(const MapElitesSettings& s, std::size_t n) {
  const IsoLineDd op{s.sigma_iso * (s.upper - s.lower), s.sigma_line, s.lower, s.upper};
  return {std::make_shared<genome::Box>(n, s.lower, s.upper), [op](const Archive& archive, Rng& rng) {
            const Elite& x = select_uniform(archive, rng);
            const Elite& y = select_uniform(archive, rng);
            return iso_line_dd(x.genome, y.genome, op, rng);
          }};
}

}  // namespace

MapElites::MapElites(const MapElitesSettings& settings, std::size_t genome_size, Archive archive)
    : MapElites(settings, iso_line_dd_genomes(settings, genome_size), std::move(archive)) {
  require(n_ >= 1, "genome size must be at least 1");
}

MapElites::MapElites(const MapElitesSettings& settings, MapElitesGenomes genomes, Archive archive)
    : s_(settings), g_(std::move(genomes)), n_(g_.representation->genes()), archive_(std::move(archive)) {
  require(s_.batch >= 1 && s_.batch <= kMaxMapElitesBatch, "batch must be 1 to 1,000,000");
  require(s_.initial >= 1 && s_.initial <= kMaxMapElitesBatch, "initial must be 1 to 1,000,000");
  require(s_.sigma_iso >= 0.0 && s_.sigma_iso <= kMaxStepSize, "sigma_iso must be in [0, 1000]");
  require(s_.sigma_line >= 0.0 && s_.sigma_line <= kMaxStepSize, "sigma_line must be in [0, 1000]");
  require(std::abs(s_.lower) <= kMaxGeneBound, "lower must lie within +-1e6");
  require(std::abs(s_.upper) <= kMaxGeneBound && s_.lower < s_.upper, "upper must lie within +-1e6, above lower");
  if (const std::string why = misfit_elite(archive_); !why.empty()) require(false, "the archive holds " + why);
}

std::string MapElites::misfit_elite(const Archive& archive) const {
  for (const std::size_t cell : archive.filled_cells())
    if (std::string why = g_.representation->misfit(archive.elite(cell)->genome); !why.empty()) return why;
  return {};
}

void MapElites::start(std::span<const double> genome) {
  const std::string why = g_.representation->misfit(genome);
  require(why.empty(), "the start genome: " + why);
  first_.assign(genome.begin(), genome.end());
}

std::vector<Genome> MapElites::ask(Rng& rng) {
  std::vector<Genome> out;
  if (archive_.filled() == 0) {
    out = g_.representation->first(s_.initial, rng);
  } else {
    out.reserve(s_.batch);
    if (g_.begin) g_.begin(archive_);
    while (out.size() < s_.batch) out.push_back(g_.child(archive_, rng));
  }
  if (!first_.empty()) {
    out.front() = std::move(first_);
    first_.clear();
  }
  pending_ = out;
  asked_ = true;
  return out;
}

std::vector<InsertResult> MapElites::tell(std::span<const double> fitness,
                                          std::span<const std::vector<double>> descriptors) {
  if (!asked_) throw std::logic_error("MAP-Elites: tell without an ask");
  require(fitness.size() == pending_.size() && descriptors.size() == pending_.size(),
          std::to_string(pending_.size()) + " fitness values and descriptors expected");
  for (const auto& d : descriptors)
    require(d.size() == archive_.space().size() && std::all_of(d.begin(), d.end(), [](double v) { return std::isfinite(v); }),
            "every descriptor needs " + std::to_string(archive_.space().size()) + " finite numbers");
  std::vector<InsertResult> results;
  results.reserve(pending_.size());
  for (std::size_t i = 0; i < pending_.size(); ++i)
    results.push_back(archive_.insert(std::move(pending_[i]), fitness[i], descriptors[i]));
  pending_.clear();
  asked_ = false;
  ++generation_;
  return results;
}

void MapElites::write(StateWriter& w) const {
  w.put(std::string(kFormat) + std::string(g_.representation->tag()));
  w.put(kVersion);
  w.put(static_cast<std::uint64_t>(n_));
  w.put(static_cast<std::uint64_t>(s_.batch));
  w.put(static_cast<std::uint64_t>(s_.initial));
  w.put(s_.sigma_iso);
  w.put(s_.sigma_line);
  put_fixed(w, *g_.representation);
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
  if (const std::string why = format_mismatch(r.text(), kFormat, "a MAP-Elites", *g_.representation); !why.empty())
    fail(why);
  if (const auto v = r.get<std::uint32_t>(); v != kVersion) fail("format version " + std::to_string(v) + ", expected 1");
  if (const auto n = r.get<std::uint64_t>(); n != n_)
    fail("saved for a genome of " + std::to_string(n) + " values, this one has " + std::to_string(n_));
  if (r.get<std::uint64_t>() != s_.batch) fail("batch differs from the saved one");
  if (r.get<std::uint64_t>() != s_.initial) fail("initial differs from the saved one");
  if (r.get<double>() != s_.sigma_iso) fail("sigma_iso differs from the saved one");
  if (r.get<double>() != s_.sigma_line) fail("sigma_line differs from the saved one");
  if (const std::string why = fixed_differs(r, *g_.representation); !why.empty()) fail(why);
  const auto generation = r.get<std::uint64_t>();
  Genome first = r.doubles();
  if (!first.empty())
    if (const std::string why = g_.representation->misfit(first); !why.empty()) fail("the start genome: " + why);
  Archive archive = archive_.read_like(r);
  r.finish();
  if (const std::string why = misfit_elite(archive); !why.empty()) fail("an elite: " + why);
  generation_ = generation;
  first_ = std::move(first);
  archive_ = std::move(archive);
  pending_.clear();
  asked_ = false;
}

double map_elites_memory_bytes(const MapElitesSettings& settings, std::size_t genome_size, std::size_t cells,
                               std::size_t descriptors, double filled, bool cvt) {
  const double candidates = static_cast<double>(std::max(settings.batch, settings.initial));
  const double generation = rows_bytes(2.0 * candidates, static_cast<double>(genome_size)) +
                            rows_bytes(candidates, static_cast<double>(descriptors));
  return archive_memory_bytes(cells, genome_size, descriptors, filled, cvt) + generation;
}

}  // namespace esc::evo::qd
