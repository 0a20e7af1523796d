#pragma once
// The paper's workloads that `esc bench` times, compiled from the shipped scripts: obstacle
// avoidance with the 8-14-6 symbolic controller, the energy experiment's Elman 17-5-2
// classical controller (CC), and its symbolic supervisor (SS) over four evolved behaviors
// (experiments/bench/evolved_behaviors.json: genomes of short real runs, so that the
// behaviors avoid walls as evolved ones do; zero weights would drive into a wall).
#include <memory>
#include <string>
#include <vector>

#include "compiler/compiler.hpp"

namespace esc::cli {

struct PaperWorkload {
  std::string label;     // how the tables name it
  const eval::ExperimentSpec* experiment = nullptr;
  const control::ControllerSpec* controller = nullptr;
};

class PaperWorkloads {
 public:
  // nullptr after printing what is missing or broken.
  [[nodiscard]] static std::unique_ptr<PaperWorkloads> load();
  // The workloads point into the scripts held here.
  PaperWorkloads(const PaperWorkloads&) = delete;
  PaperWorkloads& operator=(const PaperWorkloads&) = delete;

  PaperWorkload obstacle;
  PaperWorkload energy;
  PaperWorkload supervisor;
  // The supervisor's behaviors' genomes, in its behaviors' order.
  std::vector<std::vector<double>> behavior_genomes;

 private:
  PaperWorkloads() = default;
  compiler::CompileResult obstacle_script_;
  compiler::CompileResult energy_script_;
  control::ControllerSpec supervisor_spec_;
};

}  // namespace esc::cli
