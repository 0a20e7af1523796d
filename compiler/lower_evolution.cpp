#include "compiler/lower_evolution.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "compiler/algorithm_options.hpp"
#include "compiler/names.hpp"
#include "compiler/setting_values.hpp"
#include "runtime/evo/registry.hpp"

namespace esc::compiler {

namespace {

using X = eval::ExperimentSpec;


std::string kind_of(const control::ControllerSpec& c) {
  return c.is_tree() ? "a tree controller" : c.is_graph() ? "a NEAT network" : "a network";
}

// "networks are", for the help that names the algorithms of c's kind.
std::string kind_plural(const control::ControllerSpec& c) {
  return c.is_tree() ? "trees are" : c.is_graph() ? "NEAT networks are" : "networks are";
}

// The algorithm that evolves x.controllers[i] now that `by` and `networks` are set.
std::string algorithm_of(const X& x, std::size_t i) {
  const evo::Algorithm* a = x.evolution_of(x.controllers[i]).algorithm;
  return a != nullptr ? std::string(a->name) : std::string();
}

}  // namespace

std::vector<std::string> algorithms_for(genome::GenomeKind kind) {
  std::vector<std::string> v;
  for (const evo::Algorithm& a : evo::algorithms())
    if (a.kinds.has(kind)) v.emplace_back(a.name);
  return v;
}

genome::GenomeKind genome_kind(const control::ControllerSpec& c) noexcept {
  return c.is_tree() ? genome::GenomeKind::Tree : c.is_graph() ? genome::GenomeKind::Graph : genome::GenomeKind::Vector;
}

// Whether `name` evolves a compared controller, or (NEAT) gives the operators that vary a
// NEAT network another algorithm selects, as `evolve gp` does for trees.
bool in_use(const X& x, std::string_view name) {
  if (x.evaluates_only()) return false;
  for (const control::ControllerSpec& c : x.controllers) {
    const evo::Algorithm* a = x.evolution_of(c).algorithm;
    if (a != nullptr && a->name == name) return true;
    if (c.is_graph() && name == X::kGraphOperators) return true;
  }
  return false;
}

std::vector<std::string> algorithm_names() {
  std::vector<std::string> v;
  for (const evo::Algorithm& a : evo::algorithms()) v.emplace_back(a.name);
  return v;
}

bool is_algorithm_evolve(const ast::ExpItem& item) {
  return item.kind == ast::ExpItem::Kind::Evolve && !item.refs.empty() &&
         find_algorithm_options(item.refs[0].text) != nullptr;
}

void lower_evolve(const ast::ExpItem& item, X& x, EvolveItems& items, Sink& sink) {
  const std::string& name = item.refs[0].text;
  if (const ast::ExpItem* first = items.of(name)) {
    sink.error(item.where, fmt::format("`evolve {}` is already given in this experiment", name))
        .notes.emplace_back(first->where, "first given here");
    return;
  }
  items.given.emplace(name, &item);
  items.order.push_back(name);
  find_algorithm_options(name)->lower(item, x, sink);
}

void choose_algorithms(const ast::ExperimentDecl& d, X& x, const std::vector<const ast::Name*>& compared,
                       const std::vector<const ast::Name*>& by, const EvolveItems& items, Sink& sink) {
  // Networks compared without `by`: the default's (the ES), unless the experiment names
  // another algorithm for networks and not the default.
  if (items.of(x.networks) == nullptr)
    for (const std::string& name : items.order)
      if (evo::find_algorithm(name)->kinds.has(genome::GenomeKind::Vector)) {
        x.networks = name;
        break;
      }
  for (std::size_t i = 0; i < x.controllers.size() && i < by.size(); ++i) {
    const ast::Name& name = *by[i];
    if (name.text.empty()) continue;
    const control::ControllerSpec& c = x.controllers[i];
    const evo::Algorithm* a = evo::find_algorithm(name.text);
    if (a == nullptr) {
      suggest(sink.error(name.where, fmt::format("unknown algorithm `{}`", name.text)), name.text, algorithm_names(),
              {.otherwise = fmt::format("algorithms: {}", quoted_list(algorithm_names()))});
      continue;
    }
    if (!a->kinds.has(genome_kind(c))) {
      sink.error(name.where, fmt::format("`{}` cannot evolve `{}`: it is {}", name.text, c.name, kind_of(c)))
          .help.push_back(fmt::format("{} evolved by {}", kind_plural(c), quoted_list(algorithms_for(genome_kind(c)))));
      continue;
    }
    x.controllers[i].evolved_by = name.text;
  }
  // The experiment's generations, given once, by one algorithm's `evolve` (GP's are its own:
  // the trees').
  const auto generations_of = [](const ast::ExpItem* item) -> const SourceRange* {
    if (item == nullptr) return nullptr;
    if (item->generations) return &item->generations->where;
    for (const ast::EsOption& o : item->options)
      if (o.name.text == "generations") return &o.where;
    return nullptr;
  };
  const SourceRange* first = nullptr;
  for (const std::string& name : items.order) {
    if (find_algorithm_options(name)->has_key("generations")) continue;
    const SourceRange* here = generations_of(items.of(name));
    if (here == nullptr) continue;
    if (first == nullptr) {
      first = here;
      continue;
    }
    sink.error(*here, "the experiment's number of generations is already given")
        .notes.emplace_back(*first, "first given here");
  }
  if (x.evaluates_only()) return;
  // Those generations are the networks'; trees, whatever selects them, run for the GP's.
  bool any_network = false;
  for (const control::ControllerSpec& c : x.controllers)
    any_network = any_network || genome_kind(c) == genome::GenomeKind::Vector;
  const ast::ExpItem* operators = items.of(X::kTreeOperators);
  if (first != nullptr && !any_network && operators != nullptr && !x.controllers.empty())
    sink.error(*first, fmt::format("these generations are the networks', and experiment `{}` compares only trees",
                                   d.name.text))
        .help.push_back("trees run for the GP's generations: `evolve gp(...) for N generations`");
  // Every algorithm in use has its settings (its defaults when no `evolve` gives them), but
  // GP, whose settings only the script gives (a tree without them is reported below); an
  // `evolve` of an algorithm held only where it is used that evolves none of the compared
  // controllers is a mistake (the ES's settings are in every experiment, GP's vary every tree).
  for (std::size_t i = 0; i < x.controllers.size(); ++i) {
    const AlgorithmOptions* o = find_algorithm_options(algorithm_of(x, i));
    if (o != nullptr && o->scope != evo::SettingsScope::Given) o->settings_in(x);
  }
  for (const std::string& name : items.order) {
    if (find_algorithm_options(name)->scope != evo::SettingsScope::InUse || in_use(x, name)) continue;
    const ast::ExpItem& item = *items.of(name);
    const evo::Algorithm& a = *evo::find_algorithm(name);
    Diagnostic& diag = sink.error(item.refs[0].where, fmt::format("`evolve {}` evolves none of the controllers "
                                                                  "experiment `{}` compares", name, d.name.text));
    const bool fits_one = std::any_of(x.controllers.begin(), x.controllers.end(),
                                      [&](const control::ControllerSpec& c) { return a.kinds.has(genome_kind(c)); });
    if (a.kinds == genome::GenomeKinds{genome::GenomeKind::Graph} && !fits_one)
      diag.help.push_back(fmt::format("`{}` evolves NEAT networks only: declare one with `neat(...)`, such as "
                                      "`controller N = neat(ir[0..7] -> wheels)`", name));
    else if (a.kinds == genome::GenomeKinds{genome::GenomeKind::Vector} && !any_network)
      diag.help.push_back(fmt::format("`{}` evolves networks; the compared controllers are trees, evolved by {}", name,
                                      quoted_list(algorithms_for(genome::GenomeKind::Tree))));
    else
      diag.help.push_back(fmt::format("name it for a controller in `compare`: `CONTROLLER by {}`", name));
  }
  for (std::size_t i = 0; i < x.controllers.size() && i < compared.size(); ++i) {
    const control::ControllerSpec& c = x.controllers[i];
    const std::string a = algorithm_of(x, i);
    if (c.is_tree() && a == X::kTreeOperators && operators == nullptr) {
      sink.error(compared[i]->where, fmt::format("`{}` is a tree controller, but experiment `{}` has no "
                                                 "`evolve gp(...)` to evolve it", c.name, d.name.text))
          .help.push_back("add `evolve gp(population 150, tournament 7) for 50 generations`");
    } else if (c.is_tree() && operators == nullptr) {
      // Every algorithm varies trees with the GP's operators (runtime/genome/tree/tree_variation.hpp).
      sink.error(compared[i]->where, fmt::format("`{}` is a tree controller evolved by `{}`, but experiment `{}` has no "
                                                 "`evolve gp(...)` to give its tree operators", c.name, a, d.name.text))
          .help.push_back(fmt::format("add `evolve gp(max_depth 12, max_size 100) for 50 generations`: `{}` selects, "
                                      "the GP's crossover and mutations vary, for the GP's generations", a));
    } else if (genome_kind(c) == genome::GenomeKind::Vector && a == X::kDefaultNetworks && operators != nullptr &&
               items.of(X::kDefaultNetworks) == nullptr) {
      sink.error(compared[i]->where, fmt::format("`{}` is a network, but experiment `{}` only evolves trees "
                                                 "(`evolve gp`)", c.name, d.name.text))
          .help.push_back("networks are evolved by the ES: add `evolve es(mu 30, lambda 150) for 250 generations`");
    }
  }
  if (operators != nullptr)
    if (std::string m = check_tree_operators(x); !m.empty()) sink.error(operators->where, m);
  for (const auto& [name, item] : items.given) check_algorithm_settings(x, item->where, sink, name);
}

void check_algorithm_settings(const X& x, const SourceRange& where, Sink& sink, std::string_view algorithm) {
  for (std::size_t i = 0; i < x.controllers.size(); ++i) {
    const std::string a = algorithm_of(x, i);
    if ((!algorithm.empty() && a != algorithm) || a == X::kTreeOperators) continue;
    const AlgorithmOptions* o = find_algorithm_options(a);
    const std::any* s = o != nullptr ? o->held_by(x) : nullptr;
    if (s == nullptr) continue;
    // A tree without `evolve gp` is reported at its name in `compare` (choose_algorithms).
    if (x.controllers[i].is_tree() && x.tree_operators() == nullptr) continue;
    if (std::string m = o->problem(*s, x.problem_of(x.controllers[i])); !m.empty()) {
      sink.error(where, fmt::format("impossible {} settings for `{}`: {}", o->what, x.controllers[i].name, m));
      return;
    }
  }
}

std::string check_tree_operators(const X& x) {
  const AlgorithmOptions& gp = *find_algorithm_options(X::kTreeOperators);
  const std::any* s = gp.held_by(x);
  if (s == nullptr) return {};
  bool any_tree = false;
  for (const control::ControllerSpec& c : x.controllers) {
    if (!c.is_tree()) continue;
    any_tree = true;
    if (std::string m = gp.problem(*s, x.problem_of(c)); !m.empty())
      return fmt::format("impossible {} settings for tree controller `{}`: {}", gp.what, c.name, m);
  }
  if (std::string m = any_tree ? std::string() : gp.problem(*s, evo::Problem{}); !m.empty())
    return fmt::format("impossible {} settings: {}", gp.what, m);
  return {};
}

}  // namespace esc::compiler
