// Regression checks: a fresh run's special points and labelled branch points against the files
// stored in results/. Special points must agree in type and order, the continuation parameter
// to a relative 1e-8 and every other variable of the solution to 1e-7.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "stickslip/io/run.hpp"

namespace stickslip {

struct CheckTolerances {
  double parameter_relative = 1e-8;
  double solution = 1e-7;  // absolute, scaled by max(1, |value|)
};

struct Difference {
  std::string file;     // "special-points.csv" or "branch.csv"
  std::string row;      // label, or "row N"
  std::string column;
  std::string stored;
  std::string fresh;
};

std::vector<Difference> CompareWithStored(const RunFiles& fresh, const std::filesystem::path& stored_dir,
                                          const std::string& parameter, const CheckTolerances& tolerances = {});

}  // namespace stickslip
