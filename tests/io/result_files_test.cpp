// The result files' one reader and one writer: every stored run reads and writes back to the same
// bytes, a row means what its columns say, and a damaged file is an error naming the file, the
// line and the column, never a crash.
#include "stickslip/io/result_files.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "stickslip/invalid_input.hpp"
#include "stickslip/orbits/orbit_measures.hpp"

#include "support/file_text.hpp"

namespace stickslip {
namespace {

namespace fs = std::filesystem;

const fs::path kResults = fs::path(STICKSLIP_SOURCE_DIR) / "results";
const fs::path kRun = kResults / "paper-5.1-omega-up";

RunFiles StoredTexts(const fs::path& dir) {
  return {Slurp(dir / "branch.csv"), Slurp(dir / "special-points.csv"), Slurp(dir / "summary.json")};
}

std::vector<fs::path> StoredRuns() {
  std::vector<fs::path> runs;
  for (const auto& entry : fs::directory_iterator(kResults)) {
    if (fs::exists(entry.path() / "summary.json")) runs.push_back(entry.path());
  }
  std::sort(runs.begin(), runs.end());
  return runs;
}

TEST(ResultFiles, ReadingThenWritingEveryStoredRunGivesItsBytes) {
  const std::vector<fs::path> runs = StoredRuns();
  ASSERT_GE(runs.size(), 19u);
  for (const fs::path& dir : runs) {
    SCOPED_TRACE(dir.string());
    const RunFiles stored = StoredTexts(dir);
    const RunFiles written = FormatRunFiles(ReadRunFiles(dir));
    EXPECT_EQ(written.branch_csv, stored.branch_csv);
    EXPECT_EQ(written.special_points_csv, stored.special_points_csv);
    EXPECT_EQ(written.summary_json, stored.summary_json);
  }
}

// The measure columns of every stored row are those of the row's own orbit, to the last bit: the
// monitor computed them from the orbit the row stores.
TEST(ResultFiles, EveryStoredRowCarriesTheMeasuresOfItsOwnOrbit) {
  for (const fs::path& dir : StoredRuns()) {
    SCOPED_TRACE(dir.string());
    const StoredRun run = ReadRunFiles(dir);
    std::vector<const StoredPoint*> points;
    for (const StoredPoint& p : run.branch) points.push_back(&p);
    for (const StoredSpecialPoint& s : run.special_points) points.push_back(&s.point);
    for (const StoredPoint* p : points) {
      const OrbitMeasures m = Measure(OrbitOf(run, *p));
      orbit_columns::ForEachMeasure(m, [&](const char* name, const auto& value) {
        const double expected = static_cast<double>(value);
        if (std::isnan(expected)) {
          EXPECT_TRUE(std::isnan(Named(p->measures, name))) << p->pt << " " << name;
        } else {
          EXPECT_EQ(Named(p->measures, name), expected) << p->pt << " " << name;
        }
      });
    }
  }
}

// The tables write a non-finite number as fmt does (inf, -inf, nan), the form numpy, pandas and
// Python's float() read, and their reader takes it back; summary.json holds no such number.
TEST(ResultFiles, NonFiniteNumbersInTheTablesRoundTrip) {
  StoredRun run = ReadRunFiles(kResults / "paper-5.1-omega-up");
  const double inf = std::numeric_limits<double>::infinity();
  run.branch[1].margins[0].second = inf;
  run.branch[1].margins[1].second = std::numeric_limits<double>::quiet_NaN();
  run.branch[1].fold_test = std::numeric_limits<double>::quiet_NaN();
  const RunFiles files = FormatRunFiles(run);
  EXPECT_NE(files.branch_csv.find(",inf,nan,"), std::string::npos);
  const StoredRun back = ParseRunFiles(files, kResults / "paper-5.1-omega-up");
  EXPECT_EQ(back.branch[1].margins[0].second, inf);
  EXPECT_TRUE(std::isnan(back.branch[1].margins[1].second));
  EXPECT_TRUE(std::isnan(back.branch[1].fold_test));
  EXPECT_EQ(FormatRunFiles(back).branch_csv, files.branch_csv);
}

// The first row of paper-5.1-omega-up/branch.csv, field by field (the values are the file's text).
TEST(ResultFiles, ReaderGivesEachColumnItsMeaning) {
  const StoredRun run = ReadRunFiles(kRun);
  EXPECT_EQ(run.summary.signature, "slip- slip+ stick slip+");
  EXPECT_EQ(run.summary.parameter, "omega");
  EXPECT_EQ(run.summary.termination, "terminal-event");
  ASSERT_EQ(run.branch.size(), 106u);
  const StoredPoint& p = run.branch.front();
  EXPECT_EQ(p.pt, 1);
  EXPECT_EQ(p.label, "EP1");
  const Orbit orbit = OrbitOf(run, p);
  EXPECT_EQ(orbit.parameters.omega, 0.5711986642890533);
  EXPECT_EQ(orbit.parameters.u_r, 0.4962);
  EXPECT_EQ(orbit.phi, 0.31766724083352016);
  EXPECT_EQ(orbit.v10, -0.2579458242291443);
  ASSERT_EQ(orbit.durations.size(), 4u);
  EXPECT_EQ(orbit.durations[3], 2.9998603518755917);
  // Four listed segments give 4 margins for each slip, 4 for the stick and sliding-friction.
  ASSERT_EQ(p.margins.size(), 17u);
  EXPECT_EQ(p.margins.front().first, "duration:1");
  EXPECT_EQ(p.margins.front().second, orbit.durations[0]);  // a duration margin is the duration
  EXPECT_EQ(p.margins[1].first, "velocity:1");
  EXPECT_EQ(p.margins[1].second, std::numeric_limits<double>::infinity());
  EXPECT_EQ(p.margins.back().first, "sliding-friction");
  EXPECT_EQ(p.margins.back().second, orbit.parameters.u_s);
  ASSERT_EQ(p.multipliers.size(), 4u);
  EXPECT_EQ(p.multipliers[0], std::complex<double>(0.7027261158856764, 0.794660591714117));
  EXPECT_EQ(p.multipliers[1], std::conj(p.multipliers[0]));
  EXPECT_FALSE(p.stable);  // |mu1| = 1.06
  EXPECT_EQ(p.flip_test, 5.191639239866712);
  EXPECT_TRUE(p.admissible);
  // The measures are those of the row's own orbit, to the last bit; per period 3 stops, 1 stick.
  const OrbitMeasures m = Measure(orbit);
  EXPECT_EQ(Named(p.measures, "amplitude:x1"), m.amplitude_x1);
  EXPECT_EQ(Named(p.measures, "amplitude:x2"), m.amplitude_x2);
  EXPECT_EQ(Named(p.measures, "peak-to-peak:x2"), m.peak_to_peak_x2);
  EXPECT_EQ(Named(p.measures, "stick-fraction"), m.stick_fraction);
  EXPECT_EQ(Named(p.measures, "stops"), 3);
  EXPECT_EQ(Named(p.measures, "sticks"), 1);
  EXPECT_EQ(p.newton_iterations, 2);
  EXPECT_EQ(p.step_size, 0.0);
  EXPECT_EQ(run.branch[1].step_size, 0.005);

  ASSERT_EQ(run.special_points.size(), 7u);
  const StoredSpecialPoint& fold = run.special_points[3];
  EXPECT_EQ(fold.type, "LP");
  EXPECT_EQ(fold.point.label, "LP4");
  EXPECT_EQ(fold.point.pt, 48);
  EXPECT_EQ(fold.test_function, "tangent:lambda");
  EXPECT_TRUE(fold.located);
  EXPECT_EQ(Named(fold.point.solution, "omega"), 0.5868188660921189);
}

TEST(ResultFiles, LabelledPointGivesTheOrbitVariablesOfTheSpecialPoint) {
  const LabelledPoint point = ReadLabelledPoint(kResults, "paper-5.1-omega-up", "LP4");
  EXPECT_EQ(point.signature, "slip- slip+ stick slip+");
  EXPECT_EQ(point.type, "LP");
  EXPECT_EQ(point.test_function, "tangent:lambda");
  ASSERT_EQ(point.variables.size(), 13u);  // 5 parameters, phi, x10, x20, v10, 4 durations
  EXPECT_EQ(point.variables[2], std::make_pair(std::string("omega"), 0.5868188660921189));
  EXPECT_EQ(point.variables.back().first, "d4");
}

// Issue 11: a branch ending at a located fold wrote two rows "LP3" (the fold, then the end's EP).
TEST(ResultFiles, EverySpecialPointOfAStoredRunHasALabelOfItsOwn) {
  int runs = 0;
  for (const fs::directory_entry& entry : fs::directory_iterator(kResults)) {
    if (!fs::exists(entry.path() / "summary.json")) continue;
    ++runs;
    const StoredRun run = ReadRunFiles(entry.path());
    std::vector<std::string> labels;
    for (const StoredSpecialPoint& s : run.special_points) {
      EXPECT_EQ(std::count(labels.begin(), labels.end(), s.point.label), 0)
          << entry.path().filename() << ": " << s.point.label << " twice";
      labels.push_back(s.point.label);
      EXPECT_TRUE(s.point.label.starts_with(s.type)) << entry.path().filename() << ": " << s.point.label << " is a " << s.type;
    }
  }
  EXPECT_GE(runs, 19);
}

TEST(ResultFiles, TheEndAtALocatedFoldIsAnEndPointWithTheNextLabel) {
  const StoredRun run = ReadRunFiles(kResults / "paper-5.2-omega-up");
  ASSERT_GE(run.special_points.size(), 2u);
  const StoredSpecialPoint& fold = run.special_points[run.special_points.size() - 2];
  const StoredSpecialPoint& end = run.special_points.back();
  EXPECT_EQ(fold.point.label, "LP3");
  EXPECT_EQ(end.type, "EP");
  EXPECT_EQ(end.point.label, "EP4");
  EXPECT_EQ(end.point.pt, fold.point.pt);
  EXPECT_EQ(ReadLabelledPoint(kResults, "paper-5.2-omega-up", "EP4").variables,
            ReadLabelledPoint(kResults, "paper-5.2-omega-up", "LP3").variables);
}

// ---- Damaged files: each is one InvalidInput whose message names where.

// The message of the InvalidInput that parsing `files` throws ("" if none is thrown).
std::string ParseError(const RunFiles& files) {
  try {
    ParseRunFiles(files, "stored");
  } catch (const InvalidInput& e) {
    return e.what();
  }
  return "";
}

// `text` with line `line` (1-based) replaced by what `edit` makes of it.
template <typename Edit>
std::string EditLine(const std::string& text, int line, Edit edit) {
  std::istringstream in(text);
  std::string out, l;
  for (int k = 1; std::getline(in, l); ++k) out += (k == line ? edit(l) : l) + "\n";
  return out;
}

std::vector<std::string> Fields(const std::string& line) {
  std::vector<std::string> fields;
  std::istringstream in(line);
  for (std::string f; std::getline(in, f, ',');) fields.push_back(f);
  return fields;
}

std::string Join(const std::vector<std::string>& fields) {
  std::string line;
  for (const std::string& f : fields) line += (line.empty() ? "" : ",") + f;
  return line;
}

TEST(ResultFiles, RowShorterThanItsHeaderNamesFileAndLine) {
  RunFiles files = StoredTexts(kRun);
  files.branch_csv = EditLine(files.branch_csv, 3, [](std::string l) { return l.substr(0, l.rfind(',')); });
  EXPECT_EQ(ParseError(files), "stored/branch.csv:3: the row has 55 fields, the header 56: valid one field per column");
}

TEST(ResultFiles, MissingColumnNamesFileAndColumn) {
  RunFiles files = StoredTexts(kRun);
  const int omega = 4;  // pt, label, chi, eta, omega
  for (int line = 1; line <= 8; ++line) {
    files.special_points_csv = EditLine(files.special_points_csv, line, [&](const std::string& l) {
      std::vector<std::string> fields = Fields(l);
      fields.erase(fields.begin() + omega);
      return Join(fields);
    });
  }
  EXPECT_EQ(ParseError(files), "stored/special-points.csv:1: column 'omega' is missing");
}

// A run stored before the measure columns existed is refused by name (run it again to regenerate).
// `table` without `count` columns from the one named `first` (the header's), on its `lines` lines.
std::string WithoutColumns(const std::string& table, int lines, const std::string& first, int count) {
  const std::vector<std::string> header = Fields(table.substr(0, table.find('\n')));
  const auto at = std::find(header.begin(), header.end(), first) - header.begin();
  auto drop = [&](const std::string& l) {
    std::vector<std::string> fields = Fields(l);
    fields.erase(fields.begin() + at, fields.begin() + at + count);
    return Join(fields);
  };
  std::string edited = table;
  for (int line = 1; line <= lines; ++line) edited = EditLine(edited, line, drop);
  return edited;
}

TEST(ResultFiles, FileWithoutTheMeasureColumnsNamesTheFirstMissing) {
  RunFiles files = StoredTexts(kRun);
  const std::vector<std::string> header = Fields(files.branch_csv.substr(0, files.branch_csv.find('\n')));
  const auto first = std::find(header.begin(), header.end(), "amplitude:x1") - header.begin();
  ASSERT_EQ(header[first + 5], "sticks");
  files.branch_csv = WithoutColumns(files.branch_csv, 107, "amplitude:x1", 6);
  EXPECT_EQ(ParseError(files), "stored/branch.csv:1: column 'amplitude:x1' is missing");
}

// A run stored before friction-work and equivalent-damping existed reads, with them nan, and says
// which it lacks (`check` leaves them out).
TEST(ResultFiles, FileWithoutTheFrictionMeasuresReadsThemAsNaN) {
  RunFiles files = StoredTexts(kRun);
  const std::vector<std::string> header = Fields(files.branch_csv.substr(0, files.branch_csv.find('\n')));
  const auto first = std::find(header.begin(), header.end(), "friction-work") - header.begin();
  ASSERT_EQ(header[first + 1], "equivalent-damping");
  const StoredRun whole = ParseRunFiles(files, "stored");
  files.branch_csv = WithoutColumns(files.branch_csv, 107, "friction-work", 2);
  files.special_points_csv = WithoutColumns(files.special_points_csv, 8, "friction-work", 2);
  const StoredRun old = ParseRunFiles(files, "stored");
  EXPECT_EQ(old.absent_measures, (std::vector<std::string>{"friction-work", "equivalent-damping"}));
  ASSERT_EQ(old.branch.size(), whole.branch.size());
  for (std::size_t i = 0; i < old.branch.size(); ++i) {
    EXPECT_TRUE(std::isnan(Named(old.branch[i].measures, "friction-work")));
    EXPECT_TRUE(std::isnan(Named(old.branch[i].measures, "equivalent-damping")));
    EXPECT_EQ(Named(old.branch[i].measures, "amplitude:x2"), Named(whole.branch[i].measures, "amplitude:x2"));
  }
  EXPECT_TRUE(std::isnan(Named(old.special_points.back().point.measures, "friction-work")));
  // Written again (a re-save), the nan columns read back.
  const RunFiles again = FormatRunFiles(old);
  EXPECT_NE(again.branch_csv.find(",nan,nan,"), std::string::npos);
  EXPECT_TRUE(std::isnan(Named(ParseRunFiles(again, "stored").branch.front().measures, "friction-work")));
  // Both columns or neither, and the same in both tables.
  RunFiles one = StoredTexts(kRun);
  one.branch_csv = WithoutColumns(one.branch_csv, 107, "equivalent-damping", 1);
  EXPECT_EQ(ParseError(one), "stored/branch.csv:1: column 'equivalent-damping' is missing");
  RunFiles mixed = StoredTexts(kRun);
  mixed.branch_csv = WithoutColumns(mixed.branch_csv, 107, "friction-work", 2);
  EXPECT_EQ(ParseError(mixed), "stored/special-points.csv:1: the point columns differ from branch.csv's: valid the same, "
                               "then type, test_function, located");
}

TEST(ResultFiles, CountThatIsNotAWholeNumberNamesLineAndColumn) {
  RunFiles files = StoredTexts(kRun);
  const std::vector<std::string> header = Fields(files.branch_csv.substr(0, files.branch_csv.find('\n')));
  const auto stops = std::find(header.begin(), header.end(), "stops") - header.begin();
  files.branch_csv = EditLine(files.branch_csv, 4, [&](const std::string& l) {
    std::vector<std::string> fields = Fields(l);
    fields[stops] = "3.5";
    return Join(fields);
  });
  EXPECT_EQ(ParseError(files), "stored/branch.csv:4: column 'stops' = '3.5' is not an integer");
}

TEST(ResultFiles, UnknownColumnIsAnError) {
  RunFiles files = StoredTexts(kRun);
  files.branch_csv = EditLine(files.branch_csv, 1, [](const std::string& l) {
    return std::string(l).replace(l.find("margin:G:3"), 10, "margin_G:3");
  });
  EXPECT_EQ(ParseError(files), "stored/branch.csv:1: column 'margin_G:3' is unknown or repeated");
}

TEST(ResultFiles, FieldThatIsNotANumberNamesLineAndColumn) {
  RunFiles files = StoredTexts(kRun);
  files.branch_csv = EditLine(files.branch_csv, 4, [](const std::string& l) {
    std::vector<std::string> fields = Fields(l);
    fields[9] = "4.2x";  // x20
    return Join(fields);
  });
  EXPECT_EQ(ParseError(files), "stored/branch.csv:4: column 'x20' = '4.2x' is not a number");
}

TEST(ResultFiles, FlagOtherThanZeroOrOneIsAnError) {
  RunFiles files = StoredTexts(kRun);
  files.special_points_csv = EditLine(files.special_points_csv, 2, [](const std::string& l) {
    return l.substr(0, l.rfind(',')) + ",yes";
  });
  EXPECT_EQ(ParseError(files), "stored/special-points.csv:2: column 'located' = 'yes' is invalid: valid 0 or 1");
}

TEST(ResultFiles, MissingSummaryKeyNamesTheKey) {
  RunFiles files = StoredTexts(kRun);
  const auto at = files.summary_json.find("  \"signature\"");
  files.summary_json.erase(at, files.summary_json.find('\n', at) + 1 - at);
  EXPECT_EQ(ParseError(files), "stored/summary.json: key 'signature' is missing");
}

TEST(ResultFiles, InvalidJsonNamesLineAndColumn) {
  RunFiles files = StoredTexts(kRun);
  // Line 3 is `  "stickslip_version": "0.1.0",` (31 characters): a second comma is column 32.
  files.summary_json = EditLine(files.summary_json, 3, [](const std::string& l) { return l + ","; });
  const std::string error = ParseError(files);
  EXPECT_TRUE(error.starts_with("stored/summary.json: invalid JSON: parse error at line 3, column 32:")) << error;
}

TEST(ResultFiles, WrongTypeOfSummaryValueIsAnError) {
  RunFiles files = StoredTexts(kRun);
  files.summary_json = EditLine(files.summary_json, 8, [](const std::string&) { return R"(  "points": "106",)"; });
  EXPECT_EQ(ParseError(files), R"(stored/summary.json: key 'points' = "106" is invalid: valid a count (an integer >= 0))");
}

// Units are a [model]'s: the paper's model is scaled (hostile review: a paper run's summary given
// units was read and the units ignored).
TEST(ResultFiles, UnitsInAPaperRunsSummaryAreAnError) {
  RunFiles files = StoredTexts(kRun);
  files.summary_json = EditLine(files.summary_json, 8, [](const std::string& l) { return R"(  "units": {"length": "m"},)" "\n" + l; });
  EXPECT_EQ(ParseError(files), "stored/summary.json: key 'units' is invalid: valid only in a [model]'s run (the paper's model is scaled)");
}

TEST(ResultFiles, SummaryCountsMustMatchTheTables) {
  RunFiles files = StoredTexts(kRun);
  files.branch_csv = EditLine(files.branch_csv, 107, [](const std::string&) { return std::string(); });
  EXPECT_EQ(ParseError(files), "stored/summary.json: key 'points' = 106 differs from the 105 rows of branch.csv");
}

// Two rows with one label: a restart from it would take either (hostile review of the [model]
// restarts: a copied TR2 row was restarted from silently).
TEST(ResultFiles, LabelGivenTwiceIsAnError) {
  RunFiles files = StoredTexts(kRun);
  files.special_points_csv = EditLine(files.special_points_csv, 3, [](const std::string& l) {
    return std::regex_replace(l, std::regex(",TR2,"), ",EP1,");
  });
  EXPECT_EQ(ParseError(files),
            "stored/special-points.csv: key 'label' = 'EP1' (row 3) is invalid: an earlier row has it: valid each "
            "label once");
}

TEST(ResultFiles, UnknownLabelListsTheValidOnes) {
  try {
    ReadLabelledPoint(kResults, "paper-5.1-omega-up", "XX9");
    FAIL() << "no exception";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("valid labels EP1, TR2, UZ3, LP4, UZ5, GR6"), std::string::npos) << e.what();
  }
}

TEST(ResultFiles, MissingRunIsAnErrorNamingTheFile) {
  try {
    ReadRunFiles(kResults / "no-such-run");
    FAIL() << "no exception";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(std::string(e.what()), "cannot read '" + (kResults / "no-such-run" / "branch.csv").string() + "'");
  }
}

}  // namespace
}  // namespace stickslip
