// What a model says about itself as data: its parameters (name, meaning, unit, valid range), the
// names of its coordinates and state components. The layers above name things through it: file
// columns, messages, the keys a front end accepts. BifurcationKit's `BifurcationProblem` carries
// the parameter lens and the record-from-solution names the same way; COCO's toolboxes take the
// labels of a problem from its constructor.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace stickslip {

struct ParameterDescription {
  std::string name;     // key in files, on the command line and in Python: "omega"
  std::string meaning;  // one line for --help and reference pages
  std::string unit;     // "1" for a scaled (dimensionless) parameter, otherwise SI: "rad/s", "N"
  double minimum = 0.0;  // the closed valid range, as the model validates it
  double maximum = 0.0;
  std::string range;  // the range as messages and --help print it: "0.01 <= chi <= 0.99"
};

// How messages name the contact's quantities (the changes of orbit type, orbits/adjacent_type.hpp):
// by default the paper's, x2 being its contact's coordinate and s the friction force; a model of
// its own gives its words.
struct ContactWords {
  std::string velocity = "x2'";  // the contact's velocity relative to its surface
  std::string acceleration = "x2''";
  std::string jerk = "x2'''";
  std::string force = "s";                // the friction force a stick needs
  std::string kinetic_level = "eta u_s";  // its level in a slip
  std::string static_level = "eta u_r";   // the most a stick holds
  std::string no_friction = "u_s = 0";    // the kinetic level vanishing
  const char* abnormal_grazing = "grazing-sliding (u_r = u_s)";  // a bifurcation's name
};

// The units of a model's numbers: of its lengths (the coordinates), times and forces, every other
// unit derived from them. All empty for a scaled model (the paper's: every quantity dimensionless).
struct ModelUnits {
  std::string length, time, force;

  // Each unit by its name, as run files and summaries name them.
  static constexpr std::array<std::pair<const char*, std::string ModelUnits::*>, 3> kNamed = {
      {{"length", &ModelUnits::length}, {"time", &ModelUnits::time}, {"force", &ModelUnits::force}}};

  bool Scaled() const { return length.empty(); }
  // The derived units; "" for a scaled model.
  std::string Frequency() const { return Scaled() ? "" : "rad/" + time; }
  std::string Speed() const { return Scaled() ? "" : length + "/" + time; }
  std::string Energy() const {
    return Scaled() ? "" : length == "m" && force == "N" ? "J" : force + " " + length;
  }
  std::string ViscousDamping() const { return Scaled() ? "" : force + " " + time + "/" + length; }
  bool operator==(const ModelUnits&) const = default;
};

// A model's default units: SI.
inline ModelUnits SiUnits() { return {"m", "s", "N"}; }

// Throws InvalidInput naming units.length, units.time or units.force unless each is 1 to
// kMaxUnitBytes bytes of UTF-8 with no space at either end, no control character (nor a line
// separator or direction mark) and no '$' (figures' math markup); a message per rule.
inline constexpr std::size_t kMaxUnitBytes = 16;
void CheckUnits(const ModelUnits& units);

struct ModelDescription {
  std::string name;  // "pascal-2014"
  // In the order of the model's parameter derivatives (the columns of every d/dparameters).
  std::vector<ParameterDescription> parameters;
  std::vector<std::string> coordinates;       // "x1", "x2": the generalised coordinates q
  std::vector<std::string> state_components;  // "x1", "x2", "x1'", "x2'": (q, q')
  // The state by name as the columns of a file of states along a motion (a sweep's section): x1, x2,
  // v1, v2 in the paper's model.
  std::vector<std::string> state_columns;
  // The state at t = 0 by name, as set keys and result columns name it (x10, x20, v10, v20 in the
  // paper's model). An orbit's start variables are all but the last (the contact's velocity, zero at the
  // orbit's origin, a stop: orbits/orbit_layout.hpp).
  std::vector<std::string> initial_state;
  ContactWords contact;
  ModelUnits units;  // empty: scaled

  int ParameterCount() const { return static_cast<int>(parameters.size()); }
  std::optional<int> ParameterIndex(std::string_view name) const;
  // The index of a parameter a run varies (a sweep's, a map's axis, a trace's), by name: one of
  // the parameters, but the forcing frequency (index 0) of a model without forcing (`autonomous`),
  // which plays no part. Throws InvalidInput naming `field`, valid the names it may take (without
  // `varied_already`, a parameter the run varies already: a curve's second is another).
  int VariedParameter(std::string_view field, const std::string& parameter, bool autonomous,
                      std::string_view varied_already = {}) const;
  int StateSize() const { return static_cast<int>(state_components.size()); }
};

}  // namespace stickslip
