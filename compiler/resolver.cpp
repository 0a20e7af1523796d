#include "compiler/resolver.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "compiler/names.hpp"
#include "compiler/robot_settings.hpp"

namespace esc::compiler {

namespace {

// In the order of Decl's alternatives.
constexpr std::string_view kKindNames[] = {"arena",      "robot",      "behavior", "fitness",      "controller",
                                           "experiment", "library",    "primitive set", "study"};
static_assert(std::size(kKindNames) == std::variant_size_v<Decl>);

std::string article(std::string_view kind) {
  const bool vowel = !kind.empty() && std::string_view("aeiou").find(kind[0]) != std::string_view::npos;
  return std::string(vowel ? "an " : "a ") + std::string(kind);
}

}  // namespace

std::string_view kind_name(const Decl& d) noexcept { return kKindNames[d.index()]; }

const ast::DeclHead& head(const Decl& d) noexcept {
  return *std::visit([](const auto* p) -> const ast::DeclHead* { return p; }, d);
}

void Resolver::add(const Decl& d) {
  const ast::DeclHead& h = head(d);
  if (h.name.text.empty()) return;
  auto [it, inserted] = symbols_.try_emplace(h.name.text, d);
  if (inserted) return;
  const Decl& first = it->second;
  Diagnostic& diag = sink_.error(h.name.where, fmt::format("`{}` is already declared", h.name.text));
  diag.notes.emplace_back(head(first).name.where, fmt::format("first declared here, as {}", article(kind_name(first))));
  diag.help.push_back(
      "every arena, robot, behavior, fitness, controller, experiment, library, primitive set and study needs its "
      "own name");
}

void Resolver::declare(const ast::Module& m) {
  modules_.push_back(&m);
  sensor_names_.reset();
  // In source order, so that "first declared here" points at the earlier one.
  std::vector<Decl> all;
  const auto collect = [&](const auto& v) {
    for (const auto& d : v) all.emplace_back(&d);
  };
  collect(m.arenas);
  collect(m.robots);
  collect(m.behaviors);
  collect(m.fitnesses);
  collect(m.controllers);
  collect(m.experiments);
  collect(m.libraries);
  collect(m.primitives);
  collect(m.studies);
  std::stable_sort(all.begin(), all.end(), [](const Decl& a, const Decl& b) { return head(a).order < head(b).order; });
  for (const Decl& d : all) add(d);
}

const Decl* Resolver::lookup(const ast::Name& ref, const Decl& want) {
  if (ref.text.empty()) return nullptr;
  const std::string_view want_kind = kind_name(want);
  const auto it = symbols_.find(ref.text);
  if (it == symbols_.end()) {
    std::vector<std::string> same_kind;
    for (const auto& [name, d] : symbols_)
      if (d.index() == want.index()) same_kind.push_back(name);
    Suggestion how;
    if (same_kind.empty())
      how.otherwise = fmt::format("no {} is declared; declare one, or import a file that does", want_kind);
    else if (same_kind.size() <= 8)
      how.otherwise = fmt::format("declared {}s: {}", want_kind, quoted_list(same_kind, ", "));
    suggest(sink_.error(ref.where, fmt::format("unknown {} `{}`", want_kind, ref.text)), ref.text, same_kind, how);
    return nullptr;
  }
  const Decl& d = it->second;
  if (d.index() != want.index()) {
    Diagnostic& diag = sink_.error(ref.where, fmt::format("`{}` is {}, not {}", ref.text, article(kind_name(d)),
                                                          article(want_kind)));
    diag.notes.emplace_back(head(d).name.where, fmt::format("`{}` is declared here", ref.text));
    return nullptr;
  }
  if (head(d).poisoned) return nullptr;
  return &d;
}

const SensorNames& Resolver::sensor_names() {
  if (sensor_names_) return *sensor_names_;
  SensorNames& names = sensor_names_.emplace();
  for (const RenamableSensors& r : kRenamableSensors) names.emplace(r.observable, r.observable);
  // A name reads one array in the whole program: a second array by the same name is refused
  // where it is given (once, however often the names are gathered again).
  const auto add = [&](const std::vector<ast::Setting>& settings) {
    for (const ast::Setting& s : settings)
      for (const RenamableSensors& r : kRenamableSensors) {
        if (s.key.text != r.setting || s.value.kind != ast::Value::Kind::Word) continue;
        const auto [it, fresh] = names.emplace(s.value.text, r.observable);
        if (fresh || it->second == r.observable || !clashes_reported_.insert(&s).second) continue;
        for (const RenamableSensors& other : kRenamableSensors)
          if (other.observable == it->second)
            sink_.error(s.value.where, fmt::format("`{}` already names {} (`{} {}`); the {} need a name of their own",
                                                   s.value.text, other.what, other.setting, s.value.text, r.what));
      }
  };
  for (const ast::Module* m : modules_) {
    for (const ast::RobotDecl& r : m->robots) add(r.settings);
    for (const ast::ExperimentDecl& x : m->experiments)
      for (const ast::ExpItem& item : x.items)
        if (item.kind == ast::ExpItem::Kind::Robot) add(item.settings);
  }
  return names;
}

}  // namespace esc::compiler
