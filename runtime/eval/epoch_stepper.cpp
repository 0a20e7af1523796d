#include "runtime/eval/epoch_stepper.hpp"

#include <algorithm>

namespace esc::eval {

sim::World world_of(const ExperimentSpec& spec) {
  sim::World world(spec.arena, spec.robot_params());
  if (spec.formation.kind != sim::FormationKind::Random) world.set_formation(spec.formation);
  return world;
}

void EpochStepper::begin(std::uint64_t seed, int epoch) {
  seed_ = seed;
  epoch_ = epoch;
  step_ = 0;
  rng_ = Rng(seed, {static_cast<std::uint64_t>(epoch)});
  world_->begin_epoch(rng_);   // random zones, then the start poses, then reset
  for (expr::Frame& frame : frames_) frame.fill(0.0);
  start_centroid_ = group_ ? centroid(*world_) : sim::Vec2{};
  sense();
}

EpochStepper::SensorCounts EpochStepper::widest(const sim::World& world) noexcept {
  SensorCounts n;
  for (std::size_t i = 0; i < world.robots(); ++i) {
    const sim::RobotParams& body = world.robot(i);
    n.ranges = std::max(n.ranges, body.rangefinders.angles_rad.size());
    n.radars = std::max(n.radars, static_cast<std::size_t>(body.radars));
    n.grounds = std::max(n.grounds, body.ground.mounts.size());
    n.bumpers = std::max(n.bumpers, body.bumpers.size());
  }
  return n;
}

TraceStep EpochStepper::traced(const control::WheelCommand& cmd, int action, double fitness,
                               std::size_t robot) const {
  const sim::RobotState& state = world_->state(robot);
  const expr::Frame& frame = frames_[robot];
  TraceStep t;
  t.energy = state.floor.energy;
  const auto zones = world_->zone_centers();
  t.zone_count = std::min(zones.size(), t.zones.size());
  std::copy_n(zones.begin(), t.zone_count, t.zones.begin());
  t.epoch = epoch_;
  t.step = step_ - 1;
  t.robot = static_cast<int>(robot);
  t.pose = state.pose;
  t.ir = ir_[robot];
  t.light = light_[robot];
  // Read back from the frame, where sense() wrote them (a radar reads 0 without a goal).
  t.range_count = widest_.ranges;
  t.radar_count = widest_.radars;
  t.ground_count = widest_.grounds;
  t.bumper_count = widest_.bumpers;
  std::copy_n(frame.begin() + expr::slot::range, t.range_count, t.range.begin());
  std::copy_n(frame.begin() + expr::slot::radar, t.radar_count, t.radar.begin());
  std::copy_n(frame.begin() + expr::slot::ground_sensor, t.ground_count, t.ground.begin());
  std::copy_n(frame.begin() + expr::slot::bumper, t.bumper_count, t.bumper.begin());
  t.grouped = frames_.size() > 1;
  if (t.grouped) std::copy_n(frame.begin() + expr::slot::centroid_x, t.group.size(), t.group.begin());
  t.left_command = cmd.left;
  t.right_command = cmd.right;
  t.left_speed_mps = state.wheel_speed_mps[0];
  t.right_speed_mps = state.wheel_speed_mps[1];
  t.action = action;
  t.fitness = fitness;
  t.collided = state.collided;
  return t;
}

}  // namespace esc::eval
