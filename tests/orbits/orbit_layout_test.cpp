// The named layout of an orbit's variables agrees with the positions the periodicity equations
// use, for the paper's model and the test model.
#include "stickslip/orbits/orbit_layout.hpp"

#include <gtest/gtest.h>

#include "stickslip/model/pascal_2014.hpp"
#include "stickslip/orbits/periodicity_equations.hpp"
#include "support/den_hartog_oscillator.hpp"

namespace stickslip {
namespace {

template <typename Model>
void ExpectLayoutOfTheEquations(const Model& model, const char* signature) {
  const BasicPeriodicityEquations<Model> equations(model, Signature::Parse(signature), Shooting::kSingle);
  const int n = equations.signature().size();
  const OrbitLayout layout(model.Description(), n);
  EXPECT_EQ(layout.Count(), equations.FullCount());
  EXPECT_EQ(layout.Phi(), equations.Phi());
  for (int i = 0; i < n; ++i) EXPECT_EQ(layout.Duration(i), equations.Duration(i));
  for (int k = 0; k < Model::kParameterCount; ++k) {
    EXPECT_EQ(layout.Parameter(k), equations.Parameter(k));
    EXPECT_EQ(layout.Name(layout.Parameter(k)), model.Description().parameters[k].name);
  }
  for (int i = 0; i < layout.Count(); ++i) EXPECT_EQ(layout.IndexOf(layout.Name(i)), i) << layout.Name(i);
  EXPECT_FALSE(layout.IndexOf(fmt::format("d{}", n + 1)));
}

TEST(OrbitLayout, NamesThePaperModelsVariablesInTheEquationsOrder) {
  ExpectLayoutOfTheEquations(Pascal2014{}, "slip- stick slip+");
  const OrbitLayout layout(Pascal2014{}.Description(), 2);
  std::vector<std::string> names;
  for (int i = 0; i < layout.Count(); ++i) names.push_back(layout.Name(i));
  EXPECT_EQ(names, (std::vector<std::string>{"x10", "x20", "v10", "phi", "d1", "d2", "chi", "eta", "omega", "u_s", "u_r"}));
}

TEST(OrbitLayout, NamesTheTestModelsVariablesFromItsDescription) {
  const DenHartogOscillator model = DenHartogModel();  // the layout refers to its description
  ExpectLayoutOfTheEquations(model, "slip- slip+");
  const OrbitLayout layout(model.Description(), 2);
  EXPECT_EQ(layout.Name(0), "x_0");  // its coordinate x at t = 0: the start without the contact's velocity
  EXPECT_EQ(layout.Name(1), "phi");
  EXPECT_EQ(layout.Name(layout.Parameter(1)), "F_k");
}

}  // namespace
}  // namespace stickslip
