#include "runtime/store/study_directory.hpp"

#include <algorithm>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "runtime/store/seed_json.hpp"

namespace esc::store {

namespace fs = std::filesystem;

namespace {

nlohmann::ordered_json settings_object(const std::vector<eval::ConditionSetting>& settings) {
  nlohmann::ordered_json o = nlohmann::ordered_json::object();
  for (const eval::ConditionSetting& s : settings) o[s.key] = s.value;
  return o;
}

// The database just created, loaded, with the directory's lock (held from before it was
// judged empty, so that no other process sees it holding nothing in between).
StudyDirectory::Opened created(const fs::path& dir, const eval::StudySpec& study, const std::vector<SourceFile>& sources,
                               const std::vector<LaunchInfo>& launches) {
  auto lock = create_output_directory(dir);
  (void)ResultsDb::create_study(dir, study, sources, launches);
  return {std::move(lock), ResultsDb::open(dir).load()};
}

}  // namespace

std::vector<StoredExperiment> study_conditions(std::vector<StoredExperiment> all) {
  if (all.empty() || !std::all_of(all.begin(), all.end(), [](const StoredExperiment& e) { return e.condition.has_value(); }))
    throw StoreError("the database does not hold a study");
  std::stable_sort(all.begin(), all.end(),
                   [](const StoredExperiment& a, const StoredExperiment& b) { return a.condition->index < b.condition->index; });
  return all;
}

StudyDirectory::StudyDirectory(fs::path dir, const eval::StudySpec& study, const std::vector<SourceFile>& sources,
                               const std::vector<LaunchInfo>& launches)
    : StudyDirectory(dir, created(dir, study, sources, launches)) {
  const nlohmann::ordered_json files = write_sources(dir_, sources);
  nlohmann::ordered_json conditions = nlohmann::ordered_json::array();
  for (const eval::ConditionSpec& c : study.conditions) {
    // The condition's own settings.json, with the study's sources one level up.
    nlohmann::ordered_json up = files;
    for (auto& f : up) f["stored_as"] = "../" + f["stored_as"].get<std::string>();
    nlohmann::ordered_json doc = settings_json(c.experiment, sources, up);
    doc["study"] = study.name;
    doc["condition"] = c.name;
    doc["condition_settings"] = settings_object(c.settings);
    fs::create_directories(dir_ / c.directory);
    write_atomically(dir_ / c.directory / "settings.json", doc.dump(2) + "\n");
    conditions.push_back({{"name", c.name},
                          {"experiment", c.experiment.name},
                          {"directory", c.directory},
                          {"settings", settings_object(c.settings)}});
  }
  const nlohmann::ordered_json doc = {
      {"study", study.name}, {"seed", seed_json(study.seed)}, {"sources", files}, {"conditions", conditions}};
  write_atomically(dir_ / "settings.json", doc.dump(2) + "\n");
}

StudyDirectory::StudyDirectory(fs::path dir, std::vector<StoredExperiment> stored)
    : StudyDirectory(dir, Opened{DirectoryLock::acquire(dir), std::move(stored)}) {}

StudyDirectory::StudyDirectory(fs::path dir, Opened opened)
    : dir_(std::move(dir)), lock_(std::move(opened.lock)), stored_(study_conditions(std::move(opened.stored))) {
  name_ = stored_.front().condition->study;
  seed_ = stored_.front().condition->study_seed;
  for (const StoredExperiment& e : stored_) {
    eval::CampaignResult partial = e.result();
    partial.experiment = e.name;
    partial.seed = e.seed;
    summaries_.push_back({e.condition->name, e.condition->settings, std::move(partial)});
  }
  write_summary();
}

void StudyDirectory::carry_on(const std::vector<std::optional<CarryOn>>& conditions) {
  std::vector<ResultsDb::Extension> extensions;
  for (std::size_t i = 0; i < conditions.size(); ++i)
    if (conditions[i]) extensions.push_back({stored_.at(i).id, conditions[i]->spec, conditions[i]->overrides});
  if (extensions.empty()) return;
  ResultsDb::open(dir_).extend(extensions);
  for (std::size_t i = 0; i < conditions.size(); ++i)
    if (conditions[i]) RunDirectory::rewrite_settings(dir_ / stored_.at(i).condition->directory, *conditions[i]->spec);
}

RunDirectory StudyDirectory::open_condition(std::size_t i, const eval::ResumePoint& point) {
  const StoredExperiment& e = stored_.at(i);
  ResultsDb db = ResultsDb::open(dir_);
  db.select_experiment(e.id);
  return RunDirectory::resume(dir_ / e.condition->directory, std::move(db), e, point,
                              [this, i](const eval::CampaignResult& partial) {
                                summaries_.at(i).result = partial;
                                write_summary();
                              });
}

void StudyDirectory::write_summary() const {
  write_atomically(dir_ / "summary.json", summary_text(study_summary_json(name_, seed_, summaries_)));
}

}  // namespace esc::store
