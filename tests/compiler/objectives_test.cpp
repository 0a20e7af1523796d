// Objectives and behavior descriptors: what the compiler makes of `fitness F in [..]`,
// `objective G minimize in [..]` and `descriptor D: EXPR in [..] by R`, its diagnostics, and
// the values an evaluation measures for them.
#include <gtest/gtest.h>

#include "runtime/eval/evaluator.hpp"
#include "tests/compiler/helpers.hpp"

namespace esc::compiler::test {
namespace {

// A robot that never stops an epoch early: 3 epochs of 20 steps.
std::string script(const std::string& items, const std::string& fitnesses = "") {
  return "arena a { size 1m x 1m }\n"
         "fitness f { step: forward_speed }\n"
         "fitness count_steps { step: 1 }\n"
         "fitness bonus { step: 0  epoch: 2  evaluation: 5 }\n" +
         fitnesses +
         "controller c = mlp(ir[0..7] -> wheels)\n"
         "experiment e { arena a  epochs 3 x 20 steps  compare c\n" + items + "\n}\n";
}

CompileResult compiled(const std::string& text) { return compile_source(text, "objectives.esc", options()); }

eval::ExperimentSpec experiment(const std::string& items, const std::string& fitnesses = "") {
  const CompileResult r = compiled(script(items, fitnesses));
  EXPECT_TRUE(r.ok()) << rendered(r);
  return r.ok() ? r.experiments.at(0) : eval::ExperimentSpec{};
}

std::string errors(const std::string& items, const std::string& fitnesses = "") {
  const CompileResult r = compiled(script(items, fitnesses));
  EXPECT_FALSE(r.ok()) << "compiled: " << items;
  return rendered(r);
}

TEST(Objectives, AnExperimentWithTheFitnessAloneDeclaresNone) {
  const eval::ExperimentSpec x = experiment("fitness f");
  EXPECT_TRUE(x.objectives.empty());
  EXPECT_TRUE(x.further.empty());
  EXPECT_TRUE(x.descriptors.empty());
  EXPECT_EQ(x.resolved_settings.count("objectives"), 0u);
  EXPECT_EQ(x.resolved_settings.count("descriptors"), 0u);
}

TEST(Objectives, FurtherObjectivesFollowTheFitnessWithTheirDirectionAndRange) {
  const eval::ExperimentSpec x =
      experiment("fitness f in [-60, 60]\n objective count_steps minimize in [0, 6000cm]\n objective bonus");
  ASSERT_EQ(x.objectives.size(), 3u);
  EXPECT_EQ(x.objectives[0].name, "f");
  EXPECT_FALSE(x.objectives[0].minimize);
  EXPECT_EQ(x.objectives[0].range, (eval::DeclaredRange{-60, 60}));
  EXPECT_EQ(x.objectives[1].name, "count_steps");
  EXPECT_TRUE(x.objectives[1].minimize);
  EXPECT_EQ(x.objectives[1].range, (eval::DeclaredRange{0, 60}));   // in SI
  EXPECT_FALSE(x.objectives[2].range.has_value());
  ASSERT_EQ(x.further.size(), 2u);
  EXPECT_EQ(x.further[1].name, "bonus");
  EXPECT_EQ(x.resolved_settings.at("objectives"),
            "f in [-60, 60]; count_steps minimize in [0, 60]; bonus");
}

TEST(Objectives, DescriptorsKeepTheirReductionRangeAndText) {
  const eval::ExperimentSpec x = experiment(
      "fitness f\n descriptor late: epoch in [0, 2] by last\n descriptor clock: time in [0, 10s]\n"
      " descriptor moved: evaluation: steps in [0, 60]");
  ASSERT_EQ(x.descriptors.size(), 3u);
  EXPECT_EQ(x.descriptors[0].name, "late");
  EXPECT_EQ(x.descriptors[0].reduce, eval::Reduction::Last);
  EXPECT_EQ(x.descriptors[1].reduce, eval::Reduction::Mean);
  EXPECT_EQ(x.descriptors[1].range, (eval::DeclaredRange{0, 10}));
  EXPECT_TRUE(x.descriptors[2].at_evaluation);
  EXPECT_EQ(x.resolved_settings.at("descriptors"),
            "late: epoch in [0, 2] by last; clock: time in [0, 10]; moved: evaluation: steps in [0, 60]");
}

// The values an evaluation measures: 3 epochs of 20 steps, none stopped early.
TEST(Objectives, AnEvaluationMeasuresEveryObjectiveAndDescriptor) {
  const eval::ExperimentSpec x = experiment(
      "fitness f\n objective count_steps minimize in [0, 100]\n objective bonus\n"
      " descriptor mean_epoch: epoch in [0, 2]\n descriptor sum_epoch: epoch in [0, 3] by sum\n"
      " descriptor min_epoch: epoch in [0, 2] by min\n descriptor max_epoch: epoch in [0, 2] by max\n"
      " descriptor first_step: step in [0, 20] by first\n descriptor last_epoch: epoch in [0, 2] by last\n"
      " descriptor steps_all: evaluation: steps in [0, 60]\n descriptor steps_epoch: steps in [0, 20]");
  eval::Evaluator ev(x);
  const control::ControllerSpec& c = x.controllers.front();
  const eval::Evaluation e = ev.evaluate(c, std::vector<double>(c.genome_size(), 0.1), 7);
  ASSERT_EQ(e.steps, 60);
  // Measured as declared: the minimised objective is not negated here.
  EXPECT_EQ(e.objectives, (std::vector<double>{60.0, 3 * 2.0 + 5.0}));
  // `step` on an epoch's last frame is that step's index, 19; the aggregate `steps` counts 20.
  EXPECT_EQ(e.descriptors, (std::vector<double>{1.0, 3.0, 0.0, 2.0, 19.0, 2.0, 60.0, 20.0}));
  // Declaring objectives and descriptors does not change the fitness.
  const eval::ExperimentSpec plain = experiment("fitness f");
  eval::Evaluator pev(plain);
  EXPECT_EQ(pev.evaluate(plain.controllers.front(), std::vector<double>(c.genome_size(), 0.1), 7).fitness, e.fitness);
}

TEST(Objectives, MistakesAreLocatedAndExplained) {
  EXPECT_NE(errors("fitness f\n objective count_steps in [5, 5]")
                .find("the range of objective `count_steps` is empty: 5 is not below 5"),
            std::string::npos);
  EXPECT_NE(errors("fitness f\n objective f").find("fitness `f` is already an objective of this experiment"),
            std::string::npos);
  EXPECT_NE(errors("fitness f\n objective count_steps\n objective count_steps").find("first given here"),
            std::string::npos);
  EXPECT_NE(errors("fitness f\n objective stopper", "fitness stopper { step: 1 stop epoch when step > 3 }\n")
                .find("objective `stopper` has a `stop epoch when` condition"),
            std::string::npos);
  EXPECT_NE(errors("fitness f\n objective nowhere").find("nowhere"), std::string::npos);
  const std::string reduction = errors("fitness f\n descriptor d: epoch in [0, 2] by maen");
  EXPECT_NE(reduction.find("unknown reduction `maen`; did you mean `mean`?"), std::string::npos) << reduction;
  EXPECT_NE(errors("fitness f\n descriptor d: evaluation: steps in [0, 60] by max")
                .find("a descriptor evaluated once at the end of the evaluation has no epochs to reduce"),
            std::string::npos);
  EXPECT_NE(errors("fitness f\n descriptor d: epoch in [0, 2]\n descriptor d: time in [0, 1]")
                .find("descriptor `d` is already declared in this experiment"),
            std::string::npos);
  EXPECT_NE(errors("fitness f\n descriptor f: epoch in [0, 2]")
                .find("descriptor `f` has the name of an objective of this experiment"),
            std::string::npos);
  EXPECT_NE(errors("fitness f\n descriptor d: epoch in [0, 2parsecs]").find("unknown unit `parsecs`"),
            std::string::npos);
  EXPECT_NE(errors("fitness f\n descriptor d: nonsense in [0, 1]").find("nonsense"), std::string::npos);
  // A descriptor needs its range: the archive's cells and the novelty's scale come from it.
  EXPECT_NE(errors("fitness f\n descriptor d: epoch").find("objectives.esc"), std::string::npos);
}

TEST(Objectives, InStaysAName) {
  // `in(zone)` is still the observable, and `in` a word scripts may use as a name.
  const CompileResult r = compiled(
      "arena a { size 1m x 1m  zone home circle radius 10cm at (50cm, 50cm) }\n"
      "fitness f { step: in(home) }\n"
      "controller c = mlp(ir[0..7] -> wheels)\n"
      "experiment e { arena a  fitness f  compare c  descriptor home_share: in(home) in [0, 1] }\n");
  EXPECT_TRUE(r.ok()) << rendered(r);
}

}  // namespace
}  // namespace esc::compiler::test
