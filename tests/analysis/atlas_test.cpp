// The atlas: over a small range of the section 4.1 data every exact orbit found from the brute
// force lies on a traced branch, the paper's own orbit (solved from its printed digits, not from the
// atlas) lies on one too, every attractor of an independent census (tests/data/paper-4.1-census.csv,
// made once with other settings) lies on one, no branch is a shorter orbit written over several
// periods, the result does not depend on the thread count, and bad options are refused naming the
// field.
#include "stickslip/analysis/atlas.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "stickslip/invalid_input.hpp"
#include "stickslip/model/pascal_2014/modal.hpp"
#include "stickslip/model/pascal_2014/paper_examples.hpp"
#include "stickslip/orbits/least_period.hpp"
#include "stickslip/orbits/orbit_origin.hpp"
#include "support/solved_presets.hpp"

namespace stickslip {
namespace {

// A small atlas of the section 4.1 data over omega in [0.55, 0.65]: its period-3 sticking families,
// the fold and the grazing at omega = 0.5999775 where the period-3 orbit's stick vanishes onto the
// period-1 family, and the paper's orbit at omega = 0.6.
AtlasOptions SmallOptions(int threads) {
  AtlasOptions o;
  o.brute_force.first = {ParameterId::kOmega, 0.55, 0.65, 4};
  o.brute_force.transient_periods = 300;
  o.brute_force.scattered_starts = 2;
  o.brute_force.threads = threads;
  return o;
}

const Atlas& SmallAtlas() {
  static const Atlas atlas = ComputeAtlas(SolvedPreset("paper-4.1").parameters, SmallOptions(2));
  return atlas;
}

TEST(Atlas, EveryExactOrbitFoundFromTheBruteForceLiesOnATracedBranch) {
  const Atlas& atlas = SmallAtlas();
  ASSERT_GT(atlas.PeriodicWithinLimit(), 0);
  EXPECT_EQ(atlas.OnBranches(), atlas.PeriodicWithinLimit());
  for (const AtlasAttractor& a : atlas.attractors) {
    if (a.found && a.found->Found()) {
      EXPECT_EQ(a.fate, AttractorFate::kOnBranch) << "omega " << a.value << ": " << a.reason;
    }
    // Nothing is dropped: an attractor not on a branch says why.
    if (a.fate != AttractorFate::kOnBranch) {
      EXPECT_FALSE(a.reason.empty());
    }
  }
}

TEST(Atlas, ThePapersOrbitSolvedFromItsPrintedDigitsLiesOnABranch) {
  const Atlas& atlas = SmallAtlas();
  BranchMembershipOptions options;
  options.parameter = "omega";
  const BranchMembership m = FindOnBranches(SolvedPreset("paper-4.1"), atlas.Branches(), options);
  EXPECT_TRUE(m.on_branch) << m.message;
}

TEST(Atlas, NoBranchIsAShorterOrbitWrittenOverSeveralPeriods) {
  // At omega = 0.5999775 the stick of the period-3 orbit 'slip- stick slip+ slip- / antisymmetric
  // period 3' vanishes onto the period-1 family: the branch beyond is the period-1 orbit, and is
  // traced as such.
  for (const OrbitBranch* branch : SmallAtlas().Branches()) {
    for (const Orbit* orbit : {&branch->orbits.front(), &branch->orbits.back()}) {
      EXPECT_NE(ReduceToLeastPeriod(*orbit).status, LeastPeriodStatus::kReduced) << orbit->signature.ToString();
    }
  }
}

TEST(Atlas, DoesNotDependOnTheThreadCount) {
  const Atlas one = ComputeAtlas(SolvedPreset("paper-4.1").parameters, SmallOptions(1));
  const Atlas& two = SmallAtlas();
  ASSERT_EQ(one.attractors.size(), two.attractors.size());
  for (std::size_t k = 0; k < one.attractors.size(); ++k) {
    EXPECT_EQ(one.attractors[k].fate, two.attractors[k].fate);
    EXPECT_EQ(one.attractors[k].branch, two.attractors[k].branch);
    EXPECT_EQ(one.attractors[k].point, two.attractors[k].point);
  }
  const std::vector<const OrbitBranch*> a = one.Branches(), b = two.Branches();
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    ASSERT_EQ(a[k]->orbits.size(), b[k]->orbits.size());
    EXPECT_EQ(a[k]->orbits.back().parameters.omega, b[k]->orbits.back().parameters.omega);
  }
}

// An orbit type up to the choice of origin (a trace keeps its start's origin, so one family met from
// two starts is written from two segment ends): the least of its rotations' texts.
std::string UpToOrigin(const Signature& signature) {
  std::string least = signature.ToString();
  for (int j = 0; j < OriginCount(signature); ++j) least = std::min(least, WithOriginAt(signature, j).ToString());
  return least;
}

// What two atlases must share: every branch's orbit type (up to origin), and every located special
// point (not the ends, which a step size places) by kind and parameter, each once. Which branch a
// point is stored on is not compared: where several margins change sign at one point, a branch that
// one atlas traces into it another may trace out of it.
struct Shared {
  std::set<std::string> types;
  std::vector<std::pair<std::string, double>> points;
};

Shared SharedOf(const Atlas& atlas) {
  Shared shared;
  for (const OrbitBranch* b : atlas.Branches()) {
    shared.types.insert(UpToOrigin(b->orbits.front().signature));
    for (const SpecialPoint& s : b->branch.special_points) {
      if (s.type != "EP" && s.located) shared.points.emplace_back(s.type, s.lambda);
    }
  }
  std::sort(shared.points.begin(), shared.points.end());
  const auto same = [](const auto& a, const auto& b) { return a.first == b.first && std::abs(a.second - b.second) <= 1e-8; };
  shared.points.erase(std::unique(shared.points.begin(), shared.points.end(), same), shared.points.end());
  return shared;
}

TEST(Atlas, EveryAdjacentTypeIsFollowedWhateverTheStepSize) {
  // At omega = 0.5999775 three margins change sign at once (SK, T0, GR) and more than one adjacent
  // type is confirmed: which one a trace takes depends on where its steps land; the atlas follows
  // every one, so two step sizes give the same orbit types and special points.
  AtlasOptions coarse = SmallOptions(2), fine = SmallOptions(2);
  coarse.brute_force.first = fine.brute_force.first = {ParameterId::kOmega, 0.58, 0.62, 2};
  fine.continuation.step.ds = coarse.continuation.step.ds / 3;
  fine.continuation.step.ds_max = coarse.continuation.step.ds_max / 3;
  const Parameters base = SolvedPreset("paper-4.1").parameters;
  const Shared a = SharedOf(ComputeAtlas(base, coarse)), b = SharedOf(ComputeAtlas(base, fine));
  EXPECT_EQ(a.types, b.types);
  EXPECT_GE(a.types.size(), 4u);  // 'slip- / antisymmetric', 'slip- stick / antisymmetric' and two period-3 types
  ASSERT_EQ(a.points.size(), b.points.size());
  for (std::size_t k = 0; k < a.points.size(); ++k) {
    EXPECT_EQ(a.points[k].first, b.points[k].first);
    EXPECT_NEAR(a.points[k].second, b.points[k].second, 1e-8) << a.points[k].first;
  }
}

struct CensusAttractor {
  double omega = 0.0;
  double section_phase = 0.0;
  State section = State::Zero();
  std::string signature;
};

// tests/data/paper-4.1-census.csv: '#' comments, a header, then omega, section_phase, period,
// signature, x1, x2, v1, v2 (the signature without commas).
std::vector<CensusAttractor> ReadCensus() {
  std::ifstream in(std::filesystem::path(STICKSLIP_SOURCE_DIR) / "tests/data/paper-4.1-census.csv");
  std::vector<CensusAttractor> census;
  std::string line;
  bool header = true;
  while (std::getline(in, line)) {
    if (line.empty() || line.front() == '#') continue;
    if (std::exchange(header, false)) continue;
    std::vector<std::string> f;
    std::stringstream fields(line);
    for (std::string field; std::getline(fields, field, ',');) f.push_back(field);
    CensusAttractor a{std::stod(f[0]), std::stod(f[1]), State(std::stod(f[4]), std::stod(f[5]), std::stod(f[6]), std::stod(f[7])), f[3]};
    census.push_back(a);
  }
  return census;
}

TEST(Atlas, FindsEveryAttractorOfAnIndependentCensus) {
  const std::vector<CensusAttractor> census = ReadCensus();
  ASSERT_EQ(census.size(), 46u);
  const Parameters base = SolvedPreset("paper-4.1").parameters;
  AtlasOptions o;  // the atlas's own settings, as `stickslip atlas --preset paper-4.1` takes them, on a grid of 0.01
  o.brute_force.first = {ParameterId::kOmega, 0.3, 0.45, 15};
  o.brute_force.centre = FindPaperExample("paper-4.1")->initial_state;
  const Atlas atlas = ComputeAtlas(base, o);
  BranchMembershipOptions membership;
  membership.parameter = "omega";
  FindOrbitOptions find;
  find.transient_periods = 100;  // the census's states have settled
  for (const CensusAttractor& a : census) {
    Parameters p = base;
    p.omega = a.omega;
    const FindOrbitResult found = FindOrbit(p, a.section, a.section_phase, find);
    ASSERT_TRUE(found.Found()) << "omega " << a.omega << " '" << a.signature << "': " << found.message;
    const BranchMembership m = FindOnBranches(found.solution->orbit, atlas.Branches(), membership);
    EXPECT_TRUE(m.on_branch) << "omega " << a.omega << " '" << a.signature << "': " << m.message;
  }
}

void ExpectRefused(const AtlasOptions& options, const std::string& field) {
  try {
    ComputeAtlas(SolvedPreset("paper-4.1").parameters, options);
    ADD_FAILURE() << "accepted; want " << field << " refused";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.field(), field) << e.what();
  }
}

TEST(Atlas, RefusesAPeriodLimitOutOfRange) {
  for (int limit : {0, AtlasOptions::kMaxMultiple + 1}) {
    AtlasOptions o = SmallOptions(1);
    o.max_multiple = limit;
    ExpectRefused(o, "max_multiple");
  }
}

TEST(Atlas, RefusesAGridValueOnANaturalFrequency) {
  // omega1 of eq. 56 for chi = 0.3, eta = 4, as a grid value.
  const Parameters p = SolvedPreset("paper-4.1").parameters;
  const double omega1 = NaturalFrequencies(p.chi, p.eta).first;
  AtlasOptions o = SmallOptions(1);
  o.brute_force.first = {ParameterId::kOmega, omega1 - 0.1, omega1, 2};
  ExpectRefused(o, "grid");
}

}  // namespace
}  // namespace stickslip
