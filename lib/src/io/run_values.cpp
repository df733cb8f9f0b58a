// A run's values checked against their valid ranges, whichever front end gave them, and the
// complaints about its keys in that front end's words (KeyError, io/run_fields.hpp).
#include <algorithm>
#include <cmath>
#include <string>
#include <string_view>

#include <fmt/format.h>

#include "stickslip/io/run_file.hpp"

namespace stickslip {

namespace {

// Whether `text` is valid UTF-8: no stray continuation byte, no truncated sequence, no overlong
// form, no surrogate, nothing above U+10FFFF.
bool IsUtf8(std::string_view text) {
  for (std::size_t i = 0; i < text.size();) {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
    const unsigned char lead = byte(i);
    const int length = lead < 0x80 ? 1 : lead >= 0xc2 && lead <= 0xdf ? 2 : lead >= 0xe0 && lead <= 0xef ? 3
                                                                             : lead >= 0xf0 && lead <= 0xf4 ? 4 : 0;
    if (length == 0 || i + length > text.size()) return false;
    for (int k = 1; k < length; ++k) {
      if ((byte(i + k) & 0xc0) != 0x80) return false;
    }
    // The second byte's range where the lead alone does not exclude overlong forms, surrogates
    // and code points past U+10FFFF.
    const unsigned char second = length > 1 ? byte(i + 1) : 0x80;
    if ((lead == 0xe0 && second < 0xa0) || (lead == 0xed && second > 0x9f) || (lead == 0xf0 && second < 0x90) ||
        (lead == 0xf4 && second > 0x8f)) {
      return false;
    }
    i += static_cast<std::size_t>(length);
  }
  return true;
}

}  // namespace

bool IsRunName(std::string_view name) {
  // A control character would break the one-line messages and listings that name the run.
  const bool control = std::any_of(name.begin(), name.end(), [](char c) {
    const auto u = static_cast<unsigned char>(c);
    return u < 0x20 || u == 0x7f;
  });
  return !name.empty() && name.size() <= kMaxRunNameLength && name != "." && !control && name.find('/') == std::string_view::npos &&
         name.find("..") == std::string_view::npos && name.find(':') == std::string_view::npos && IsUtf8(name);
}

RunFileError KeyError(const RunFile& run, const std::string& key, const std::string& what) {
  if (run.naming == RunNaming::kOptions) {
    const std::string option = OptionOfKey(key);
    return RunFileError(fmt::format("{} {}", option, what), option);
  }
  return RunFileError(fmt::format("{}: key '{}' {}", run.Location(key), key, what), key);
}

std::string RangeIn(const RunFile& run) {
  return run.naming == RunNaming::kOptions ? fmt::format("'{},{}'", run.range_min, run.range_max)
                                           : fmt::format("[{}, {}]", run.range_min, run.range_max);
}

std::string RunInMessages(const RunFile& run) { return run.naming == RunNaming::kOptions ? run.output : run.path; }

namespace {

// A key's name inside a message about another key: continuation.ds_min in a run file, ds-min on
// the command line.
std::string NameIn(const RunFile& run, std::string_view key) {
  return run.naming == RunNaming::kOptions ? OptionOfKey(key) : std::string(key);
}

// A restart continues one thing from its label (so it has a label): the branch leaving it or a
// boundary's curve; and a curve ends at the codimension-two point where a second margin reaches zero.
void CheckOneRestartKind(const RunFile& run) {
  // The branch that leaves a bifurcation leaves it on the side `direction` names; a trace has
  // none (both ways from its start would go out along one side and back along the other). A
  // trace follows branches in one parameter, not a boundary's curve in two.
  const std::string_view trace = run.naming == RunNaming::kOptions ? "trace" : "a [trace] table";
  if (run.trace && run.restart_switch_branch) {
    throw KeyError(run, "start.restart.switch_branch",
                   fmt::format("= true is invalid with {}: valid false (a trace goes both ways from its start, the "
                               "branch that leaves a bifurcation one way: continue that branch, then trace from a "
                               "point of it)",
                               trace));
  }
  if (run.trace && !run.restart_boundary.empty()) {
    throw KeyError(run, "start.restart.boundary",
                   fmt::format("= '{}' is invalid with {}: valid left out (a trace follows branches in one parameter; "
                               "continue a boundary's curve with a run of one branch)",
                               run.restart_boundary, trace));
  }
  const std::string restart = NameIn(run, "start.restart");
  if (run.restart_run.empty() && run.restart_switch_branch) {
    throw KeyError(run, "start.restart.switch_branch",
                   fmt::format("= true is invalid without {}: valid with {} RUN:LABEL at a PD or an SB", restart, restart));
  }
  if (run.restart_run.empty() && !run.restart_boundary.empty()) {
    throw KeyError(run, "start.restart.boundary",
                   fmt::format("= '{}' is invalid without {}: valid with {} RUN:LABEL at a located special point",
                               run.restart_boundary, restart, restart));
  }
  if (run.restart_boundary.empty()) return;
  if (run.restart_switch_branch) {
    throw KeyError(run, "start.restart.boundary",
                   fmt::format("cannot go with {}: give one of them", NameIn(run, "start.restart.switch_branch")));
  }
  if (run.continue_past_type_changes) {
    throw KeyError(run, "continuation.continue_past_type_changes",
                   fmt::format("= true is invalid with {}: valid false (a curve in two parameters ends at the "
                               "codimension-two point where a second margin reaches zero)",
                               NameIn(run, "start.restart.boundary")));
  }
}

}  // namespace

void CheckStepValues(const RunFile& run) {
  const BranchSteps& s = run.steps;
  const std::string ds = NameIn(run, "continuation.ds");
  const std::string ds_min = NameIn(run, "continuation.ds_min");
  const std::string ds_max = NameIn(run, "continuation.ds_max");
  // The bound that is wrong whatever ds is, by its own name; then ds between them.
  if (!(s.ds_min > 0)) {
    throw KeyError(run, "continuation.ds_min", fmt::format("= {} is invalid: valid range {} > 0", s.ds_min, ds_min));
  }
  if (!(s.ds_max >= s.ds_min)) {
    throw KeyError(run, "continuation.ds_max",
                   fmt::format("= {} is invalid: valid range {} >= {} ({})", s.ds_max, ds_max, ds_min, s.ds_min));
  }
  if (!(s.ds_min <= s.ds && s.ds <= s.ds_max)) {
    throw KeyError(run, "continuation.ds", fmt::format("= {} is invalid: valid range 0 < {} ({}) <= {} <= {} ({})", s.ds,
                                                       ds_min, s.ds_min, ds, ds_max, s.ds_max));
  }
  if (s.max_points < 1 || s.max_points > kMaxRunPoints) {
    throw KeyError(run, "continuation.max_points",
                   fmt::format("= {} is invalid: valid range {}", s.max_points,
                               WholeNumberRange(NameIn(run, "continuation.max_points"), 1, kMaxRunPoints)));
  }
}

void CheckRunValues(const RunFile& run) {
  if (!IsRunName(run.output)) {
    throw KeyError(run, "output", fmt::format("= '{}' is invalid: valid {}", run.output, kRunNameRule));
  }
  if (!(std::isfinite(run.range_min) && std::isfinite(run.range_max) && run.range_min < run.range_max)) {
    throw KeyError(run, "continuation.range",
                   fmt::format("= {} is invalid: valid range MIN < MAX, both finite", RangeIn(run)));
  }
  CheckStepValues(run);
  CheckOneRestartKind(run);
  const std::string max_amplitude = NameIn(run, "continuation.max_amplitude");
  if (!(run.max_amplitude > 0.0 && std::isfinite(run.max_amplitude))) {
    throw KeyError(run, "continuation.max_amplitude",
                   fmt::format("= {} is invalid: valid range a finite {} > 0", run.max_amplitude, max_amplitude));
  }
  if (!(run.resonance_approach >= 0.0 && run.resonance_approach < 1.0)) {
    throw KeyError(run, "continuation.resonance_approach",
                   fmt::format("= {} is invalid: valid range 0 <= {} < 1 (0: never)", run.resonance_approach,
                               NameIn(run, "continuation.resonance_approach")));
  }
}

}  // namespace stickslip
