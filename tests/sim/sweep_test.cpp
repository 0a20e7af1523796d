// Area sweeping: the grid of visited cells, new_cell on entry steps, cells_visited.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>

#include "sim_test_util.hpp"

namespace esc::sim {
namespace {

RobotParams no_inertia() {
  RobotParams r;
  r.motor.inertia = false;
  return r;
}

TEST(SimSweep, GridSize) {
  World w(test::empty_arena(0.6, 0.6), RobotParams{});
  EXPECT_EQ(w.sweep_columns(), 15);  // 0.6 / 0.04, no sliver column from rounding
  EXPECT_EQ(w.sweep_rows(), 15);
  ArenaSpec a = test::empty_arena(0.65, 0.3);
  a.sweep_cell_m = 0.1;
  World v(a, RobotParams{});
  EXPECT_EQ(v.sweep_columns(), 7);  // the last column is partial
  EXPECT_EQ(v.sweep_rows(), 3);
}

TEST(SimSweep, StraightAcrossTheArena) {
  const ArenaSpec a = test::empty_arena(0.6, 0.6);
  World w(a, no_inertia());
  w.reset({0.05, 0.3, 0.0});
  EXPECT_EQ(w.state().floor.cells_visited, 1);  // the start cell
  EXPECT_FALSE(w.state().floor.new_cell);
  int prev_col = static_cast<int>(std::floor(0.05 / 0.04));
  int entries = 0;
  for (int i = 0; i < 60; ++i) {  // 8 mm per step: to x = 0.53
    w.step(1.0, 1.0);
    const int col = static_cast<int>(std::floor(w.state().pose.x_m / 0.04));
    EXPECT_EQ(w.state().floor.new_cell, col != prev_col) << "step " << i;
    entries += w.state().floor.new_cell ? 1 : 0;
    prev_col = col;
  }
  EXPECT_NEAR(w.state().pose.x_m, 0.53, 1e-6);
  EXPECT_EQ(w.state().floor.cells_visited, 13);  // columns 1 .. 13 of row 7
  EXPECT_EQ(entries, 12);
  // Back over the same cells: nothing new.
  for (int i = 0; i < 40; ++i) {
    w.step(-1.0, -1.0);
    EXPECT_FALSE(w.state().floor.new_cell);
  }
  EXPECT_EQ(w.state().floor.cells_visited, 13);
  // A new epoch forgets them.
  w.reset({0.3, 0.3, 0.0});
  EXPECT_EQ(w.state().floor.cells_visited, 1);
  w.step(1.0, 1.0);
  EXPECT_EQ(w.state().floor.cells_visited, 1);  // 0.308 is still column 7
  for (int i = 0; i < 5; ++i) w.step(1.0, 1.0);
  EXPECT_EQ(w.state().floor.cells_visited, 2);
}

TEST(SimSweep, CountsDistinctCellsOfAWanderingPath) {
  ArenaSpec a = test::empty_arena(0.6, 0.6);
  a.sweep_cell_m = 0.05;
  a.cylinders.push_back({{0.3, 0.3}, 0.05});
  World w(a, RobotParams{});
  Rng rng(4);
  w.reset(w.random_free_pose(rng));
  std::set<std::pair<int, int>> cells;
  const auto cell = [&] {
    // A body pressed into a wall may sit a fraction of a millimetre beyond it.
    return std::pair{std::clamp(static_cast<int>(std::floor(w.state().pose.x_m / 0.05)), 0, 11),
                     std::clamp(static_cast<int>(std::floor(w.state().pose.y_m / 0.05)), 0, 11)};
  };
  cells.insert(cell());
  double l = 0, r = 0;
  for (int i = 0; i < 3000; ++i) {
    if (i % 15 == 0) {
      l = rng.uniform(-0.3, 1.0);
      r = rng.uniform(-0.3, 1.0);
    }
    w.step(l, r);
    const bool fresh = cells.insert(cell()).second;
    EXPECT_EQ(w.state().floor.new_cell, fresh) << i;
    EXPECT_EQ(w.state().floor.cells_visited, static_cast<int>(cells.size()));
  }
  EXPECT_GT(cells.size(), 20U);
}

}  // namespace
}  // namespace esc::sim
