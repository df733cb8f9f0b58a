// A run file restarting from a stored run's labelled point, continued in omega over [0.3, 0.9]:
// how the tests start curves and branches at points of results/ (MakeSetup with the results
// root that holds `run`).
#pragma once

#include <string>

#include "stickslip/io/run_file.hpp"

namespace stickslip {

inline RunFile RestartInOmega(const std::string& run, const std::string& label) {
  RunFile file;
  file.path = "test";
  file.output = "curve";
  file.restart_run = run;
  file.restart_label = label;
  file.parameter = "omega";
  file.range_min = 0.3;
  file.range_max = 0.9;
  return file;
}

}  // namespace stickslip
