#include "runtime/eval/observe.hpp"

#include <cmath>

namespace esc::eval {

void observe_robot(const sim::World& world, const std::array<double, sim::kIrSensors>& ir,
                   expr::Frame& frame) noexcept {
  const sim::RobotState& s = world.state();
  const sim::KheperaParams& p = world.robot();
  const double full_step_m = p.motor.max_speed_mps * p.control_step_s;
  const double left = s.wheel_speed_mps[0] / p.motor.max_speed_mps;
  const double right = s.wheel_speed_mps[1] / p.motor.max_speed_mps;
  frame[expr::slot::speed] = s.displacement_m / full_step_m;
  frame[expr::slot::forward_speed] = s.forward_displacement_m / full_step_m;
  frame[expr::slot::wheel_diff] = std::abs(left - right) / 2.0;
  frame[expr::slot::wheels] = left;
  frame[expr::slot::wheels + 1] = right;
  frame[expr::slot::collision] = s.collided ? 1.0 : 0.0;
  for (std::size_t i = 0; i < ir.size(); ++i) frame[expr::slot::ir + i] = ir[i];
}

void observe_clock(int epoch, int step, double control_step_s, expr::Frame& frame) noexcept {
  frame[expr::slot::epoch] = epoch;
  frame[expr::slot::step] = step;
  frame[expr::slot::time] = step * control_step_s;
}

}  // namespace esc::eval
