// `behavior b = evolved from experiment E controller C`: name resolution, the
// dependencies of the compiled experiment, imported experiments and dependency cycles.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <variant>

#include "helpers.hpp"

namespace esc::compiler {
namespace {

using test::options;
using test::rendered;

const std::string kBasic =
    "arena r { size 1m x 1m }\n"
    "fitness f { step: speed }\n"
    "behavior go(p) { wheels(p, p) }\n"
    "controller CC = mlp(ir[0..7] -> hidden 3 -> wheels)\n"
    "experiment basic { arena r  fitness f  compare CC }\n";

TEST(EvolvedBehavior, FillsADependencyOfTheSupervisor) {
  const std::string text = kBasic +
                           "behavior avoid = evolved from experiment basic controller CC\n"
                           "controller SV = supervisor(elman(ir[0..7], energy -> hidden 5), behaviors [avoid, go(0.5)])\n"
                           "experiment top { arena r  fitness f  compare CC, SV }\n";
  const CompileResult r = compile_source(text, "evolved.esc", options());
  ASSERT_TRUE(r.ok()) << rendered(r);
  ASSERT_EQ(r.experiments.size(), 2u);
  EXPECT_EQ(r.all_experiments.size(), 2u);
  const eval::ExperimentSpec& top = r.experiments[1];
  EXPECT_TRUE(r.experiments[0].dependencies.empty());
  ASSERT_EQ(top.dependencies.size(), 1u);
  EXPECT_EQ(top.dependencies[0].experiment, "basic");
  EXPECT_EQ(top.dependencies[0].controller, "CC");
  ASSERT_EQ(top.dependencies[0].targets.size(), 1u);
  EXPECT_EQ(top.dependencies[0].targets[0], (std::pair<std::size_t, std::size_t>{1, 0}));
  const control::ControllerSpec& sv = top.controllers[1];
  ASSERT_EQ(sv.behaviors.size(), 2u);
  EXPECT_EQ(sv.behaviors[0].name, "avoid");
  const auto* fixed = std::get_if<control::FixedController>(&sv.behaviors[0].what);
  ASSERT_NE(fixed, nullptr);
  ASSERT_NE(fixed->spec, nullptr);
  EXPECT_EQ(fixed->spec->name, "CC");
  EXPECT_EQ(fixed->spec->genome_size(), 3u * (1 + 8) + 2u * (1 + 3));   // 8-3-2 with biases
  EXPECT_TRUE(fixed->genome.empty());                              // filled by `esc run`
  EXPECT_TRUE(std::holds_alternative<control::BehaviorCall>(sv.behaviors[1].what));
  EXPECT_EQ(sv.genome_size(), 5u * (1 + 9 + 5) + 2u * (1 + 5));   // only the supervisor's own weights
}

TEST(EvolvedBehavior, TheExperimentMayBeImported) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "esc-evolved-import";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "basic.esc") << kBasic;
  const std::string main =
      "import \"basic.esc\"\n"
      "behavior avoid = evolved from experiment basic controller CC\n"
      "controller SV = supervisor(mlp(ir[0..7] -> hidden 2), behaviors [avoid, go(0.5)])\n"
      "experiment top { arena r  fitness f  compare SV }\n";
  std::ofstream(dir / "main.esc") << main;
  const CompileResult r = compile_file(dir / "main.esc", options());
  ASSERT_TRUE(r.ok()) << rendered(r);
  ASSERT_EQ(r.experiments.size(), 1u);   // only the main file's
  EXPECT_EQ(r.experiments[0].name, "top");
  ASSERT_EQ(r.all_experiments.size(), 2u);
  bool has_basic = false;
  for (const auto& x : r.all_experiments) has_basic = has_basic || x.name == "basic";
  EXPECT_TRUE(has_basic);
  ASSERT_EQ(r.experiments[0].dependencies.size(), 1u);
  EXPECT_EQ(r.experiments[0].dependencies[0].experiment, "basic");
}

TEST(EvolvedBehavior, MisspelledNamesAreLocatedWithASuggestion) {
  const std::string text = kBasic +
                           "behavior avoid = evolved from experiment basci controller CC\n"
                           "controller SV = supervisor(mlp(ir[0..7]), behaviors [avoid])\n"
                           "experiment top { arena r  fitness f  compare SV }\n";
  const CompileResult r = compile_source(text, "evolved.esc", options());
  EXPECT_FALSE(r.ok());
  EXPECT_NE(rendered(r).find("evolved.esc:6:42: error: unknown experiment `basci`; did you mean `basic`?"),
            std::string::npos)
      << rendered(r);
}

TEST(EvolvedBehavior, TakesNoArgumentsAndIsNoAction) {
  const std::string text = kBasic +
                           "behavior avoid = evolved from experiment basic controller CC\n"
                           "controller SV = supervisor(mlp(ir[0..7]), behaviors [avoid(1)])\n"
                           "controller SY = symbolic(mlp(ir[0..7]), actions [avoid])\n"
                           "experiment top { arena r  fitness f  compare SV, SY }\n";
  const CompileResult r = compile_source(text, "evolved.esc", options());
  EXPECT_FALSE(r.ok());
  const std::string out = rendered(r);
  EXPECT_NE(out.find("`avoid` is an evolved controller and takes no arguments"), std::string::npos) << out;
  EXPECT_NE(out.find("it can be a supervisor's behavior, not a symbolic controller's action"), std::string::npos)
      << out;
}

TEST(EvolvedBehavior, ACycleOfExperimentsIsAnError) {
  const std::string text =
      "arena r { size 1m x 1m }\n"
      "fitness f { step: speed }\n"
      "behavior go(p) { wheels(p, p) }\n"
      "behavior from_a = evolved from experiment a controller sa\n"
      "behavior from_b = evolved from experiment b controller sb\n"
      "behavior from_c = evolved from experiment c controller sc\n"
      "controller sa = supervisor(mlp(ir[0..7]), behaviors [from_b, go(0.5)])\n"
      "controller sb = supervisor(mlp(ir[0..7]), behaviors [from_c])\n"
      "controller sc = supervisor(mlp(ir[0..7]), behaviors [from_a])\n"
      "experiment a { arena r  fitness f  compare sa }\n"
      "experiment b { arena r  fitness f  compare sb }\n"
      "experiment c { arena r  fitness f  compare sc }\n";
  const CompileResult r = compile_source(text, "cycle.esc", options());
  EXPECT_FALSE(r.ok());
  EXPECT_TRUE(r.experiments.empty());
  const std::string out = rendered(r);
  EXPECT_NE(out.find("cycle.esc:4:43: error: experiments depend on each other's evolved controllers in a cycle: "
                     "`a` -> `b` -> `c` -> `a`"),
            std::string::npos)
      << out;
  EXPECT_EQ(out.find("cycle:", out.find("cycle:") + 1), std::string::npos) << "reported more than once:\n" << out;
}

}  // namespace
}  // namespace esc::compiler
