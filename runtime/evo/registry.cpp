#include "runtime/evo/registry.hpp"

#include <algorithm>

#include "runtime/evo/cmaes/cmaes_optimizer.hpp"
#include "runtime/evo/cmaes/cmaes_options.hpp"
#include "runtime/evo/es/es_optimizer.hpp"
#include "runtime/evo/gp/gp_optimizer.hpp"

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
template <class Settings, class R, R (*F)(const Settings&, std::size_t)>
R of(const std::any& settings, std::size_t genome_size) {
  return F(std::any_cast<const Settings&>(settings), genome_size);
}

}  // namespace

const std::vector<Algorithm>& algorithms() {
  static const std::vector<Algorithm> table = {
      {"es", 1, true, false, &make<EsSettings, &make_es>, &of<EsSettings, std::size_t, &es_population>,
       &of<EsSettings, double, &es_memory_bytes>},
      {"gp", 1, false, true, &make<gp::GpSettings, &gp::make_gp>,
       &of<gp::GpSettings, std::size_t, &gp::gp_population>, &of<gp::GpSettings, double, &gp::gp_memory_bytes>},
      {"cmaes", 1, true, false, &make<CmaesSettings, &make_cmaes>,
       &of<CmaesSettings, std::size_t, &cmaes_population>, &of<CmaesSettings, double, &cmaes_memory_bytes>, "CMA-ES",
       &cmaes_options, &defaults<CmaesSettings>, &cmaes_problem},
  };
  return table;
}

const Algorithm* find_algorithm(std::string_view name) noexcept {
  const auto& all = algorithms();
  const auto it = std::find_if(all.begin(), all.end(), [&](const Algorithm& a) { return a.name == name; });
  return it == all.end() ? nullptr : &*it;
}

}  // namespace esc::evo
