// The replay picture and table, in process: what they draw and write for given steps.
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "runtime/report/trajectory_csv.hpp"
#include "runtime/report/trajectory_svg.hpp"
#include "tests/report/helpers.hpp"

namespace esc::report {
namespace {

std::vector<eval::TraceStep> two_epochs() {
  std::vector<eval::TraceStep> steps;
  for (int epoch = 0; epoch < 2; ++epoch)
    for (int step = 0; step < 4; ++step) {
      eval::TraceStep t;
      t.epoch = epoch;
      t.step = step;
      t.pose = {0.1 + 0.05 * step, 0.2 + 0.1 * epoch, 0.0};
      t.action = step < 2 ? 0 : 2;
      t.collided = epoch == 1 && step == 3;
      t.zone_count = 1;
      t.zones[0] = {0.3, 0.1 + 0.2 * epoch};   // a random zone, elsewhere each epoch
      steps.push_back(t);
    }
  return steps;
}

TrajectoryFigure figure(const std::vector<eval::TraceStep>& steps, std::vector<std::string> choices) {
  TrajectoryFigure f;
  f.title = "A & <B>";
  f.arena.width_m = 0.6;
  f.arena.height_m = 0.4;
  f.arena.cylinders.push_back({{0.3, 0.2}, 0.03});
  sim::Zone zone;
  zone.radius_m = 0.05;
  zone.random_position = true;
  zone.recharge = true;
  f.arena.zones.push_back(zone);
  f.bodies = {{0.0275, {}}};
  f.choices = std::move(choices);
  f.steps = steps;
  return f;
}

using test::count;

TEST(TrajectorySvg, ColoursByActionMarksEpochsZonesAndCollisions) {
  const auto steps = two_epochs();
  const std::string svg = trajectory_svg(figure(steps, {"forward", "left", "right"}));
  EXPECT_EQ(svg.rfind("<?xml", 0), 0U);
  EXPECT_NE(svg.find("A &amp; &lt;B&gt;"), std::string::npos) << "title not escaped";
  // Per epoch: one stretch of `forward` (#4e79a7), one of `right` (#59a14f).
  EXPECT_EQ(count(svg, R"(<path stroke="#4e79a7")"), 2U);
  EXPECT_EQ(count(svg, R"(<path stroke="#59a14f")"), 2U);
  EXPECT_NE(svg.find("forward (50% of steps)"), std::string::npos);
  EXPECT_NE(svg.find("left (0% of steps)"), std::string::npos);
  // The random zone where it was in each epoch, labelled; one collision.
  EXPECT_NE(svg.find(">epoch 1</text>"), std::string::npos);
  EXPECT_NE(svg.find(">epoch 2</text>"), std::string::npos);
  EXPECT_EQ(count(svg, R"(r="3" fill="#111111")"), 1U + 1U) << "one collision, one legend mark";
}

TEST(TrajectorySvg, ClassicalHeadsAreColouredByEpoch) {
  const auto steps = two_epochs();
  std::vector<eval::TraceStep> classical = steps;
  for (auto& t : classical) t.action = -1;
  const std::string svg = trajectory_svg(figure(classical, {}));
  EXPECT_NE(svg.find("path, by epoch"), std::string::npos);
  EXPECT_NE(svg.find("epoch 1 (4 steps)"), std::string::npos);
  EXPECT_EQ(count(svg, "<path stroke="), 2U);
}

// Coloured by behavior, epochs from one fixed start would lie on each other: each has its
// dash pattern, in the legend; a scale bar says how large the arena is.
TEST(TrajectorySvg, EpochsColouredByBehaviorAreDashedApartOverAScaleBar) {
  const std::string svg = trajectory_svg(figure(two_epochs(), {"forward", "left", "right"}));
  EXPECT_EQ(count(svg, R"(stroke-dasharray="9 4" d=)"), 2U) << "epoch 2's two stretches";
  EXPECT_NE(svg.find("path, by epoch"), std::string::npos);
  EXPECT_NE(svg.find("epoch 2 (4 steps)"), std::string::npos);
  EXPECT_NE(svg.find(">10 cm</text>"), std::string::npos) << "a 60 cm arena's bar";
  std::vector<eval::TraceStep> classical = two_epochs();
  for (auto& t : classical) t.action = -1;
  EXPECT_EQ(trajectory_svg(figure(classical, {})).find("stroke-dasharray=\"9 4\""), std::string::npos)
      << "colours tell a classical head's epochs apart already";
}

TEST(TrajectorySvg, DrawsSegmentWallsAsTheirRectanglesAndTheGoal) {
  const auto steps = two_epochs();   // the figure's span points into it
  TrajectoryFigure f = figure(steps, {});
  const std::string without = trajectory_svg(f);
  EXPECT_EQ(without.find(">goal</text>"), std::string::npos);
  // A vertical wall 20 cm long, 1 cm thick, centred at (0.5 m, 0.2 m): a 200 x 10 mm rectangle
  // turned by -90 degrees (SVG's y runs down) about its centre.
  f.arena.walls.push_back({{0.5, 0.1}, {0.5, 0.3}, 0.01});
  f.arena.goal = sim::Vec2{0.55, 0.35};
  const std::string svg = trajectory_svg(f);
  EXPECT_EQ(count(svg, R"(fill="#8d96a8")"), count(without, R"(fill="#8d96a8")") + 1U);
  EXPECT_NE(svg.find(R"(width="200.0" height="10.0" fill="#8d96a8" transform="rotate(-90.000)"), std::string::npos)
      << svg;
  EXPECT_EQ(count(svg, R"(stroke="#c51b7d")"), 2U) << "the goal, and its legend mark";
  EXPECT_NE(svg.find(">goal</text>"), std::string::npos);
}

// Three robots over two epochs: a row per robot per step, in robot order.
std::vector<eval::TraceStep> a_group() {
  std::vector<eval::TraceStep> rows;
  for (const eval::TraceStep& t : two_epochs())
    for (int r = 0; r < 3; ++r) {
      eval::TraceStep u = t;
      u.robot = r;
      u.grouped = true;
      u.pose.y_m += 0.05 * r;
      u.group = {0.25, 0.5, 0.0, 0.05 * r, 0.05, 0.0666, 0.05};
      rows.push_back(u);
    }
  return rows;
}

// Every robot's path in its own colour, its start and its end, and a legend of the robots.
TEST(TrajectorySvg, AGroupsRobotsAreDrawnEachInItsColour) {
  const auto rows = a_group();
  const std::string svg = trajectory_svg(figure(rows, {"forward", "left", "right"}));
  EXPECT_NE(svg.find("path, by robot"), std::string::npos);
  for (const char* colour : {"#4e79a7", "#f28e2b", "#59a14f"})
    EXPECT_EQ(count(svg, fmt::format(R"(<path stroke="{}")", colour)), 2U) << colour << ": a path per epoch";
  EXPECT_EQ(count(svg, R"(fill-opacity="0.35")"), 6U) << "every robot at the end of each epoch";
  EXPECT_NE(svg.find(">robot 3 (1 collision step)</text>"), std::string::npos);
  EXPECT_NE(svg.find(">epoch 2 (4 steps)</text>"), std::string::npos) << "steps, not rows";
}

// A group of several bodies: each robot drawn with its own, a disc or an outline.
TEST(TrajectorySvg, AGroupsRobotsAreDrawnEachWithItsBody) {
  const auto rows = a_group();
  TrajectoryFigure f = figure(rows, {});
  f.bodies = {{0.0275, {}}, {0.037, {}}, {0.05, {{-0.03, -0.04}, {0.05, 0.0}, {-0.03, 0.04}}}};
  const std::string svg = trajectory_svg(f);
  EXPECT_EQ(count(svg, R"(r="27.5" fill=")"), 2U) << "robot 1 at the end of each epoch, a Khepera's disc";
  EXPECT_EQ(count(svg, R"(r="37.0" fill=")"), 2U) << "robot 2, an e-puck's";
  EXPECT_EQ(count(svg, "<polygon points="), 2U) << "robot 3, its outline";
  f.bodies.resize(1);
  EXPECT_EQ(count(trajectory_svg(f), R"(r="27.5" fill=")"), 6U) << "one body for all";
}

// A group's CSV: a robot column after the step, from 1, and the group's observables last.
TEST(TrajectoryCsv, AGroupHasARobotColumnAndItsObservables) {
  const auto rows = a_group();
  const std::string csv = trajectory_csv(rows, {}, 0.1);
  const std::string header = csv.substr(0, csv.find('\n'));
  EXPECT_EQ(header, trajectory_csv_header({}, 0, 0, 0, 0, true));
  EXPECT_EQ(header.rfind("epoch,step,robot,time_s,", 0), 0U) << header;
  EXPECT_NE(header.find(",collided,centroid_x_m,centroid_y_m,centroid_moved_m,centroid_distance_m,nearest_robot_m,"
                        "robot_distance_m,spread_m"),
            std::string::npos)
      << header;
  EXPECT_EQ(count(csv, "\n"), 1U + rows.size());
  EXPECT_NE(csv.find("\n1,1,3,0.1,"), std::string::npos);
  EXPECT_NE(csv.find(",0.25,0.5,0,0.10000000000000001,0.050000000000000003,0.066600000000000006,0.050000000000000003\n"),
            std::string::npos);
}

TEST(TrajectoryCsv, OneRowPerStepCountedFromOne) {
  const auto steps = two_epochs();
  const std::string csv = trajectory_csv(steps, {"forward", "left", "right"}, 0.1);
  EXPECT_EQ(count(csv, "\n"), 1U + steps.size());
  const std::size_t columns = count(trajectory_csv_header({}, 0, 0), ",") + 1;
  EXPECT_EQ(columns, 30U);
  const std::string second = csv.substr(csv.find('\n') + 1);
  EXPECT_EQ(second.rfind("1,1,0.1,0.10000000000000001,", 0), 0U) << second.substr(0, 60);
  EXPECT_NE(csv.find(",right,"), std::string::npos);
  EXPECT_NE(csv.find("\n2,4,0.4,"), std::string::npos);
}

TEST(TrajectoryCsv, RangefindersAndRadarsFollowTheLightsWhereTheRobotHasThem) {
  auto steps = two_epochs();
  for (eval::TraceStep& t : steps) {
    t.range_count = 2;
    t.range = {0.25, 1.0};
    t.radar_count = 4;
    t.radar = {0.0, 0.0, 1.0, 0.0};
  }
  const std::string csv = trajectory_csv(steps, {}, 0.1);
  const std::string header = csv.substr(0, csv.find('\n'));
  EXPECT_EQ(header, trajectory_csv_header({}, 2, 4));
  EXPECT_EQ(count(header, ",") + 1, 30U + 6U);
  EXPECT_NE(header.find(",light7,range0,range1,radar0,radar1,radar2,radar3,energy,"), std::string::npos) << header;
  const std::string first = csv.substr(header.size() + 1, csv.find('\n', header.size() + 1) - header.size() - 1);
  EXPECT_NE(first.find(",0.25,1,0,0,1,0,1,,"), std::string::npos) << "ranges, radars, then energy 1 " << first;
}

TEST(TrajectoryCsv, GroundSensorsByTheirNameAndBumpersFollowTheRadars) {
  auto steps = two_epochs();
  for (eval::TraceStep& t : steps) {
    t.ground_count = 2;
    t.ground = {0.0, 1.0};
    t.bumper_count = 1;
    t.bumper = {1.0};
  }
  const std::string csv = trajectory_csv(steps, {}, 0.1, {"prox_horizontal", 7, "prox_ground"});
  const std::string header = csv.substr(0, csv.find('\n'));
  EXPECT_EQ(header, trajectory_csv_header({"prox_horizontal", 7, "prox_ground"}, 0, 0, 2, 1));
  EXPECT_NE(header.find(",light6,prox_ground0,prox_ground1,bumper0,energy,"), std::string::npos) << header;
  const std::string first = csv.substr(header.size() + 1, csv.find('\n', header.size() + 1) - header.size() - 1);
  EXPECT_EQ(count(first, ","), count(header, ","));
  EXPECT_NE(first.find(",0,1,1,1,,"), std::string::npos) << "ground, bumper, then energy 1 " << first;
}

TEST(TrajectoryCsv, TheIrColumnsAreTheRobotsSensorsByTheirName) {
  const auto steps = two_epochs();
  const std::string puck = trajectory_csv(steps, {}, 0.1, {"prox", 8});
  EXPECT_EQ(puck.substr(0, puck.find('\n')), trajectory_csv_header({"prox", 8}, 0, 0));
  EXPECT_NE(puck.find(",right_speed_mps,prox0,prox1,"), std::string::npos);
  EXPECT_EQ(puck.find(",ir0,"), std::string::npos);
  const std::string none = trajectory_csv(steps, {}, 0.1, {"ir", 0});
  const std::string header = none.substr(0, none.find('\n'));
  EXPECT_NE(header.find(",right_speed_mps,energy,"), std::string::npos) << header;
  const std::string first = none.substr(header.size() + 1, none.find('\n', header.size() + 1) - header.size() - 1);
  EXPECT_EQ(count(first, ","), count(header, ","));
}

}  // namespace
}  // namespace esc::report
