// A run file's [model] (io/model_table.hpp): a chain table is the chain it writes out (the
// matrices assembled by hand, as Den Hartog's and the belt's users write them), a matrices table
// reads its Matrix Market files and puts the contact's coordinate last keeping every name, and
// every way a table can be wrong is refused naming the key.
#include "stickslip/io/model_table.hpp"

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "stickslip/invalid_input.hpp"
#include "stickslip/io/run_file.hpp"

namespace stickslip {
namespace {

const std::string kThreeMasses = R"([model]
kind = "chain"
masses = [1.0, 2.0, 3.0]
names = ["left", "middle", "right"]
springs = [{ between = ["left", "ground"], k = 10.0 }, { between = ["left", "middle"], k = 20.0 },
           { between = ["middle", "right"], k = 30.0 }]
dampers = [{ between = ["right", "ground"], c = 0.5 }, { between = ["left", "right"], c = 0.25 }]
forcing = { left = 4.0 }
contact = "middle"
friction_slope = -0.1
parameters = { omega = 1.5, F_k = 0.3, F_s = 0.4, v_b = 0.2 }
)";

// K, C, M and g of kThreeMasses in the order left, right, middle (the contact's mass last), by hand.
Eigen::Matrix3d Stiffness() { return (Eigen::Matrix3d() << 30, 0, -20, 0, 30, -30, -20, -30, 50).finished(); }
Eigen::Matrix3d Damping() { return (Eigen::Matrix3d() << 0.25, -0.25, 0, -0.25, 0.75, 0, 0, 0, 0).finished(); }

void ExpectTheThreeMasses(const LinearOscillatorData& data) {
  EXPECT_EQ(data.mass, Eigen::Vector3d(1, 3, 2).asDiagonal().toDenseMatrix());
  EXPECT_EQ(data.stiffness, Stiffness());
  EXPECT_EQ(data.damping, Damping());
  EXPECT_EQ(data.forcing, Eigen::Vector3d(4, 0, 0));
  EXPECT_EQ(data.coordinates, (std::vector<std::string>{"left", "right", "middle"}));
  EXPECT_EQ(data.friction_slope, -0.1);
}

TEST(ModelTable, AChainIsTheMatricesItsMassesSpringsAndDampersMake) {
  const ModelTable table = ParseModelTable(kThreeMasses, "three.toml");
  ExpectTheThreeMasses(ModelDataOf(table));
  const DynamicLinearOscillator model = ModelOf(table);
  const DynamicLinearOscillator::Parameters p = ParametersOf(model, table);
  EXPECT_EQ(std::vector<double>({p.omega, p.F_k, p.F_s, p.v_b}), std::vector<double>({1.5, 0.3, 0.4, 0.2}));
  const DynamicLinearOscillator::Parameters faster = ParametersOf(model, table, {{"v_b", 0.7}, {"omega", 2.0}});
  EXPECT_EQ(faster.v_b, 0.7);
  EXPECT_EQ(faster.omega, 2.0);
}

class MatrixFiles : public testing::Test {
 protected:
  void SetUp() override {
    folder_ = std::filesystem::temp_directory_path() /
              ("model_table_test_" + std::string(testing::UnitTest::GetInstance()->current_test_info()->name()));
    std::filesystem::remove_all(folder_);
    std::filesystem::create_directories(folder_);
  }
  void TearDown() override { std::filesystem::remove_all(folder_); }
  void Write(const std::string& name, const std::string& text) const { std::ofstream(folder_ / name) << text; }
  std::string RunFile(const std::string& model) const {
    const std::filesystem::path file = folder_ / "model.toml";
    std::ofstream(file) << model;
    return file.string();
  }
  std::filesystem::path folder_;
};

// The same three masses as Matrix Market files in the order left, middle, right, K and M as an FE
// code exports them (one triangle of a symmetric matrix), C in full, g an array.
TEST_F(MatrixFiles, AreReadExactlyAndTheContactsCoordinateIsPutLast) {
  Write("M.mtx", "%%MatrixMarket matrix coordinate real symmetric\n3 3 3\n1 1 1\n2 2 2\n3 3 3\n");
  Write("K.mtx", "%%MatrixMarket matrix coordinate real symmetric\n3 3 5\n1 1 30\n2 1 -20\n2 2 50\n3 2 -30\n3 3 30\n");
  Write("C.mtx", "%%MatrixMarket matrix array real general\n3 3\n0.25\n0\n-0.25\n0\n0\n0\n-0.25\n0\n0.75\n");
  Write("g.mtx", "%%MatrixMarket matrix array real general\n3 1\n4\n0\n0\n");
  const ModelTable table = ReadModelTable(RunFile(R"([model]
kind = "matrices"
mass = "M.mtx"
stiffness = "K.mtx"
damping = "C.mtx"
forcing = "g.mtx"
coordinates = ["left", "middle", "right"]
contact = "middle"
friction_slope = -0.1
)"));
  ExpectTheThreeMasses(ModelDataOf(table));
}

TEST_F(MatrixFiles, ThatDoNotFitTogetherAreRefusedNamingTheKey) {
  Write("M.mtx", "%%MatrixMarket matrix array real general\n2 2\n1\n0\n0\n1\n");
  Write("K3.mtx", "%%MatrixMarket matrix array real symmetric\n3 3\n2\n-1\n0\n2\n-1\n1\n");
  Write("K.mtx", "%%MatrixMarket matrix array real symmetric\n2 2\n2\n-1\n1\n");
  Write("g3.mtx", "%%MatrixMarket matrix array real general\n3 1\n1\n0\n0\n");
  Write("cut.mtx", "%%MatrixMarket matrix coordinate real general\n2 2 2\n1 1 1\n");
  const auto field_of = [&](const std::string& keys) {
    try {
      ModelDataOf(ReadModelTable(RunFile("[model]\nkind = \"matrices\"\n" + keys)));
    } catch (const InvalidInput& e) {
      return e.field() + ": " + e.what();
    }
    return std::string("accepted");
  };
  const std::string contact = "contact = \"x2\"\n";
  EXPECT_EQ(field_of("mass = \"M.mtx\"\nstiffness = \"K3.mtx\"\n" + contact).rfind("model.stiffness", 0), 0u);
  EXPECT_EQ(field_of("mass = \"M.mtx\"\nstiffness = \"K.mtx\"\nforcing = \"g3.mtx\"\n" + contact).rfind("model.forcing", 0), 0u);
  EXPECT_EQ(field_of("mass = \"cut.mtx\"\nstiffness = \"K.mtx\"\n" + contact).rfind("model.mass", 0), 0u);
  EXPECT_EQ(field_of("mass = \"none.mtx\"\nstiffness = \"K.mtx\"\n" + contact).rfind("model.mass", 0), 0u);
  EXPECT_EQ(field_of("mass = \"M.mtx\"\nstiffness = \"K.mtx\"\ncontact = \"x3\"\n").rfind("model.contact", 0), 0u);
  EXPECT_EQ(field_of("mass = \"M.mtx\"\nstiffness = \"K.mtx\"\ncoordinates = [\"a\", \"a\"]\n" + contact).rfind("model.coordinates", 0), 0u);
  EXPECT_EQ(field_of("mass = \"M.mtx\"\nstiffness = \"K.mtx\"\n" + contact), "accepted");
}

// Each bad table, the key its message must name, and words of the message.
struct BadTable {
  std::string replace;  // a line of kThreeMasses ...
  std::string with;     // ... replaced by this
  std::string field;
  std::string says;
};

TEST(ModelTable, RefusesEveryTableThatIsNoModelNamingTheKey) {
  const std::vector<BadTable> cases = {
      {"kind = \"chain\"", "kind = \"beam\"", "model.kind", "valid \"chain\" or \"matrices\""},
      {"kind = \"chain\"", "", "model.kind", "is missing"},
      {"contact = \"middle\"", "contact = \"wheel\"", "model.contact", "one of 'left', 'middle', 'right'"},
      {"contact = \"middle\"", "", "model.contact", "is missing"},
      {"forcing = { left = 4.0 }", "forcing = { wheel = 4.0 }", "model.forcing.wheel", "is not a mass"},
      {"forcing = { left = 4.0 }", "forcing = { left = \"4\" }", "model.forcing.left", "must be a number"},
      {"masses = [1.0, 2.0, 3.0]", "masses = [1.0, -2.0, 3.0]", "model.masses[1]", "> 0"},
      {"masses = [1.0, 2.0, 3.0]", "masses = [1.0, 2.0]", "model.names", "valid one per mass, 2"},
      {"friction_slope = -0.1", "friction_slop = -0.1", "model.friction_slop", "did you mean 'model.friction_slope'"},
      // A misspelt required key is named beside the one missing.
      {"masses = [1.0, 2.0, 3.0]", "maases = [1.0, 2.0, 3.0]", "model.masses", "('model.maases' at bad.toml:"},
      {"contact = \"middle\"", "contakt = \"middle\"", "model.contact", "('model.contakt' at bad.toml:"},
      {"{ between = [\"left\", \"ground\"], k = 10.0 }", "{ between = [\"left\", \"ground\"], kk = 10.0 }",
       "model.springs[0].k", "('model.springs[0].kk' at bad.toml:"},
      {"{ between = [\"left\", \"ground\"], k = 10.0 }", "{ between = [\"left\", \"left\"], k = 10.0 }",
       "model.springs[0].between", "two different ends"},
      {"{ between = [\"left\", \"ground\"], k = 10.0 }", "{ between = [\"left\", \"ground\"], k = -10.0 }",
       "model.springs[0].k", "valid >= 0"},
      {"{ between = [\"left\", \"ground\"], k = 10.0 }", "{ between = [\"left\"], k = 10.0 }", "model.springs[0].between",
       "two names"},
      {"{ between = [\"left\", \"ground\"], k = 10.0 }", "{ between = [\"left\", \"ground\"], c = 10.0 }",
       "model.springs[0].k", "is missing"},
      // No spring to the ground: a rigid-body mode, a singular stiffness.
      {"{ between = [\"left\", \"ground\"], k = 10.0 }", "{ between = [\"left\", \"right\"], k = 10.0 }", "model.springs",
       ""},
      {"F_k = 0.3, F_s = 0.4", "F_k = 0.3, F_s = 0.2", "model.parameters.F_s", "F_k = 0.3 <="},
      {"F_k = 0.3, F_s = 0.4", "F_s = 0.4", "model.parameters.F_k", "is missing"},
      {"omega = 1.5,", "Omega = 1.5,", "model.parameters.Omega", "omega, F_k, F_s, v_b"},
      {"omega = 1.5,", "", "model.parameters.omega", "is missing"},
      {"friction_slope = -0.1", "friction_slope = -0.1\nunits = \"mm\"", "model.units", "must be a table"},
      {"friction_slope = -0.1", "friction_slope = -0.1\nunits = { mass = \"kg\" }", "model.units.mass", "unknown"},
      {"friction_slope = -0.1", "friction_slope = -0.1\nunits = { length = 1.0 }", "model.units.length",
       "must be a string"},
      {"friction_slope = -0.1", "friction_slope = -0.1\nunits = { time = \"\" }", "model.units.time",
       "it has 0 bytes"},
      {"friction_slope = -0.1", "friction_slope = -0.1\nunits = { time = \"ms \" }", "model.units.time", "it has a space at an end"},
      {"friction_slope = -0.1", "friction_slope = -0.1\nunits = { force = \"k\\u0085N\" }", "model.units.force",
       "it has a control character"},
      {"friction_slope = -0.1", "friction_slope = -0.1\nunits = { force = \"\\u202eN\" }", "model.units.force",
       "it has a control character"},
      {"friction_slope = -0.1", "friction_slope = -0.1\nunits = { force = \"$N$\" }", "model.units.force", "it has a '$'"},
      {"friction_slope = -0.1", "friction_slope = -0.1\nunits = { length = \"m\\nm\" }", "model.units.length",
       "it has a control character"},
      {"friction_slope = -0.1", "friction_slope = -0.1\nunits = { length = \"micrometres-longer\" }",
       "model.units.length", "it has 18 bytes"},
  };
  for (const BadTable& c : cases) {
    std::string text = kThreeMasses;
    const std::size_t at = text.find(c.replace);
    ASSERT_NE(at, std::string::npos) << c.replace;
    text.replace(at, c.replace.size(), c.with);
    try {
      const ModelTable table = ParseModelTable(text, "bad.toml");
      const DynamicLinearOscillator model = ModelOf(table);
      ParametersOf(model, table);
      ADD_FAILURE() << "accepted: " << c.with;
    } catch (const InvalidInput& e) {
      EXPECT_EQ(e.field(), c.field) << e.what();
      EXPECT_NE(std::string(e.what()).find(c.says), std::string::npos) << e.what();
      EXPECT_EQ(std::string(e.what()).rfind("bad.toml:", 0), 0u) << "not placed in the file: " << e.what();
    }
  }
}

// Units label the numbers (they are not converted): each parameter's derived from them, SI for those
// left out; declared SI is the model without a declaration, fingerprint and all, and other units
// make another model.
TEST(ModelTable, DeclaredUnitsNameEveryParameterAndSiIsTheDefault) {
  const auto with = [](const std::string& units) {
    return ModelOf(ParseModelTable(kThreeMasses + units, "three.toml"));
  };
  const auto units_of = [](const DynamicLinearOscillator& model) {
    std::vector<std::string> out;
    for (const ParameterDescription& p : model.Description().parameters) out.push_back(p.unit);
    return out;
  };
  const DynamicLinearOscillator si = with("");
  EXPECT_EQ(units_of(si), (std::vector<std::string>{"rad/s", "N", "N", "m/s"}));
  const DynamicLinearOscillator declared_si = with("units = { length = \"m\", time = \"s\", force = \"N\" }\n");
  const DynamicLinearOscillator small = with("units = { length = \"mm\", time = \"ms\", force = \"kN\" }\n");
  EXPECT_EQ(units_of(small), (std::vector<std::string>{"rad/ms", "kN", "kN", "mm/ms"}));
  EXPECT_EQ(small.Description().units.Energy(), "kN mm");
  EXPECT_EQ(small.Description().units.ViscousDamping(), "kN ms/mm");
  EXPECT_EQ(si.Description().units.Energy(), "J");
  EXPECT_EQ(units_of(with("units = { time = \"min\" }\n")), (std::vector<std::string>{"rad/min", "N", "N", "m/min"}));
  const auto fingerprint = [](const DynamicLinearOscillator& model) {
    Fingerprint hash;
    model.Data().AddTo(hash);
    return hash.Value();
  };
  EXPECT_EQ(fingerprint(declared_si), fingerprint(si));
  EXPECT_NE(fingerprint(small), fingerprint(si));
  EXPECT_EQ(small.Data().units, (ModelUnits{"mm", "ms", "kN"}));
}

TEST(ModelTable, IsNotTakenByTheRunCommandsWhichSayWhereItIs) {
  try {
    ParseRunFile(kThreeMasses, "three.toml");
    ADD_FAILURE() << "a [model] run file was taken by ParseRunFile";
  } catch (const RunFileError& e) {
    EXPECT_EQ(e.field(), "model");
    EXPECT_NE(std::string(e.what()).find("find --model"), std::string::npos) << e.what();
  }
  try {
    ParseModelTable("output = \"x\"\n", "none.toml");
    ADD_FAILURE() << "a run file without [model] was taken";
  } catch (const RunFileError& e) {
    EXPECT_EQ(e.field(), "model");
  }
}

}  // namespace
}  // namespace stickslip
