// Exact derivatives of the monodromy matrix (orbits/stability.hpp) with respect to every orbit
// variable, for any model (model/oscillator_model.hpp): forward-mode AD through the templated
// walk, transition and saltation matrices. The variables are the periodicity equations' full
// vector (periodicity_equations.hpp: the start state without the contact's velocity, phi, the
// durations, the parameters; for the paper's model orbit.hpp's x10, x20, v10, phi, d1..dn, chi,
// eta, omega, u_s, u_r). What the curves of folds, period doublings, symmetry breakings and torus
// points (branches/floquet_condition.hpp) add to the periodicity equations.
#pragma once

#include <span>
#include <vector>

// <Eigen/Core> must precede the unsupported AutoDiff module.
#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

#include "stickslip/model/oscillator_model.hpp"
#include "stickslip/orbits/orbit.hpp"
#include "stickslip/orbits/stability.hpp"

namespace stickslip {

template <int kStateSize>
struct BasicMonodromyGradient {
  using Matrix = Eigen::Matrix<double, kStateSize, kStateSize>;
  Matrix period;                // M over the whole period (Stability::monodromy)
  std::vector<Matrix> d_period;  // dM/dv, one per variable
  Matrix listed;                // over the listed segments: the half period of an antisymmetric orbit
  std::vector<Matrix> d_listed;
};
using MonodromyGradient = BasicMonodromyGradient<Pascal2014::kStateSize>;

// The same at run-time size, as the model-free layers take it (orbits/orbit_problem.hpp).
template <int kStateSize>
BasicMonodromyGradient<Eigen::Dynamic> ToDynamic(const BasicMonodromyGradient<kStateSize>& g) {
  if constexpr (kStateSize == Eigen::Dynamic) {
    return g;
  } else {
    return {g.period, {g.d_period.begin(), g.d_period.end()}, g.listed, {g.d_listed.begin(), g.d_listed.end()}};
  }
}

namespace floquet_gradients {

// Derivatives held on the stack up to this many directions (15 listed segments of the paper's
// model): the heap allocations of dynamic ones were half the cost of a curve's point.
inline constexpr int kStackDirections = 24;

template <typename Dual, int S>
void Split(const Eigen::Matrix<Dual, S, S>& m, int variables, Eigen::Matrix<double, S, S>* value,
           std::vector<Eigen::Matrix<double, S, S>>* derivatives) {
  const Eigen::Index size = m.rows();
  value->resize(size, size);
  derivatives->assign(static_cast<std::size_t>(variables), Eigen::Matrix<double, S, S>::Zero(size, size));
  for (Eigen::Index i = 0; i < size; ++i) {
    for (Eigen::Index j = 0; j < size; ++j) {
      (*value)(i, j) = m(i, j).value();
      const auto& d = m(i, j).derivatives();
      for (int k = 0; k < d.size(); ++k) (*derivatives)[static_cast<std::size_t>(k)](i, j) = d(k);
    }
  }
}

template <typename Dual, typename Model>
BasicMonodromyGradient<Model::kStateSize> Gradients(const Model& model, const BasicOrbit<Model>& orbit) {
  constexpr int P = Model::kParameterCount;
  const int S = model.StateSize(), n = orbit.signature.size();
  const int variables = S + n + P;
  auto seed = [&](double value, int direction) { return Dual(value, variables, direction); };
  // The contact's velocity (the last component) is at rest at the origin, a stop: not a
  // variable, but the rest velocity where the model has one (a belt's speed).
  typename Model::template StateT<Dual> x0(S);
  for (int k = 0; k + 1 < S; ++k) x0(k) = seed(orbit.start(k), k);
  std::vector<Dual> durations;
  for (int i = 0; i < n; ++i) durations.push_back(seed(orbit.durations[i], S + i));
  typename Model::template ParametersT<Dual> p;
  for (int k = 0; k < P; ++k) Model::ParameterAt(p, k) = seed(Model::ParameterAt(orbit.parameters, k), S + n + k);
  x0(S - 1) = RestVelocity<Model>(p, Dual(orbit.start(S - 1), Dual::DerType::Zero(variables)));
  const MonodromyT<Dual, Model> m =
      Monodromy<Dual>(model, orbit.signature, x0, seed(orbit.phi, S - 1), std::span<const Dual>(durations), p);
  BasicMonodromyGradient<Model::kStateSize> result;
  Split(m.period, variables, &result.period, &result.d_period);
  Split(m.listed, variables, &result.listed, &result.d_listed);
  return result;
}

}  // namespace floquet_gradients

template <typename Model>
BasicMonodromyGradient<Model::kStateSize> MonodromyGradients(const Model& model, const BasicOrbit<Model>& orbit) {
  using namespace floquet_gradients;
  const int variables = model.StateSize() + orbit.signature.size() + Model::kParameterCount;
  if (variables <= kStackDirections) {
    return Gradients<Eigen::AutoDiffScalar<Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kStackDirections, 1>>>(model, orbit);
  }
  return Gradients<Eigen::AutoDiffScalar<Eigen::VectorXd>>(model, orbit);
}
MonodromyGradient MonodromyGradients(const Orbit& orbit);

}  // namespace stickslip
