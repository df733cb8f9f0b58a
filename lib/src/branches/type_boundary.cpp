#include "stickslip/branches/type_boundary.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "stickslip/invalid_input.hpp"
#include "stickslip/orbits/adjacent_type.hpp"

namespace stickslip {

namespace ov = orbit_variables;

TypeBoundarySetup TypeBoundary(const LocatedTypeChange& located, const OrbitContinuationSetup& branch_setup,
                               std::string_view second) {
  const Orbit& orbit = located.orbit;
  const std::vector<Margin> margins = AdmissibilityMargins(orbit);
  const auto margin = std::find_if(margins.begin(), margins.end(), [&](const Margin& m) { return m.Name() == located.margin; });
  const char* valid = "reversal:i, abnormal-stop:i, or duration:i of a stick (the boundaries held by a zero-length stick)";
  if (margin == margins.end()) throw InvalidInput("margin", located.margin, valid);
  const std::string base = margin->base;
  const int n = orbit.signature.size();
  const bool stick_duration = base == "duration" && orbit.signature.segments()[margin->segment] == Mode::kStick;
  if (base != "reversal" && base != "abnormal-stop" && !stick_duration) throw InvalidInput("margin", located.margin, valid);
  const std::optional<int> second_index = ov::IndexOf(n, second);
  if (!second_index || *second_index < ov::Parameter(n, ParameterId::kChi) || second == located.parameter) {
    throw InvalidInput("second", std::string(second),
                       fmt::format("a parameter other than the continued {}: chi, eta, omega, u_s, u_r", located.parameter));
  }

  TypeBoundarySetup result{.setup = branch_setup, .held = "", .stick = margin->segment};
  UnknownChoice unknowns = located.unknowns;
  if (stick_duration) {
    result.setup.start = orbit;
  } else {
    const bool equal_friction = orbit.parameters.u_r == orbit.parameters.u_s;
    const std::vector<AdjacentType> adjacent = AdjacentTypes(base, margin->segment, orbit.signature, equal_friction);
    const auto insert = std::find_if(adjacent.begin(), adjacent.end(), [](const AdjacentType& a) {
      return a.kind == TypeEdit::kInsert && a.edit.signature.segments()[a.new_segment] == Mode::kStick;
    });
    if (insert == adjacent.end()) throw InvalidInput("margin", located.margin, valid);
    result.setup.start = AdjacentStart(orbit, *margin, *insert);
    result.stick = insert->new_segment;
    for (std::string& name : unknowns.fix) name = insert->edit.Renamed(name);
    for (std::string& name : unknowns.release) name = insert->edit.Renamed(name);
  }
  result.held = ov::Name(result.setup.start.signature.size(), ov::Duration(result.stick));
  if (std::find(unknowns.release.begin(), unknowns.release.end(), second) != unknowns.release.end()) {
    throw InvalidInput("second", std::string(second), "a parameter not released already");
  }
  unknowns.fix.push_back(result.held);
  unknowns.release.emplace_back(second);
  result.setup.unknowns = std::move(unknowns);
  result.setup.parameter = located.parameter;
  result.setup.options.continue_past_terminal = false;
  // The zero-length stick's own margins and the force condition of the stop that enters it sit on
  // zero along the curve: they define it. The multipliers are those of an orbit on the boundary
  // (its stick's saltation included): their tests are no bifurcations of the curve.
  const int count = result.setup.start.signature.size();
  for (const Margin& m : AdmissibilityMargins(result.setup.start)) {
    if (m.segment == result.stick || (std::string_view(m.base) == "stick-entry" && m.segment == (result.stick + count - 1) % count)) {
      result.setup.unwatched.push_back(std::string(orbit_columns::kMarginPrefix) + m.Name());
    }
  }
  for (const char* test : {orbit_columns::kFlipTest, orbit_columns::kTorusTest, orbit_columns::kSymmetryTest}) {
    result.setup.unwatched.emplace_back(test);
  }
  return result;
}

}  // namespace stickslip
