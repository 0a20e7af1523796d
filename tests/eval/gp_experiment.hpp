#pragma once
// The small obstacle-avoidance experiment of test_experiment.hpp with GP settings and two
// tree controllers built from runtime objects: a Wheels tree and an Action tree over
// forward, left and right (the GP twin of a symbolic controller).
#include <memory>

#include "runtime/genome/tree/primitive_set.hpp"
#include "tests/control/behaviors.hpp"
#include "tests/eval/test_experiment.hpp"

namespace esc::testing {

inline std::vector<genome::tree::Primitive> avoidance_primitives() {
  using expr::Op;
  std::vector<genome::tree::Primitive> p;
  for (Op op : {Op::Add, Op::Sub, Op::Mul, Op::Min, Op::Max, Op::Lt, Op::Gt}) p.push_back(genome::tree::prim::function(op));
  p.push_back(genome::tree::prim::if_then_else(genome::tree::Type::Number));
  for (int i = 0; i < 8; ++i) p.push_back(*genome::tree::prim::observable("ir[" + std::to_string(i) + "]"));
  p.push_back(genome::tree::prim::erc(-1.0, 1.0));
  return p;
}

// A tree controller over avoidance_primitives(): a Wheels tree (Classical head) or an
// Action tree over forward, left and right (Symbolic head).
inline control::ControllerSpec tree_controller(const std::string& name, control::Head head) {
  control::ControllerSpec c;
  c.name = name;
  c.head = head;
  auto p = avoidance_primitives();
  if (head == control::Head::Classical) p.push_back(genome::tree::prim::wheels());
  if (head == control::Head::Symbolic) {
    c.actions = {control::testing::forward(), control::testing::left(), control::testing::right()};
    for (std::uint32_t k = 0; k < 3; ++k) p.push_back(genome::tree::prim::action(c.actions[k].name, k, 1));
    p.push_back(genome::tree::prim::if_then_else(genome::tree::Type::Action));
  }
  const genome::tree::Type root = head == control::Head::Classical ? genome::tree::Type::Wheels : genome::tree::Type::Action;
  c.primitives = std::make_shared<const genome::tree::PrimitiveSet>(std::move(p), root);
  c.primitives_name = "avoid";
  return c;
}

inline eval::ExperimentSpec gp_experiment() {
  eval::ExperimentSpec e = small_experiment();
  e.name = "small_gp";
  evo::gp::GpSettings s;
  s.population = 24;
  s.generations = 6;
  s.tournament = 3;
  s.init_min_depth = 2;
  s.init_max_depth = 4;
  s.max_depth = 8;
  s.max_size = 40;
  e.algorithm_settings[eval::ExperimentSpec::kTreeOperators] = s;
  e.controllers = {tree_controller("GW", control::Head::Classical), tree_controller("GS", control::Head::Symbolic)};
  return e;
}

}  // namespace esc::testing
