#include "compiler/algorithm_options.hpp"

#include "compiler/cmaes_options.hpp"
#include "compiler/option_table.hpp"
#include "compiler/table_lookup.hpp"

namespace esc::compiler {

namespace {

// A row's functions over an algorithm's option table (`Table`) and its own check (`Problem`).
template <class Settings, const std::vector<OptionRow<Settings>>& (*Table)(),
          std::string (*Problem)(const Settings&, std::size_t)>
struct Rows {
  static std::any defaults() { return Settings{}; }
  static void lower(const ast::ExpItem& item, std::any& settings, Sink& sink, std::string_view method,
                    std::string_view what) {
    ast::ExpItem options = item;
    options.generations.reset();
    read_options(options, method, what, Table(), std::any_cast<Settings&>(settings), sink);
  }
  static bool has_key(std::string_view key) { return find_option_key(Table(), key) != nullptr; }
  static bool set(std::any& settings, std::string_view key, const ast::Value& value, Sink& sink) {
    const OptionRow<Settings>* o = find_option_key(Table(), key);
    return o->read(*o, std::any_cast<Settings&>(settings), value, sink);
  }
  static std::vector<std::string> keys() { return option_keys(Table()); }
  static bool takes_range(std::string_view key) {
    const OptionRow<Settings>* o = find_option_key(Table(), key);
    return o != nullptr && o->shape == OptionShape::Range;
  }
  static void resolve(const std::any& settings, std::map<std::string, std::string>& resolved, std::string_view name) {
    const auto& s = std::any_cast<const Settings&>(settings);
    for (const OptionRow<Settings>& o : Table()) resolved[std::string(name) + "." + std::string(o.key)] = o.text(o, s);
  }
  static std::string problem(const std::any& settings, std::size_t genome_size) {
    return Problem(std::any_cast<const Settings&>(settings), genome_size);
  }
};

using Cmaes = Rows<evo::CmaesSettings, &cmaes_options, &cmaes_problem>;

}  // namespace

const std::vector<AlgorithmOptions>& further_algorithms() {
  static const std::vector<AlgorithmOptions> table = {
      {"cmaes", "CMA-ES", &Cmaes::defaults,
       [](const ast::ExpItem& i, std::any& s, Sink& k) { Cmaes::lower(i, s, k, "cmaes", "CMA-ES"); }, &Cmaes::has_key,
       &Cmaes::set, &Cmaes::keys, &Cmaes::takes_range,
       [](const std::any& s, std::map<std::string, std::string>& r) { Cmaes::resolve(s, r, "cmaes"); },
       &Cmaes::problem},
  };
  return table;
}

const AlgorithmOptions* find_further_algorithm(std::string_view name) {
  return find_row(further_algorithms(), &AlgorithmOptions::name, name);
}

}  // namespace esc::compiler
