#include "cli/bench_paper.hpp"

#include <fstream>
#include <variant>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli/library_path.hpp"
#include "cli/load.hpp"

namespace esc::cli {

namespace {

const eval::ExperimentSpec* first_experiment(const compiler::CompileResult& c, const std::filesystem::path& script) {
  if (c.ok() && !c.experiments.empty()) return &c.experiments.front();
  fmt::print(stderr, "esc: error: {} declares no experiment to benchmark\n", script.string());
  return nullptr;
}

const control::ControllerSpec* controller(const eval::ExperimentSpec& e, const std::string& name) {
  for (const control::ControllerSpec& c : e.controllers)
    if (c.name == name) return &c;
  fmt::print(stderr, "esc: error: experiment `{}` has no controller `{}` to benchmark\n", e.name, name);
  return nullptr;
}

// Fills `ss`'s evolved behaviors with the genomes of `file`, in order; false after saying why.
bool evolved_behaviors(control::ControllerSpec& ss, const std::filesystem::path& file,
                       std::vector<std::vector<double>>& genomes) {
  std::ifstream in(file);
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  if (!in || j.is_discarded() || !j.contains("behaviors") || !j["behaviors"].is_array()) {
    fmt::print(stderr, "esc: error: cannot read the behaviors' genomes from {}\n", file.string());
    return false;
  }
  const auto& listed = j["behaviors"];
  if (listed.size() != ss.behaviors.size()) {
    fmt::print(stderr, "esc: error: {} holds {} genomes; controller `{}` supervises {} behaviors\n", file.string(),
               listed.size(), ss.name, ss.behaviors.size());
    return false;
  }
  for (std::size_t i = 0; i < listed.size(); ++i) {
    auto* fixed = std::get_if<control::FixedController>(&ss.behaviors[i].what);
    const auto genome = listed[i].value("genome", std::vector<double>{});
    if (fixed == nullptr || fixed->spec == nullptr || genome.size() != fixed->spec->genome_size()) {
      fmt::print(stderr, "esc: error: the genome of `{}` in {} does not fit behavior `{}` of controller `{}`\n",
                 listed[i].value("name", std::string{"?"}), file.string(), ss.behaviors[i].name, ss.name);
      return false;
    }
    fixed->genome = genome;
    genomes.push_back(genome);
  }
  return true;
}

}  // namespace

std::unique_ptr<PaperWorkloads> PaperWorkloads::load() {
  std::unique_ptr<PaperWorkloads> w(new PaperWorkloads);
  const std::filesystem::path dir = standard_library_dir();
  const std::filesystem::path obstacle_script = dir / "paper/obstacle_avoidance.esc";
  const std::filesystem::path energy_script = dir / "paper/energy.esc";
  w->obstacle_script_ = load_script(obstacle_script);
  w->energy_script_ = load_script(energy_script);
  const eval::ExperimentSpec* obstacle = first_experiment(w->obstacle_script_, obstacle_script);
  const eval::ExperimentSpec* energy = first_experiment(w->energy_script_, energy_script);
  if (obstacle == nullptr || energy == nullptr) return nullptr;
  w->obstacle = {"obstacle avoidance, SC 8-14-6", obstacle, controller(*obstacle, "SC_8_14_6")};
  w->energy = {"energy, CC Elman 17-5r-2", energy, controller(*energy, "CC")};
  const control::ControllerSpec* ss = controller(*energy, "SS");
  if (w->obstacle.controller == nullptr || w->energy.controller == nullptr || ss == nullptr) return nullptr;
  w->supervisor_spec_ = *ss;
  if (!evolved_behaviors(w->supervisor_spec_, dir / "bench/evolved_behaviors.json", w->behavior_genomes))
    return nullptr;
  w->supervisor = {"energy, SS Elman 17-5r-4 over 4 evolved behaviors", energy, &w->supervisor_spec_};
  return w;
}

}  // namespace esc::cli
