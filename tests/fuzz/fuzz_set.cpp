// libFuzzer target: `esc run --set KEY=VALUE` on any bytes (KEY before the first `=`),
// over the paper's obstacle-avoidance experiment and a GP experiment. A value is refused
// with a message or accepted; what is accepted passes the runtime's own checks.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "compiler/compiler.hpp"
#include "fuzz_checks.hpp"

namespace {

std::vector<esc::eval::ExperimentSpec> compiled() {
  esc::compiler::CompileOptions options;
  options.import_paths.push_back(ESC_SOURCE_DIR "/experiments");
  std::vector<esc::eval::ExperimentSpec> out;
  for (const char* file : {"/experiments/paper/obstacle_avoidance.esc", "/experiments/gp/nn_vs_gp.esc"}) {
    const auto r = esc::compiler::compile_file(std::string(ESC_SOURCE_DIR) + file, options);
    if (!r.ok()) std::abort();
    out.push_back(r.experiments.front());
  }
  return out;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::vector<esc::eval::ExperimentSpec> experiments = compiled();
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const std::size_t eq = text.find('=');
  if (eq == std::string_view::npos) return 0;
  for (const esc::eval::ExperimentSpec& original : experiments) {
    esc::eval::ExperimentSpec x = original;
    if (esc::compiler::apply_setting(x, text.substr(0, eq), text.substr(eq + 1)).empty())
      esc::fuzz::require_runnable(x);
  }
  return 0;
}
