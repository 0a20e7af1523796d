// Step aggregates (`mean(x)`, `sum(x)`, `min(x)`, `max(x)`, `fraction(c)`, `last(x)`) in
// descriptors and fitness end terms, and `positions(K)` descriptors: what the compiler makes
// of them, its diagnostics, and the values an evaluation measures.
#include <gtest/gtest.h>

#include "runtime/eval/evaluator.hpp"
#include "tests/compiler/helpers.hpp"

namespace esc::compiler::test {
namespace {

// 3 epochs of 20 steps, none stopped early unless `stop` says so; the fitness `f` without a
// range unless `items` names it.
std::string script(const std::string& items, const std::string& fitnesses = "", const std::string& stop = "") {
  const std::string fitness = items.find("fitness f") == std::string::npos ? "fitness f\n" : "";
  return "arena a { size 1m x 1m }\n"
         "fitness f { step: forward_speed " + stop + " }\n" + fitnesses +
         "controller c = mlp(ir[0..7] -> wheels)\n"
         "experiment e { arena a  epochs 3 x 20 steps  compare c\n" + fitness + items + "\n}\n";
}

CompileResult compiled(const std::string& text) { return compile_source(text, "aggregates.esc", options()); }

eval::ExperimentSpec experiment(const std::string& text) {
  const CompileResult r = compiled(text);
  EXPECT_TRUE(r.ok()) << rendered(r);
  return r.ok() ? r.experiments.at(0) : eval::ExperimentSpec{};
}

eval::Evaluation evaluate(const eval::ExperimentSpec& x, eval::TraceSink* trace = nullptr) {
  eval::Evaluator ev(x);
  const control::ControllerSpec& c = x.controllers.front();
  return ev.evaluate(c, std::vector<double>(c.genome_size(), 0.3), 11, trace);
}

std::string diagnostics(const std::string& text) { return rendered(compiled(text)); }

TEST(StepAggregates, SamplesAreEvenlySpacedFromTheFirstStepToTheLast) {
  EXPECT_EQ(expr::sampled_step(0, 1, 150), 149);
  EXPECT_EQ(expr::sampled_step(0, 5, 150), 0);
  EXPECT_EQ(expr::sampled_step(1, 5, 150), 37);    // 37.25
  EXPECT_EQ(expr::sampled_step(2, 5, 150), 75);    // 74.5, halves up
  EXPECT_EQ(expr::sampled_step(4, 5, 150), 149);
  EXPECT_EQ(expr::sampled_step(1, 2, 1), 0);
}

// `step` on a step's frame is its index in the epoch, 0 .. 19; `epoch` 0 .. 2.
TEST(StepAggregates, DescriptorsFoldEveryStepOfTheEpochOrOfTheEvaluation) {
  const eval::ExperimentSpec x = experiment(script(
      "descriptor m: mean(step) in [0, 20]\n descriptor s: sum(step) in [0, 600] by sum\n"
      " descriptor lo: min(step) in [0, 20]\n descriptor hi: max(step) in [0, 20]\n"
      " descriptor late: fraction(step >= 15) in [0, 1]\n descriptor end: last(step) in [0, 20]\n"
      " descriptor share_of_steps: mean(step) / steps in [0, 1]\n"
      " descriptor all: evaluation: mean(epoch) in [0, 2]\n descriptor third: evaluation: fraction(epoch == 2) in [0, 1]\n"
      " descriptor two: max(step, 2) in [0, 20]"));
  const eval::Evaluation e = evaluate(x);
  ASSERT_EQ(e.steps, 60);
  // Each epoch's value, then the mean over the 3 epochs (`by mean`), summed in epoch order.
  const double share = 9.5 / 20;
  EXPECT_EQ(e.descriptors,
            (std::vector<double>{9.5, 3 * 190.0, 0.0, 19.0, 0.25, 19.0, (share + share + share) / 3, 1.0, 1.0 / 3, 19.0}));
  EXPECT_EQ(x.resolved_settings.at("descriptors").substr(0, 57),
            "m: mean(step) in [0, 20]; s: sum(step) in [0, 600] by sum");
}

TEST(StepAggregates, AnEpochStoppedEarlyFoldsTheStepsItRan) {
  const eval::ExperimentSpec x = experiment(
      script("descriptor m: mean(step) in [0, 20]\n descriptor end: last(step) in [0, 20]\n"
             " descriptor n: evaluation: sum(1) in [0, 60]",
             "", "stop epoch when step >= 4"));
  const eval::Evaluation e = evaluate(x);
  ASSERT_EQ(e.steps, 15);
  EXPECT_EQ(e.descriptors, (std::vector<double>{2.0, 4.0, 15.0}));
}

// An objective is a fitness declaration: its end terms fold steps as a descriptor does.
TEST(StepAggregates, FitnessEndTermsFoldStepsToo) {
  const eval::ExperimentSpec x = experiment(
      script("objective g", "fitness g { step: 0  epoch: max(step)  evaluation: 100 * mean(epoch == 1) }\n"));
  ASSERT_EQ(x.further.size(), 1u);
  EXPECT_EQ(x.further[0].epoch_aggregates.size(), 1u);
  EXPECT_EQ(x.further[0].evaluation_aggregates.size(), 1u);
  const eval::Evaluation e = evaluate(x);
  EXPECT_DOUBLE_EQ(e.objectives.at(0), 3 * 19.0 + 100.0 / 3);
}

// The fitness of an experiment is what it was whatever its descriptors fold.
TEST(StepAggregates, FoldingLeavesTheFitnessAsItWas) {
  const eval::Evaluation plain = evaluate(experiment(script("")));
  const eval::Evaluation folded = evaluate(experiment(script("descriptor m: mean(speed) in [0, 1]")));
  EXPECT_EQ(plain.fitness, folded.fitness);
  EXPECT_GT(folded.descriptors.at(0), 0.0);
}

struct Poses final : eval::TraceSink {
  std::vector<eval::TraceStep> steps;
  void on_step(const eval::TraceStep& s) override { steps.push_back(s); }
};

// `positions(3)`: x and y after steps 0, 10 and 19 of the last epoch (`by last`), as the
// trace of the same evaluation shows them.
TEST(StepAggregates, PositionsAreTheRobotsPlaceAtSampledSteps) {
  const eval::ExperimentSpec x = experiment(script("descriptor path: positions(3) in [0, 1m] by last"));
  ASSERT_EQ(x.descriptors.size(), 6u);
  EXPECT_EQ(x.descriptors[0].name, "path_x0");
  EXPECT_EQ(x.descriptors[1].name, "path_y0");
  EXPECT_EQ(x.descriptors[5].name, "path_y2");
  EXPECT_EQ(x.descriptors[3].range, (eval::DeclaredRange{0, 1}));
  EXPECT_EQ(x.resolved_settings.at("descriptors"), "path: positions(3) in [0, 1] by last");
  Poses trace;
  const eval::Evaluation e = evaluate(x, &trace);
  ASSERT_EQ(trace.steps.size(), 60u);
  std::vector<double> expected;
  for (const int step : {0, 10, 19}) {
    const sim::Pose& p = trace.steps[40 + static_cast<std::size_t>(step)].pose;
    expected.push_back(p.x_m);
    expected.push_back(p.y_m);
  }
  EXPECT_EQ(e.descriptors, expected);
  EXPECT_NE(expected[0], expected[4]);   // the robot moved
}

// The samples follow the epoch's steps as `--set steps=N` leaves them.
TEST(StepAggregates, PositionsFollowTheStepsSetLater) {
  eval::ExperimentSpec x = experiment(script("descriptor path: positions(2) in [0, 1m] by last"));
  ASSERT_EQ(apply_setting(x, "steps", "8"), "");
  Poses trace;
  const eval::Evaluation e = evaluate(x, &trace);
  ASSERT_EQ(trace.steps.size(), 24u);
  EXPECT_EQ(e.descriptors.at(2), trace.steps[23].pose.x_m);
  EXPECT_EQ(e.descriptors.at(1), trace.steps[16].pose.y_m);
}

TEST(StepAggregates, QualityDiversityTakesPositions) {
  EXPECT_TRUE(compiled(script("fitness f in [0, 60]\n descriptor path: positions(1) in [0, 1m] by last\n"
                              " evolve map_elites(bins 5) for 2 generations"))
                  .ok());
  EXPECT_TRUE(compiled(script("fitness f in [0, 60]\n descriptor path: positions(5) in [0, 1m]\n"
                              " evolve cvt_map_elites(cells 20, samples 100) for 2 generations"))
                  .ok());
}

TEST(StepAggregates, MistakesAreLocatedAndExplained) {
  const std::string step = diagnostics(with_step("mean(speed)"));
  EXPECT_NE(step.find("2:19: error: `mean(x)` folds x over the steps of an epoch or an evaluation"), std::string::npos)
      << step;
  EXPECT_NE(diagnostics(script("descriptor d: mean(speed, 1) in [0, 1]")).find("`mean` takes 1 argument"),
            std::string::npos);
  EXPECT_NE(diagnostics(script("descriptor d: mean(mean(speed)) in [0, 1]")).find("`mean(x)` folds x"),
            std::string::npos);
  EXPECT_NE(diagnostics(script("descriptor d: mean(steps) in [0, 1]")).find("`steps` counts the steps"),
            std::string::npos);
  EXPECT_NE(diagnostics(script("descriptor d: min(speed, 1, 2) in [0, 1]")).find("`min` takes 2 arguments"),
            std::string::npos);
  for (const std::string k : {"0", "2.5", "513", "speed", "5cm"})
    EXPECT_NE(diagnostics(script("descriptor p: positions(" + k + ") in [0, 1m]"))
                  .find("`positions(K)` samples K positions of the robot: K is a whole number from 1 to 512"),
              std::string::npos)
        << k;
  EXPECT_NE(diagnostics(script("descriptor p: positions(1) in [0, 1m]\n descriptor p_x0: x in [0, 1m]"))
                .find("error"),
            std::string::npos);
}

TEST(StepAggregates, ReadingTheLastStepAloneIsWarnedOf) {
  const CompileResult r = compiled(script("descriptor turning: wheel_diff in [0, 1]"));
  ASSERT_TRUE(r.ok());
  const std::string out = rendered(r);
  EXPECT_NE(out.find("warning: descriptor `turning` reads `wheel_diff` on the last step of each epoch only"),
            std::string::npos)
      << out;
  EXPECT_NE(out.find("write `mean(wheel_diff)`"), std::string::npos) << out;
  EXPECT_NE(diagnostics(script("descriptor bump: evaluation: collision in [0, 1]")).find("of the evaluation only"),
            std::string::npos);
  // Said explicitly, folded, or a state the robot is in: no warning.
  for (const std::string d : {"last(wheel_diff)", "mean(wheel_diff)", "x", "cells_visited", "fraction(collision)"})
    EXPECT_TRUE(compiled(script("descriptor d: " + d + " in [0, 1]")).diagnostics.empty()) << d;
}

}  // namespace
}  // namespace esc::compiler::test
