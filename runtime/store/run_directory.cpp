#include "runtime/store/run_directory.hpp"

#include <stdexcept>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "runtime/store/summary_json.hpp"

namespace esc::store {

namespace fs = std::filesystem;

std::uint64_t content_hash(std::string_view text, std::uint64_t h) noexcept {
  for (unsigned char ch : text) {
    h ^= ch;
    h *= 0x100000001b3ULL;
  }
  return h;
}

void write_atomically(const fs::path& file, std::string_view text) {
  const fs::path tmp = fs::path(file).concat(".tmp");
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out << text;
    out.flush();
    if (!out) throw std::runtime_error(fmt::format("cannot write {}", tmp.string()));
  }
  fs::rename(tmp, file);
}

RunDirectory::RunDirectory(fs::path dir, const eval::ExperimentSpec& spec,
                           const std::vector<SourceFile>& sources)
    : dir_(std::move(dir)) {
  std::error_code ec;
  if (fs::exists(dir_, ec) && !(fs::is_directory(dir_, ec) && fs::is_empty(dir_, ec)))
    throw std::runtime_error(fmt::format(
        "output directory `{}` already exists and is not empty; results are never overwritten: "
        "choose another --out or remove it", dir_.string()));
  fs::create_directories(dir_ / "sources", ec);
  if (ec) throw std::runtime_error(fmt::format("cannot create `{}`: {}", dir_.string(), ec.message()));

  content_hash_ = content_hash(spec.name);
  nlohmann::ordered_json files = nlohmann::ordered_json::array();
  for (const SourceFile& s : sources) {
    content_hash_ = content_hash(s.text, content_hash(s.name.generic_string(), content_hash_));
    const std::string flat = fmt::format("{:02}-{}", files.size(), s.name.filename().string());
    write_atomically(dir_ / "sources" / flat, s.text);
    files.push_back({{"name", s.name.generic_string()}, {"stored_as", "sources/" + flat}});
  }
  nlohmann::ordered_json settings(spec.resolved_settings);
  nlohmann::ordered_json doc = {{"experiment", spec.name},
                                {"seed", spec.seed},
                                {"content_hash", fmt::format("{:016x}", content_hash_)},
                                {"sources", files},
                                {"settings", settings}};
  write_atomically(dir_ / "settings.json", doc.dump(2) + "\n");
  partial_.experiment = spec.name;
  partial_.seed = spec.seed;
  write_summary();
}

fs::path RunDirectory::run_file(const control::ControllerSpec& c, int run, std::string_view ext) const {
  return dir_ / c.name / fmt::format("run-{:02}{}", run + 1, ext);
}

void RunDirectory::generation_done(const control::ControllerSpec& controller, int run,
                                   const eval::GenerationStats& g) {
  const std::string key = fmt::format("{}/{}", controller.name, run);
  if (key != csv_key_) {
    fs::create_directories(dir_ / controller.name);
    csv_ = std::ofstream(run_file(controller, run, ".csv"), std::ios::trunc);
    csv_ << "generation,best,mean,sd,evaluations,steps,seconds\n";
    csv_key_ = key;
  }
  csv_ << fmt::format("{},{:.17g},{:.17g},{:.17g},{},{},{:.3f}\n", g.generation, g.best, g.mean, g.sd,
                      g.evaluations, g.steps, g.seconds);
  csv_.flush();
  if (!csv_) throw std::runtime_error(fmt::format("cannot write {}", run_file(controller, run, ".csv").string()));
}

void RunDirectory::run_done(const control::ControllerSpec& controller, const eval::RunResult& run) {
  nlohmann::ordered_json best = {{"controller", controller.name},
                                 {"architecture", controller.architecture()},
                                 {"run", run.run},
                                 {"seed", run.seed},
                                 {"fitness", run.best_fitness},
                                 {"genome", run.best_genome}};
  write_atomically(run_file(controller, run.run, ".best.json"), best.dump(1) + "\n");
  if (partial_.controllers.empty() || partial_.controllers.back().name != controller.name)
    partial_.controllers.push_back({controller.name, controller.architecture(), controller.genome_size(), {}});
  partial_.controllers.back().runs.push_back(run);
  write_summary();
}

void RunDirectory::finish(const eval::CampaignResult& result) {
  partial_ = result;
  write_summary();
}

void RunDirectory::write_summary() {
  write_atomically(dir_ / "summary.json", summary_json(partial_).dump(2) + "\n");
}

}  // namespace esc::store
