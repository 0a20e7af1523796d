// Descriptors folded over every step (examples/qd_descriptors.esc): a short MAP-Elites run
// over mean speed and the fraction of steps near a wall, and a CVT over sampled positions,
// whose archives agree with replays: `esc replay --member CELL` measures each elite again in
// its own evaluation and finds the descriptors stored with it, bit for bit. The same for a
// group's descriptors (experiments/examples/group_repertoire.esc: five robots' spread and
// how far their centroid moved).
#include <algorithm>
#include <cstdlib>
#include <map>
#include <regex>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/cli/esc_process.hpp"
#include "tests/cli/results_support.hpp"

namespace {

using namespace cli_test;

const std::string kExample = std::string(ESC_SOURCE_DIR) + "/examples/qd_descriptors.esc";
const std::string kGroupExample = std::string(ESC_SOURCE_DIR) + "/experiments/examples/group_repertoire.esc";

std::size_t column(const std::vector<std::string>& header, const std::string& name) {
  const auto it = std::find(header.begin(), header.end(), name);
  EXPECT_NE(it, header.end()) << name;
  return static_cast<std::size_t>(it - header.begin());
}

// The descriptors `esc replay --member` printed: "cell 3 descriptors: a 0.25, b 0.5 (as stored)".
std::vector<double> replayed_descriptors(const std::string& output) {
  const std::regex line(R"(descriptors: (.*) \(as stored\))");
  std::smatch m;
  if (!std::regex_search(output, m, line)) return {};
  std::vector<double> values;
  const std::string list = m[1];
  const std::regex value(R"([A-Za-z_0-9]+ ([-+0-9.eE]+|inf|nan))");
  for (auto it = std::sregex_iterator(list.begin(), list.end(), value); it != std::sregex_iterator(); ++it)
    values.push_back(std::strtod((*it)[1].str().c_str(), nullptr));
  return values;
}

void archive_agrees_with_replays(const std::string& experiment, const std::vector<std::string>& names,
                                 const std::string& script = kExample) {
  const fs::path dir = scratch("qd-" + experiment);
  const Outcome ran = esc("run " + script + " --experiment " + experiment +
                          " --runs 1 --generations 3 --set epochs=1 --set steps=60 --out " + dir.string());
  ASSERT_EQ(ran.status, 0) << ran.output;
  const Outcome archive = esc("export " + dir.string() + " --table archive");
  ASSERT_EQ(archive.status, 0) << archive.output;
  const auto rows = csv_rows(archive.output);
  ASSERT_GT(rows.size(), 3u) << archive.output;
  const std::vector<std::string>& header = rows.front();
  const std::size_t cell = column(header, "cell"), generation = column(header, "generation");
  std::vector<std::size_t> described;
  for (const std::string& n : names) described.push_back(column(header, n));
  // The final archive: each cell's last row. Replay up to 6 of its elites.
  std::map<std::string, std::vector<double>> stored;
  std::map<std::string, int> latest;
  for (std::size_t r = 1; r < rows.size(); ++r) {
    const int g = std::stoi(rows[r][generation]);
    auto& at = latest.try_emplace(rows[r][cell], -1).first->second;
    if (g < at) continue;
    at = g;
    std::vector<double>& values = stored[rows[r][cell]];
    values.clear();
    for (const std::size_t c : described) values.push_back(std::strtod(rows[r][c].c_str(), nullptr));
  }
  int replayed = 0;
  for (const auto& [c, values] : stored) {
    if (++replayed > 6) break;
    const Outcome again = esc("replay " + dir.string() + " --member " + c + " --out " + (dir / "replays").string());
    ASSERT_EQ(again.status, 0) << again.output;
    EXPECT_NE(again.output.find(", as in its own evaluation)"), std::string::npos) << again.output;
    EXPECT_EQ(replayed_descriptors(again.output), values) << "cell " << c << "\n" << again.output;
  }
}

TEST(QdDescriptors, MeanSpeedAndTimeNearAWallAgreeWithReplays) {
  archive_agrees_with_replays("qd_descriptors", {"mean_speed", "near_wall"});
}

TEST(QdDescriptors, SampledPositionsAgreeWithReplays) {
  std::vector<std::string> names;
  for (int i = 0; i < 4; ++i) {
    names.push_back("path_x" + std::to_string(i));
    names.push_back("path_y" + std::to_string(i));
  }
  archive_agrees_with_replays("paths", names);
}

TEST(QdDescriptors, AGroupsSpreadAndCentroidAgreeWithReplays) {
  archive_agrees_with_replays("group_repertoire", {"apart", "travelled"}, kGroupExample);
}

}  // namespace
