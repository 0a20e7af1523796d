#include "runtime/evo/registry.hpp"

#include <algorithm>

#include "runtime/evo/cmaes/cmaes_optimizer.hpp"
#include "runtime/evo/cmaes/cmaes_options.hpp"
#include "runtime/evo/es/es_optimizer.hpp"
#include "runtime/evo/gp/gp_optimizer.hpp"
#include "runtime/evo/map_elites/map_elites_optimizer.hpp"
#include "runtime/evo/map_elites/map_elites_options.hpp"
#include "runtime/evo/neat/neat_optimizer.hpp"
#include "runtime/evo/neat/neat_options.hpp"
#include "runtime/evo/novelty/novelty_optimizer.hpp"
#include "runtime/evo/novelty/novelty_options.hpp"
#include "runtime/evo/nsga2/nsga2_optimizer.hpp"
#include "runtime/evo/nsga2/nsga2_options.hpp"

namespace esc::evo {

namespace {

// The registry's signatures over an algorithm's own settings type.
template <class Settings, std::unique_ptr<Optimizer> (*Make)(const Settings&, const Problem&)>
std::unique_ptr<Optimizer> make(const std::any& settings, const Problem& problem) {
  return Make(std::any_cast<const Settings&>(settings), problem);
}
template <class Settings>
std::any defaults() {
  return Settings{};
}
std::any cvt_defaults() {
  MapElitesRunSettings s;
  s.cvt = true;
  return s;
}
// A function of the settings and the genome's size alone.
template <class Settings, class R, R (*F)(const Settings&, std::size_t)>
R of(const std::any& settings, const Problem& problem) {
  return F(std::any_cast<const Settings&>(settings), problem.genome_size);
}
// A function of the settings and the whole problem.
template <class Settings, class R, R (*F)(const Settings&, const Problem&)>
R on(const std::any& settings, const Problem& problem) {
  return F(std::any_cast<const Settings&>(settings), problem);
}
// A memory peak that does not depend on how long the run is.
template <class Settings, MemoryPeak (*F)(const Settings&, std::size_t)>
MemoryPeak peak_of(const std::any& settings, const Problem& problem, int /*generations*/) {
  return F(std::any_cast<const Settings&>(settings), problem.genome_size);
}
template <class Settings, MemoryPeak (*F)(const Settings&, const Problem&)>
MemoryPeak peak_on(const std::any& settings, const Problem& problem, int /*generations*/) {
  return F(std::any_cast<const Settings&>(settings), problem);
}
template <class Settings, MemoryPeak (*F)(const Settings&, const Problem&, int)>
MemoryPeak peak_over(const std::any& settings, const Problem& problem, int generations) {
  return F(std::any_cast<const Settings&>(settings), problem, generations);
}

}  // namespace

const std::vector<Algorithm>& algorithms() {
  using enum genome::GenomeKind;
  static const std::vector<Algorithm> table = {
      {"es", 1, {Vector}, &make<EsSettings, &make_es>, &of<EsSettings, std::size_t, &es_population>,
       &peak_of<EsSettings, &es_memory_peak>, "the ES"},
      {"gp", 1, {Tree}, &make<gp::GpSettings, &gp::make_gp>,
       &of<gp::GpSettings, std::size_t, &gp::gp_population>, &peak_of<gp::GpSettings, &gp::gp_memory_peak>, "GP"},
      {"cmaes", 1, {Vector}, &make<CmaesSettings, &make_cmaes>,
       &of<CmaesSettings, std::size_t, &cmaes_population>, &peak_of<CmaesSettings, &cmaes_memory_peak>, "CMA-ES",
       &cmaes_options, &defaults<CmaesSettings>, &of<CmaesSettings, std::string, &cmaes_problem>},
      {"nsga2", 1, {Vector, Tree}, &make<Nsga2Settings, &make_nsga2>, &on<Nsga2Settings, std::size_t, &nsga2_population>,
       &peak_on<Nsga2Settings, &nsga2_memory_peak>, "NSGA-II", &nsga2_options, &defaults<Nsga2Settings>,
       &on<Nsga2Settings, std::string, &nsga2_problem>},
      {"map_elites", 1, {Vector, Tree}, &make<MapElitesRunSettings, &make_map_elites>,
       &on<MapElitesRunSettings, std::size_t, &map_elites_population>,
       &peak_over<MapElitesRunSettings, &map_elites_memory_peak>, "MAP-Elites", &map_elites_options,
       &defaults<MapElitesRunSettings>, &on<MapElitesRunSettings, std::string, &map_elites_problem>},
      {"cvt_map_elites", 1, {Vector, Tree}, &make<MapElitesRunSettings, &make_map_elites>,
       &on<MapElitesRunSettings, std::size_t, &map_elites_population>,
       &peak_over<MapElitesRunSettings, &map_elites_memory_peak>, "CVT-MAP-Elites", &cvt_map_elites_options,
       &cvt_defaults, &on<MapElitesRunSettings, std::string, &map_elites_problem>},
      {"novelty", 1, {Vector, Tree}, &make<NoveltyRunSettings, &make_novelty>,
       &on<NoveltyRunSettings, std::size_t, &novelty_population>, &peak_on<NoveltyRunSettings, &novelty_memory_peak>,
       "novelty search", &novelty_options, &defaults<NoveltyRunSettings>,
       &on<NoveltyRunSettings, std::string, &novelty_problem>},
      {"neat", 1, {Graph}, &make<NeatSettings, &make_neat_run>, &on<NeatSettings, std::size_t, &neat_run_population>,
       &peak_on<NeatSettings, &neat_run_memory_peak>, "NEAT", &neat_options, &defaults<NeatSettings>,
       &on<NeatSettings, std::string, &neat_run_problem>},
  };
  return table;
}

const Algorithm* find_algorithm(std::string_view name) noexcept {
  const auto& all = algorithms();
  const auto it = std::find_if(all.begin(), all.end(), [&](const Algorithm& a) { return a.name == name; });
  return it == all.end() ? nullptr : &*it;
}

}  // namespace esc::evo
