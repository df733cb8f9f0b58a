// The model interface: what the algorithms above the model (the exact simulator and the
// periodicity equations today; the segment walk, margins and stability next) may ask of an oscillator with one Coulomb
// contact. An algorithm is a template on a type M satisfying OscillatorModel; it is compiled for
// each model (no virtual call per flow evaluation, and forward-mode AD runs through the model's
// scalar templates), and erased at the boundary the layers above already use. COCO's
// `ode_isol2hspo` asks the same of a hybrid system (a vector field, events and resets per mode,
// labelled by a signature); Ceres keeps its templated functors behind `CostFunction` the same way.
//
// What a model provides, for one contact whose relative velocity is s:
//   - its description as data (model_description.hpp): parameter names, units and ranges, the
//     names of the state's components;
//   - State and Parameters types as templates on the scalar (StateT<T>, ParametersT<T>, with
//     ParameterAt(p, k) in the order of the description), their sizes, which parameters are the
//     forcing frequency and the kinetic and static friction levels, Validate(p) (the first
//     violation, not thrown) and ValidateClosedForm(p) (only what the closed forms need: the
//     solvers ask it of every iterate);
//   - the motion in a mode from a state and a forcing phase (MotionInMode), exact in closed form,
//     with StateAt(elapsed): the flow; both templated on the scalar (MotionT<T>), so that the walk
//     over an orbit's segments runs in AD for the margins' and the monodromy's gradients; the flow
//     with its exact derivatives; the contact's acceleration in a mode (an abnormal stop's second
//     end condition);
//   - the contact's velocity s and "at rest" (s = 0 exactly, and s = 0 to rounding);
//   - the stick force (the friction force a stick needs, signed so that s > threshold drives a
//     slip with s < 0), its rate along a motion at rest (the transversality of a stick exit, and
//     minus the contact's jerk at an abnormal stop, up to a positive factor), and the static
//     threshold it must stay within; Coulomb's law at rest
//     (ModeFromRest); whether abnormal stops (s = s' = 0 in a slip, which needs static = kinetic
//     level) can occur;
//   - along a motion, the contact velocity, the stick force and each coordinate (positions, in
//     the order of the description's coordinates) as functions of the elapsed time in a form the
//     root finder can search without missing a root (EventFunction: a SinusoidSum for undamped
//     closed forms, numerics/sinusoid_sum.hpp, or an ExponentialSum, exponential_sum.hpp), and
//     which coordinates a stick holds fixed;
//   - the forcing frequency (the forcing is cos(omega t + phi));
//   - the monodromy's factors: each mode's transition matrix (the flow's Jacobian with respect to
//     its start) and the saltation matrix at each kind of segment end.
// A model that an integrator can also run, the independent check of its closed forms, provides
// its equations of motion and what Coulomb's law needs written from them
// (IntegrableOscillatorModel, integrable_oscillator_model.hpp).
//
// The state's size is fixed at compile time (kStateSize: the paper's model, 4) or, for a model
// whose size comes from a file, known at run time: kStateSize is then Eigen::Dynamic and the
// states are Eigen::VectorXd. StateSize() is the size either way; the layers above make states
// and matrices of that size (FilledState, StateMatrixT, IdentityOfState, FixedSizeDefault) and
// never assume one.
//
// How what comes next fits (the general-oscillator issue):
//   - viscous damping: the motion in a mode has complex eigenvalues, so the functions along a
//     motion become sums of exponentially weighted sinusoids (the generalised root finder); the
//     interface is unchanged.
//   - a moving belt (linear_oscillator.hpp): s = q_N' - v_b; "at rest" means s = 0, so the
//     contact velocity, AtRest and NearRest take the parameters, and the orbit's origin has
//     q_N' = v_b (kRestVelocityParameter), not 0.
//   - no forcing (Autonomous): the period is the durations' sum, an unknown of the orbit; the
//     periodicity equations pin the meaningless phase instead of the period.
//   - several contacts: Mode becomes a tuple of contact states and ModeFromRest a small linear
//     complementarity problem (Glocker & Studer 2005); the contact-velocity and stick-force
//     members take the contact's index.
#pragma once

#include <concepts>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "stickslip/invalid_input.hpp"
#include "stickslip/model/model_description.hpp"
#include "stickslip/model/mode.hpp"
#include "stickslip/numerics/exponential_sum.hpp"
#include "stickslip/numerics/sinusoid_sum.hpp"

namespace stickslip {

// The functions of time the root finder searches without missing a root.
template <typename F>
concept EventFunction = std::same_as<F, SinusoidSum> || std::same_as<F, ExponentialSum>;

template <typename M>
concept OscillatorModel =
    requires(const M& model, Mode mode, const typename M::State& x, const typename M::Parameters& p,
             const typename M::Motion& motion, double phase) {
      // Sizes and the scalar templates that forward-mode AD runs through.
      { M::kStateSize } -> std::convertible_to<int>;  // or Eigen::Dynamic
      { model.StateSize() } -> std::convertible_to<int>;
      { M::kParameterCount } -> std::convertible_to<int>;
      { M::kForcingFrequencyParameter } -> std::convertible_to<int>;
      { M::kKineticLevelParameter } -> std::convertible_to<int>;
      { M::kStaticLevelParameter } -> std::convertible_to<int>;
      // The parameter that is the contact's velocity at rest (a belt's speed), or -1 for a fixed
      // surface: at the orbit's origin the contact's velocity is this parameter, not a variable.
      { M::kRestVelocityParameter } -> std::convertible_to<int>;
      requires std::same_as<typename M::State, typename M::template StateT<double>>;
      requires std::same_as<typename M::Parameters, typename M::template ParametersT<double>>;
      requires std::same_as<typename M::Motion, typename M::template MotionT<double>>;
      { M::ParameterAt(p, 0) } -> std::convertible_to<double>;
      { model.Description() } -> std::same_as<const ModelDescription&>;
      { model.Validate(p) } -> std::same_as<std::optional<InvalidInput>>;
      { model.ValidateClosedForm(p) } -> std::same_as<std::optional<InvalidInput>>;
      // The motion in a mode, the flow, and the flow with its derivatives (state, start, elapsed
      // time, phase, parameters: model/pascal_2014/flows.hpp's BasicFlowDerivatives).
      { model.MotionInMode(mode, x, phase, p) } -> std::same_as<typename M::Motion>;
      { motion.StateAt(phase) } -> std::convertible_to<typename M::State>;
      { model.Flow(mode, x, phase, phase, p) } -> std::same_as<typename M::State>;
      { model.FlowWithDerivatives(mode, x, phase, phase, p) } -> std::same_as<typename M::FlowDerivatives>;
      { model.ForcingFrequency(p) } -> std::same_as<double>;
      // No forcing at all: the orbit's period is its durations' sum, its phase meaningless.
      { model.Autonomous() } -> std::same_as<bool>;
      // The natural frequencies of a slip that bound nothing: those of an undamped slip, at which
      // a forced orbit that never sticks has no bounded amplitude; none where a slip is damped.
      { model.UndampedSlipFrequencies(p) } -> std::same_as<std::vector<double>>;
      // The monodromy's factors: the flow's Jacobian with respect to the start state over a
      // segment's duration, and the saltation matrix at its end from one mode into the next.
      { model.TransitionMatrix(mode, phase, p) } -> std::convertible_to<Eigen::Matrix<double, M::kStateSize, M::kStateSize>>;
      { model.SaltationMatrix(mode, mode, x, phase, p) } -> std::convertible_to<Eigen::Matrix<double, M::kStateSize, M::kStateSize>>;
      // The contact.
      { model.ContactVelocity(x, p) } -> std::same_as<double>;
      { model.ContactAcceleration(mode, x, phase, p) } -> std::same_as<double>;
      { model.AtRest(x, p) } -> std::same_as<typename M::State>;
      { model.NearRest(x, p) } -> std::same_as<bool>;
      { model.StickForce(x, phase, p) } -> std::same_as<double>;
      { model.StickForceRate(x, phase, p) } -> std::same_as<double>;
      { model.StaticThreshold(p) } -> std::same_as<double>;
      // The friction force in a slip, in the units of the stick force: F_k + alpha |s| opposing the
      // slip speed s, the kinetic level F_k and its slope alpha (0: Coulomb's constant level).
      { model.KineticForce(p) } -> std::same_as<double>;
      { model.FrictionSlope() } -> std::same_as<double>;
      { model.AbnormalStopsPossible(p) } -> std::same_as<bool>;
      { model.ModeFromRest(x, phase, p) } -> std::same_as<Mode>;
      // Along a motion, for the root finder.
      requires EventFunction<typename M::EventFunction>;
      { model.ContactVelocityAlong(motion) } -> std::same_as<typename M::EventFunction>;
      { model.CoordinateAlong(motion, 0) } -> std::same_as<typename M::EventFunction>;
      { model.HeldInStick(0) } -> std::same_as<bool>;
      { model.StickForceAlong(motion, phase, p) } -> std::same_as<typename M::EventFunction>;
    };

// A state of the model's size with every component `value`, and the model's square matrices.
template <typename M, typename T>
typename M::template StateT<T> FilledState(const M& model, const T& value) {
  return M::template StateT<T>::Constant(model.StateSize(), value);
}
template <typename M, typename T = double>
using StateMatrixT = Eigen::Matrix<T, M::kStateSize, M::kStateSize>;
template <typename M>
StateMatrixT<M> IdentityOfState(const M& model) {
  return StateMatrixT<M>::Identity(model.StateSize(), model.StateSize());
}
// A member's default: zero (the identity where `identity`) at a fixed size, empty at a run-time
// size (sized where the model is known).
template <typename Matrix, bool identity = false>
Matrix FixedSizeDefault() {
  if constexpr (Matrix::SizeAtCompileTime == Eigen::Dynamic) {
    return Matrix();
  } else if constexpr (identity) {
    return Matrix::Identity();
  } else {
    return Matrix::Zero();
  }
}

// The contact's velocity at rest: the belt's speed, or 0 against a fixed surface.
template <typename M, typename T>
T RestVelocity(const typename M::template ParametersT<T>& p, const T& zero) {
  if constexpr (M::kRestVelocityParameter < 0) {
    return zero;
  } else {
    return M::ParameterAt(p, M::kRestVelocityParameter);
  }
}

}  // namespace stickslip
