#pragma once
// Every optimizer a script can name, in one table. Each algorithm's folder under
// runtime/evo/ defines one value type that describes it (cmaes/cmaes_optimizer.hpp: its
// name, the genome kinds it evolves, the format of its saved state, and how its own settings
// type makes an optimizer, sizes a generation, weighs in memory and reads in scripts);
// Algorithm erases that type once, as pagmo2's algorithm does a user's, so that the table
// is one line per algorithm (registry.cpp) and callers hold the settings as a std::any.
// Adding an algorithm: docs/optimizers.md.
#include <any>
#include <concepts>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "runtime/evo/algorithm_options.hpp"
#include "runtime/evo/memory_peak.hpp"
#include "runtime/evo/optimizer.hpp"
#include "runtime/genome/kind.hpp"

namespace esc::evo {

// What an algorithm's value type provides: its settings type, what it is, and these over
// its settings. `options()` (its options as scripts write them), `defaults()` (else its
// settings type's own), `problem()` (why settings cannot run on a problem; else none),
// `conflict()` (options that do not go together, whatever the settings evolve; else none),
// `scope` (else InUse) and `bare_keys` (else false: `--set NAME.KEY`) are optional, as
// pagmo2 detects a problem's optional members.
template <class A>
concept AlgorithmValue = requires(const A a, const typename A::Settings& s, const Problem& p, int generations) {
  { a.name } -> std::convertible_to<std::string_view>;
  { a.what } -> std::convertible_to<std::string_view>;
  { a.kinds } -> std::convertible_to<genome::GenomeKinds>;
  { a.state_format } -> std::convertible_to<std::uint32_t>;
  { a.make(s, p) } -> std::same_as<std::unique_ptr<Optimizer>>;
  { a.population(s, p) } -> std::same_as<std::size_t>;
  { a.memory(s, p, generations) } -> std::same_as<MemoryPeak>;
};

class Algorithm {
 public:
  template <AlgorithmValue A>
  explicit Algorithm(A a)
      : name(a.name), what(a.what), kinds(a.kinds), state_format(a.state_format), scope(scope_of(a)),
        bare_keys(bare_keys_of(a)), model_(std::make_shared<const Model<A>>(std::move(a))) {}

  std::string_view name;          // as scripts and stored states name it
  std::string_view what;          // in messages: "CMA-ES", "ES"
  genome::GenomeKinds kinds;      // what it evolves: a network's weights, trees, ...
  // The layout of save()'s bytes: a stored state of another format is refused, not misread.
  std::uint32_t state_format = 1;
  SettingsScope scope = SettingsScope::InUse;
  // Whether scripts write its `--set` keys and resolved settings without `NAME.` (the ES's
  // `mu`, the paper's spelling); its options are read alike.
  bool bare_keys = false;

  // `settings` holds the algorithm's own settings type (as the compiler made it).
  // A fresh optimizer for one run. Throws std::invalid_argument on impossible settings.
  [[nodiscard]] std::unique_ptr<Optimizer> make(const std::any& settings, const Problem& problem) const {
    return model_->make(settings, problem);
  }
  // Candidates of a run's first generation for `problem` (its genome_size 0 for a tree):
  // what the campaign sizes its rounds by. This, memory and problem read only the problem's
  // sizes and declared ranges, never its seed or start.
  [[nodiscard]] std::size_t population(const std::any& settings, const Problem& problem) const {
    return model_->population(settings, problem);
  }
  // What one run of `generations` holds at its peak (memory_peak.hpp): what the campaign's
  // memory check counts for it, and names when it cannot fit.
  [[nodiscard]] MemoryPeak memory(const std::any& settings, const Problem& problem, int generations) const {
    return model_->memory(settings, problem, generations);
  }
  // Its options as scripts write them, its default settings, why settings cannot run on
  // `problem` ("" when they can: an archive's cells need declared descriptors, ...), and the
  // options of `settings` that do not go together whatever they evolve (the ES's comma
  // selection needs lambda >= mu; empty when they do). A value type without them has none,
  // its settings type's defaults, and no such reasons.
  [[nodiscard]] const std::vector<AlgorithmOption>& options() const { return model_->options(); }
  [[nodiscard]] std::any defaults() const { return model_->defaults(); }
  [[nodiscard]] std::string problem(const std::any& settings, const Problem& problem) const {
    return model_->problem(settings, problem);
  }
  [[nodiscard]] OptionRefusal conflict(const std::any& settings) const { return model_->conflict(settings); }

 private:
  template <class A>
  static SettingsScope scope_of(const A& a) {
    if constexpr (requires { a.scope; }) return a.scope;
    else return SettingsScope::InUse;
  }
  template <class A>
  static bool bare_keys_of(const A& a) {
    if constexpr (requires { a.bare_keys; }) return a.bare_keys;
    else return false;
  }

  struct Concept {
    virtual ~Concept() = default;
    [[nodiscard]] virtual std::unique_ptr<Optimizer> make(const std::any& s, const Problem& p) const = 0;
    [[nodiscard]] virtual std::size_t population(const std::any& s, const Problem& p) const = 0;
    [[nodiscard]] virtual MemoryPeak memory(const std::any& s, const Problem& p, int generations) const = 0;
    [[nodiscard]] virtual const std::vector<AlgorithmOption>& options() const = 0;
    [[nodiscard]] virtual std::any defaults() const = 0;
    [[nodiscard]] virtual std::string problem(const std::any& s, const Problem& p) const = 0;
    [[nodiscard]] virtual OptionRefusal conflict(const std::any& s) const = 0;
  };

  template <class A>
  struct Model final : Concept {
    using Settings = typename A::Settings;
    explicit Model(A a) : value(std::move(a)) {}
    static const Settings& of(const std::any& s) { return std::any_cast<const Settings&>(s); }

    std::unique_ptr<Optimizer> make(const std::any& s, const Problem& p) const override { return value.make(of(s), p); }
    std::size_t population(const std::any& s, const Problem& p) const override { return value.population(of(s), p); }
    MemoryPeak memory(const std::any& s, const Problem& p, int generations) const override {
      return value.memory(of(s), p, generations);
    }
    const std::vector<AlgorithmOption>& options() const override {
      if constexpr (requires { value.options(); }) {
        return value.options();
      } else {
        static const std::vector<AlgorithmOption> none;
        return none;
      }
    }
    std::any defaults() const override {
      if constexpr (requires { value.defaults(); }) return value.defaults();
      else return Settings{};
    }
    std::string problem(const std::any& s, const Problem& p) const override {
      if constexpr (requires { value.problem(of(s), p); }) return value.problem(of(s), p);
      else return {};
    }
    OptionRefusal conflict(const std::any& s) const override {
      if constexpr (requires { value.conflict(of(s)); }) return value.conflict(of(s));
      else return {};
    }

    A value;
  };

  std::shared_ptr<const Concept> model_;
};

[[nodiscard]] const std::vector<Algorithm>& algorithms();
// The algorithm called `name`, or null.
[[nodiscard]] const Algorithm* find_algorithm(std::string_view name) noexcept;

// The state a run evaluating a stored genome keeps (none), named so that the store tells it
// from an algorithm's.
inline constexpr std::string_view kEvaluateOnly = "evaluate";

}  // namespace esc::evo
