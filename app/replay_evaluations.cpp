#include "app/replay_evaluations.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "app/error.hpp"
#include "app/output_files.hpp"
#include "app/run_evaluations.hpp"
#include "runtime/report/evaluation_map.hpp"

namespace esc::app {

namespace {

namespace fs = std::filesystem;

// Passes each generation made again on, counted from 1.
class Generations final : public eval::CampaignListener {
 public:
  Generations(const GenerationsMade& progress, int generations) : progress_(progress), generations_(generations) {}
  void generation_done(const control::ControllerSpec& /*controller*/, int /*run*/,
                       const eval::GenerationStats& g) override {
    if (progress_) progress_(g.generation + 1, generations_);
  }

 private:
  const GenerationsMade& progress_;
  int generations_;
};

std::string evaluations_csv(const RunEvaluations& e) {
  std::string out = "generation,candidate";
  for (const std::string& name : e.objectives) out += "," + name;
  for (const std::string& name : e.descriptors) out += "," + name;
  out += "\n";
  const std::size_t width = e.width();
  for (std::size_t k = 0; k < e.size(); ++k) {
    out += fmt::format("{},{}", e.generation[k], e.candidate[k]);
    for (std::size_t i = 0; i < width; ++i) out += fmt::format(",{:.17g}", e.values[k * width + i]);
    out += "\n";
  }
  return out;
}

}  // namespace

ReplayedEvaluations replay_evaluations(const StoredRun& stored, const eval::ExperimentSpec& ran,
                                       const std::string& controller, int run, int threads, bool over_arena,
                                       const fs::path& out, const GenerationsMade& progress) {
  const std::size_t descriptors = ran.descriptors.size();
  if (over_arena && descriptors < 2)
    throw Error(ErrorKind::Request, fmt::format("--arena draws the first two descriptors as the robot's x and y, but "
                                                "experiment `{}` declares {}", ran.name,
                                                descriptors == 0 ? "none" : "one"));
  // As many generations as the stored run made: one its optimizer or a success stopped early
  // is made again up to there.
  const std::size_t made = finished_run(stored, controller, run).run->generations.size();
  Generations generations(progress, std::max(1, static_cast<int>(made)));
  const RunEvaluations e = run_evaluations(stored, ran, controller, run, threads, &generations);
  std::error_code ec;
  fs::create_directories(out, ec);
  ReplayedEvaluations written{controller, run, e.size(), out, fmt::format("evaluations-{}-run-{:02}", controller, run + 1),
                              descriptors >= 2};
  write_atomically(out / (written.stem + ".csv"), evaluations_csv(e));
  if (written.svg) {
    std::vector<double> x(e.size()), y(e.size());
    for (std::size_t k = 0; k < e.size(); ++k) {
      x[k] = e.values[k * e.width() + e.objectives.size()];
      y[k] = e.values[k * e.width() + e.objectives.size() + 1];
    }
    report::EvaluationMap map;
    const auto& condition = stored.stored->condition;
    map.title = fmt::format("Where {} run {}'s {} evaluations fall, in {}", controller, run + 1, e.size(),
                            condition ? fmt::format("condition {} of study {}", condition->name, condition->study)
                                      : fmt::format("experiment {}", ran.name));
    map.x_title = e.descriptors[0];
    map.y_title = e.descriptors[1];
    map.x_range = {e.descriptor_ranges[0].lower, e.descriptor_ranges[0].upper};
    map.y_range = {e.descriptor_ranges[1].lower, e.descriptor_ranges[1].upper};
    map.x = x;
    map.y = y;
    map.arena = over_arena ? &ran.arena : nullptr;
    write_atomically(out / (written.stem + ".svg"), report::evaluation_map_svg(map));
  }
  return written;
}

}  // namespace esc::app
