#include "stickslip/branches/bifurcation_branches.hpp"

#include <optional>
#include <string>
#include <vector>

#include "stickslip/branches/model_bifurcation_branches.hpp"

namespace stickslip {

namespace bifurcation_detail {

UnknownChoice Unfolded(const ModelDescription& model, const UnknownChoice& choice, int listed, int repeats) {
  const OrbitLayout layout(model, listed);
  const OrbitLayout unfolded_layout(model, listed * repeats);
  UnknownChoice unfolded = choice;
  unfolded.fix.clear();
  for (const std::string& name : choice.fix) {
    const std::optional<int> index = layout.IndexOf(name);
    if (!index || *index < layout.Duration(0) || *index >= layout.Duration(listed)) {
      unfolded.fix.push_back(name);
      continue;
    }
    for (int k = 0; k < repeats; ++k) unfolded.fix.push_back(unfolded_layout.Name(*index + k * listed));
  }
  return unfolded;
}

Eigen::VectorXd UnfoldedTangent(const ModelDescription& model, const OrbitVariableSet& variables,
                                const std::vector<int>& free, const Eigen::VectorXd& tangent, bool tie_static_friction,
                                int unfolded, const std::vector<int>& unfolded_free) {
  const OrbitLayout& layout = variables.layout;
  const int n = variables.signature.size();
  Eigen::VectorXd full = Eigen::VectorXd::Zero(layout.Count());
  for (std::size_t k = 0; k < free.size(); ++k) full(free[k]) = tangent(static_cast<int>(k));
  if (tie_static_friction) full(variables.static_level) = full(variables.kinetic_level);
  const OrbitLayout unfolded_layout(model, unfolded);
  const int parameters = model.ParameterCount();
  Eigen::VectorXd repeated(unfolded_layout.Count());
  repeated.head(unfolded_layout.Duration(0)) = full.head(layout.Duration(0));
  for (int j = 0; j < unfolded; ++j) repeated(unfolded_layout.Duration(j)) = full(layout.Duration(j % n));
  repeated.tail(parameters) = full.tail(parameters);
  Eigen::VectorXd known(static_cast<Eigen::Index>(unfolded_free.size()));
  for (std::size_t k = 0; k < unfolded_free.size(); ++k) known(static_cast<int>(k)) = repeated(unfolded_free[k]);
  return known;
}

}  // namespace bifurcation_detail

template BifurcationBranchStart BranchFromBifurcation(const SpecialPoint& special, const OrbitContinuationSetup& setup,
                                                      int side);
template BifurcationBranchStart BranchFromBifurcation(const std::string& type, const OrbitContinuationSetup& setup,
                                                      int side);

}  // namespace stickslip
