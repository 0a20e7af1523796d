// libFuzzer target: the compiler's front end on any bytes. Whatever the input, compiling
// must end with diagnostics or experiments, never a crash, a hang or a sanitizer report,
// and what it accepts must be accepted by the runtime too: every compiled experiment's
// robot and arena pass the World's own checks, each compared controller's algorithm (the
// ES, GP, NEAT, ...) takes its settings and genome, and its resolved settings render. Run
// by ctest for a few seconds over experiments/, examples/ and tests/bad/ (docs/install.md:
// how to run it longer).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "compiler/compiler.hpp"
#include "fuzz_checks.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  esc::compiler::CompileOptions options;
  options.import_paths.push_back(ESC_SOURCE_DIR "/experiments");
  const esc::compiler::CompileResult r =
      esc::compiler::compile_source(text, ESC_SOURCE_DIR "/experiments/fuzz-input.esc", options);
  (void)esc::compiler::render_all(r.diagnostics, r.sources);
  for (const esc::eval::ExperimentSpec& x : r.experiments) esc::fuzz::require_runnable(x);
  return 0;
}
