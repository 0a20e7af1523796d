// Behavior use in the fitness: `using(B)` on every step, the end terms (`epoch:`,
// `evaluation:`) over an epoch's or an evaluation's aggregates (`count(B)`, `share(B)`,
// `steps`), compiled from scripts and evaluated on fixed genomes and seeds; and their
// compile errors.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "helpers.hpp"
#include "runtime/eval/evaluator.hpp"
#include "runtime/genome/tree/primitive_set.hpp"

namespace esc::compiler {
namespace {

using test::options;
using test::rendered;

// A symbolic controller, a supervisor (a behavior listed twice) and the GP twin of the
// symbolic one, in a small arena where collisions end epochs early.
std::string world(const std::string& fitness) {
  return "import \"lib/khepera.esc\"\n"
         "arena small { size 50cm x 40cm  cylinder at (25cm, 20cm) radius 3cm  start random }\n"
         "fitness f { " + fitness + " }\n"
         "primitives p { functions + - * min max < > if  terminals ir[0..7], erc(-1, 1) }\n"
         "controller SC = symbolic(mlp(ir[0..7] -> hidden 3), actions [forward, left, right])\n"
         "controller SV = supervisor(mlp(ir[0..7] -> hidden 2), behaviors [forward(0.8), left(0.5), forward(0.3)])\n"
         "controller GS = tree(actions [forward, left, right], primitives p)\n"
         "experiment e { arena small  fitness f  epochs 4 x 90 steps  evolve es(mu 2, lambda 4)  "
         "evolve gp(population 10)  compare SC, SV, GS }\n";
}

eval::ExperimentSpec compiled(const std::string& fitness) {
  const CompileResult r = compile_source(world(fitness), "use.esc", options());
  EXPECT_TRUE(r.ok()) << rendered(r);
  return r.ok() ? r.experiments.at(0) : eval::ExperimentSpec{};
}

// A deterministic genome per index: weights spread over [-1, 1].
std::vector<double> genome(const control::ControllerSpec& c, int k) {
  std::vector<double> g(c.genome_size());
  for (std::size_t i = 0; i < g.size(); ++i) g[i] = std::sin(1.7 * static_cast<double>(i) + 0.9 * k);
  return g;
}

// An Action tree: `if ir[2] > 0.2 then left(0.6) else forward(0.9)`, encoded.
std::vector<double> tree_genome(const control::ControllerSpec& c);

struct Step {
  int epoch, action;
};
struct Recorder final : eval::TraceSink {
  std::vector<Step> steps;
  void on_step(const eval::TraceStep& t) override { steps.push_back({t.epoch, t.action}); }
};

TEST(BehaviorUse, UsingSummedOverStepsIsTheUsageCount) {
  for (const char* b : {"forward", "left", "right"}) {
    eval::ExperimentSpec spec = compiled(std::string("step: using(") + b + ")");
    ASSERT_FALSE(spec.controllers.empty());
    eval::Evaluator ev(spec);
    std::int64_t seen = 0;
    for (int k = 0; k < 6; ++k) {
      const control::ControllerSpec& sc = spec.controllers[0];
      const eval::Evaluation e = ev.evaluate(sc, genome(sc, k), 1000 + static_cast<std::uint64_t>(k));
      const auto names = sc.choice_names();
      const auto at = static_cast<std::size_t>(std::find(names.begin(), names.end(), b) - names.begin());
      ASSERT_EQ(e.usage.size(), 3u);
      EXPECT_EQ(e.fitness, static_cast<double>(e.usage[at])) << b << " genome " << k;
      std::int64_t total = 0;
      for (const std::int64_t u : e.usage) total += u;
      EXPECT_EQ(total, e.steps);
      seen += e.usage[at];
    }
    EXPECT_GT(seen, 0) << "no genome used " << b << ": the test would prove nothing";
  }
}

TEST(BehaviorUse, UsingNamesASupervisorsListingAndATreesAction) {
  // `forward` is the supervisor's first listing of it, `forward_2` its second.
  eval::ExperimentSpec spec = compiled("step: 100 * using(forward) + using(forward_2)");
  ASSERT_EQ(spec.controllers.size(), 3u);
  eval::Evaluator ev(spec);
  const control::ControllerSpec& sv = spec.controllers[1];
  std::int64_t both = 0;
  for (int k = 0; k < 6; ++k) {
    const eval::Evaluation e = ev.evaluate(sv, genome(sv, k), 77 + static_cast<std::uint64_t>(k));
    ASSERT_EQ(e.usage.size(), 3u);
    EXPECT_EQ(e.fitness, 100.0 * static_cast<double>(e.usage[0]) + static_cast<double>(e.usage[2]));
    both += e.usage[0] * e.usage[2];
  }
  EXPECT_GT(both, 0) << "no genome used both listings";
  const control::ControllerSpec& gs = spec.controllers[2];
  const eval::Evaluation t = ev.evaluate(gs, tree_genome(gs), 5);
  ASSERT_EQ(t.usage.size(), 3u);
  EXPECT_GT(t.usage[0], 0);
  EXPECT_GT(t.usage[1], 0);
  EXPECT_EQ(t.fitness, 100.0 * static_cast<double>(t.usage[0]));   // a tree's forward; it has no forward_2
}

TEST(BehaviorUse, TheNameAUsageTablePrintsIsTheSameChoice) {
  // SV's usage table prints `forward(0.8)`, `left(0.5)`, `forward_2(0.3)`: copied into
  // using(), each reads what its name without arguments reads.
  const eval::ExperimentSpec printed = compiled("step: using(left)");
  ASSERT_EQ(printed.controllers.at(1).choice_names(), (std::vector<std::string>{"forward(0.8)", "left(0.5)", "forward_2(0.3)"}));
  eval::ExperimentSpec plain = compiled("step: 100 * using(forward) + using(forward_2)");
  eval::ExperimentSpec table = compiled("step: 100 * using(forward(0.8)) + using(forward_2(0.3))");
  eval::Evaluator a(plain), b(table);
  for (int k = 0; k < 4; ++k) {
    const control::ControllerSpec& sv = plain.controllers[1];
    const eval::Evaluation x = a.evaluate(sv, genome(sv, k), 77 + static_cast<std::uint64_t>(k));
    const eval::Evaluation y = b.evaluate(table.controllers[1], genome(sv, k), 77 + static_cast<std::uint64_t>(k));
    EXPECT_EQ(x.fitness, y.fitness) << k;
    EXPECT_GT(x.fitness, 0.0) << k;
  }
}

TEST(BehaviorUse, AnEpochTermAddsExactlyItsValuesOnAFixedTrajectory) {
  // Integer terms: every sum is exact, so with - without is the terms' sum itself.
  eval::ExperimentSpec without = compiled("step: using(forward)  stop epoch when collision");
  eval::ExperimentSpec with = compiled("step: using(forward)  stop epoch when collision  epoch: 2 * count(forward) - steps");
  eval::Evaluator a(without), b(with);
  const control::ControllerSpec& sc = without.controllers[0];
  for (int k = 0; k < 4; ++k) {
    Recorder trace;
    const eval::Evaluation plain = a.evaluate(sc, genome(sc, k), 31 + static_cast<std::uint64_t>(k), &trace);
    const eval::Evaluation termed = b.evaluate(with.controllers[0], genome(sc, k), 31 + static_cast<std::uint64_t>(k));
    double terms = 0.0;
    for (int epoch = 0; epoch < with.epochs; ++epoch) {
      double forward = 0.0, steps = 0.0;
      for (const Step& s : trace.steps)
        if (s.epoch == epoch) {
          steps += 1.0;
          forward += s.action == 0 ? 1.0 : 0.0;
        }
      terms += 2.0 * forward - steps;
    }
    EXPECT_EQ(termed.steps, plain.steps);
    EXPECT_EQ(termed.fitness - plain.fitness, terms) << "genome " << k;
  }
}

TEST(BehaviorUse, ThePapersConstraintIsAddedAtEachEpochsEndAsWritten) {
  eval::ExperimentSpec spec = compiled(
      "step: max(forward_speed, 0) * (1 - sqrt(wheel_diff))  stop epoch when collision  "
      "epoch: -100 * abs(share(left) - 0.1)");
  eval::ExperimentSpec plain_spec = compiled("step: max(forward_speed, 0) * (1 - sqrt(wheel_diff))  stop epoch when collision");
  ASSERT_TRUE(spec.fitness.epoch_end.has_value());
  eval::Evaluator ev(spec), plain(plain_spec);
  const control::ControllerSpec& sc = spec.controllers[0];
  bool stopped_early = false;
  for (int k = 0; k < 4; ++k) {
    // The step terms of the fixed trajectory, read from the trace of the run without the
    // end term (its fitness so far, step after step), then the end terms added where the
    // evaluator adds them: after each epoch's last step.
    struct Full final : eval::TraceSink {
      std::vector<eval::TraceStep> steps;
      void on_step(const eval::TraceStep& t) override { steps.push_back(t); }
    } trace;
    (void)plain.evaluate(plain_spec.controllers[0], genome(sc, k), 9 + static_cast<std::uint64_t>(k), &trace);
    double fitness = 0.0, before = 0.0;
    for (int epoch = 0; epoch < spec.epochs; ++epoch) {
      double left = 0.0, steps = 0.0;
      for (const eval::TraceStep& t : trace.steps) {
        if (t.epoch != epoch) continue;
        fitness += t.fitness - before;   // this step's term, as the evaluator added it
        before = t.fitness;
        steps += 1.0;
        left += t.action == 1 ? 1.0 : 0.0;
      }
      stopped_early = stopped_early || steps < spec.steps;
      fitness += -100.0 * std::abs(left / steps - 0.1);
    }
    const eval::Evaluation e = ev.evaluate(sc, genome(sc, k), 9 + static_cast<std::uint64_t>(k));
    EXPECT_NEAR(e.fitness, fitness, 1e-9) << "genome " << k;
  }
  EXPECT_TRUE(stopped_early) << "no epoch ended on a collision: the test would not cover a stopped epoch";
}

TEST(BehaviorUse, ThePapersConstraintIsExactlyTheSumWrittenInItsOrder) {
  // A step term of whole numbers, so the trace gives each step's term exactly; the epoch
  // term is the paper's. The fitness is every term added in the evaluator's order.
  eval::ExperimentSpec plain = compiled("step: using(forward)  stop epoch when collision");
  eval::ExperimentSpec spec =
      compiled("step: using(forward)  stop epoch when collision  epoch: -100 * abs(share(left) - 0.1)");
  eval::Evaluator base(plain), ev(spec);
  const control::ControllerSpec& sc = spec.controllers[0];
  for (int k = 0; k < 4; ++k) {
    Recorder trace;
    (void)base.evaluate(plain.controllers[0], genome(sc, k), 21 + static_cast<std::uint64_t>(k), &trace);
    double fitness = 0.0;
    for (int epoch = 0; epoch < spec.epochs; ++epoch) {
      double left = 0.0, steps = 0.0;
      for (const Step& s : trace.steps) {
        if (s.epoch != epoch) continue;
        fitness += s.action == 0 ? 1.0 : 0.0;
        left += s.action == 1 ? 1.0 : 0.0;
        steps += 1.0;
      }
      fitness += -100.0 * std::abs(left / steps - 0.1);
    }
    EXPECT_EQ(ev.evaluate(sc, genome(sc, k), 21 + static_cast<std::uint64_t>(k)).fitness, fitness) << "genome " << k;
  }
}

TEST(BehaviorUse, AnEvaluationTermReadsTheWholeEvaluation) {
  eval::ExperimentSpec plain = compiled("step: 0");
  eval::ExperimentSpec spec = compiled("step: 0  evaluation: 1000 * share(right) + steps");
  eval::Evaluator ev(spec), base(plain);
  const control::ControllerSpec& sc = spec.controllers[0];
  for (int k = 0; k < 3; ++k) {
    const eval::Evaluation e = ev.evaluate(sc, genome(sc, k), 3);
    const eval::Evaluation b = base.evaluate(plain.controllers[0], genome(sc, k), 3);
    EXPECT_EQ(b.fitness, 0.0);
    EXPECT_EQ(e.fitness, 1000.0 * (static_cast<double>(e.usage[2]) / static_cast<double>(e.steps)) +
                             static_cast<double>(e.steps));
  }
}

TEST(BehaviorUse, AClassicalControllerUsesNothing) {
  const std::string text =
      "arena a { size 1m x 1m }\n"
      "behavior go(p) { wheels(p, p) }\n"
      "fitness f { step: 1 + using(go)  epoch: count(go) }\n"
      "controller CC = mlp(ir[0..7] -> wheels)\n"
      "controller SV = supervisor(mlp(ir[0..7]), behaviors [go(0.5)])\n"
      "experiment e { arena a  fitness f  epochs 2 x 10 steps  compare CC, SV }\n";
  const CompileResult r = compile_source(text, "classical.esc", options());
  ASSERT_TRUE(r.ok()) << rendered(r);
  const eval::ExperimentSpec& spec = r.experiments[0];
  eval::Evaluator ev(spec);
  const eval::Evaluation cc = ev.evaluate(spec.controllers[0], genome(spec.controllers[0], 0), 1);
  EXPECT_EQ(cc.fitness, 20.0);   // 1 per step; `go` never acts
  EXPECT_TRUE(cc.usage.empty());
  const eval::Evaluation sv = ev.evaluate(spec.controllers[1], genome(spec.controllers[1], 0), 1);
  EXPECT_EQ(sv.fitness, 20.0 + 20.0 + 20.0);   // its only behavior acts on every step
}

TEST(BehaviorUse, ALibraryMemberNamesEveryListingOfIt) {
  const std::string text =
      "arena a { size 1m x 1m }\n"
      "library moves { behavior spin() { wheels(1, -1) }  behavior still() { wheels(0, 0) } }\n"
      "fitness f { step: using(moves.spin)  epoch: 1000 * count(spin_2) }\n"
      "controller SV = supervisor(mlp(ir[0..7]), behaviors [moves, moves])\n"
      "experiment e { arena a  fitness f  epochs 2 x 30 steps  compare SV }\n";
  const CompileResult r = compile_source(text, "members.esc", options());
  ASSERT_TRUE(r.ok()) << rendered(r);
  const eval::ExperimentSpec& spec = r.experiments[0];
  EXPECT_EQ(spec.controllers[0].choice_names(), (std::vector<std::string>{"spin", "still", "spin_2", "still_2"}));
  eval::Evaluator ev(spec);
  std::int64_t seen = 0;
  for (int k = 0; k < 8; ++k) {
    const eval::Evaluation e = ev.evaluate(spec.controllers[0], genome(spec.controllers[0], k), 4);
    EXPECT_EQ(e.fitness, static_cast<double>(e.usage[0] + e.usage[2]) + 1000.0 * static_cast<double>(e.usage[2]));
    seen += e.usage[0] * e.usage[2];
  }
  EXPECT_GT(seen, 0);
}

TEST(BehaviorUse, ChoicesAreNumberedAcrossTheExperiment) {
  eval::ExperimentSpec spec = compiled("step: using(left)");
  ASSERT_EQ(spec.controllers.size(), 3u);
  // SC's and GS's `left` are one choice; SV's listings of `forward` are two.
  EXPECT_EQ(spec.controllers[0].choices[1].id, spec.controllers[2].choices[1].id);
  EXPECT_NE(spec.controllers[1].choices[0].id, spec.controllers[1].choices[2].id);
  EXPECT_EQ(spec.controllers[1].choices[2].name, "forward_2");
  EXPECT_EQ(spec.choice_ids, 4u);   // forward, left, right and forward_2 (SV's left(0.5) is `left`)
}

// Compile errors, each located, with "did you mean" where a name is close.
struct BadUse {
  std::string fitness;
  std::string message;
};

class BehaviorUseErrors : public ::testing::TestWithParam<BadUse> {};

TEST_P(BehaviorUseErrors, AreReportedAtTheirPlace) {
  const CompileResult r = compile_source(world(GetParam().fitness), "bad.esc", options());
  ASSERT_FALSE(r.ok());
  EXPECT_NE(rendered(r).find(GetParam().message), std::string::npos) << rendered(r);
}

INSTANTIATE_TEST_SUITE_P(
    Fitness, BehaviorUseErrors,
    ::testing::Values(
        BadUse{"step: using(fowrard)",
               "bad.esc:3:25: error: `fowrard` is not an action or behavior of the controllers compared by experiment "
               "`e`; did you mean `forward`?"},
        BadUse{"step: share(left)", "error: `share(B)` is an aggregate over an epoch or an evaluation"},
        BadUse{"step: steps", "error: `steps` counts the steps of an epoch or an evaluation"},
        BadUse{"step: 1  epoch: count(2)", "error: `count` takes the name of an action or behavior"},
        BadUse{"step: 1  epoch: 1  epoch: 2", "error: the fitness already has an `epoch:` term"},
        BadUse{"step: 1  evaluation: sahre(left)", "error: unknown function `sahre`; did you mean `share`?"},
        BadUse{"step: using(forward(0.5))",
               "bad.esc:3:25: error: `forward(0.5)` is not an action or behavior of the controllers compared by "
               "experiment `e`; did you mean `forward(0.8)`?"},
        BadUse{"step: using(forward(speed))", "bad.esc:3:33: error: `using(forward(...))` takes the arguments the "
                                              "behavior was listed with: constants"},
        BadUse{"step: using(useless.crash)",
               "error: `useless.crash` is not an action or behavior of the controllers compared by experiment `e`"}));

TEST(BehaviorUse, ABehaviorCannotReadUsing) {
  const CompileResult r = compile_source(
      "behavior odd() { wheels(using(odd), 0) }\narena a { size 1m x 1m }\nfitness f { step: speed }\n"
      "controller SV = supervisor(mlp(ir[0..7]), behaviors [odd])\nexperiment e { arena a  fitness f  compare SV }\n",
      "behavior.esc", options());
  ASSERT_FALSE(r.ok());
  EXPECT_NE(rendered(r).find("behavior.esc:1:25: error: `using(B)` can be read only by a fitness"), std::string::npos)
      << rendered(r);
}

TEST(BehaviorUse, ALibraryIsMarkedUselessOrNothing) {
  const std::string lib = "library junk useless { behavior crash() { wheels(1, 1) } }\n"
                          "library other { behavior still() { wheels(0, 0) } }\n"
                          "arena a { size 1m x 1m }\nfitness f { step: speed }\n"
                          "controller SV = supervisor(mlp(ir[0..7]), behaviors [junk, other])\n"
                          "experiment e { arena a  fitness f  compare SV }\n";
  const CompileResult r = compile_source(lib, "marked.esc", options());
  ASSERT_TRUE(r.ok()) << rendered(r);
  const auto& choices = r.experiments[0].controllers[0].choices;
  ASSERT_EQ(choices.size(), 2u);
  EXPECT_TRUE(choices[0].useless);
  EXPECT_EQ(choices[0].library, "junk");
  EXPECT_EQ(choices[0].behavior, "junk.crash");
  EXPECT_FALSE(choices[1].useless);
  const CompileResult bad = compile_source("library junk uselss { behavior crash() { wheels(1, 1) } }\n", "mark.esc",
                                           options());
  EXPECT_NE(rendered(bad).find("mark.esc:1:14: error: unknown mark `uselss` for library `junk`; did you mean "
                               "`useless`?"),
            std::string::npos)
      << rendered(bad);
}

std::vector<double> tree_genome(const control::ControllerSpec& c) {
  const auto& set = *c.primitives;
  const auto id = [&](std::string_view name, genome::tree::Type result) {
    for (std::size_t i = 0; i < set.primitives().size(); ++i)
      if (set.primitives()[i].name == name && set.primitives()[i].result == result) return static_cast<double>(i);
    ADD_FAILURE() << "no primitive " << name;
    return 0.0;
  };
  using genome::tree::Type;
  // Postfix, two doubles per node (id, value): ir[2] 0.2 > 0.6 left 0.9 forward if.
  return {id("ir[2]", Type::Number), 0.0, id("erc", Type::Number), 0.2, id(">", Type::Bool), 0.0,
          id("erc", Type::Number), 0.6, id("left", Type::Action), 0.0, id("erc", Type::Number), 0.9,
          id("forward", Type::Action), 0.0, id("if", Type::Action), 0.0};
}

}  // namespace
}  // namespace esc::compiler
