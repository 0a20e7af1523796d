#pragma once
// Settings esc gained after runs were stored without them. Each comes with the value that
// does exactly what esc did before it existed (`robot.motor_noise` 0: the wheels follow
// their commands), so a stored run that lacks one ran with that value: its resume, replay
// and dependency fingerprint treat the two alike, and adding a setting neither strands old
// runs nor invalidates the dependency cache.
#include <map>
#include <string>

namespace esc::eval {

// Whether `key` = `value` is a later setting at the value that means "as before it existed".
[[nodiscard]] bool as_before_it_existed(const std::string& key, const std::string& value);

// Whether resolved settings `now` are those a run stored as `stored`, a later setting that
// `stored` lacks counting as equal when `now` holds it at its as-before value.
[[nodiscard]] bool same_settings(const std::map<std::string, std::string>& now,
                                 const std::map<std::string, std::string>& stored);

}  // namespace esc::eval
