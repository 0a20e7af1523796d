// The application layer as a library sees it: a run and its resume return their outcome and
// tell their events (never print), refusals are typed errors, and an experiment whose
// dependencies were never prepared does not run; the clients read stored runs through it,
// and replay them.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <unistd.h>

#include <gtest/gtest.h>

#include "app/compile.hpp"
#include "app/error.hpp"
#include "app/import_path.hpp"
#include "app/replay.hpp"
#include "app/results.hpp"
#include "app/run.hpp"
#include "app/settings.hpp"
#include "app/store_errors.hpp"
#include "app/stored_run.hpp"
#include "runtime/store/run_directory.hpp"
#include "runtime/eval/campaign.hpp"

namespace esc::app {
namespace {

namespace fs = std::filesystem;

const fs::path kStartFrom = fs::path(ESC_SOURCE_DIR) / "tests/cli/data/start_from.esc";

compiler::CompileOptions options() { return compile_options(fs::path(ESC_SOURCE_DIR) / "experiments"); }

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("esc-app-test-" + std::to_string(getpid()) + "-" + name);
  fs::remove_all(dir);
  return dir;
}

// Every event, as a test can inspect it.
class Recorded final : public Events {
 public:
  std::vector<Note> notes;
  int generations = 0;
  int experiments_done = 0;

  void note(const Note& n) override { notes.push_back(n); }
  std::unique_ptr<Progress> progress(const eval::ExperimentSpec&, const std::string&, eval::CampaignListener& next,
                                     std::int64_t) override {
    return std::make_unique<Counting>(next, generations);
  }
  void experiment_done(const eval::ExperimentSpec&, const eval::CampaignResult&) override { ++experiments_done; }

  [[nodiscard]] int count(Note::Kind kind) const {
    return static_cast<int>(std::count_if(notes.begin(), notes.end(), [&](const Note& n) { return n.kind == kind; }));
  }

 private:
  class Counting final : public Progress {
   public:
    Counting(eval::CampaignListener& next, int& generations) : Progress(next), generations_(generations) {}
    void generation_done(const control::ControllerSpec& c, int run, const eval::GenerationStats& g) override {
      Progress::generation_done(c, run, g);
      ++generations_;
    }

   private:
    int& generations_;
  };
};

RunRequest small_run(const std::string& experiment, const fs::path& out) {
  RunRequest r;
  r.script = kStartFrom;
  r.experiment = experiment;
  r.overrides.runs = 1;
  r.overrides.generations = 2;
  r.execution.threads = 2;
  r.out = out;
  return r;
}

TEST(App, ARunAndItsCarryOnReturnTheirOutcomeAndTellTheirEvents) {
  const fs::path out = fresh_dir("carry-on");
  Recorded events;
  const Outcome first = run(small_run("basic", out), options(), events);
  ASSERT_EQ(first.conditions.size(), 1U);
  EXPECT_TRUE(first.ran);
  EXPECT_TRUE(first.study.empty());
  EXPECT_EQ(first.conditions.front().result.controllers.size(), 2U);   // CC and SC
  EXPECT_EQ(events.generations, 2 * 2);                                // 2 controllers x 1 run x 2 generations
  EXPECT_EQ(events.experiments_done, 1);
  EXPECT_EQ(events.count(Note::Kind::Start), 1);
  EXPECT_TRUE(fs::exists(out / "esc.db"));
  // What a stop says: the generations to make, none stored yet, and how to start it again.
  const Note& started = *std::find_if(events.notes.begin(), events.notes.end(),
                                      [](const Note& n) { return n.kind == Note::Kind::Start; });
  EXPECT_EQ(started.generations, 4);
  EXPECT_EQ(started.generations_stored, 0);
  EXPECT_EQ(started.restart, "esc run " + fs::absolute(kStartFrom).lexically_normal().string() +
                                 " --experiment basic --runs 1 --generations 2 --out " + out.string());

  ResumeRequest more;
  more.dir = out;
  more.generations = 3;
  Recorded carried;
  const Outcome longer = resume(more, options(), carried);
  EXPECT_TRUE(longer.ran);
  EXPECT_EQ(carried.count(Note::Kind::Resume), 1);
  const Note& resumed = *std::find_if(carried.notes.begin(), carried.notes.end(),
                                      [](const Note& n) { return n.kind == Note::Kind::Resume; });
  EXPECT_EQ(resumed.generations, 6);
  EXPECT_EQ(resumed.generations_stored, 4);
  EXPECT_EQ(carried.generations, 2);   // one more generation of each controller
  for (const eval::ControllerResult& c : longer.conditions.front().result.controllers)
    EXPECT_EQ(c.runs.front().generations.size(), 3U);

  Recorded again;
  const Outcome nothing = resume(ResumeRequest{out, {}, {}, {}, {}, false}, options(), again);
  EXPECT_FALSE(nothing.ran);
  EXPECT_EQ(again.count(Note::Kind::Complete), 1);
  EXPECT_EQ(again.generations, 0);
  fs::remove_all(out);
}

TEST(App, DependenciesArePreparedAndTold) {
  const fs::path out = fresh_dir("dependency");
  Recorded events;
  const Outcome o = run(small_run("again", out), options(), events);
  EXPECT_GE(events.count(Note::Kind::Dependency), 2);   // running `basic`, then its genomes read
  EXPECT_EQ(events.experiments_done, 2);                 // `basic`, then `again`
  EXPECT_TRUE(fs::exists(out / "deps"));
  EXPECT_EQ(o.conditions.front().result.controllers.size(), 2U);
  fs::remove_all(out);
}

TEST(App, AnExperimentWhoseDependenciesWereNotPreparedDoesNotRun) {
  Recorded events;
  compiler::CompileResult compiled = compile(kStartFrom, options(), events);
  for (const std::string name : {"again", "onwards"}) {
    const eval::ExperimentSpec& spec = pick_experiment(compiled, kStartFrom, name);
    eval::CampaignListener quiet;
    try {
      (void)eval::run_campaign(spec, {}, quiet);
      ADD_FAILURE() << name << " ran without the genomes of `basic`";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("needs the results of basic first"), std::string::npos) << e.what();
    }
  }
}

TEST(App, ARunStoppedBeforeItsFirstGenerationIsToldHowItWasStarted) {
  const fs::path out = fresh_dir("nothing-stored");
  Recorded events;
  RunRequest r = small_run("basic", out);
  r.overrides.seed = 11;
  r.overrides.set = {"epochs=1"};
  compiler::CompileResult compiled = compile(kStartFrom, options(), events);
  eval::ExperimentSpec& spec = pick_experiment(compiled, kStartFrom, "basic");
  apply_settings(r.overrides, spec);
  // What a run killed before its first generation leaves: the experiment stored, no generation.
  { const store::RunDirectory dir(out, spec, sources_of(compiled), launch_info(r.overrides, kStartFrom, &spec)); }
  try {
    (void)resume(ResumeRequest{out, {}, {}, {}, {}, false}, options(), events);
    ADD_FAILURE() << "resumed a run that stored nothing";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Results);
    EXPECT_NE(e.problems().front().message.find("nothing was stored to resume"), std::string::npos) << e.what();
    EXPECT_EQ(e.problems().front().help,
              "esc run " + fs::absolute(kStartFrom).lexically_normal().string() +
                  " --experiment basic --runs 1 --generations 2 --seed 11 --set epochs=1 --out " + out.string());
  }
  fs::remove_all(out);
}

TEST(App, RefusalsAreTypedErrorsWithTheirMessages) {
  Recorded events;
  const fs::path out = fresh_dir("refused");
  RunRequest bad_setting = small_run("basic", out);
  bad_setting.overrides.set = {"epochs=0", "lambda=-1"};
  try {
    (void)run(bad_setting, options(), events);
    ADD_FAILURE() << "ran with epochs=0";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Setting);
    EXPECT_EQ(e.problems().size(), 2U);   // every refused setting, not the first alone
    EXPECT_EQ(e.problems().front().message.rfind("epochs=0: ", 0), 0U) << e.what();
  }
  RunRequest misspelt = small_run("basik", out);
  try {
    (void)run(misspelt, options(), events);
    ADD_FAILURE() << "ran an experiment the script does not declare";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Script);
    EXPECT_EQ(e.problems().front().help, "did you mean `basic`?");
  }
  const fs::path script = fresh_dir("typo.esc");
  std::ofstream(script) << "experiment e { epochs 2 x 10 stepz }\n";
  try {
    (void)compile(script, options(), events);
    ADD_FAILURE() << "a typo compiled";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Script);
    ASSERT_NE(e.script(), nullptr);
    EXPECT_FALSE(e.script()->ok());
    EXPECT_NE(std::string(e.what()).find("typo.esc:1:"), std::string::npos) << e.what();
  }
  try {
    (void)resume(ResumeRequest{out / "never", {}, {}, {}, {}, false}, options(), events);
    ADD_FAILURE() << "resumed a directory that does not exist";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Results);
  }
  EXPECT_FALSE(fs::exists(out));   // nothing written by any refusal
  fs::remove(script);
  EXPECT_TRUE(events.notes.empty());
}

// What the esc program and the Python module read through app/: the same experiment by each
// reader, a genome file's checks, and the store's error for a directory that is not a run's.
TEST(App, StoredRunsAreReadThroughTheApplicationLayer) {
  const fs::path out = fresh_dir("read");
  Recorded events;
  (void)run(small_run("basic", out), options(), events);
  Recorded reading;
  const store::StoredExperiment single = read_single(out);
  const std::vector<store::StoredExperiment> stored = read_stored(locate_run(out), out, reading);
  const store::StoredDirectory untouched = read_untouched(out, reading);
  EXPECT_TRUE(reading.notes.empty());   // an undamaged log: nothing to warn of
  ASSERT_EQ(stored.size(), 1U);
  ASSERT_EQ(untouched.experiments.size(), 1U);
  EXPECT_EQ(untouched.path, out);
  for (const store::StoredExperiment* e : {&single, &stored.front(), &untouched.experiments.front()}) {
    EXPECT_EQ(e->name, "basic");
    ASSERT_EQ(e->controllers.size(), 2U);
    EXPECT_EQ(e->controllers.front().finished.size(), 1U);
  }

  const eval::RunResult& best = single.controllers.front().finished.front();
  nlohmann::json genome = nlohmann::json::parse(std::ifstream(out / "CC" / "run-01.best.json"));
  EXPECT_TRUE(genome_file_intact(genome));
  EXPECT_EQ(genome_file_seed(genome),
            eval::evaluation_seed(best.seed, best.best_generation, static_cast<std::size_t>(best.best_index)));
  genome["fitness"] = genome["fitness"].get<double>() + 1.0;
  EXPECT_FALSE(genome_file_intact(genome));
  genome.erase("checksum");   // a file of an esc before checksums
  genome.erase("evaluation_seed");
  EXPECT_TRUE(genome_file_intact(genome));
  EXPECT_EQ(genome_file_seed(genome), std::nullopt);

  try {
    (void)read_single(out / "never");
    ADD_FAILURE() << "read a directory that does not exist";
  } catch (const StoreError& e) {
    EXPECT_EQ(std::string(e.what()), "`" + (out / "never").string() + "` is not a directory");
  }
  fs::remove_all(out);
}

// Each subject replayed, as a listener hears it.
class Heard final : public ReplayListener {
 public:
  std::vector<std::string> subjects;
  void replayed(const ReplayedSubject& s) override { subjects.push_back(s.controller); }
};

TEST(App, AReplayReturnsWhatItReplayedAndTellsEachSubject) {
  const fs::path out = fresh_dir("replay");
  Recorded events;
  (void)run(small_run("basic", out), options(), events);
  ReplayRequest request;
  request.source = out;
  Heard heard;
  const ReplayOutcome faithful = replay(request, options(), events, heard);
  ASSERT_EQ(faithful.subjects.size(), 2U);
  EXPECT_TRUE(faithful.evaluations.empty());
  const store::StoredExperiment stored = read_single(out);
  for (std::size_t i = 0; i < 2; ++i) {
    const ReplayedSubject& s = faithful.subjects[i];
    EXPECT_EQ(s.controller, stored.controllers[i].name);
    EXPECT_EQ(heard.subjects[i], s.controller);
    EXPECT_TRUE(s.replayed);
    EXPECT_TRUE(s.problems.empty());
    EXPECT_TRUE(s.faithful);
    EXPECT_TRUE(s.identical_to_stored_replay);   // bit for bit the evaluation esc.db stores
    EXPECT_EQ(s.fitness, stored.controllers[i].finished.front().best_fitness);
    EXPECT_EQ(s.stem, "replay-" + s.controller + "-run-01");
    EXPECT_TRUE(fs::is_regular_file(out / (s.stem + ".svg")));
    EXPECT_TRUE(fs::is_regular_file(out / (s.stem + ".csv")));
    // The figure it returns (for an animation) is the one its SVG draws, still whole once
    // the outcome holds it.
    EXPECT_FALSE(s.drawn.empty());
    std::ifstream svg(out / (s.stem + ".svg"));
    EXPECT_EQ(report::trajectory_svg(s.figure()), std::string(std::istreambuf_iterator<char>(svg), {}));
  }

  // Another seed: checked against nothing, named so that it stands beside the faithful files.
  request.controller = "CC";
  request.seed = 7;
  const ReplayOutcome seeded = replay(request, options(), events, heard);
  ASSERT_EQ(seeded.subjects.size(), 1U);
  EXPECT_FALSE(seeded.subjects.front().faithful);
  EXPECT_FALSE(seeded.subjects.front().identical_to_stored_replay);
  EXPECT_EQ(seeded.subjects.front().stem, "replay-CC-run-01-seed-7");

  // What was asked for does not fit the run: a Request refusal, with esc's sentence.
  request.seed.reset();
  request.epochs = "9";
  try {
    (void)replay(request, options(), events, heard);
    ADD_FAILURE() << "replayed epoch 9 of a run with fewer";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Request);
    EXPECT_NE(std::string(e.what()).find("--epochs 9: `9` is not an epoch"), std::string::npos) << e.what();
  }
  request.epochs.clear();
  request.controller = "CX";
  try {
    (void)replay(request, options(), events, heard);
    ADD_FAILURE() << "replayed a controller the run does not compare";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Results);
    ASSERT_EQ(e.problems().size(), 1U);
    EXPECT_EQ(e.problems().front().help, "did you mean `CC`?");
  }
  EXPECT_EQ(heard.subjects.size(), 3U);   // the refusals replayed nothing
  fs::remove_all(out);
}

}  // namespace
}  // namespace esc::app
