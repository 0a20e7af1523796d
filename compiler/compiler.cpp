// The compiler driver: reads the main script and its imports (each file once), parses
// them, declares every name, checks every declaration and lowers the main file's
// experiments.
#include "compiler/compiler.hpp"

#include <array>
#include <deque>
#include <fstream>
#include <functional>
#include <map>
#include <set>

#include <fmt/format.h>

#include "compiler/lower_arena.hpp"
#include "compiler/lower_behavior.hpp"
#include "compiler/lower_controller.hpp"
#include "compiler/lower_experiment.hpp"
#include "compiler/lower_fitness.hpp"
#include "compiler/lower_primitives.hpp"
#include "compiler/lower_robot.hpp"
#include "compiler/lower_study.hpp"
#include "compiler/parse.hpp"
#include "compiler/resolver.hpp"
#include "compiler/text.hpp"

namespace esc::compiler {

namespace fs = std::filesystem;

bool CompileResult::ok() const noexcept {
  for (const Diagnostic& d : diagnostics)
    if (d.severity == Severity::Error) return false;
  return true;
}

namespace {

constexpr std::uintmax_t kMaxFileBytes = 16u << 20;

// Reads a whole file; an error message instead when it cannot.
bool read_file(const fs::path& p, std::string& out, std::string& error) {
  std::error_code ec;
  if (fs::is_directory(p, ec)) {
    error = "is a directory";
    return false;
  }
  const auto size = fs::file_size(p, ec);
  if (!ec && size > kMaxFileBytes) {
    error = fmt::format("is too large ({} bytes; scripts are at most {} bytes)", size, kMaxFileBytes);
    return false;
  }
  std::ifstream in(p, std::ios::binary);
  if (!in) {
    error = "cannot be opened";
    return false;
  }
  // At most one byte past the limit, whatever the file claims: a device or a pipe
  // (`import "/dev/zero"`) has no size and would be read forever.
  out.clear();
  std::array<char, 1 << 16> chunk{};
  while (out.size() <= kMaxFileBytes && in.read(chunk.data(), chunk.size()).gcount() > 0)
    out.append(chunk.data(), static_cast<std::size_t>(in.gcount()));
  if (out.size() > kMaxFileBytes) {
    error = fmt::format("is too large (more than {} bytes; scripts are at most {} bytes)", kMaxFileBytes, kMaxFileBytes);
    out.clear();
    return false;
  }
  return true;
}

class Driver {
 public:
  Driver(const CompileOptions& options, CompileResult& result) : options_(options), result_(result) {}

  void run(std::string_view text, const fs::path& name) {
    const std::size_t main = load(text, name, key_of(name));
    // Follow imports breadth-first; each file is loaded once.
    for (std::size_t i = 0; i < modules_.size(); ++i) {
      for (const ast::Import& imp : modules_[i].imports) {
        fs::path display, key;
        if (!resolve(imp, modules_[i].file, display, key)) continue;
        if (loaded_.count(key) != 0) {
          edges_[i].push_back(loaded_[key]);
          continue;
        }
        std::string content, error;
        if (!read_file(display, content, error)) {
          sink_.error(imp.where, fmt::format("cannot read `{}`: it {}", display.string(), error));
          continue;
        }
        const std::size_t j = load(content, display, key);
        edges_[i].push_back(j);
      }
    }
    // Declare names with imported files first (post-order), then check everything.
    Resolver names(sink_);
    std::set<std::size_t> done;
    std::function<void(std::size_t, int)> visit = [&](std::size_t i, int depth) {
      if (!done.insert(i).second) return;
      if (depth < 1000)
        for (std::size_t j : edges_[i]) visit(j, depth + 1);
      names.declare(modules_[i]);
    };
    visit(main, 0);
    for (std::size_t i = 0; i < modules_.size(); ++i)
      if (done.count(i) == 0) names.declare(modules_[i]);
    std::vector<eval::ExperimentSpec> all;
    std::vector<eval::StudySpec> studies;
    auto experiments = lower_all(names, modules_[main], all, studies);
    result_.diagnostics = std::move(sink_.items());
    if (result_.ok()) {
      result_.experiments = std::move(experiments);
      result_.all_experiments = std::move(all);
      result_.studies = std::move(studies);
      result_.first_declared = first_declared(modules_[main]);
    }
  }

 private:
  static std::string first_declared(const ast::Module& m) {
    const ast::DeclHead* first = nullptr;
    const auto earliest = [&](const auto& decls) {
      for (const auto& d : decls)
        if (first == nullptr || d.order < first->order) first = &d;
    };
    earliest(m.experiments);
    earliest(m.studies);
    return first == nullptr ? std::string() : first->name.text;
  }

  // Lowers every declaration of every file once (each reported once); returns the main
  // file's experiments, every file's in `all`, and the main file's studies (every file's are
  // checked).
  std::vector<eval::ExperimentSpec> lower_all(Resolver& names, const ast::Module& main,
                                              std::vector<eval::ExperimentSpec>& all,
                                              std::vector<eval::StudySpec>& studies) {
    ArenaLowering arenas(sink_);
    RobotLowering robots(sink_, names);
    BehaviorLowering behaviors(sink_, names, arenas);
    FitnessLowering fitnesses(sink_, names, arenas);
    PrimitivesLowering primitives(sink_, names);
    ControllerLowering controllers(sink_, names, behaviors, primitives);
    ExperimentLowering experiments(sink_, names, Lowerings{arenas, robots, behaviors, fitnesses, controllers});
    for (const ast::Module* m : names.modules()) {
      for (const auto& d : m->arenas) (void)arenas.lower(d);
      for (const auto& d : m->robots) (void)robots.lower(d);
      for (const auto& d : m->behaviors) (void)behaviors.lower(d);
      for (const auto& d : m->libraries) check_library_mark(d, sink_);
      for (const auto& d : m->fitnesses) (void)fitnesses.lower(d);
      for (const auto& d : m->primitives) (void)primitives.lower(d);
      for (const auto& d : m->controllers) (void)controllers.lower(d);
    }
    experiments.check_cycles();
    std::vector<eval::ExperimentSpec> out;
    for (const ast::Module* m : names.modules())
      for (const auto& d : m->experiments) {
        const auto& x = experiments.lower(d);
        if (!x) continue;
        all.push_back(*x);
        if (m == &main) out.push_back(*x);
      }
    StudyLowering study_lowering(sink_, names, experiments);
    for (const ast::Module* m : names.modules())
      for (const auto& d : m->studies)
        if (auto s = study_lowering.lower(d); s && m == &main) studies.push_back(std::move(*s));
    return out;
  }

  static fs::path key_of(const fs::path& p) {
    std::error_code ec;
    fs::path k = fs::weakly_canonical(p, ec);
    return ec ? p.lexically_normal() : k;
  }

  std::size_t load(std::string_view text, const fs::path& display, const fs::path& key) {
    const CleanText clean = clean_utf8(text);
    result_.sources[display] = clean.display;
    modules_.push_back(parse_module(clean, display, sink_));
    edges_.emplace_back();
    loaded_[key] = modules_.size() - 1;
    return modules_.size() - 1;
  }

  bool resolve(const ast::Import& imp, const fs::path& from, fs::path& display, fs::path& key) {
    if (imp.path.empty()) {
      sink_.error(imp.where, "empty import path");
      return false;
    }
    std::vector<fs::path> candidates;
    const fs::path rel(imp.path);
    if (rel.is_absolute()) {
      candidates.push_back(rel);
    } else {
      candidates.push_back((from.parent_path() / rel).lexically_normal());
      for (const fs::path& dir : options_.import_paths) candidates.push_back((dir / rel).lexically_normal());
    }
    for (const fs::path& c : candidates) {
      std::error_code ec;
      if (fs::is_regular_file(c, ec)) {
        display = c;
        key = key_of(c);
        return true;
      }
      // A device or a pipe: reading it could block or never end.
      if (fs::exists(c, ec) && !fs::is_directory(c, ec)) {
        sink_.error(imp.where, fmt::format("cannot import `{}`: it is not a regular file", c.string()));
        return false;
      }
    }
    // Directories were passed over (a file of the same name may come later in the path);
    // when no file was found, one of them is what the script meant.
    for (const fs::path& c : candidates) {
      std::error_code ec;
      if (fs::is_directory(c, ec)) {
        Diagnostic& d = sink_.error(imp.where, fmt::format("cannot import `{}`: {} is a directory", imp.path, c.string()));
        d.help.push_back(fmt::format("import a script file in it, e.g. `{}/NAME.esc`", imp.path));
        return false;
      }
    }
    std::string searched;
    for (const fs::path& c : candidates) searched += (searched.empty() ? "" : ", ") + c.string();
    Diagnostic& d = sink_.error(imp.where, fmt::format("cannot find `{}`; searched: {}", imp.path, searched));
    d.help.push_back("imports are found beside the importing file, then in each import path ($ESC_PATH, then "
                     "the shipped experiments/ directory)");
    return false;
  }

  const CompileOptions& options_;
  CompileResult& result_;
  Sink sink_;
  std::deque<ast::Module> modules_;
  std::vector<std::vector<std::size_t>> edges_;
  std::map<fs::path, std::size_t> loaded_;
};

}  // namespace

CompileResult compile_source(std::string_view text, const fs::path& name, const CompileOptions& options) {
  CompileResult result;
  try {
    Driver driver(options, result);
    driver.run(text, name);
  } catch (const std::exception& e) {
    result.experiments.clear();
    result.all_experiments.clear();
    result.studies.clear();
    result.diagnostics.push_back(Diagnostic{Severity::Error, SourceRange{name, 0, 0, 1},
                                            fmt::format("internal compiler error: {}", e.what()), {}, {}});
  } catch (...) {
    result.experiments.clear();
    result.diagnostics.push_back(
        Diagnostic{Severity::Error, SourceRange{name, 0, 0, 1}, "internal compiler error", {}, {}});
  }
  return result;
}

CompileResult compile_file(const fs::path& file, const CompileOptions& options) {
  std::string text, error;
  if (!read_file(file, text, error)) {
    CompileResult r;
    r.diagnostics.push_back(Diagnostic{Severity::Error, SourceRange{file, 0, 0, 1},
                                       fmt::format("cannot read `{}`: it {}", file.string(),
                                                   error == "cannot be opened" ? "does not exist or cannot be opened"
                                                                               : error),
                                       {}, {}});
    return r;
  }
  return compile_source(text, file, options);
}

}  // namespace esc::compiler
