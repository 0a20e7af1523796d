#include "runtime/evo/nsga2/nsga2.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <string_view>

#include "runtime/genome/vector/box.hpp"
#include "runtime/evo/limits.hpp"
#include "runtime/evo/nsga2/variation.hpp"

namespace esc::evo {

namespace {

constexpr std::string_view kFormat = "esc-nsga2";
constexpr std::uint32_t kVersion = 1;

void require(bool ok, const std::string& message) {
  if (!ok) throw std::invalid_argument("NSGA-II: " + message);
}

std::string text(double v) { return std::to_string(v); }
std::string text(std::size_t v) { return std::to_string(v); }

void put_rows(StateWriter& w, const std::vector<std::vector<double>>& rows) {
  w.put(static_cast<std::uint64_t>(rows.size()));
  for (const auto& row : rows) w.put(std::span<const double>(row));
}

std::vector<std::vector<double>> get_rows(StateReader& r) {
  std::vector<std::vector<double>> rows(r.count(sizeof(std::uint64_t)));  // each row holds its length at least
  for (auto& row : rows) row = r.doubles();
  return rows;
}

}  // namespace

void check_nsga2_settings(const Nsga2Settings& s) {
  require(s.population >= 2 && s.population <= kNsga2MaxPopulation && s.population % 2 == 0,
          "population must be even, in [2, " + std::to_string(kNsga2MaxPopulation) + "], got " +
              std::to_string(s.population));
  require(s.crossover >= 0.0 && s.crossover <= 1.0, "crossover must be a probability in [0, 1], got " + text(s.crossover));
  require(std::isfinite(s.eta_crossover) && s.eta_crossover >= 0.0,
          "eta_crossover must be a finite number >= 0, got " + text(s.eta_crossover));
  require(std::isfinite(s.eta_mutation) && s.eta_mutation >= 0.0,
          "eta_mutation must be a finite number >= 0, got " + text(s.eta_mutation));
  require(s.mutation >= 0.0 && s.mutation <= 1.0,
          "mutation must be a probability in [0, 1] (0: 1 / n), got " + text(s.mutation));
  require(std::abs(s.lower) <= kMaxGeneBound && std::abs(s.upper) <= kMaxGeneBound && s.lower < s.upper,
          "lower (" + text(s.lower) + ") must be below upper (" + text(s.upper) + "), both within +-1e6");
}

double nsga2_memory_bytes(const Nsga2Settings& settings, std::size_t n, std::size_t objectives) {
  const double big_n = static_cast<double>(settings.population);
  const double genes = static_cast<double>(n), m = static_cast<double>(objectives);
  const double saved = big_n * (genes + m + 3.0) * sizeof(double);   // parents, objectives, crowding
  // The tell: parents, children and candidates handed out, their objectives (the caller's
  // copy too), the merged rows, and per point of 2 N its rank, crowding, front, the sort's
  // orders and the selection's, beside the last generation's saved state.
  const double telling = rows_bytes(3.0 * big_n, genes) + rows_bytes(3.0 * big_n, m) + 2.0 * big_n * sizeof(Genome) +
                         2.0 * big_n * 7.0 * sizeof(double) + saved;
  // Saving after it: the parents and the candidates still handed out, the parents' objectives,
  // the core's state and the run's state around it, which holds its old block and the new
  // one, twice as large, as it grows past the core's, while the run still holds the last
  // generation's (as heaptrack shows them at the peak).
  const double run_state = writer_bytes(saved + 2.0 * big_n * sizeof(double));
  const double saving = rows_bytes(2.0 * big_n, genes) + rows_bytes(big_n, m) + writer_bytes(saved) + 2.5 * run_state;
  return std::max(telling, saving);
}

Nsga2Genomes box_genomes(const Nsga2Settings& s, std::size_t n) {
  const double p_mutation = s.mutation > 0.0 ? s.mutation : 1.0 / static_cast<double>(n);
  return {std::make_shared<genome::Box>(n, s.lower, s.upper), [s, p_mutation](Genome& a, Genome& b, Rng& rng) {
            if (rng.uniform() < s.crossover) simulated_binary_crossover(a, b, s.eta_crossover, s.lower, s.upper, rng);
            polynomial_mutation(a, s.eta_mutation, p_mutation, s.lower, s.upper, rng);
            polynomial_mutation(b, s.eta_mutation, p_mutation, s.lower, s.upper, rng);
          }};
}

Nsga2::Nsga2(const Nsga2Settings& settings, std::size_t n) : s_(settings), n_(n) {
  check_nsga2_settings(s_);
  require(n_ >= 1, "the number of genes n must be at least 1, got 0");
  g_ = box_genomes(s_, n_);
}

Nsga2::Nsga2(const Nsga2Settings& settings, Nsga2Genomes genomes)
    : s_(settings), g_(std::move(genomes)), n_(g_.representation->genes()) {
  check_nsga2_settings(s_);
}

double Nsga2::mutation_probability() const noexcept {
  return s_.mutation > 0.0 ? s_.mutation : 1.0 / static_cast<double>(n_);
}

void Nsga2::start(Rng& rng) {
  std::vector<std::vector<double>> first = g_.representation->first(population_size(), rng);
  *this = Nsga2(s_, g_);
  initial_ = std::move(first);
  started_ = true;
}

void Nsga2::start(std::span<const double> point) {
  const std::string why = g_.representation->misfit(point);
  require(why.empty(), "the start point: " + why);
  *this = Nsga2(s_, g_);
  initial_.emplace_back(point.begin(), point.end());
  started_ = true;
}

std::vector<std::vector<double>> Nsga2::ask(Rng& rng) {
  if (!started_) throw std::logic_error("NSGA-II: ask before start");
  const std::size_t big_n = population_size();
  if (generation_ == 0) {
    children_ = initial_;
    for (auto& x : g_.representation->first(big_n - children_.size(), rng)) children_.push_back(std::move(x));
  } else {
    const std::vector<std::size_t> winners = crowded_tournament_winners(ranking_, rng);
    if (g_.begin) g_.begin(parents_);
    children_.clear();
    for (std::size_t t = 0; t < big_n; t += 2) {
      std::vector<double> a = parents_[winners[t]];
      std::vector<double> b = parents_[winners[t + 1]];
      g_.vary(a, b, rng);
      children_.push_back(std::move(a));
      children_.push_back(std::move(b));
    }
  }
  asked_ = true;
  return children_;
}

void Nsga2::rescore(std::span<const std::vector<double>> parents) {
  require(parents.size() == parents_.size(), "rescore needs the objectives of " + text(parents_.size()) +
                                                 " parents, got " + text(parents.size()));
  for (const auto& row : parents)
    require(row.size() == objective_count_, "every parent needs " + text(objective_count_) + " objectives, got " +
                                                text(row.size()));
  objectives_.assign(parents.begin(), parents.end());
}

std::vector<std::size_t> Nsga2::tell(std::span<const std::vector<double>> objectives) {
  if (!asked_) throw std::logic_error("NSGA-II: tell without a pending ask");
  require(objectives.size() == children_.size(), "tell needs the objectives of " + text(children_.size()) +
                                                     " candidates (the population), got " + text(objectives.size()));
  const std::size_t m = objective_count_ > 0 ? objective_count_ : objectives.front().size();
  for (const auto& row : objectives)
    if (row.size() != m || m == 0)
      require(false, "every candidate needs the same number of objectives, at least 1 (" + text(m) +
                         (objective_count_ > 0 ? ", as told before" : "") + "), got " + text(row.size()));

  // The first generation becomes the parents; later, parents and children compete.
  std::vector<std::vector<double>> merged = std::move(parents_);
  ObjectiveRows merged_f = std::move(objectives_);
  for (auto& x : children_) merged.push_back(std::move(x));
  merged_f.insert(merged_f.end(), objectives.begin(), objectives.end());
  const Ranking ranking = rank_and_crowd(merged_f);
  const std::vector<std::size_t> kept = select_survivors(ranking, population_size());

  parents_.clear();
  objectives_.clear();
  ranking_ = Ranking{};
  for (const std::size_t i : kept) {
    parents_.push_back(std::move(merged[i]));
    objectives_.push_back(std::move(merged_f[i]));
    ranking_.rank.push_back(ranking.rank[i]);
    ranking_.crowding.push_back(ranking.crowding[i]);
  }
  children_.clear();
  initial_.clear();
  asked_ = false;
  objective_count_ = m;
  ++generation_;
  return kept;
}

std::vector<std::size_t> Nsga2::first_front() const {
  std::vector<std::size_t> front;
  for (std::size_t i = 0; i < ranking_.rank.size(); ++i)
    if (ranking_.rank[i] == 0) front.push_back(i);
  return front;
}

StateBytes Nsga2::save() const {
  StateWriter w;
  w.put(std::string(kFormat) + std::string(g_.representation->tag()));
  w.put(kVersion);
  w.put(static_cast<std::uint64_t>(n_));
  w.put(static_cast<std::int32_t>(s_.population));
  put_fixed(w, *g_.representation);
  w.put(static_cast<std::uint8_t>(started_));
  w.put(generation_);
  w.put(static_cast<std::uint64_t>(objective_count_));
  put_rows(w, initial_);
  put_rows(w, parents_);
  put_rows(w, objectives_);
  w.put(std::span<const double>(ranking_.crowding));
  return std::move(w).take();
}

void Nsga2::load(std::span<const std::uint8_t> bytes) {
  StateReader r(bytes);
  const auto fail = [](const std::string& why) { throw std::invalid_argument("NSGA-II state: " + why); };
  if (const std::string why = format_mismatch(r.text(), kFormat, "an NSGA-II", *g_.representation); !why.empty())
    fail(why);
  if (const auto v = r.get<std::uint32_t>(); v != kVersion) fail("format version " + std::to_string(v) + ", expected 1");
  if (const auto n = r.get<std::uint64_t>(); n != n_)
    fail("saved for n = " + std::to_string(n) + ", this optimizer has n = " + text(n_));
  if (const auto p = r.get<std::int32_t>(); p != s_.population)
    fail("saved for a population of " + std::to_string(p) + ", this optimizer has " + std::to_string(s_.population));
  if (const std::string why = fixed_differs(r, *g_.representation); !why.empty()) fail(why);

  Nsga2 next(s_, g_);
  const auto started = r.get<std::uint8_t>();
  if (started > 1) fail("a flag is neither 0 nor 1");
  next.started_ = started == 1;
  next.generation_ = r.get<std::uint64_t>();
  next.objective_count_ = static_cast<std::size_t>(r.get<std::uint64_t>());
  next.initial_ = get_rows(r);
  next.parents_ = get_rows(r);
  next.objectives_ = get_rows(r);
  next.ranking_.crowding = r.doubles();
  r.finish();

  const std::size_t big_n = population_size();
  const bool told = next.generation_ > 0;
  if (!next.started_ && (told || !next.initial_.empty())) fail("a state before start holds a population");
  if (next.started_ && !told && next.initial_.size() != 1 && next.initial_.size() != big_n)
    fail("the first candidates are neither a start point nor a population");
  if (told && !next.initial_.empty()) fail("first candidates after the first generation");
  if (next.parents_.size() != (told ? big_n : 0) || next.objectives_.size() != next.parents_.size() ||
      next.ranking_.crowding.size() != next.parents_.size())
    fail("the population, its objectives and crowding distances do not match the population size " + text(big_n));
  if (told != (next.objective_count_ > 0)) fail("the number of objectives does not match the generation");
  for (const auto* rows : {&next.initial_, &next.parents_})
    for (const auto& x : *rows)
      if (const std::string why = g_.representation->misfit(x); !why.empty()) fail("a candidate: " + why);
  for (const auto& f : next.objectives_)
    if (f.size() != next.objective_count_) fail("a point with another number of objectives");
  for (const double d : next.ranking_.crowding)
    if (!(d >= 0.0)) fail("a crowding distance that is NaN or negative");

  // The ranks follow from the objectives: the survivors of whole fronts keep their fronts.
  next.ranking_.rank.assign(next.parents_.size(), 0);
  const auto fronts = nondominated_fronts(next.objectives_);
  for (std::size_t k = 0; k < fronts.size(); ++k)
    for (const std::size_t i : fronts[k]) next.ranking_.rank[i] = k;
  *this = std::move(next);
}

}  // namespace esc::evo
