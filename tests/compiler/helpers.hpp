#pragma once
// Shared helpers of the compiler tests.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "compiler/compiler.hpp"

namespace esc::compiler::test {

inline std::filesystem::path source_dir() { return ESC_SOURCE_DIR; }

inline CompileOptions options() {
  CompileOptions o;
  o.import_paths.push_back(source_dir() / "experiments");
  return o;
}

inline std::string rendered(const CompileResult& r) { return render_all(r.diagnostics, r.sources); }

// The first experiment of script text `text` compiled as file `file` (a test fails if it
// does not compile).
inline eval::ExperimentSpec first_experiment(const std::string& text, const std::string& file) {
  const auto r = compile_source(text, file, options());
  EXPECT_TRUE(r.ok()) << rendered(r);
  return r.ok() ? r.experiments.at(0) : eval::ExperimentSpec{};
}

// The rendered diagnostics of script text that must not compile.
inline std::string refusal(const std::string& text, const std::string& file) {
  const auto r = compile_source(text, file, options());
  EXPECT_FALSE(r.ok());
  return rendered(r);
}

// The paper's obstacle-avoidance experiment, compiled (a test fails if it does not compile).
inline eval::ExperimentSpec paper() {
  const auto r = compile_file(source_dir() / "experiments/paper/obstacle_avoidance.esc", options());
  EXPECT_TRUE(r.ok()) << rendered(r);
  return r.experiments.at(0);
}

// A complete script around one fitness `step:` expression.
inline std::string with_step(const std::string& step) {
  return "arena a { size 1m x 1m }\n"
         "fitness f { step: " + step + " }\n"
         "controller c = mlp(ir[0..7] -> wheels)\n"
         "experiment e { arena a  fitness f  compare c }\n";
}

}  // namespace esc::compiler::test
