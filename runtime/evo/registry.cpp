#include "runtime/evo/registry.hpp"

#include <algorithm>

#include "runtime/evo/es/es_optimizer.hpp"
#include "runtime/evo/gp/gp_optimizer.hpp"

namespace esc::evo {

namespace {

template <class Settings, std::unique_ptr<Optimizer> (*Make)(const Settings&, const Problem&)>
std::unique_ptr<Optimizer> make(const std::any& settings, const Problem& problem) {
  return Make(std::any_cast<const Settings&>(settings), problem);
}

}  // namespace

const std::vector<Algorithm>& algorithms() {
  static const std::vector<Algorithm> table = {
      {"es", 1, true, false, &make<EsSettings, &make_es>},
      {"gp", 1, false, true, &make<gp::GpSettings, &gp::make_gp>},
  };
  return table;
}

const Algorithm* find_algorithm(std::string_view name) noexcept {
  const auto& all = algorithms();
  const auto it = std::find_if(all.begin(), all.end(), [&](const Algorithm& a) { return a.name == name; });
  return it == all.end() ? nullptr : &*it;
}

}  // namespace esc::evo
