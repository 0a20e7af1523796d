// Bodies from the command line: the library's navigator (acceleration drive, kinematic)
// evolves NEAT networks that improve, whatever the threads; its replay CSV has the sensors it
// has (rangefinders and radars, no IR columns) and reproduces the stored fitness. The Thymio
// II's replay draws its outline and names its seven sensors.
#include <algorithm>
#include <string>

#include <gtest/gtest.h>

#include "tests/cli/esc_process.hpp"
#include "tests/cli/results_support.hpp"

namespace {

using namespace cli_test;

std::string tiny_navigator() { return std::string(ESC_SOURCE_DIR) + "/tests/cli/data/tiny_navigator.esc"; }

TEST(Bodies, TheNavigatorEvolvesAndImprovesWhateverTheThreads) {
  const fs::path one = scratch("navigator-threads-1");
  const fs::path two = scratch("navigator-threads-2");
  const Outcome a = esc("run " + tiny_navigator() + " --threads 1 --out " + one.string());
  ASSERT_EQ(a.status, 0) << a.output;
  const Outcome b = esc("run " + tiny_navigator() + " --threads 2 --out " + two.string());
  ASSERT_EQ(b.status, 0) << b.output;
  expect_same_results(one, two, {"N"}, 2);
  const auto summary = read_json(one / "summary.json");
  for (int run = 0; run < 2; ++run) {
    const auto& r = summary["controllers"]["N"]["runs"][run];
    EXPECT_GT(r["best_fitness"].get<double>(), r["best"][0].get<double>()) << "run " << run + 1;
  }
  const fs::path replay = scratch("navigator-replay");
  const Outcome shown = esc("replay " + one.string() + " --out " + replay.string());   // the best run's
  ASSERT_EQ(shown.status, 0) << shown.output;
  EXPECT_NE(shown.output.find("identical to the stored replay"), std::string::npos) << shown.output;
  std::string csv;
  for (const auto& f : fs::directory_iterator(replay))
    if (f.path().extension() == ".csv") csv = slurp(f.path());
  const std::string header = csv.substr(0, csv.find('\n'));
  EXPECT_NE(header.find(",right_speed_mps,range0,range1,range2,range3,range4,range5,radar0,"), std::string::npos)
      << header;
  EXPECT_EQ(header.find(",ir0"), std::string::npos) << header;
}

TEST(Bodies, TheThymiosReplayDrawsItsOutlineAndNamesItsSensors) {
  const fs::path dir = scratch("thymio-run");
  const Outcome run = esc("run " + std::string(ESC_SOURCE_DIR) +
                          "/experiments/bodies/thymio_obstacle_avoidance.esc --experiment thymio_obstacle_avoidance "
                          "--runs 1 --generations 2 --set epochs=1 --set steps=60 --controllers SC_8_14_6 --out " +
                          dir.string());
  ASSERT_EQ(run.status, 0) << run.output;
  const fs::path replay = scratch("thymio-replay");
  const Outcome shown = esc("replay " + dir.string() + " --out " + replay.string());
  ASSERT_EQ(shown.status, 0) << shown.output;
  EXPECT_NE(shown.output.find("identical to the stored replay"), std::string::npos) << shown.output;
  std::string csv, svg;
  for (const auto& f : fs::directory_iterator(replay)) {
    if (f.path().extension() == ".csv") csv = slurp(f.path());
    if (f.path().extension() == ".svg") svg = slurp(f.path());
  }
  const std::string header = csv.substr(0, csv.find('\n'));
  EXPECT_NE(header.find(",prox_horizontal6,"), std::string::npos) << header;
  EXPECT_EQ(header.find(",prox_horizontal7"), std::string::npos) << header;
  // Its two ground sensors by their name, after the lights (it has no rangefinders, radars or
  // bumpers), each row reading 0 or 1 there.
  EXPECT_NE(header.find(",light6,prox_ground0,prox_ground1,energy,"), std::string::npos) << header;
  const std::string first = csv.substr(header.size() + 1, csv.find('\n', header.size() + 1) - header.size() - 1);
  EXPECT_EQ(std::count(first.begin(), first.end(), ','), std::count(header.begin(), header.end(), ','));
  // The body at the end of the epoch: its 13 vertices, not a circle.
  const auto at = svg.find("<polygon points=\"");
  ASSERT_NE(at, std::string::npos);
  const std::string points = svg.substr(at, svg.find('"', at + 17) - at);
  EXPECT_EQ(std::count(points.begin(), points.end(), ','), 13) << points;
}

}  // namespace
