// Controllers per body (docs/groups.md): `per_body(bot: c, eye: ce)` gives each body of a group
// its own network, so that bodies reading other sensors drive one group; the genome holds every
// network's weights, in the declaration's order.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "runtime/core/rng.hpp"
#include "runtime/eval/evaluator.hpp"
#include "runtime/eval/genome_fit.hpp"
#include "tests/compiler/helpers.hpp"

namespace esc::compiler::test {
namespace {

// `bot` reads eight IR sensors as `ir`; `eye`, the same body, two as `eye`.
std::string script(const std::string& controllers, const std::string& items,
                   const std::string& fitness_body = "step: forward_speed") {
  return "robot bot { inertia on }\n"
         "robot eye = bot { ir_name eye  ir_sensors [(30deg, 30deg), (-30deg, -30deg)] }\n"
         "robot twin = bot { }\n"
         "arena a { size 3m x 3m  start random }\n"
         "fitness f { " + fitness_body + " }\n"
         "controller c = mlp(ir[0..7] -> wheels)\n"
         "controller ce = mlp(eye[0..1] -> hidden 2 -> wheels)\n" +
         controllers + "\nexperiment e { arena a  fitness f  epochs 2 x 30 steps  " + items + " }\n";
}

const std::string kBoth = "controller both = per_body(bot: c, eye: ce)";
// Two robots of each body, a metre apart: too far to sense or meet each other in 30 steps.
const std::string kApart = "formation at [(1m, 1m, 0deg), (2m, 1m, 90deg), (1m, 2m, 180deg), (2m, 2m, 270deg)]";
// The same four, a few centimetres apart: they meet.
const std::string kCrowded =
    "formation at [(30cm, 30cm, 0deg), (42cm, 30cm, 90deg), (30cm, 42cm, 180deg), (42cm, 42cm, 270deg)]";

std::vector<double> random_weights(std::size_t n, std::uint64_t seed) {
  Rng rng(seed);
  std::vector<double> w(n);
  for (double& g : w) g = rng.uniform(-2.0, 2.0);
  return w;
}

std::vector<double> joined(std::vector<double> a, const std::vector<double>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

struct Collect final : eval::TraceSink {
  std::vector<eval::TraceStep> steps;
  void on_step(const eval::TraceStep& t) override { steps.push_back(t); }
};

std::vector<eval::TraceStep> trace(const eval::ExperimentSpec& x, const std::vector<double>& genome) {
  eval::Evaluator evaluator(x);
  Collect rows;
  (void)evaluator.evaluate(x.controllers.front(), genome, 5, &rows);
  return rows.steps;
}

TEST(PerBody, EachBodyIsGivenItsNetworkAndTheGenomeHoldsThemAll) {
  const eval::ExperimentSpec x = first_experiment(script(kBoth, "compare both  robot bot x 2, eye x 2"), "p.esc");
  ASSERT_EQ(x.controllers.size(), 1u);
  const control::ControllerSpec& both = x.controllers.front();
  ASSERT_TRUE(both.per_body());
  EXPECT_EQ(both.network_bodies, (std::vector<std::string>{"bot", "eye"}));
  EXPECT_EQ(both.body_networks, (std::vector<std::size_t>{0, 1}));
  // 8 inputs to 2 outputs: 18 weights; 2 inputs, 2 hidden, 2 outputs: 6 + 6.
  EXPECT_EQ(both.genome_size(), 18u + 12u);
  EXPECT_EQ(both.network_offset(1), 18u);
  EXPECT_EQ(both.architecture(), "bot 8-2 / eye 2-2-2");
  EXPECT_EQ(x.problem_of(both).genome_size, 30u);
  EXPECT_EQ(both.networks[1].mlp.inputs.size(), 2u);
  // Listed in another order, the genome follows the declaration; the bodies keep theirs.
  const eval::ExperimentSpec y = first_experiment(
      script("controller both = per_body(eye: ce, bot: c)", "compare both  robot bot x 2, eye x 2"), "p.esc");
  EXPECT_EQ(y.controllers.front().body_networks, (std::vector<std::size_t>{1, 0}));
  EXPECT_EQ(y.controllers.front().network_offset(1), 12u);
}

TEST(PerBody, TwoBodiesAlikeWithEqualNetworksAreTheClonalTeam) {
  const eval::ExperimentSpec clonal = first_experiment(script("", "compare c  robot bot x 2, twin x 2  " + kCrowded), "p.esc");
  const eval::ExperimentSpec per_body = first_experiment(
      script("controller both = per_body(bot: c, twin: c)", "compare both  robot bot x 2, twin x 2  " + kCrowded),
      "p.esc");
  const std::vector<double> a = random_weights(clonal.controllers.front().genome_size(), 3);
  const eval::Evaluation one = eval::Evaluator(clonal).evaluate(clonal.controllers.front(), a, 7);
  const eval::Evaluation two = eval::Evaluator(per_body).evaluate(per_body.controllers.front(), joined(a, a), 7);
  EXPECT_EQ(one.fitness, two.fitness);
  EXPECT_EQ(one.steps, two.steps);
  // And not by chance: another network for the twins drives them otherwise.
  const eval::Evaluation other =
      eval::Evaluator(per_body).evaluate(per_body.controllers.front(), joined(a, random_weights(a.size(), 4)), 7);
  EXPECT_NE(one.fitness, other.fitness);
}

TEST(PerBody, AStoredGenomeIsReadOnlyInItsNetworksOrder) {
  const eval::ExperimentSpec x = first_experiment(script(kBoth, "compare both  robot bot x 2, eye x 2"), "p.esc");
  const control::ControllerSpec& both = x.controllers.front();
  EXPECT_EQ(eval::layout_problem(both, "bot 8-2 / eye 2-2-2"), "");
  EXPECT_EQ(eval::layout_problem(both, ""), "") << "a genome file from before architectures were stored";
  EXPECT_EQ(eval::layout_problem(both, "kh 8-2 / ey 2-2-2"), "") << "bodies renamed, networks in order";
  EXPECT_NE(eval::layout_problem(both, "eye 2-2-2 / bot 8-2"), "");
  // Two bodies of alike networks, listed the other way round: each would read the other's.
  const eval::ExperimentSpec twins = first_experiment(
      script("controller both = per_body(bot: c, twin: c)", "compare both  robot bot x 2, twin x 2"), "p.esc");
  EXPECT_NE(eval::layout_problem(twins.controllers.front(), "twin 8-2 / bot 8-2"), "");
  // One network: a plain controller's genome is a controller per body's of one body, and back.
  const eval::ExperimentSpec alone =
      first_experiment(script("controller one = per_body(bot: c)", "compare one  robot bot"), "p.esc");
  EXPECT_EQ(eval::layout_problem(alone.controllers.front(), "8-2"), "");
  EXPECT_EQ(eval::layout_problem(first_experiment(script("", "compare c  robot bot"), "p.esc").controllers.front(),
                                 "bot 8-2"),
            "");
}

TEST(PerBody, EachRobotIsDrivenByItsOwnBodysNetwork) {
  const eval::ExperimentSpec x = first_experiment(script(kBoth, "compare both  robot bot x 2, eye x 2  " + kApart), "p.esc");
  const control::ControllerSpec& both = x.controllers.front();
  const std::vector<double> bot = random_weights(18, 1), eye = random_weights(12, 2), eye2 = random_weights(12, 3);
  const std::vector<eval::TraceStep> a = trace(x, joined(bot, eye)), b = trace(x, joined(bot, eye2));
  ASSERT_EQ(a.size(), b.size());
  ASSERT_FALSE(a.empty());
  bool eyes_differ = false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(a[i].robot, b[i].robot);
    if (x.body_of(static_cast<std::size_t>(a[i].robot)) == 0) {
      EXPECT_EQ(a[i].pose.x_m, b[i].pose.x_m) << "row " << i;
      EXPECT_EQ(a[i].left_command, b[i].left_command) << "row " << i;
    } else {
      eyes_differ = eyes_differ || a[i].left_command != b[i].left_command;
    }
  }
  EXPECT_TRUE(eyes_differ);
  eval::Evaluator evaluator(x);
  EXPECT_THROW((void)evaluator.evaluate(both, bot, 5), std::invalid_argument);
}

TEST(PerBody, BodiesReadingOtherSensorsNeedANetworkEach) {
  std::string out = refusal(script("", "compare c  robot bot x 2, eye x 2"), "p.esc");
  EXPECT_NE(out.find("p.esc:9:83: error: `eye` has another number of `ir_sensors` than `bot` (2 against 8): the bodies "
                     "of a group share the sensors one controller reads"),
            std::string::npos)
      << out;
  EXPECT_NE(out.find("help: compare controllers with a network per body: `controller NAME = per_body(bot: NETWORK, "
                     "eye: NETWORK)`"),
            std::string::npos)
      << out;
  EXPECT_NE(out.find("note: `c` is one network for every body"), std::string::npos) << out;
  // Every compared controller: one per body beside one that is not is still refused.
  out = refusal(script(kBoth, "compare both, c  robot bot x 2, eye x 2"), "p.esc");
  EXPECT_NE(out.find("`eye` has another number of `ir_sensors`"), std::string::npos) << out;
  // The drive and the step are the world's, networks per body or not.
  out = refusal(script("robot slow = eye { control_step 200ms }\ncontroller both = per_body(bot: c, slow: ce)",
                       "compare both  robot bot x 2, slow x 2"),
                "p.esc");
  EXPECT_NE(out.find("another `control_step`"), std::string::npos) << out;
}

TEST(PerBody, AControllerPerBodyMustFitTheGroup) {
  // A body without a network, at the compared name.
  std::string out = refusal(script("controller one = per_body(bot: c)", "compare one  robot bot x 2, eye x 2"), "p.esc");
  EXPECT_NE(out.find("p.esc:9:65: error: controller `one` has no network for `eye`, a body of experiment `e`'s group"),
            std::string::npos)
      << out;
  // A network for a body the group lacks.
  out = refusal(script(kBoth, "compare both  robot bot x 2"), "p.esc");
  EXPECT_NE(out.find("controller `both` has a network for `eye`, a body experiment `e` does not have"),
            std::string::npos)
      << out;
  // A network that reads what its body does not have.
  out = refusal(script("controller crossed = per_body(bot: ce, eye: c)", "compare crossed  robot bot x 2, eye x 2"),
                "p.esc");
  EXPECT_NE(out.find("`ir` names IR sensors, but body `eye` of experiment `e`'s group calls its IR sensors `eye`"),
            std::string::npos)
      << out;
  // The measures are read on every robot: not by a name the bodies give apart.
  out = refusal(script(kBoth, "compare both  robot bot x 2, eye x 2", "step: ir[0]"), "p.esc");
  EXPECT_NE(out.find("the experiment's measures read the IR sensors, which `bot` calls `ir` and `eye` `eye`"),
            std::string::npos)
      << out;
  // A sensor no body has is said once, where the fitness reads it.
  out = refusal(script(kBoth, "compare both  robot bot x 2, eye x 2", "step: range[0]"), "p.esc");
  EXPECT_NE(out.find("1 error generated"), std::string::npos) << out;
  // Roles within bodies are not built.
  out = refusal(script(kBoth, "compare both  robot bot x 2, eye x 2  roles 2"), "p.esc");
  EXPECT_NE(out.find("`both` is a controller per body: its genome holds a network per body, not per role"),
            std::string::npos)
      << out;
  // A frozen behavior is one network.
  out = refusal(script(kBoth, "compare both  robot bot x 2, eye x 2") +
                    "behavior frozen = evolved from experiment e controller both\n"
                    "controller sup = supervisor(mlp(ir[0..7] -> hidden 2), behaviors [frozen])\n"
                    "experiment e2 { arena a  fitness f  compare sup  robot bot }\n",
                "p.esc");
  EXPECT_NE(out.find("`frozen` freezes `both`, a controller per body, and a behavior is one network"), std::string::npos)
      << out;
  // A network supervising another experiment's evolved controller.
  out = refusal(script("robot solo = bot { }\n", "compare c  robot solo") +
                    "behavior frozen = evolved from experiment e controller c\n"
                    "controller sup = supervisor(mlp(ir[0..7] -> hidden 2), behaviors [frozen])\n"
                    "controller team = per_body(bot: sup, eye: ce)\n"
                    "experiment e2 { arena a  fitness f  compare team  robot bot, eye }\n",
                "p.esc");
  EXPECT_NE(out.find("`sup` supervises `frozen`, an evolved controller: a controller per body's networks take "
                     "hand-written behaviors only"),
            std::string::npos)
      << out;
  // A behavior both networks act with is bound on each body: reading `ir[7]` on `eye` is an
  // error whichever body the group lists first.
  const std::string veer = "behavior veer(p) { wheels(p * (1 - ir[7]), p) }\n"
                           "controller sk = symbolic(mlp(ir[0..7] -> hidden 2), actions [veer])\n"
                           "controller se = symbolic(mlp(eye[0..1] -> hidden 2), actions [veer])\n"
                           "controller team = per_body(bot: sk, eye: se)";
  for (const std::string group : {"robot bot x 2, eye x 2", "robot eye x 2, bot x 2"}) {
    out = refusal(script(veer, "compare team  " + group), "p.esc");
    EXPECT_NE(out.find("calls its IR sensors `eye`"), std::string::npos) << group << "\n" << out;
  }
  // What the arena decides is said once, not once per body.
  out = refusal(script("behavior home(p) { wheels(p * in(base), p) }\n"
                       "controller hk = symbolic(mlp(ir[0..7] -> hidden 2), actions [home])\n"
                       "controller he = symbolic(mlp(eye[0..1] -> hidden 2), actions [home])\n"
                       "controller team = per_body(bot: hk, eye: he)",
                       "compare team  robot bot x 2, eye x 2"),
                "p.esc");
  EXPECT_NE(out.find("base"), std::string::npos) << out;
  EXPECT_EQ(out.find("1 error generated"), out.find("error generated") - 2) << out;
  // A robot alone is a group of one body.
  const eval::ExperimentSpec alone =
      first_experiment(script("controller one = per_body(bot: c)", "compare one  robot bot"), "p.esc");
  EXPECT_EQ(alone.controllers.front().body_networks, (std::vector<std::size_t>{0}));
}

TEST(PerBody, EveryBodyMustGiveWhatIsReadOnIt) {
  // A measure the first body gives and a further one lacks: at the group, naming that body.
  const std::string ground = "robot gnd = bot { ground_sensors [(9deg, 2cm), (-9deg, 2cm)] }\n"
                             "controller cg = per_body(gnd: c, bot: c)";
  const std::string out =
      refusal(script(ground, "compare cg  robot gnd x 2, bot x 2", "step: ground_sensor[0]"), "p.esc");
  EXPECT_NE(out.find("p.esc:10:69: error: the experiment's measures read what a body of its group lacks: "
                     "`ground_sensor[0]` reads ground sensor 0, but body `bot`"),
            std::string::npos)
      << out;
  EXPECT_NE(out.find("1 error generated"), std::string::npos) << out;
  // A setting that takes sensors from every body: each body's own network is checked on it.
  eval::ExperimentSpec x = first_experiment(script(kBoth, "compare both  robot eye x 2, bot x 2"), "p.esc");
  const std::string m = apply_setting(x, "robot.ir_sensors", "[(30deg, 30deg), (-30deg, -30deg)]");
  EXPECT_NE(m.find("`ir[2]` reads IR sensor 2, but body `bot`"), std::string::npos) << m;
}

TEST(PerBody, ItsNetworksAreNetworksOfOneHead) {
  const std::string more = "behavior go(p) { wheels(p, p) }\nbehavior turn(p) { wheels(p, -p) }\n"
                           "controller s = symbolic(mlp(ir[0..7] -> hidden 2), actions [go, turn])\n"
                           "controller s2 = symbolic(mlp(eye[0..1] -> hidden 2), actions [turn, go])\n"
                           "controller n = neat(eye[0..1] -> wheels)\n";
  std::string out = refusal(script(more + "controller m = per_body(bot: s, eye: ce)", "compare m  robot bot, eye"), "p.esc");
  EXPECT_NE(out.find("`ce` (classical, choosing the wheels) has another head than `s` (symbolic, choosing [go, turn])"),
            std::string::npos)
      << out;
  out = refusal(script(more + "controller m = per_body(bot: s, eye: s2)", "compare m  robot bot, eye"), "p.esc");
  EXPECT_NE(out.find("has another head than `s`"), std::string::npos) << out;
  out = refusal(script(more + "controller m = per_body(bot: c, eye: n)", "compare m  robot bot, eye"), "p.esc");
  EXPECT_NE(out.find("`n` is a NEAT network: a controller per body holds networks of fixed topology"), std::string::npos)
      << out;
  out = refusal(script(kBoth + "\ncontroller m = per_body(bot: both, eye: ce)", "compare m  robot bot, eye"), "p.esc");
  EXPECT_NE(out.find("`both` is itself a controller per body"), std::string::npos) << out;
  out = refusal(script("controller m = per_body(bot: c, bot: c)", "compare m  robot bot"), "p.esc");
  EXPECT_NE(out.find("body `bot` is given a network twice"), std::string::npos) << out;
  out = refusal(script("controller m = per_body(bott: c)", "compare m  robot bot"), "p.esc");
  EXPECT_NE(out.find("bott"), std::string::npos) << out;
  // Symbolic networks of one head, their behaviors bound per body.
  const eval::ExperimentSpec x = first_experiment(
      script(more + "controller s3 = symbolic(mlp(eye[0..1] -> hidden 2), actions [go, turn])\n"
                    "controller m = per_body(bot: s, eye: s3)",
             "compare m  robot bot x 2, eye x 2"),
      "p.esc");
  EXPECT_EQ(x.controllers.front().choice_names(), (std::vector<std::string>{"go", "turn"}));
  EXPECT_EQ(x.controllers.front().architecture(), "bot 8-2-4 / eye 2-2-4");   // two actions, one parameter each
}

}  // namespace
}  // namespace esc::compiler::test
