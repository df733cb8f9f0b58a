#include <filesystem>

#include <gtest/gtest.h>

#include "stickslip/branches/type_switch.hpp"
#include "stickslip/io/run.hpp"

namespace stickslip {
namespace {

namespace fs = std::filesystem;

TEST(TypeSwitchSurvey, EveryLocatedTypeChangeOfTheRunFiles) {
  std::vector<std::string> files;
  for (const auto& entry : fs::directory_iterator(fs::path(STICKSLIP_SOURCE_DIR) / "continuation-scripts")) {
    if (entry.path().extension() == ".toml") files.push_back(entry.path().string());
  }
  std::sort(files.begin(), files.end());
  for (const std::string& file : files) {
    const RunFile run = ReadRunFile(file);
    std::vector<std::pair<OrbitContinuationSetup, int>> todo = {{MakeSetup(run, fs::path(STICKSLIP_SOURCE_DIR) / "results"), 0}};
    while (!todo.empty()) {
      auto [setup, depth] = todo.back();
      todo.pop_back();
      const OrbitBranch b = ContinueOrbit(setup);
      std::printf("%*s%s %s: %zu points, %s %s\n", 2 * depth, "", fs::path(file).stem().c_str(),
                  setup.start.signature.ToString().c_str(), b.branch.points.size(), ToString(b.branch.end), b.branch.end_message.c_str());
      for (const SpecialPoint& s : b.branch.special_points) {
        if (s.test_function.rfind("margin:", 0) != 0) continue;
        const LocatedTypeChange located = TypeChangeAt(b, s, setup);
        const TypeSwitch sw = SwitchAt(located);
        std::printf("%*s%s %s lambda=%.10g past=%d -> %s %s dir=%d persists=%d\n%*s  %s\n", 2 * depth, "",
                    s.type.c_str(), located.margin.c_str(), s.lambda, located.past, ToString(sw.status),
                    sw.adjacent ? sw.adjacent->edit.signature.ToString().c_str() : "-", sw.direction, sw.persists,
                    2 * depth, "", sw.reason.c_str());
        if (sw.status == TypeSwitchStatus::kConfirmed && depth < 3) {
          OrbitContinuationSetup next = setup;
          next.start = *sw.start;
          next.unknowns = sw.unknowns;
          next.options.direction = sw.direction;
          next.options.max_points = 400;
          todo.push_back({next, depth + 1});
        }
      }
    }
  }
}

}  // namespace
}  // namespace stickslip
