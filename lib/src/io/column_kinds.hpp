// Internal to io/: the valid values of every kind of numeric column in stickslip's tables, stated
// once, so that every reader checks a column of one kind the same way. A reader takes a field
// with CsvTable::Value(row, column, kind); a value outside the kind's valid values is refused as
//   "<file>:<line>: column 'u_s' = '1e308' is invalid: valid |u_s| <= 1000 (...)".
// Non-finite values are valid only where the format documents them for that column (lib/README.md,
// "Result files"): an inapplicable margin is inf, a Floquet quantity that could not be
// computed nan, det(H + I) of an orbit that is not antisymmetric nan.
#pragma once

#include <limits>
#include <string>
#include <string_view>

#include "stickslip/model/pascal_2014/parameters.hpp"

namespace stickslip::detail {

struct ValidValues {
  double min = -std::numeric_limits<double>::infinity();  // a finite value: min <= value <= max
  double max = std::numeric_limits<double>::infinity();
  bool finite = true;      // finite values are valid (within min, max)
  bool inf = false;        // +inf is valid
  bool minus_inf = false;  // -inf is valid
  bool nan = false;        // nan is valid
  std::string text;        // the valid values as a message states them

  bool Holds(double value) const;
};

// A model parameter as an input gives it (a map's grid): the range of the model's description,
// "min <= name <= max".
ValidValues ModelParameter(ParameterId id);
// The same on a stored branch, but the friction levels (the model's kinetic and static level, u_s
// and u_r) within |value| <= their maximum, since a released kinetic level ends its family where
// it reaches 0, located to the event tolerance on either side (-2.7e-11 in
// results/paper-4.2-omega-up).
ValidValues BranchParameter(ParameterId id);
// Any finite number: a start state's component, a phase, a section state.
ValidValues Finite();
// Duration `name` of an orbit of period `period` (orbits/start_problem.hpp, IsDurationOfPeriod):
// 0 to the period to rounding where the row is admissible; any finite number on a row past a
// change of orbit type (admissible = 0), where a segment's length may have turned negative.
ValidValues Duration(std::string_view name, double period, bool admissible);
// The sum of the sticks' durations over the period: 0 to 1 (to rounding) where admissible.
ValidValues Fraction(bool admissible);
// A finite number >= 0: an amplitude, a peak-to-peak, a step size, stops or sticks per period.
ValidValues NonNegative();
// A brute force's amplitude of the contact over the recorded periods: a finite number >= 0, or nan
// where the simulation stopped early or the search for an extremum was cut short
// (analysis/settled_motion.hpp).
ValidValues SettledAmplitude();
// The friction work per period and its equivalent viscous damping: a finite number (of the kinetic
// level's sign: below 0 only where a released u_s ends its family, located to either side of 0),
// or nan (the damping where the contact's coordinate does not move; either where a file written
// before the column was read and written again).
ValidValues FrictionMeasure();
// An admissibility margin: a finite number, inf where the margin does not apply, nan where it
// could not be computed (margins.hpp SmallestMargin: undefined).
ValidValues Margin();
// A Floquet multiplier's part: a finite number, or nan where it could not be computed.
ValidValues FloquetValue();
// det(M - I), det(M + I), the torus test: a Floquet value, or inf or -inf where the product over the
// multipliers overflows (the torus test of ten multipliers, a five-mass chain's, has 45 factors).
ValidValues FloquetProduct();
// det(H + I): a Floquet product of an antisymmetric orbit; nan for any other.
ValidValues SymmetryTest(bool antisymmetric);

}  // namespace stickslip::detail
