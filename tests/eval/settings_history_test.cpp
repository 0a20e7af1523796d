// Settings added to esc later (runtime/eval/settings_history.hpp): a stored run that lacks
// one ran with its as-before value, so resume, replay and the dependency fingerprint treat
// the two alike; any other difference still counts.
#include <gtest/gtest.h>

#include "runtime/eval/fingerprint.hpp"
#include "runtime/eval/settings_history.hpp"

namespace esc::eval {
namespace {

TEST(SettingsHistory, AMissingLaterSettingAtItsAsBeforeValueIsTheSame) {
  const std::map<std::string, std::string> stored{{"epochs", "10"}, {"robot.ir_noise", "0"}};
  std::map<std::string, std::string> now = stored;
  now["robot.motor_noise"] = "0";
  EXPECT_TRUE(same_settings(now, stored));
  EXPECT_TRUE(same_settings(stored, stored));
  now["robot.motor_noise"] = "0.1";
  EXPECT_FALSE(same_settings(now, stored));
  now["robot.motor_noise"] = "0";
  now["epochs"] = "5";
  EXPECT_FALSE(same_settings(now, stored));
  // A key the run stored and esc no longer has is a difference, as is an unknown new key.
  EXPECT_FALSE(same_settings({{"epochs", "10"}}, stored));
  EXPECT_FALSE(same_settings({{"epochs", "10"}, {"robot.ir_noise", "0"}, {"robot.new", "0"}}, stored));
}

TEST(SettingsHistory, TheFingerprintOmitsALaterSettingAtItsAsBeforeValue) {
  ExperimentSpec a;
  a.name = std::string("e");   // from a char literal GCC 12 warns falsely (-Wrestrict, its bug 105329)
  a.resolved_settings = {{"epochs", "10"}};
  ExperimentSpec b = a;
  b.resolved_settings = {{"epochs", "10"}, {"robot.motor_noise", "0"}};
  EXPECT_EQ(fingerprint(a), fingerprint(b));
  b.resolved_settings = {{"epochs", "10"}, {"robot.motor_noise", "0.05"}};
  EXPECT_NE(fingerprint(a), fingerprint(b));
}

}  // namespace
}  // namespace esc::eval
