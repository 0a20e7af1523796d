#include <fmt/format.h>

#include "cli/commands.hpp"
#include "cli/library_path.hpp"
#include "cli/load.hpp"

namespace esc::cli {

int check_command(const std::vector<std::filesystem::path>& files) {
  int status = kExitOk;
  for (const auto& given : files) {
    const std::filesystem::path f = find_main_script(given);
    const compiler::CompileResult r = load_script(f);
    if (!r.ok()) {
      status = kExitBadInput;
      continue;
    }
    std::string names;
    for (const auto& e : r.experiments) names += (names.empty() ? "" : ", ") + e.name;
    std::string studies;
    for (const auto& s : r.studies)
      studies += fmt::format("{}{} ({} condition{})", studies.empty() ? "" : ", ", s.name, s.conditions.size(),
                             s.conditions.size() == 1 ? "" : "s");
    if (!follower_rank())
      fmt::print("{}: ok ({} experiment{}{}{}{}{})\n", f.string(), r.experiments.size(),
                 r.experiments.size() == 1 ? "" : "s", names.empty() ? "" : ": ", names,
                 studies.empty() ? "" : fmt::format("; {} stud{}: ", r.studies.size(), r.studies.size() == 1 ? "y" : "ies"),
                 studies);
  }
  return status;
}

}  // namespace esc::cli
