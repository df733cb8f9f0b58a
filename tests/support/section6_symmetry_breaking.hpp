// A start near the symmetry breaking of section 6's orbit type, shared by the tests of branch
// switching there and of its curve in two parameters.
#pragma once

#include "stickslip/io/run.hpp"

namespace stickslip {

// The §6 type `slip- stick slip- / antisymmetric` continued down in omega past its type changes
// (the orbit is no motion there: a test of the algebra, not of the physics) meets a multiplier -1
// of its half-period map at omega = 0.55014: a symmetry breaking. The guess is a point of that
// continuation just above it.
inline OrbitContinuationSetup Section6AboveItsSymmetryBreaking() {
  RunFile run;
  run.path = "(test)";
  run.output = "test";
  run.preset = "paper-6";
  run.set = {{"omega", 0.5501955483169749}};
  run.guess = {{"x10", 9.936832707872899}, {"x20", 11.737822390429132}, {"v10", -6.552116682904398},
               {"phi", 3.586861573229454}, {"d1", 3.129379765497387}, {"d2", 1.8950732856966541},
               {"d3", 0.6855034600859811}};
  run.parameter = "omega";
  run.direction = -1;
  run.range_min = 0.54;
  run.range_max = 0.56;
  run.steps.ds = 0.01;
  run.steps.ds_max = 0.02;
  run.steps.max_points = 30;
  run.continue_past_type_changes = true;
  return MakeSetup(run, "results");
}

}  // namespace stickslip
