// What every stickslip subcommand shares: exit codes, strict number parsing, the --set/--preset
// vocabulary for parameters and initial states.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "stickslip/model/flows.hpp"
#include "stickslip/model/parameters.hpp"

namespace stickslip::cli {

// Stable exit codes (documented in the README and in --help).
inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;     // an internal or I/O failure
inline constexpr int kExitBadInput = 2;    // invalid options or values; nothing was written
inline constexpr int kExitNoConvergence = 3;

// Bad user input: the message is one line naming the field, its value and the valid range.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A decimal number, the whole text, finite; otherwise InputError
// "<field> = '<text>' is not a finite number: valid range <valid_range>".
double ParseNumber(std::string_view field, std::string_view text, std::string_view valid_range);

// The physical data and the initial state and phase: the keys chi, eta, omega, u_s, u_r, x10,
// x20, v10, v20, phi of --set, everywhere in stickslip.
struct ModelInput {
  Parameters parameters;
  State initial_state = State::Zero();
  double phi = 0.0;
  std::string preset;  // empty when none
};

// The help text of --set, listing every key with its meaning and valid range.
std::string SetKeysHelp();

// A parameter's valid range as the messages print it, e.g. "0 < chi < 1".
std::string ValidRange(ParameterId id);

// Starts from the preset's printed values (if `preset` is not empty), applies every
// "key=value" of `assignments`, checks that the parameters were all given and are valid
// (Validate) and that the state is finite. Throws InputError.
ModelInput ResolveModelInput(const std::string& preset, const std::vector<std::string>& assignments);

// The same, starting instead (if `point` is not empty) from a labelled point "RUN:LABEL" of a
// continuation run stored under `results`: its data, its orbit's initial state (x2' = 0 there)
// and phase. At most one of `preset` and `point`.
ModelInput ResolveModelInput(const std::string& preset, const std::string& point, const std::string& results,
                             const std::vector<std::string>& assignments);

// "chi=0.3 eta=4 omega=0.6 u_s=0.1 u_r=0.2996", numbers in shortest round-trip form.
std::string DescribeParameters(const Parameters& p);

}  // namespace stickslip::cli
