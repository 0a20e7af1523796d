#pragma once
// Lowers `fitness` declarations to eval::FitnessSpec: the `step:` term and the stop
// conditions, resolved in an experiment's arena when given.
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "compiler/ast.hpp"
#include "compiler/lower_arena.hpp"
#include "compiler/sink.hpp"
#include "runtime/eval/experiment.hpp"

namespace esc::compiler {

struct LoweredFitness {
  eval::FitnessSpec spec;
  std::string step_text;                  // source text, for resolved settings
  std::vector<std::string> stop_texts;
};

class FitnessLowering {
 public:
  FitnessLowering(Sink& sink, ArenaLowering& arenas) : sink_(sink), arenas_(arenas) {}

  // Memoised per (fitness, arena); what does not depend on the arena is reported once.
  const std::optional<LoweredFitness>& lower(const ast::FitnessDecl& d, const ast::ArenaDecl* arena = nullptr);

 private:
  Sink& sink_;
  ArenaLowering& arenas_;
  std::map<std::pair<const ast::FitnessDecl*, const ast::ArenaDecl*>, std::optional<LoweredFitness>> fitnesses_;
};

}  // namespace esc::compiler
