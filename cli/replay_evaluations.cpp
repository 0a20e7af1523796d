#include "cli/replay_evaluations.hpp"

#include <algorithm>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "app/output_files.hpp"
#include "app/run_evaluations.hpp"
#include "app/stored_run.hpp"
#include "cli/load.hpp"
#include "runtime/report/evaluation_map.hpp"

namespace esc::cli {

namespace {

namespace fs = std::filesystem;

// One line at every tenth of the run: a maze run made again takes minutes.
class Tenths final : public eval::CampaignListener {
 public:
  Tenths(std::string who, int generations) : who_(std::move(who)), generations_(generations) {}
  void generation_done(const control::ControllerSpec& /*controller*/, int /*run*/,
                       const eval::GenerationStats& g) override {
    const int done = g.generation + 1;
    if (done * 10 / generations_ != (done - 1) * 10 / generations_ || done == generations_) {
      say("esc: {} made again: {} of {} generations\n", who_, done, generations_);
      std::fflush(stdout);
    }
  }

 private:
  std::string who_;
  int generations_;
};

std::string evaluations_csv(const app::RunEvaluations& e) {
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

int replay_evaluations(const app::StoredRun& stored, const eval::ExperimentSpec& ran, const std::string& controller,
                       int run, const ReplayOptions& o, const fs::path& out) {
  const std::string who = fmt::format("{} run {}", controller, run + 1);
  const std::size_t descriptors = ran.descriptors.size();
  if (o.over_arena && descriptors < 2) {
    complain("esc: error: --arena draws the first two descriptors as the robot's x and y, but experiment `{}` "
             "declares {}\n", ran.name, descriptors == 0 ? "none" : "one");
    return kExitUsage;
  }
  // As many generations as the stored run made: one its optimizer or a success stopped early
  // is made again up to there.
  const std::size_t made = app::finished_run(stored, controller, run).run->generations.size();
  Tenths progress(who, std::max(1, static_cast<int>(made)));
  const app::RunEvaluations e = app::run_evaluations(stored, ran, controller, run, o.threads, &progress);
  std::error_code ec;
  fs::create_directories(out, ec);
  const std::string stem = fmt::format("evaluations-{}-run-{:02}", controller, run + 1);
  app::write_atomically(out / (stem + ".csv"), evaluations_csv(e));
  std::string written = stem + ".csv";
  if (descriptors >= 2) {
    std::vector<double> x(e.size()), y(e.size());
    for (std::size_t k = 0; k < e.size(); ++k) {
      x[k] = e.values[k * e.width() + e.objectives.size()];
      y[k] = e.values[k * e.width() + e.objectives.size() + 1];
    }
    report::EvaluationMap map;
    const auto& condition = stored.stored->condition;
    map.title = fmt::format("Where {}'s {} evaluations fall, in {}", who, e.size(),
                            condition ? fmt::format("condition {} of study {}", condition->name, condition->study)
                                      : fmt::format("experiment {}", ran.name));
    map.x_title = e.descriptors[0];
    map.y_title = e.descriptors[1];
    map.x_range = {e.descriptor_ranges[0].lower, e.descriptor_ranges[0].upper};
    map.y_range = {e.descriptor_ranges[1].lower, e.descriptor_ranges[1].upper};
    map.x = x;
    map.y = y;
    map.arena = o.over_arena ? &ran.arena : nullptr;
    app::write_atomically(out / (stem + ".svg"), report::evaluation_map_svg(map));
    written += ", .svg";
  }
  say("esc: {} made again, identical to the stored run in every generation: {} evaluations in {}/{}\n", who,
      e.size(), out.string(), written);
  return kExitOk;
}

}  // namespace esc::cli
