#include "stickslip/model/chain.hpp"

#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "stickslip/invalid_input.hpp"

namespace stickslip {
namespace {

void CheckLinks(const char* field, const std::vector<ChainLink>& links, int n) {
  for (std::size_t k = 0; k < links.size(); ++k) {
    const ChainLink& link = links[k];
    const std::string name = fmt::format("{}[{}]", field, k);
    const auto valid_end = [n](int i) { return i == kGround || (i >= 0 && i < n); };
    if (!valid_end(link.from) || !valid_end(link.to) || link.from == link.to) {
      throw InvalidInput(name, fmt::format("{} to {}", static_cast<long long>(link.from) + 1, static_cast<long long>(link.to) + 1),
                         fmt::format("two different masses 1 ... {} or a mass and the ground (0)", n));
    }
    if (!(link.value >= 0.0 && std::isfinite(link.value))) throw InvalidInput(name, link.value, "a finite value >= 0");
  }
}

// Adds a link's coefficient to the matrix of a chain whose coordinate of mass i is position[i].
void Assemble(Eigen::MatrixXd& matrix, const std::vector<ChainLink>& links, const std::vector<int>& position) {
  for (const ChainLink& link : links) {
    const int a = link.from == kGround ? -1 : position[link.from];
    const int b = link.to == kGround ? -1 : position[link.to];
    if (a >= 0) matrix(a, a) += link.value;
    if (b >= 0) matrix(b, b) += link.value;
    if (a >= 0 && b >= 0) {
      matrix(a, b) -= link.value;
      matrix(b, a) -= link.value;
    }
  }
}

}  // namespace

LinearOscillatorData ChainData(const Chain& chain) {
  const int n = static_cast<int>(chain.masses.size());
  if (n < 1) throw InvalidInput("masses", "none", "at least one mass");
  for (int i = 0; i < n; ++i) {
    if (!(chain.masses[i] > 0.0 && std::isfinite(chain.masses[i]))) {
      throw InvalidInput(fmt::format("masses[{}]", i), chain.masses[i], "a finite mass > 0");
    }
  }
  if (chain.contact < 0 || chain.contact >= n) {
    throw InvalidInput("contact", fmt::format("{}", static_cast<long long>(chain.contact) + 1), fmt::format("a mass 1 ... {}", n));
  }
  CheckLinks("springs", chain.springs, n);
  CheckLinks("dampers", chain.dampers, n);
  if (!chain.forcing.empty() && static_cast<int>(chain.forcing.size()) != n) {
    throw InvalidInput("forcing", fmt::format("{} values", chain.forcing.size()), fmt::format("one per mass, {}", n));
  }
  CheckCoordinateNames(chain.names, n, "names");
  // The contact's mass last, the others in their order.
  std::vector<int> position(n);
  for (int i = 0, next = 0; i < n; ++i) position[i] = i == chain.contact ? n - 1 : next++;
  LinearOscillatorData data;
  data.name = chain.name;
  data.mass = Eigen::MatrixXd::Zero(n, n);
  data.stiffness = data.damping = Eigen::MatrixXd::Zero(n, n);
  data.forcing = Eigen::VectorXd::Zero(n);
  data.coordinates.resize(n);
  for (int i = 0; i < n; ++i) {
    data.mass(position[i], position[i]) = chain.masses[i];
    if (!chain.forcing.empty()) data.forcing(position[i]) = chain.forcing[i];
    data.coordinates[position[i]] = chain.names.empty() ? fmt::format("m{}", i + 1) : chain.names[i];
  }
  Assemble(data.stiffness, chain.springs, position);
  Assemble(data.damping, chain.dampers, position);
  for (const auto& [field, matrix] : {std::pair{"springs", &data.stiffness}, std::pair{"dampers", &data.damping}}) {
    if (!matrix->allFinite()) throw InvalidInput(field, "coefficients summing past 1.8e308", "sums within double range");
  }
  return data;
}

}  // namespace stickslip
