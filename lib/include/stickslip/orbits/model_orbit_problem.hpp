// The orbit problem of one model (model/oscillator_model.hpp), compiled for it and erased to
// OrbitProblem (orbit_problem.hpp): its periodicity equations in chosen unknowns
// (orbit_system.hpp), and the orbit at the unknowns for the margins, the stability, the measures
// and the slip resonance, each computed by the orbit layer's templates on the model.
#pragma once

#include <memory>
#include <span>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

#include "stickslip/orbits/floquet_gradients.hpp"
#include "stickslip/orbits/margin_gradients.hpp"
#include "stickslip/orbits/orbit_problem.hpp"
#include "stickslip/orbits/orbit_system.hpp"

namespace stickslip {

// The variables of the periodicity equations (the full vector, then for multiple shooting the
// start states of the listed segments after the first, by the closed-form flows) at `orbit`.
template <OscillatorModel Model>
Eigen::VectorXd VariablesOf(const BasicPeriodicityEquations<Model>& equations, const BasicOrbit<Model>& orbit) {
  const int S = equations.StateSize();
  Eigen::VectorXd v(equations.VariableCount());
  v.head(S - 1) = orbit.start.head(S - 1);
  v(equations.Phi()) = orbit.phi;
  for (int i = 0; i < orbit.signature.size(); ++i) v(equations.Duration(i)) = orbit.durations[i];
  for (int k = 0; k < Model::kParameterCount; ++k) v(equations.Parameter(k)) = Model::ParameterAt(orbit.parameters, k);
  if (equations.shooting() == Shooting::kMultiple) {
    const int full = equations.FullCount();
    WalkSegments(equations.model(), orbit, Extent::kListed, PhaseRule::kAccumulated,
                 [&](const SegmentVisit<double, Model>& s) {
                   if (!s.last) v.segment(full + S * s.index, S) = s.end;
                 });
  }
  return v;
}

// The orbit of the periodicity equations' variables v (the full vector; shooting states ignored).
template <OscillatorModel Model>
BasicOrbit<Model> OrbitOf(const BasicPeriodicityEquations<Model>& equations, const Eigen::VectorXd& v) {
  std::vector<double> durations;
  for (int i = 0; i < equations.signature().size(); ++i) durations.push_back(v(equations.Duration(i)));
  return {equations.signature(), equations.ParametersOf(v), equations.StartState(v), v(equations.Phi()),
          std::move(durations)};
}

template <OscillatorModel Model>
class ModelOrbitProblem final : public OrbitProblem {
 public:
  using System = BasicOrbitSystem<Model>;
  explicit ModelOrbitProblem(System system) : system_(std::move(system)) {}

  int EquationCount() const override { return system_.EquationCount(); }
  int UnknownCount() const override { return system_.UnknownCount(); }
  void Evaluate(const Eigen::VectorXd& u, Eigen::VectorXd* residual, JacobianMatrix* jacobian) const override {
    system_.Evaluate(u, residual, jacobian);
  }
  std::optional<std::string> DomainError(const Eigen::VectorXd& u) const override { return system_.DomainError(u); }

  const ModelDescription& description() const override { return model().Description(); }
  const Signature& signature() const override { return system_.equations().signature(); }
  Shooting shooting() const override { return system_.equations().shooting(); }
  const std::vector<int>& free() const override { return system_.free(); }
  int FullCount() const override { return system_.equations().FullCount(); }
  Eigen::VectorXd Variables(const Eigen::VectorXd& u) const override { return system_.Variables(u); }
  Eigen::VectorXd Unknowns(const Eigen::VectorXd& variables) const override { return system_.Unknowns(variables); }
  Eigen::MatrixXd ToUnknowns(const Eigen::MatrixXd& d_variables) const override {
    return system_.ToUnknowns(d_variables);
  }

  std::vector<Margin> Margins(const Eigen::VectorXd& u) const override {
    return AdmissibilityMargins(model(), OrbitAt(u));
  }
  OrbitStability Stability(const Eigen::VectorXd& u) const override {
    return ToOrbitStability(StabilityOf(model(), OrbitAt(u)));
  }
  BasicOrbitMeasures Measures(const Eigen::VectorXd& u) const override { return Measure(model(), OrbitAt(u)); }
  std::optional<SlipResonance> NearestSlipResonance(const Eigen::VectorXd& u) const override {
    return stickslip::NearestSlipResonance(model(), OrbitAt(u));
  }
  int ContactCoordinate() const override { return stickslip::ContactCoordinate(model()); }

  // The paper's model's gradients are compiled once (margin_gradients.cpp, floquet_gradients.cpp).
  std::vector<MarginGradient> MarginGradients(const Eigen::VectorXd& u) const override {
    if constexpr (std::is_same_v<Model, Pascal2014>) {
      return stickslip::MarginGradients(ToOrbit(*this, u));
    } else {
      return stickslip::MarginGradients(model(), OrbitAt(u));
    }
  }
  MarginGradient MarginGradientAt(const Eigen::VectorXd& u, const Margin& margin, double tau) const override {
    if constexpr (std::is_same_v<Model, Pascal2014>) {
      return stickslip::MarginGradientAt(ToOrbit(*this, u), margin, tau);
    } else {
      return stickslip::MarginGradientAt(model(), OrbitAt(u), margin, tau);
    }
  }
  DynamicMonodromyGradient MonodromyGradients(const Eigen::VectorXd& u) const override {
    if constexpr (std::is_same_v<Model, Pascal2014>) {
      return ToDynamic(stickslip::MonodromyGradients(ToOrbit(*this, u)));
    } else {
      return ToDynamic(stickslip::MonodromyGradients(model(), OrbitAt(u)));
    }
  }
  double SegmentStart(const Eigen::VectorXd& u, int segment) const override {
    double t0 = 0.0;
    WalkSegments(model(), OrbitAt(u), Extent::kListed, PhaseRule::kFromOrigin, [&](const SegmentVisit<double, Model>& s) {
      if (s.spec.listed == segment) t0 = s.t0;
    });
    return t0;
  }

  // The orbit at the unknowns u (a curve's own unknowns may follow them), and as the layers above
  // take it (for the paper's model its Orbit).
  BasicOrbit<Model> OrbitAt(const Eigen::VectorXd& u) const {
    return OrbitOf(system_.equations(), system_.Variables(u.head(system_.UnknownCount())));
  }
  OrbitOfModel<Model> OrbitOfModelAt(const Eigen::VectorXd& u) const {
    if constexpr (std::is_same_v<Model, Pascal2014>) {
      return ToOrbit(*this, u);
    } else {
      return OrbitAt(u);
    }
  }
  const System& system() const { return system_; }
  const Model& model() const { return system_.equations().model(); }

 private:
  System system_;
};

// The model's problem behind an erased one. Throws std::logic_error for a problem of another
// model (a programming error, not input).
template <OscillatorModel Model>
const ModelOrbitProblem<Model>& ModelProblemOf(const OrbitProblem& problem) {
  const auto* system = dynamic_cast<const ModelOrbitProblem<Model>*>(&problem);
  if (!system) throw std::logic_error("ModelProblemOf: the orbit problem is of another model");
  return *system;
}

// The paper's model's, compiled once (paper_orbit_problem.cpp) instead of in every file that
// continues or solves its orbits.
extern template class BasicPeriodicityEquations<Pascal2014>;
extern template class BasicOrbitSystem<Pascal2014>;
extern template class ModelOrbitProblem<Pascal2014>;

}  // namespace stickslip
