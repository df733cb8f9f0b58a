#include "stickslip/orbits/start_problem.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include <fmt/format.h>

#include "stickslip/orbits/paper_presets.hpp"

namespace stickslip {

namespace {

namespace ov = orbit_variables;

// The set keys, from the model's description: its parameters, the state at t = 0 and the forcing
// phase. Built in place once: the keys view the description's and the meanings' strings.
struct SetKeyTable {
  explicit SetKeyTable(const ModelDescription& model) {
    for (const std::string& component : model.state_components) meanings.push_back("initial " + component);
    for (const ParameterDescription& p : model.parameters) keys.push_back({p.name, p.meaning, p.range});
    for (std::size_t k = 0; k < model.initial_state.size(); ++k) {
      keys.push_back({model.initial_state[k], meanings[k], kStateRange});
    }
    keys.push_back({"phi", "forcing phase at t = 0, cos(omega t + phi) (rad)", kStateRange});
  }
  std::vector<std::string> meanings;
  std::vector<SetKey> keys;
};

// A value given for `name`: finite, and within kStateRange if it is a start state's component
// or phase.
double Checked(std::string_view name, double value) {
  if (!std::isfinite(value)) throw InvalidInput(std::string(name), value, "a finite number");
  if (SetKeyRange(name) == kStateRange) {
    if (auto invalid = ValidateStateValue(name, value)) throw *invalid;
  }
  return value;
}

const PaperPreset* Preset(const std::string& name) {
  if (name.empty()) return nullptr;
  const PaperPreset* preset = FindPaperPreset(name);
  if (preset == nullptr) {
    throw InvalidInput::WithMessage("preset", fmt::format("preset = '{}' is unknown: valid {}", name, PaperExampleNames()));
  }
  return preset;
}

// The variables of an n-segment orbit as far as the preset, the restart point and set give
// them, and which were given. With n = 0 they are the model data and the start state only;
// v20 is kept apart, since an orbit has none.
struct Values {
  Eigen::VectorXd x;
  std::vector<bool> given;
  std::vector<bool> stored;  // the value is the restart point's, as its run computed it
  double v20 = 0.0;

  void Assign(int index, double value, bool from_restart = false) {
    x(index) = value;
    given[index] = true;
    stored[index] = from_restart;
  }
};


// The values start from a preset's or a restart point's, never from both (which would win?).
Values Assemble(const StartInput& input, const PaperPreset* preset, int n) {
  if (input.restart && !input.preset.empty()) {
    throw InvalidInput::WithMessage("restart", fmt::format("restart = '{}:{}' and preset = '{}': give at most one of them",
                                                           input.restart->run, input.restart->label, input.preset));
  }
  RefuseRepeatedNames("set", input.set, " (in set, guess or a fix value)");
  Values v{Eigen::VectorXd::Zero(ov::Count(n)), std::vector<bool>(ov::Count(n), false),
           std::vector<bool>(ov::Count(n), false)};
  if (preset != nullptr) {
    const Orbit guess = preset->Guess();
    const Eigen::VectorXd packed = ov::Pack(guess);
    for (int i = 0; i < ov::Count(n); ++i) v.Assign(i, packed(ov::IndexOf(guess.signature.size(), ov::Name(n, i)).value()));
    v.v20 = preset->example->initial_state(3);
  }
  if (input.restart) {
    for (const auto& [name, value] : input.restart->values) {
      if (const std::optional<int> index = ov::IndexOf(n, name)) v.Assign(*index, Checked(name, value), true);
    }
  }
  for (const auto& [key, value] : input.set) {
    const std::span<const SetKey> set_keys = SetKeys();
    if (std::none_of(set_keys.begin(), set_keys.end(), [&wanted = key](const SetKey& k) { return k.key == wanted; })) {
      std::vector<std::string_view> keys;
      for (const SetKey& k : set_keys) keys.push_back(k.key);
      throw InvalidInput("set", fmt::format("'{}'", key), fmt::format("keys {}", fmt::join(keys, ", ")));
    }
    if (key == "v20") {
      v.v20 = Checked(key, value);
    } else {
      v.Assign(*ov::IndexOf(n, key), Checked(key, value));
    }
  }
  return v;
}

// Every duration given and within the period (IsDurationOfPeriod); a rounding-level negative one
// is the zero-length segment it stands for, and starts as 0. A restart point's own duration
// beyond that range is a point its run stored past a change of orbit type (continue_past_type_
// changes; the result files' reader admits it only on a row that is not admissible): the branch
// restarts from it as it ran there, and its margins say it is no motion.
void CheckDurations(const Values& v, Orbit* orbit) {
  const int n = orbit->signature.size();
  const double period = orbit->Period();
  for (int i = 0; i < n; ++i) {
    const std::string name = ov::Name(n, ov::Duration(i));
    if (!v.given[ov::Duration(i)]) {
      throw InvalidInput::WithMessage("guess", fmt::format("guess misses {} (0 to the period): give the duration of segment {}", name, i + 1));
    }
    double& d = orbit->durations[i];
    if (!IsDurationOfPeriod(d, period) && !v.stored[ov::Duration(i)]) {
      throw InvalidInput(name, d,
                         fmt::format("0 <= {} <= {}, the orbit's period {} x 2 pi/omega, to rounding ({} of it)", name,
                                     period, orbit->signature.period_multiple(), kDurationRounding));
    }
    d = ZeroLengthToRounding(d, period);
  }
}

// The model's parameter k, as its description names it and gives its range.
const ParameterDescription& DescribedParameter(int k) { return Pascal2014{}.Description().parameters[k]; }

// A kinetic friction level <= 0 is no start: the sliding-friction margin ends the physical family
// there (a branch's end at u_s = 0 stores u_s to the event tolerance, -2.7e-11 in
// results/paper-4.2-omega-up).
InvalidInput ParameterError(const InvalidInput& invalid, const Parameters& p) {
  const ParameterDescription& kinetic = DescribedParameter(Pascal2014::kKineticLevelParameter);
  const double level = Pascal2014::ParameterAt(p, Pascal2014::kKineticLevelParameter);
  if (invalid.field() != kinetic.name || !(level <= 0.0)) return invalid;
  return InvalidInput(kinetic.name, level,
                      fmt::format("{}; {} <= 0 is the end of the physical family (eq. 4), where no orbit continues",
                                  kinetic.range, kinetic.name));
}

// Every parameter given (or, the static level under tie_u_r, tied to the kinetic one) and valid.
Parameters CheckedParameters(const Values& v, int n, bool tie_u_r) {
  Parameters p;
  for (int k = 0; k < Pascal2014::kParameterCount; ++k) {
    const int index = ov::FirstParameter(n) + k;
    const bool tied = tie_u_r && k == Pascal2014::kStaticLevelParameter;
    const std::string& name = DescribedParameter(k).name;
    if (!v.given[index] && !tied) {
      throw InvalidInput::WithMessage(
          name, fmt::format("{} is missing: give set {}=VALUE ({}), a preset or a restart point", name, name,
                            SetKeyRange(name)));
    }
    Pascal2014::ParameterAt(p, k) = v.x(index);
  }
  if (tie_u_r) {
    const double kinetic = Pascal2014::ParameterAt(p, Pascal2014::kKineticLevelParameter);
    Pascal2014::ParameterAt(p, Pascal2014::kStaticLevelParameter) = kinetic;
  }
  if (auto invalid = Validate(p)) throw ParameterError(*invalid, p);
  return p;
}

// The orbit type: from the preset, the signature or the restart point, in that order of
// precedence for the text; a preset's must agree with the others.
Signature OrbitType(const StartInput& input, const PaperPreset* preset) {
  const bool given = !input.signature.empty();
  const std::string field = given ? "signature" : "restart";
  const std::string text = given ? input.signature : input.restart ? input.restart->signature : "";
  if (text.empty()) {
    if (preset != nullptr) return preset->Guess().signature;
    throw InvalidInput::WithMessage("signature", "signature is missing: give exactly one of a preset, a signature "
                                                 "or a restart point");
  }
  const Signature signature = [&] {
    try {
      return Signature::Parse(text);
    } catch (const InvalidInput& e) {
      if (given) throw;  // it names the signature and says why
      throw InvalidInput::WithMessage(field, fmt::format("restart point's {}", e.what()));
    }
  }();
  // The restart's values are the variables of its own type: under another type "d2" would name
  // another segment's duration. Edit the type with signature_edits.hpp, which renames them.
  if (given && input.restart && !(Signature::Parse(input.restart->signature) == signature)) {
    throw InvalidInput::WithMessage(
        "signature", fmt::format("signature = '{}' differs from the restart point's orbit type '{}': a restart keeps "
                                 "its type (edit it with InsertSegment/RemoveSegment/SplitSegment, which rename "
                                 "the durations)",
                                 text, input.restart->signature));
  }
  if (preset != nullptr && !(preset->Guess().signature == signature)) {
    throw InvalidInput::WithMessage(
        field, fmt::format("{} gives the orbit type '{}', preset {} has '{}': give exactly one of them", field, text,
                           input.preset, preset->signature));
  }
  return signature;
}

// The preset's choice of unknowns, then the input's.
UnknownChoice Unknowns(const StartInput& input, const PaperPreset* preset) {
  if (input.paper_choice && preset == nullptr) {
    throw InvalidInput::WithMessage("paper_choice", "paper_choice = true is invalid: valid only with a preset");
  }
  UnknownChoice choice;
  if (preset != nullptr) choice = input.paper_choice ? preset->paper_choice : preset->unknowns;
  for (const FixedVariable& f : input.fix) {
    if (std::find(input.free.begin(), input.free.end(), f.name) != input.free.end()) {
      throw InvalidInput::WithMessage("fix", fmt::format("fix = '{}' is released by free as well: give it in one of them", f.name));
    }
    choice.fix.push_back(f.name);
  }
  choice.release.insert(choice.release.end(), input.free.begin(), input.free.end());
  choice.tie_static_friction = choice.tie_static_friction || input.tie_u_r;
  return choice;
}

}  // namespace

bool IsDurationOfPeriod(double d, double period) {
  return d >= -kDurationRounding * period && d <= period * (1.0 + kDurationRounding);
}

double ZeroLengthToRounding(double d, double period) {
  return d < 0.0 && d >= -kDurationRounding * period ? 0.0 : d;
}

std::span<const SetKey> SetKeys() {
  static const SetKeyTable table(Pascal2014{}.Description());
  return table.keys;
}

std::string_view SetKeyRange(std::string_view key) {
  for (const SetKey& k : SetKeys()) {
    if (k.key == key) return k.valid_range;
  }
  return "any finite number";
}

UnknownChoice StartUnknowns(const StartInput& input) { return Unknowns(input, Preset(input.preset)); }

StartProblem BuildStartProblem(const StartInput& input) {
  const PaperPreset* preset = Preset(input.preset);
  const Signature signature = OrbitType(input, preset);
  const int n = signature.size();
  const UnknownChoice unknowns = Unknowns(input, preset);

  Values v = Assemble(input, preset, n);
  if (v.v20 != 0.0) throw InvalidInput("v20", v.v20, "v20 = 0 (an orbit starts at a stop)");
  // A variable takes its value from one place (a later one won silently): set, guess or a fix value.
  NamedValues values = input.set;
  values.insert(values.end(), input.guess.begin(), input.guess.end());
  for (const FixedVariable& f : input.fix) {
    if (f.value) values.emplace_back(f.name, *f.value);
  }
  RefuseRepeatedNames("guess", values, " (in set, guess or a fix value)");
  for (const auto& [name, value] : input.guess) v.Assign(VariableIndex(n, "guess", name), Checked(name, value));
  for (const FixedVariable& f : input.fix) {
    if (f.value) v.Assign(VariableIndex(n, "fix", f.name), Checked(f.name, *f.value));
  }
  Orbit orbit = ov::Unpack(signature, v.x);
  orbit.parameters = CheckedParameters(v, n, unknowns.tie_static_friction);
  CheckDurations(v, &orbit);
  const std::vector<int> free = FreeIndices(signature, unknowns);

  std::optional<int> parameter;
  if (input.parameter) {
    parameter = ContinuedVariable(signature, free, unknowns.tie_static_friction, *input.parameter);
  }
  // Under tie_u_r, the static level follows the kinetic one: a different static level of the
  // user's was dropped silently.
  if (unknowns.tie_static_friction) {
    const std::string& kinetic = DescribedParameter(Pascal2014::kKineticLevelParameter).name;
    const std::string& static_level = DescribedParameter(Pascal2014::kStaticLevelParameter).name;
    const double level = Pascal2014::ParameterAt(orbit.parameters, Pascal2014::kKineticLevelParameter);
    for (const auto& [name, value] : values) {
      if (name != static_level || value == level) continue;
      throw InvalidInput::WithMessage(
          static_level, fmt::format("{} = {} is invalid with tie-u_r: valid {} = {} = {}, or no {} (it follows {})",
                                    static_level, value, static_level, kinetic, level, static_level, kinetic));
    }
  }
  return {std::move(orbit), unknowns, free, parameter};
}

ModelStart BuildModelStart(const StartInput& input) {
  const std::pair<const char*, bool> orbit_members[] = {
      {"signature", !input.signature.empty()}, {"guess", !input.guess.empty()},   {"free", !input.free.empty()},
      {"fix", !input.fix.empty()},             {"tie_u_r", input.tie_u_r},       {"paper_choice", input.paper_choice},
      {"parameter", input.parameter.has_value()}};
  for (const auto& [member, given] : orbit_members) {
    if (given) throw InvalidInput::WithMessage(member, fmt::format("{} is for orbits: a simulation starts from a preset, "
                                                                   "a restart point and set", member));
  }
  const Values v = Assemble(input, Preset(input.preset), 0);
  ModelStart start;
  start.parameters = CheckedParameters(v, 0, false);
  start.initial_state = State(v.x(ov::kX10), v.x(ov::kX20), v.x(ov::kV10), v.v20);
  start.phi = v.x(ov::kPhi);
  return start;
}

}  // namespace stickslip
