// The full variable vector of an orbit of any model (model/oscillator_model.hpp), named: the
// start state without the contact's velocity (zero at the origin, a stop), the forcing phase
// "phi", the durations "d1".."dn" of the listed segments and the parameters, in the periodicity
// equations' order (periodicity_equations.hpp). The names come from the model's description, so
// files, messages and front ends name the variables of any model the same way; for the paper's
// model they are x10, x20, v10, phi, d1..dn, chi, eta, omega, u_s, u_r (orbit.hpp).
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "stickslip/model/model_description.hpp"

namespace stickslip {

class OrbitLayout {
 public:
  // `model` must outlive the layout (the paper's model's description is static; a LinearOscillator's is
  // the model's member: keep the model).
  OrbitLayout(const ModelDescription& model, int segments) : model_(&model), segments_(segments) {}

  int StartVariables() const { return model_->StateSize() - 1; }
  int Phi() const { return StartVariables(); }
  int Duration(int i) const { return Phi() + 1 + i; }  // i = 0..n-1
  int Parameter(int k) const { return Duration(segments_) + k; }
  int Count() const { return Parameter(model_->ParameterCount()); }

  std::string Name(int index) const;
  std::optional<int> IndexOf(std::string_view name) const;

 private:
  const ModelDescription* model_;
  int segments_;
};

}  // namespace stickslip
