// The fields of a run specification as each front end names them: a run file by its dotted keys
// ("continuation.ds_min", placed at their line), the command line by its options (ds-min). Python
// takes the command line's words for now (its keywords spell '-' as '_': ds_min). A message is
// composed once, in the words of the front end the run came from, from the field and what is
// wrong with it; none is made by rewriting another.
//
//   KeyError(run, "continuation.range", fmt::format("= {} excludes ...", RangeIn(run)))
//     run file:     "a.toml:12:1: key 'continuation.range' = [0.3, 0.9] excludes ..."
//     command line: "range = '0.3,0.9' excludes ..."
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "stickslip/invalid_input.hpp"

namespace stickslip {

// How a run's fields are named in its messages: by a run file's keys, or by the command line's
// options (continue, trace, atlas and find --trace given by their flags; Python's continue and
// trace).
enum class RunNaming { kRunFileKeys, kOptions };

// The command line's name of a run-file key: the last part with '_' as '-' ("continuation.ds_min"
// is ds-min), but for start.restart (point), unknowns.tie_u_r (tie-u_r) and
// continuation.user_values_of (user-value).
std::string OptionOfKey(std::string_view key);

// The run-file key of a start-problem field (orbits/start_problem.hpp names them: "set" is
// start.set, "restart" start.restart); nullopt for a field that is no key, a variable out of its
// range (d1) among them.
std::optional<std::string_view> KeyOfStartField(std::string_view field);

// A start-problem error with its restart point named as the command line and Python name it
// (point); the other start fields are their names already (tie_u_r is Python's keyword, the
// command line's --tie-u_r). For the front ends that build a start without a run (solve, find,
// Python's solve).
InvalidInput OnCommandLine(const InvalidInput& error);

}  // namespace stickslip
