// `library` blocks (a supervisor's behavior list expands a library into its members) and
// experiments that start from, or only evaluate, another experiment's stored controllers.
#include <gtest/gtest.h>

#include <variant>

#include "helpers.hpp"

namespace esc::compiler {
namespace {

using test::options;
using test::rendered;

const std::string kWorld =
    "arena r { size 1m x 1m }\n"
    "fitness f { step: speed }\n"
    "controller CC = mlp(ir[0..7] -> hidden 3 -> wheels)\n"
    "experiment basic { arena r  fitness f  compare CC }\n"
    "library moves {\n"
    "  behavior spin() { wheels(1, -1) }\n"
    "  behavior avoid = evolved from experiment basic controller CC\n"
    "}\n";

std::vector<std::string> names(const control::ControllerSpec& c) {
  std::vector<std::string> n;
  for (const auto& b : c.behaviors) n.push_back(b.name);
  return n;
}

TEST(Library, ALibraryStandsForItsMembersInOrder) {
  const std::string text = kWorld +
                           "library extra { behavior still() { wheels(0, 0) } }\n"
                           "controller SV = supervisor(elman(ir[0..7] -> hidden 2), behaviors [extra, moves.spin, moves])\n"
                           "experiment top { arena r  fitness f  compare SV }\n";
  const CompileResult r = compile_source(text, "lib.esc", options());
  ASSERT_TRUE(r.ok()) << rendered(r);
  const eval::ExperimentSpec& top = r.experiments[1];
  const control::ControllerSpec& sv = top.controllers[0];
  // A member listed twice gets a numbered name, so usage tables tell them apart.
  EXPECT_EQ(names(sv), (std::vector<std::string>{"still", "spin", "spin_2", "avoid"}));
  EXPECT_EQ(sv.output_count(), 4);
  EXPECT_TRUE(std::holds_alternative<control::FixedController>(sv.behaviors[3].what));
  // The evolved member makes `basic` a dependency, filling behavior 3 of controller 0.
  ASSERT_EQ(top.dependencies.size(), 1u);
  EXPECT_EQ(top.dependencies[0].experiment, "basic");
  EXPECT_EQ(top.dependencies[0].targets[0], (std::pair<std::size_t, std::size_t>{0, 3}));
}

TEST(Library, AParametrisedMemberInALibraryNeedsItsArguments) {
  // Listed as a whole library, go(p) gets no argument.
  const std::string text = kWorld +
                           "library tuned { behavior go(p) { wheels(p, p) } }\n"
                           "controller SV = supervisor(elman(ir[0..7] -> hidden 2), behaviors [tuned])\n"
                           "experiment top { arena r  fitness f  compare SV }\n";
  const CompileResult r = compile_source(text, "lib.esc", options());
  EXPECT_FALSE(r.ok());
  EXPECT_NE(rendered(r).find("error: behavior `tuned.go` takes 1 argument, found 0"), std::string::npos) << rendered(r);
}

TEST(Library, MistakesAreReportedAtTheirPlace) {
  const std::string text = kWorld +
                           "controller A = supervisor(mlp(ir[0..7]), behaviors [moves(1)])\n"
                           "controller B = supervisor(mlp(ir[0..7]), behaviors [moves.jump])\n"
                           "experiment top { arena r  fitness f  compare A, B }\n";
  const CompileResult r = compile_source(text, "lib.esc", options());
  const std::string out = rendered(r);
  EXPECT_NE(out.find("lib.esc:9:53: error: `moves` is a library and takes no arguments"), std::string::npos) << out;
  EXPECT_NE(out.find("lib.esc:10:53: error: unknown behavior `moves.jump`"), std::string::npos) << out;
}

TEST(Library, MembersDoNotClashWithOtherNames) {
  // `spin` outside the library and `moves.spin` inside are different behaviors.
  const std::string text = kWorld +
                           "behavior spin(p) { wheels(p, -p) }\n"
                           "controller SV = supervisor(mlp(ir[0..7]), behaviors [spin(1), moves.spin])\n"
                           "experiment top { arena r  fitness f  compare SV }\n";
  const CompileResult r = compile_source(text, "lib.esc", options());
  ASSERT_TRUE(r.ok()) << rendered(r);
  EXPECT_EQ(names(r.experiments[1].controllers[0]), (std::vector<std::string>{"spin(1)", "spin_2"}));
}

TEST(StartFrom, NamesTheExperimentAndKeepsOneGenerationWhenEvaluating) {
  const std::string text = kWorld +
                           "experiment again { arena r  fitness f  evaluate from experiment basic  compare CC }\n"
                           "experiment more { arena r  fitness f  start from experiment basic\n"
                           "  evolve es(mu 3, lambda 6) for 7 generations  compare CC }\n";
  const CompileResult r = compile_source(text, "start.esc", options());
  ASSERT_TRUE(r.ok()) << rendered(r);
  const eval::ExperimentSpec& again = r.experiments[1];
  ASSERT_TRUE(again.start_from.has_value());
  EXPECT_EQ(again.start_from->experiment, "basic");
  EXPECT_TRUE(again.start_from->evaluate_only);
  EXPECT_EQ(again.max_generations(), 1);
  EXPECT_EQ(again.resolved_settings.at("start_from"), "evaluate from experiment basic");
  const eval::ExperimentSpec& more = r.experiments[2];
  EXPECT_FALSE(more.start_from->evaluate_only);
  EXPECT_EQ(more.max_generations(), 7);
}

TEST(StartFrom, TheOtherExperimentMustCompareTheSameControllers) {
  const std::string text = kWorld +
                           "controller SC = symbolic(mlp(ir[0..7]), actions [go])\n"
                           "behavior go(p) { wheels(p, p) }\n"
                           "experiment again { arena r  fitness f  evaluate from experiment basic  compare CC, SC }\n";
  const CompileResult r = compile_source(text, "start.esc", options());
  const std::string out = rendered(r);
  EXPECT_FALSE(r.ok());
  EXPECT_NE(out.find("error: experiment `basic` does not compare `SC`: there is no stored `SC` to start from"),
            std::string::npos) << out;
}

TEST(StartFrom, EvaluatingEvolvesNothing) {
  const std::string text = kWorld +
                           "experiment again { arena r  fitness f  evaluate from experiment basic\n"
                           "  evolve es(mu 3, lambda 6) for 7 generations  compare CC }\n";
  const CompileResult r = compile_source(text, "start.esc", options());
  EXPECT_NE(rendered(r).find("error: an experiment that evaluates stored controllers evolves nothing"),
            std::string::npos) << rendered(r);
}

TEST(StartFrom, ExperimentsStartingFromEachOtherAreACycle) {
  const std::string text = kWorld +
                           "experiment a { arena r  fitness f  start from experiment b  compare CC }\n"
                           "experiment b { arena r  fitness f  start from experiment a  compare CC }\n"
                           "experiment c { arena r  fitness f  start from experiment c  compare CC }\n";
  const CompileResult r = compile_source(text, "start.esc", options());
  const std::string out = rendered(r);
  EXPECT_NE(out.find("in a cycle: `a` -> `b` -> `a`"), std::string::npos) << out;
  EXPECT_NE(out.find("error: experiment `c` cannot start from itself"), std::string::npos) << out;
}

}  // namespace
}  // namespace esc::compiler
