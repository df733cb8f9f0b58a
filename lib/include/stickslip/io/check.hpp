// Regression checks: a fresh run's special points and labelled branch points against the files
// stored in results/. Special points must agree in type, order, test function and `located`;
// the continuation parameter to a relative 1e-8, every other variable of the solution and every
// measure of the orbit (amplitudes, peak-to-peak, stick fraction; the counts of stops and sticks
// exactly) to 1e-7 and the Floquet multipliers to 1e-6. The `stable` and `admissible` flags must agree wherever
// the stored point is clear of their boundary (multipliers off the unit circle, margins off
// zero, by flag_clearance); on the boundary, at a TR or a grazing, rounding decides them.
#pragma once

#include <string>
#include <vector>

#include "stickslip/io/stored_run.hpp"

namespace stickslip {

struct CheckTolerances {
  double parameter_relative = 1e-8;
  double solution = 1e-7;  // absolute, scaled by max(1, |value|)
  double multiplier = 1e-6;  // absolute, scaled by max(1, |mu|); each stored one against the nearest fresh one
  double flag_clearance = 1e-6;
};

struct Difference {
  std::string file;     // "special-points.csv" or "branch.csv"
  std::string row;      // label, or "row N"
  std::string column;
  std::string stored;
  std::string fresh;
};

// The differences of a fresh run from the stored one (ReadRunFiles), in file order; the
// continuation parameter is the fresh run's.
std::vector<Difference> CompareWithStored(const StoredRun& fresh, const StoredRun& stored,
                                          const CheckTolerances& tolerances = {});

}  // namespace stickslip
