#pragma once
// The output directory of `esc run`. It is written as the campaign goes, so a run that is
// stopped halfway keeps every finished generation:
//   sources/<file>             every script file the experiment was compiled from
//   settings.json              experiment, master seed, resolved settings, content hash
//   <controller>/run-NN.csv    per-generation statistics, one line appended per generation
//   <controller>/run-NN.best.json   best genome of the run and its fitness
//   summary.json               all runs finished so far (rewritten atomically after each)
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include "runtime/eval/campaign.hpp"

namespace esc::store {

struct SourceFile {
  std::filesystem::path name;   // as the compiler reported it
  std::string text;
};

class RunDirectory final : public eval::CampaignListener {
 public:
  // Creates `dir`. Throws std::runtime_error if it exists and is not empty (results are
  // never overwritten) or cannot be created.
  RunDirectory(std::filesystem::path dir, const eval::ExperimentSpec& spec,
               const std::vector<SourceFile>& sources);

  void generation_done(const control::ControllerSpec& controller, int run,
                       const eval::GenerationStats& stats) override;
  void run_done(const control::ControllerSpec& controller, const eval::RunResult& run) override;

  // Final summary (the same file, with every run).
  void finish(const eval::CampaignResult& result);

  [[nodiscard]] const std::filesystem::path& path() const noexcept { return dir_; }

 private:
  std::filesystem::path run_file(const control::ControllerSpec& c, int run, std::string_view ext) const;
  void write_summary();

  std::filesystem::path dir_;
  std::uint64_t content_hash_ = 0;
  eval::CampaignResult partial_;      // runs finished so far, for summary.json
  std::ofstream csv_;                 // the run being written
  std::string csv_key_;
};

// 64-bit FNV-1a of the text: a stable content key (not a cryptographic hash).
[[nodiscard]] std::uint64_t content_hash(std::string_view text, std::uint64_t h = 0xcbf29ce484222325ULL) noexcept;

// Writes `text` to `file` through a temporary file and a rename, so readers never see a
// half-written file.
void write_atomically(const std::filesystem::path& file, std::string_view text);

}  // namespace esc::store
