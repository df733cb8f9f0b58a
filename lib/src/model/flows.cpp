#include "stickslip/model/flows.hpp"

// <Eigen/Core> must precede the unsupported AutoDiff module.
#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

namespace stickslip {

const char* ToString(Mode mode) {
  switch (mode) {
    case Mode::kSlipNegative: return "slip-";
    case Mode::kSlipPositive: return "slip+";
    case Mode::kStick: break;
  }
  return "stick";
}

std::optional<Mode> ModeFromString(std::string_view text) {
  for (Mode m : {Mode::kSlipNegative, Mode::kSlipPositive, Mode::kStick}) {
    if (text == ToString(m)) return m;
  }
  return std::nullopt;
}

int SlipDirection(Mode mode) {
  switch (mode) {
    case Mode::kSlipNegative: return -1;
    case Mode::kSlipPositive: return 1;
    case Mode::kStick: break;
  }
  return 0;
}

namespace {

// Seed directions: start state (4), elapsed time, phase, the five parameters.
constexpr int kDirections = 4 + 1 + 1 + kParameterCount;
constexpr int kElapsedSeed = 4;
constexpr int kPhaseSeed = 5;
constexpr int kFirstParameterSeed = 6;
using Dual = Eigen::AutoDiffScalar<Eigen::Matrix<double, kDirections, 1>>;

Dual Seeded(double value, int direction) {
  return Dual(value, kDirections, direction);
}

}  // namespace

FlowDerivatives FlowWithDerivatives(Mode mode, const State& start, double phase, double s,
                                    const Parameters& p) {
  StateT<Dual> start_dual;
  for (int i = 0; i < 4; ++i) start_dual(i) = Seeded(start(i), i);
  BasicParameters<Dual> p_dual;
  for (int k = 0; k < kParameterCount; ++k) {
    const ParameterId id = kAllParameters[k];
    p_dual[id] = Seeded(p[id], kFirstParameterSeed + k);
  }
  const StateT<Dual> end = Flow(mode, start_dual, Seeded(phase, kPhaseSeed),
                                Seeded(s, kElapsedSeed), p_dual);
  FlowDerivatives out;
  for (int i = 0; i < 4; ++i) {
    out.state(i) = end(i).value();
    const auto& d = end(i).derivatives();
    out.d_start.row(i) = d.head<4>().transpose();
    out.d_elapsed(i) = d(kElapsedSeed);
    out.d_phase(i) = d(kPhaseSeed);
    out.d_parameters.row(i) = d.segment<kParameterCount>(kFirstParameterSeed).transpose();
  }
  return out;
}

}  // namespace stickslip
