#pragma once
// summary.json holds each run's per-generation best, mean and sd as a digest; the tests that
// read the values themselves take them from esc.db (`esc export --format json`), after
// checking that the summary's digest, count and final values are theirs. The digest is
// computed here as docs/results-store.md defines it, apart from esc's code.
#include <bit>
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/cli/esc_process.hpp"

namespace cli_test {

// FNV-1a of each value's 8 bytes, little-endian, in order: "fnv1a64:" and 16 hex digits.
inline std::string values_digest(const std::vector<double>& values) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (const double v : values)
    for (int i = 0; i < 8; ++i) h = (h ^ ((std::bit_cast<std::uint64_t>(v) >> (8 * i)) & 0xff)) * 0x100000001b3ULL;
  std::string hex(16, '0');
  for (int i = 15; i >= 0; --i, h >>= 4) hex[static_cast<std::size_t>(i)] = "0123456789abcdef"[h & 0xf];
  return "fnv1a64:" + hex;
}

// DIR's summary.json with each run's "best", "mean" and "sd" arrays put back from the
// export (by experiment or condition, controller and run), checked against the summary.
inline nlohmann::json summary_with_values(const fs::path& dir) {
  nlohmann::json summary = read_json(dir / "summary.json");
  const Outcome exported = esc("export " + dir.string() + " --format json");
  EXPECT_EQ(exported.status, 0) << exported.output;
  const nlohmann::json all = nlohmann::json::parse(exported.output);
  const auto fill = [&](const std::string& who, nlohmann::json& controllers) {
    for (const nlohmann::json& e : all.at("experiments")) {
      if (e.value("condition", e.at("name").get<std::string>()) != who) continue;
      for (auto& [name, c] : controllers.items())
        for (nlohmann::json& r : c.at("runs"))
          for (const nlohmann::json& stored : e.at("controllers").at(name).at("runs")) {
            if (stored.at("run") != r.at("run")) continue;
            std::vector<double> values;   // best, mean and sd of each generation
            for (const char* key : {"best", "mean", "sd"}) r[key] = nlohmann::json::array();
            for (const nlohmann::json& g : stored.at("generations"))
              for (const char* key : {"best", "mean", "sd"}) {
                values.push_back(g.at(key).get<double>());
                r[key].push_back(g.at(key));
              }
            EXPECT_EQ(r.at("generations"), r["best"].size()) << who << " " << name << " run " << r.at("run");
            EXPECT_EQ(r.at("values_digest"), values_digest(values)) << who << " " << name << " run " << r.at("run");
            if (!r["best"].empty()) {
              EXPECT_EQ(r.at("final"), (nlohmann::json{{"best", r["best"].back()}, {"mean", r["mean"].back()},
                                                       {"sd", r["sd"].back()}}));
            }
          }
    }
  };
  if (summary.contains("conditions"))
    for (nlohmann::json& c : summary.at("conditions")) fill(c.at("name").get<std::string>(), c.at("controllers"));
  else
    fill(summary.at("experiment").get<std::string>(), summary.at("controllers"));
  return summary;
}

}  // namespace cli_test
