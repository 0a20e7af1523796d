#include "runtime/eval/campaign.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <deque>
#include <memory>
#include <mutex>
#include <numeric>
#include <stdexcept>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include "runtime/core/rng.hpp"
#include "runtime/eval/campaign_parts.hpp"
#include "runtime/eval/evaluator.hpp"

namespace esc::eval {

namespace {

using Clock = std::chrono::steady_clock;
using detail::Evaluators;
using detail::RunJob;

// Where each job's individuals sit in the round's pool.
struct Pool {
  std::vector<std::size_t> first;   // job j's individuals are [first[j], first[j + 1])
  [[nodiscard]] std::size_t size() const { return first.back(); }
  [[nodiscard]] std::size_t job_of(std::size_t i) const {
    return static_cast<std::size_t>(std::upper_bound(first.begin(), first.end(), i) - first.begin()) - 1;
  }
};

// Tells the listener how far a long round has come, from whichever worker finishes an
// evaluation when the interval has passed; the others go on without waiting.
class RoundTicker {
 public:
  RoundTicker(CampaignListener& listener, std::size_t evaluations, Clock::time_point start)
      : listener_(listener), evaluations_(static_cast<std::int64_t>(evaluations)), start_(start) {}

  void one_done() {
    const std::int64_t done = ++done_;
    const Clock::time_point now = Clock::now();
    if (now < next_.load(std::memory_order_relaxed)) return;
    const std::unique_lock lock(mutex_, std::try_to_lock);
    if (!lock.owns_lock() || now < next_.load(std::memory_order_relaxed)) return;
    next_.store(now + kInterval, std::memory_order_relaxed);
    listener_.round_progress({done, evaluations_, std::chrono::duration<double>(now - start_).count()});
  }

 private:
  static constexpr auto kInterval =
      std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(kRoundProgressInterval_s));
  CampaignListener& listener_;
  std::int64_t evaluations_;
  Clock::time_point start_;
  std::atomic<std::int64_t> done_{0};
  std::atomic<Clock::time_point> next_{start_ + kInterval};
  std::mutex mutex_;
};

// One generation of every active run: breeds them, evaluates the pooled individuals on
// every worker and rank, and hands each run its fitness and statistics.
void advance(std::vector<std::unique_ptr<RunJob>>& active, Evaluators& ev, CampaignListener& listener) {
  const auto start = Clock::now();
  Pool pool{{0}};
  std::vector<std::size_t> choices;   // per job: its controller's actions or behaviors
  for (const auto& job : active) {
    pool.first.push_back(pool.first.back() + job->breed());
    choices.push_back(job->controller().choice_names().size());
  }
  const detail::ResultColumns columns =
      detail::result_columns(active.front()->spec(), *std::max_element(choices.begin(), choices.end()));
  const std::size_t width = columns.width;
  std::vector<double> results(pool.size() * width, 0.0);
  RoundTicker ticker(listener, pool.size(), start);
  ev.distribution.run(pool.size(), width, ev.threads, results, [&](std::size_t i) {
    const std::size_t j = pool.job_of(i);
    const RunJob& job = *active[j];
    const std::size_t k = i - pool.first[j];
    const Evaluation e = job.evaluate(ev.workers.local(), k, evaluation_seed(job.state().seed, job.generation(), k));
    detail::write_result(e, columns, &results[i * width]);
    ticker.one_done();
  });
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  std::vector<double> fitness;
  std::vector<std::int64_t> steps(active.size(), 0);
  for (std::size_t j = 0; j < active.size(); ++j)
    for (std::size_t i = pool.first[j]; i < pool.first[j + 1]; ++i)
      steps[j] += static_cast<std::int64_t>(results[i * width + detail::kResultSteps]);
  const std::int64_t all_steps = std::accumulate(steps.begin(), steps.end(), std::int64_t{0});
  listener.round_evaluated({active.size(), static_cast<std::int64_t>(pool.size()), all_steps, seconds});
  for (std::size_t j = 0; j < active.size(); ++j) {
    RunJob& job = *active[j];
    fitness.clear();
    for (std::size_t i = pool.first[j]; i < pool.first[j + 1]; ++i)
      fitness.push_back(results[i * width + detail::kResultFitness]);
    GenerationStats stats = detail::summarise(job.generation(), fitness, steps[j], seconds);
    const std::span<const double> rows(results.data() + pool.first[j] * width,
                                       (pool.first[j + 1] - pool.first[j]) * width);
    stats.usage = detail::summarise_usage(rows, width, choices[j]);
    const std::vector<evo::Outcome> outcomes = detail::outcomes_of(job.spec(), rows, columns);
    listener.candidates_evaluated(job.controller(), job.state().run, job.generation(), outcomes);
    job.evaluated(outcomes, stats);
    listener.generation_done(job.controller(), job.state().run, job.state().generations.back());
    listener.checkpoint(job.controller(), job.state());
  }
}

const RunResult* find_finished(const ResumePoint* resume, const std::string& controller, int run) {
  if (resume == nullptr) return nullptr;
  for (const auto& f : resume->finished)
    if (f.controller == controller && f.result.run == run) return &f.result;
  return nullptr;
}

const RunState* find_in_progress(const ResumePoint* resume, const std::string& controller, int run) {
  if (resume == nullptr) return nullptr;
  for (const auto& p : resume->in_progress)
    if (p.controller == controller && p.state.run == run) return &p.state;
  return nullptr;
}

}  // namespace

std::uint64_t evaluation_seed(std::uint64_t run_seed, int generation, std::size_t index) noexcept {
  return derive_seed(run_seed, {static_cast<std::uint64_t>(Stream::Evaluate), static_cast<std::uint64_t>(generation),
                                static_cast<std::uint64_t>(index)});
}

// As many objectives and descriptors as each member keeps.
std::shared_ptr<const MemberLayout> member_layout(const ExperimentSpec& spec, evo::Members kept) {
  auto layout = std::make_shared<MemberLayout>();
  layout->kind = kept.kind;
  for (const std::string& own : kept.own_objectives) {
    layout->objectives.push_back(own);
    layout->minimized.push_back(false);
  }
  for (std::size_t i = 0; i + kept.own_objectives.size() < kept.objectives; ++i) {
    layout->objectives.push_back(i == 0 ? spec.fitness.name : spec.further[i - 1].name);
    layout->minimized.push_back(spec.minimized(i));
  }
  for (std::size_t i = 0; i < kept.descriptors && i < spec.descriptors.size(); ++i) {
    const DescriptorSpec& d = spec.descriptors[i];
    layout->descriptors.push_back(d.name);
    layout->descriptor_ranges.push_back({d.range.lower, d.range.upper});
  }
  layout->bins = std::move(kept.bins);
  layout->centroids = std::move(kept.centroids);
  return layout;
}

std::uint64_t run_seed(std::uint64_t master_seed, int run) noexcept {
  return derive_seed(master_seed, {static_cast<std::uint64_t>(Stream::RunSeed), static_cast<std::uint64_t>(run)});
}

bool room_for_another_run(std::size_t active_runs, std::size_t pooled_evaluations, std::size_t workers,
                          int runs_at_once) noexcept {
  if (active_runs == 0) return true;
  if (runs_at_once > 0) return active_runs < static_cast<std::size_t>(runs_at_once);
  // Runs advance together while their generations hold fewer than this many evaluations
  // per worker: a generation's last evaluations leave workers idle until the longest one
  // ends, and pooling several runs' generations makes that tail a smaller share of each
  // round. With lambda = 150 on 2 cores, runs go one at a time.
  constexpr std::size_t kEvaluationsPerWorker = 16;
  return pooled_evaluations < kEvaluationsPerWorker * workers;
}

CampaignResult campaign_result_of(const ExperimentSpec& spec) {
  CampaignResult result;
  result.experiment = spec.name;
  result.seed = spec.seed;
  result.robots = spec.robots;
  result.roles = spec.roles;
  if (const auto it = spec.resolved_settings.find("bodies"); it != spec.resolved_settings.end())
    result.bodies = it->second;
  if (spec.success) result.success = spec.success->text();
  return result;
}

CampaignResult run_campaign(const ExperimentSpec& spec, const CampaignOptions& options,
                            CampaignListener& listener) {
  // Unfilled, a supervisor would act with empty behaviors and a `start from` run from random
  // genomes: a result that looks right and is not.
  if (const std::vector<std::string> missing = spec.unprepared(); !missing.empty())
    throw std::invalid_argument(fmt::format("experiment {} needs the results of {} first: prepare its dependencies "
                                            "(esc::app::prepare_dependencies) before running it",
                                            spec.name, fmt::join(missing, ", ")));
  CampaignResult result = campaign_result_of(spec);
  const int threads = options.threads > 0 ? options.threads : tbb::info::default_concurrency();
  // Honour a thread count above the core count too (results do not depend on it).
  const tbb::global_control allow(tbb::global_control::max_allowed_parallelism,
                                  static_cast<std::size_t>(threads));
  tbb::task_arena arena(threads);
  detail::Workers workers([&spec] { return Evaluator(spec); });
  dist::Distribution distribution;
  Evaluators ev{workers, distribution, static_cast<std::size_t>(threads)};

  // Every run, in controller then run order: finished ones (from a resume) as they are,
  // the others queued.
  struct Queued {
    const control::ControllerSpec* controller;
    int run;
    const RunState* from;
  };
  std::deque<Queued> queue;
  for (const control::ControllerSpec& c : spec.controllers) {
    ControllerResult& cr = result.controllers.emplace_back();
    cr.name = c.name;
    cr.architecture = c.architecture();
    cr.genome_size = spec.genome_size_of(c);
    cr.choices = c.choice_names();
    cr.runs.resize(static_cast<std::size_t>(spec.runs));
    for (int run = 0; run < spec.runs; ++run) {
      const auto& only = options.only_runs;
      if (!only.empty() && std::find(only.begin(), only.end(), run) == only.end()) continue;
      if (const RunResult* done = find_finished(options.resume, c.name, run))
        cr.runs[static_cast<std::size_t>(run)] = *done;
      else
        queue.push_back({&c, run, find_in_progress(options.resume, c.name, run)});
    }
  }

  // Every rank must pool the same runs: count workers the same everywhere.
  const std::size_t workers_everywhere = distribution.workers(ev.threads);
  const auto room_for_another = [&](const std::vector<std::unique_ptr<RunJob>>& active) {
    std::size_t evaluations = 0;
    for (const auto& job : active) evaluations += job->evaluations_per_generation();
    return room_for_another_run(active.size(), evaluations, workers_everywhere, options.runs_at_once);
  };
  const auto close = [&](RunJob& job) {
    const control::ControllerSpec& c = job.controller();
    RunResult& slot = result.controllers[static_cast<std::size_t>(&c - spec.controllers.data())]
                          .runs[static_cast<std::size_t>(job.state().run)];
    slot = job.close(spec, options, ev, listener);
    listener.run_done(c, slot);
  };
  std::vector<std::unique_ptr<RunJob>> active;
  arena.execute([&] {
    while (true) {
      while (!queue.empty() && room_for_another(active)) {
        const Queued q = queue.front();
        queue.pop_front();
        auto job = std::make_unique<RunJob>(spec, *q.controller, q.run, q.from);
        // A run stopped after its last generation but before it was closed.
        if (job->finished())
          close(*job);
        else
          active.push_back(std::move(job));
      }
      if (active.empty()) break;
      advance(active, ev, listener);
      for (auto it = active.begin(); it != active.end();) {
        if ((*it)->finished()) {
          close(**it);
          it = active.erase(it);
        } else {
          ++it;
        }
      }
    }
  });
  return result;
}

}  // namespace esc::eval
