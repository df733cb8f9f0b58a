// A chain (any topology) of point masses joined by springs and viscous dampers, to each other or
// to the ground, forced harmonically on any mass, with the Coulomb contact on one of them: the
// description a user writes, turned into the matrices of linear_oscillator_data.hpp. The
// coordinates are each mass's displacement; the contact's mass is put last (the linear
// oscillator's convention), the others keep their order, and every coordinate keeps its name.
#pragma once

#include <string>
#include <vector>

#include "stickslip/model/linear_oscillator_data.hpp"

namespace stickslip {

inline constexpr int kGround = -1;

// A spring or a damper between masses `from` and `to` (0-based; kGround for the ground).
struct ChainLink {
  int from = 0;
  int to = kGround;
  double value = 0.0;  // stiffness or damping coefficient, >= 0
};

struct Chain {
  std::vector<double> masses;    // > 0
  std::vector<ChainLink> springs;
  std::vector<ChainLink> dampers;
  std::vector<double> forcing;   // the amplitude on each mass; empty: none
  int contact = 0;               // the mass the contact is on
  std::vector<std::string> names;  // empty: m1 ... mn
  std::string name = "chain";
};

// Throws InvalidInput naming the field ("masses", "springs[2]", "contact", ...) for a mass that is
// not positive and finite, a link to a mass that does not exist or to itself, a negative or
// non-finite coefficient, a forcing of the wrong length, or a contact on no mass. A chain that is
// not held to the ground is refused by ModesOf (a singular stiffness).
LinearOscillatorData ChainData(const Chain& chain);

}  // namespace stickslip
