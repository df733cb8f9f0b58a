// An orbit problem of any model, erased at the boundary the layers above the orbits use: the
// periodicity equations in chosen unknowns (a NonlinearSystem for Newton and the continuation
// engine) and what those layers ask of the orbit at the unknowns (its margins, stability,
// measures, and the undamped slip frequency it nears), with the model's description for names.
// The model's arithmetic stays compiled for it inside (model_orbit_problem.hpp builds one): no
// virtual call per flow evaluation, one per point and question. As Ceres erases a templated cost
// functor to CostFunction at its solver's boundary.
//
//   std::unique_ptr<OrbitProblem> p = MakeOrbitProblem(model, start, free, tie, shooting);
//   for (const Margin& m : p->Margins(u)) ...;
#pragma once

#include <optional>
#include <vector>

#include <Eigen/Core>

#include "stickslip/model/model_description.hpp"
#include "stickslip/numerics/newton.hpp"
#include "stickslip/orbits/margins.hpp"
#include "stickslip/orbits/orbit_measures.hpp"
#include "stickslip/orbits/periodicity_equations.hpp"
#include "stickslip/orbits/signature.hpp"
#include "stickslip/orbits/slip_resonance.hpp"
#include "stickslip/orbits/stability.hpp"

namespace stickslip {

struct MarginGradient;  // orbits/margin_gradients.hpp
template <int kStateSize>
struct BasicMonodromyGradient;  // orbits/floquet_gradients.hpp
using DynamicMonodromyGradient = BasicMonodromyGradient<Eigen::Dynamic>;

class OrbitProblem : public NonlinearSystem {
 public:
  virtual const ModelDescription& description() const = 0;
  virtual const Signature& signature() const = 0;
  virtual Shooting shooting() const = 0;
  // The full variables (orbit_layout.hpp) that are unknowns, in the unknowns' order; the
  // multiple-shooting states follow them.
  virtual const std::vector<int>& free() const = 0;
  virtual int FullCount() const = 0;  // the length of the full variable vector
  // The variables (full vector, then the multiple-shooting states) at the unknowns u, and back;
  // derivatives with respect to the variables as derivatives with respect to the unknowns.
  virtual Eigen::VectorXd Variables(const Eigen::VectorXd& u) const = 0;
  virtual Eigen::VectorXd Unknowns(const Eigen::VectorXd& variables) const = 0;
  virtual Eigen::MatrixXd ToUnknowns(const Eigen::MatrixXd& d_variables) const = 0;

  // The orbit at the unknowns u (a curve's own unknowns may follow them: ignored).
  virtual std::vector<Margin> Margins(const Eigen::VectorXd& u) const = 0;
  virtual OrbitStability Stability(const Eigen::VectorXd& u) const = 0;
  virtual BasicOrbitMeasures Measures(const Eigen::VectorXd& u) const = 0;
  virtual std::optional<SlipResonance> NearestSlipResonance(const Eigen::VectorXd& u) const = 0;
  // The coordinate the contact holds in a stick (orbit_measures.hpp).
  virtual int ContactCoordinate() const = 0;

  // What a curve's defining condition asks (branches/orbit_condition.hpp), with derivatives by
  // the full variables (FullCount() columns): the margins' exact gradients (margin_gradients.hpp,
  // one per margin of Margins(u)), an interior margin's function at the time tau elapsed in its
  // segment, the monodromy matrices' (floquet_gradients.hpp), and the time from the origin at
  // which listed segment `segment` starts, as the margins' walk forms it.
  virtual std::vector<MarginGradient> MarginGradients(const Eigen::VectorXd& u) const = 0;
  virtual MarginGradient MarginGradientAt(const Eigen::VectorXd& u, const Margin& margin, double tau) const = 0;
  virtual DynamicMonodromyGradient MonodromyGradients(const Eigen::VectorXd& u) const = 0;
  virtual double SegmentStart(const Eigen::VectorXd& u, int segment) const = 0;
};

// The paper's model's orbit (orbit.hpp) at the unknowns u of its problem (a curve's own unknowns
// may follow them). Throws std::logic_error for another model's problem.
Orbit ToOrbit(const OrbitProblem& problem, const Eigen::VectorXd& u);

}  // namespace stickslip
