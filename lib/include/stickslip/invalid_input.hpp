// Bad input, the one error convention of the library: a value a caller gave lies outside its
// valid range. The message is one line naming the field, the value and the valid range (control
// characters in it are written as escapes: \n, \t, \x1b),
//   "omega = -1 is invalid: valid range omega > 0",
// and the command line maps the exception to exit code 2 with nothing written (Python will map
// it to ValueError). Numerical outcomes (no convergence, a branch that ended, a verification
// that failed) are not errors: they are statuses in the solvers' Summary and Result values.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>
#include <utility>

namespace stickslip {

class InvalidInput : public std::invalid_argument {
 public:
  // "<field> = <value> is invalid: valid range <valid_range>".
  InvalidInput(std::string field, std::string value, std::string valid_range);
  InvalidInput(std::string field, double value, std::string valid_range);
  // A message of its own that still names the field first, for input that is not one value
  // ("signature 'stik': token 1 'stik' is not a mode: valid slip-, slip+, stick").
  static InvalidInput WithMessage(std::string field, std::string message);
  // The same violation with the field named as a front end calls it ("restart" -> "point" on the
  // command line): a leading field name in the message is replaced too.
  InvalidInput Renamed(std::string field) const;
  // The message after its leading field name ("= 'paper-9' is unknown: valid ..."), or the whole
  // message when it does not start with the field; for front ends that name the field their way.
  std::string Predicate() const;

  const std::string& field() const { return field_; }
  const std::string& value() const { return value_; }
  const std::string& valid_range() const { return valid_range_; }

 private:
  InvalidInput(std::string field, std::string value, std::string valid_range, std::string message);

  std::string field_;
  std::string value_;
  std::string valid_range_;
};

// A count given as a number (an option such as steps or max-points): the whole number low <=
// value <= high, or InvalidInput "<field> = <value> is invalid: valid range whole numbers low <=
// <field> <= high".
int WholeNumber(std::string_view field, double value, int low, int high);

// Throws InvalidInput naming `field` for the first name `values` gives twice ("set gives 'F_k' twice
// (0.1 and 0.2): give it once", then `where`, e.g. " (in set, guess or a fix value)"): a repeated
// name would silently keep its last value.
void RefuseRepeatedNames(std::string_view field, const std::vector<std::pair<std::string, double>>& values,
                         std::string_view where = "");
// That valid range as messages and help texts state it: "whole numbers low <= <field> <= high".
std::string WholeNumberRange(std::string_view field, int low, int high);

}  // namespace stickslip
