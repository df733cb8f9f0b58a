#include "stickslip/model/pascal_2014/flows.hpp"

// <Eigen/Core> must precede the unsupported AutoDiff module.
#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

#include <cmath>

namespace stickslip {

FlowDerivatives FlowWithDerivatives(Mode mode, const State& start, double phase, double s,
                                    const Parameters& p) {
  // The parameters enter Q, d0, omega_j and Lambda in nested ways: forward-mode automatic
  // differentiation with one direction per parameter that a flow feels. The static level u_r, the
  // last, enters none (only the stick's end, eq. 11): its column is zero.
  constexpr int kFlowParameters = kParameterCount - 1;
  static_assert(kAllParameters[kFlowParameters] == ParameterId::kStaticFriction);
  using Dual = Eigen::AutoDiffScalar<Eigen::Matrix<double, kFlowParameters, 1>>;
  BasicParameters<Dual> p_dual;
  for (int k = 0; k < kParameterCount; ++k) {
    const ParameterId id = kAllParameters[k];
    p_dual[id] = k < kFlowParameters ? Dual(p[id], kFlowParameters, k) : Dual(p[id]);
  }
  const StateT<Dual> end = Flow(mode, StateT<Dual>(start.cast<Dual>()), Dual(phase), Dual(s), p_dual);
  FlowDerivatives out;
  for (int i = 0; i < 4; ++i) {
    out.state(i) = end(i).value();
    out.d_parameters.row(i) << end(i).derivatives().transpose(), 0.0;
  }
  out.d_start = TransitionMatrix(mode, s, p);
  // The phase enters through F only: dX/dpsi = dF(s)/dpsi - H(s) dF(0)/dpsi (eq. 5); a stick
  // does not feel the forcing (eq. 9).
  out.d_phase.setZero();
  if (mode != Mode::kStick) {
    const Eigen::Vector2d q = ForcedAmplitude(p.chi, p.eta, p.omega);
    auto d_forcing = [&](double t) {
      State f;
      f << -q * std::sin(p.omega * t + phase), -p.omega * q * std::cos(p.omega * t + phase);
      return f;
    };
    out.d_phase = d_forcing(s) - out.d_start * d_forcing(0.0);
  }
  // The time derivative is the vector field at the end (eq. 2, 9).
  out.d_elapsed << out.state.tail<2>(), Acceleration(mode, out.state, phase + p.omega * s, p);
  return out;
}

}  // namespace stickslip
