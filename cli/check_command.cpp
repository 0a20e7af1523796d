#include <fmt/format.h>

#include "cli/commands.hpp"
#include "cli/load.hpp"

namespace esc::cli {

int check_command(const std::vector<std::filesystem::path>& files) {
  int status = kExitOk;
  for (const auto& f : files) {
    const compiler::CompileResult r = load_script(f);
    if (!r.ok()) {
      status = kExitBadInput;
      continue;
    }
    std::string names;
    for (const auto& e : r.experiments) names += (names.empty() ? "" : ", ") + e.name;
    if (!follower_rank())
      fmt::print("{}: ok ({} experiment{}{}{})\n", f.string(), r.experiments.size(),
               r.experiments.size() == 1 ? "" : "s", names.empty() ? "" : ": ", names);
  }
  return status;
}

}  // namespace esc::cli
