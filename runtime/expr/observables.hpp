#pragma once
// The variables that compiled expressions, controllers and behaviors read: one flat frame
// of doubles per robot, refilled by the evaluation loop at every control step. The
// compiler resolves a script name (`ir[3]`, `forward_speed`) to a slot of this frame once,
// so reading an observable in the step loop is an array load.
//
// Each observable is documented in docs/language.md; keep the two in step.
#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

namespace esc::expr {

using Slot = std::uint32_t;

namespace slot {
inline constexpr Slot speed = 0;          // |body displacement| / (dt * max wheel speed), [0, 1]
inline constexpr Slot forward_speed = 1;  // displacement along heading / (dt * max speed), [-1, 1]
inline constexpr Slot wheel_diff = 2;     // |left - right| / 2 of measured wheel speeds, [0, 1]
inline constexpr Slot wheels = 3;         // wheels[0] left, wheels[1] right: measured speed / max
inline constexpr Slot ir = 5;             // ir[0..7]: IR proximity, 0 far .. 1 touching
inline constexpr Slot collision = 13;     // 1 if the body touched a wall or obstacle this step
inline constexpr Slot step = 14;          // index of the control step in the epoch, from 0
inline constexpr Slot time = 15;          // seconds since the epoch started
inline constexpr Slot epoch = 16;         // index of the epoch in the evaluation, from 0
inline constexpr Slot param = 17;         // param[0..3]: parameters of the running behavior
}  // namespace slot

inline constexpr Slot kIrCount = 8;
inline constexpr Slot kWheelCount = 2;
inline constexpr Slot kMaxParams = 4;
inline constexpr Slot kFrameSize = slot::param + kMaxParams;

using Frame = std::array<double, kFrameSize>;

// One script-visible observable: a scalar (count 1, not indexable) or an array.
struct Observable {
  std::string_view name;
  Slot first;
  Slot count;
  bool indexed;
  std::string_view unit;
  std::string_view summary;
};

inline constexpr std::array kObservables = {
    Observable{"speed", slot::speed, 1, false, "fraction of max speed",
               "body speed over the last step (distance covered / step time), 0 .. 1"},
    Observable{"forward_speed", slot::forward_speed, 1, false, "fraction of max speed",
               "speed along the heading over the last step, -1 (backwards) .. 1"},
    Observable{"wheel_diff", slot::wheel_diff, 1, false, "fraction",
               "|left - right| / 2 of the measured wheel speeds, 0 .. 1"},
    Observable{"wheels", slot::wheels, kWheelCount, true, "fraction of max speed",
               "measured wheel speeds, [0] left and [1] right, -1 .. 1"},
    Observable{"ir", slot::ir, kIrCount, true, "activation",
               "IR proximity sensors 0..7 (left to right, then two at the back), 0 far .. 1 touching"},
    Observable{"collision", slot::collision, 1, false, "boolean",
               "1 when the body touched a wall or an obstacle during the last step"},
    Observable{"step", slot::step, 1, false, "count", "control step within the epoch, from 0"},
    Observable{"time", slot::time, 1, false, "s", "time since the epoch started"},
    Observable{"epoch", slot::epoch, 1, false, "count", "epoch within the evaluation, from 0"},
};

[[nodiscard]] constexpr std::optional<Observable> find_observable(std::string_view name) noexcept {
  for (const auto& o : kObservables)
    if (o.name == name) return o;
  return std::nullopt;
}

}  // namespace esc::expr
