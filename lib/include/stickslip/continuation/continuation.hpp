// Pseudo-arclength continuation (Keller) of any smooth problem F(u) = 0, F: R^(n+1) -> R^n with
// its Jacobian, one of whose unknowns is the continuation parameter lambda. It knows nothing of
// friction: the orbit problem is one NonlinearSystem among possible others.
//
//   Continuation cont(problem, &monitor, options, start);
//   while (cont.Step()) { observe(cont.branch().points.back()); }   // or: cont.Run()
//
// Tangent predictor from the bordered Jacobian [J; t_prev^T] t = e, Newton corrector on
// [F(u); t.(u - u_pred)] = 0, orientation kept across folds (t.t_prev > 0), adaptive step size
// (step_size.hpp). Special points are detected by a sign change of a test function between two
// accepted points and located on the branch itself by a bracketing root finder in arclength
// (TOMS 748; bisection for the sign of a determinant): LP (fold: the lambda component of the
// tangent), BP (branch point: the sign of det [J; t^T]), UZ (user values), EP (ends), and every
// test function of the Monitor. A terminal test function ends the branch where it leaves its
// positive side; one exactly zero at the start (a start on a type boundary) ends it there if the
// first step makes it negative. A closed branch (an isola, a loop) ends where it comes back to its
// start (BranchEnd::kClosedLoop), with the start repeated as its last point.
#pragma once

#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "stickslip/continuation/monitor.hpp"
#include "stickslip/continuation/step_size.hpp"
#include "stickslip/invalid_input.hpp"
#include "stickslip/numerics/newton.hpp"
#include "stickslip/progress.hpp"

namespace stickslip {

// UZ: a user value of any unknown.
struct UserValue {
  int index = 0;       // which unknown
  double value = 0.0;
  std::string name;    // for the report, e.g. "omega=0.6"
};

// EP: a bound on an unknown other than lambda (a curve in two parameters ends where its released
// second parameter leaves a rectangle). Each finite side is a terminal test function, located on
// the branch as the parameter bounds are; the branch ends there (BranchEnd::kParameterBound) with
// the message "reached <name> = <value>" (the value to 10 significant digits). A start already
// outside the bound is not stopped by it.
struct UnknownBound {
  int index = 0;  // which unknown (not parameter_index: lambda_min and lambda_max bound that)
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  std::string name;  // for the special point and the message, e.g. "u_r"
};

// Where special points are located on the branch, and how hard the corrector tries there.
struct EventLocationOptions {
  double tolerance = 1e-11;       // final arclength bracket of a located special point
  // Corrector iterations (at least) at a trial point: near a singular point (a branch point)
  // Newton converges slowly, and a trial point cannot shrink its step as a step can.
  int corrector_iterations = 50;
  int max_iterations = 100;       // of the bracketing root finder (TOMS 748)
  // Events less than this many `tolerance`s apart in arclength are one point (a fold where a
  // stop degenerates, say), reported in a fixed order whatever the step size.
  double same_point = 10.0;
  // A fold function (the lambda component of the tangent) whose values on both sides are below
  // this is rounding noise around zero, where the branch runs at constant lambda: no fold.
  double fold_noise = 1e-8;
};

// A closed branch: once the branch has been away from its start, a step whose chord passes the
// start again, heading the way the branch left it, closes the loop. The last step is then taken
// onto the start (special points on the way located as on any step), and the branch ends there
// (BranchEnd::kClosedLoop) instead of going round again until max_points. Distances are the
// engine's: the Euclidean norm of the unknowns, as the arclength is measured.
struct ClosedLoopOptions {
  bool detect = true;
  // The start's distance from the step's chord, as a fraction of the step's length, below which
  // the step passes the start. The chord strays from a branch of curvature k by about k ds^2 / 8,
  // a fraction k ds / 8 of the step; a branch crossing the start (a branch point there) is told
  // apart by its direction (`alignment`).
  double tolerance = 0.1;
  // The cosine of the angle between the step's chord and the start's tangent, at least.
  double alignment = 0.9;
  // Only looked for once a point of the branch lay farther from the start than this many of the
  // longest step so far (the first steps pass the start: they leave it).
  double departure = 3.0;
  // The step retaken onto the start must land within this of it, relative to 1 + |start|; else
  // the branch passed near the start without returning to it (another sheet) and goes on.
  double landing = 1e-8;

  void Validate() const;  // throws InvalidInput naming the first field out of range
};

struct ContinuationOptions {
  int parameter_index = -1;  // the unknown that is lambda; required
  int direction = 1;         // +1: start towards increasing lambda, -1: decreasing
  // lambda's name in the end messages ("reached omega = 0.2"), e.g. the continued parameter's.
  std::string parameter_name = "lambda";
  double lambda_min = -std::numeric_limits<double>::infinity();  // the branch ends at these
  double lambda_max = std::numeric_limits<double>::infinity();   // bounds (located, EP)
  // Why a bound lies where it does, where it is not the range asked for ("F_k <= F_s = 0.4"):
  // the end message at that bound says it ("reached F_k = 0.4 (F_k <= F_s = 0.4)").
  std::string lambda_min_reason;
  std::string lambda_max_reason;
  int max_points = 2000;     // accepted points, the start included
  StepSizeOptions step;
  NewtonOptions corrector = [] {
    NewtonOptions o;
    o.max_iterations = 10;
    o.estimate_condition = false;
    return o;
  }();
  // Corrector iterations (at least) for the start, which may be a rough guess of a point.
  int start_iterations = 30;
  // Branch switching (continuation/branch_switching.hpp): a start on a branch point, where the
  // Jacobian at fixed lambda is singular, left along this direction (any length, either sign). The
  // first point of the branch is then the start corrected on the hyperplane
  // start_direction.(u - start) = step.ds, and the branch goes on the way the direction points
  // (`direction` is not used). Empty: the start is corrected at its lambda and heads towards
  // `direction`.
  Eigen::VectorXd start_direction;
  // A corrected point within this distance of a parameter bound, relative to 1 + |bound|, is
  // moved onto the bound (the corrector keeps lambda there only to second order in the step).
  double bound_tolerance = 1e-10;
  // A terminal test function within this of zero at the corrected start counts as zero there: a
  // start on a boundary (a type change, where a segment has zero length) is corrected only to
  // rounding, and a value of -1e-16 is no side of it.
  double start_boundary_tolerance = 1e-9;
  bool detect_folds = true;
  bool detect_branch_points = true;
  std::vector<UserValue> user_values;
  std::vector<UnknownBound> unknown_bounds;  // none by default
  // By default the branch ends at the first terminal test function leaving its positive side;
  // with this set it goes on, and such sign changes are special points like any other.
  bool continue_past_terminal = false;
  EventLocationOptions location;
  ClosedLoopOptions closed_loop;
  // Called after every accepted point (the start included) with done = the points so far, total
  // = max_points (an upper bound: most branches end earlier, at a bound or an event), unit
  // "points" and value = lambda. Empty: no reports.
  ProgressCallback progress = {};

  // Throws InvalidInput naming the first field out of its valid range (parameter_index is
  // checked against the problem by Continuation).
  void Validate() const;
};

enum class BranchEnd {
  kRunning,
  kMaxPoints,
  kParameterBound,
  kStepTooSmall,
  kTerminalEvent,
  kStartFailed,
  kStartOutsideRange,  // the start lies outside [lambda_min, lambda_max]: a branch of one point
  kFoldAtStart,  // the start is a fold and the branch runs only against the asked direction
  kClosedLoop,   // the branch came back to its start (ClosedLoopOptions): a closed branch
  kStopped,      // ended by its caller between two steps (a trace at a resonance: branches/trace.hpp)
};
const char* ToString(BranchEnd end);

struct BranchPoint {
  Eigen::VectorXd u;         // every unknown, lambda included
  double lambda = 0.0;
  double ds = 0.0;           // the step that reached it (0 for the start and located points)
  int newton_iterations = 0;
  Eigen::VectorXd tests;     // the monitor's test functions
  Eigen::VectorXd recorded;  // the monitor's recorded values
  Eigen::VectorXd tangent;   // unit tangent, oriented along the branch
  std::string label;         // special-point type, "" for a regular point
};

struct SpecialPoint {
  std::string type;           // "LP", "BP", "UZ", "EP" or a monitor type ("GR", ...)
  std::string test_function;  // which function changed sign, or why the branch ended
  int point = 0;              // index into Branch::points
  double lambda = 0.0;
  Eigen::VectorXd u;
  Eigen::VectorXd tests;
  double test_value = 0.0;    // the function that changed sign, at the located point
  bool located = true;        // false if the corrector failed inside the bracket
  double bracket = 0.0;       // final arclength bracket width
  // The unit tangent there, oriented along the branch: a later branch can start from the point
  // in a chosen direction.
  Eigen::VectorXd tangent;
};

struct Branch {
  std::vector<BranchPoint> points;
  std::vector<SpecialPoint> special_points;
  std::vector<TestFunctionInfo> test_functions;  // the monitor's
  std::vector<std::string> recorded;             // the names of the monitor's recorded values
  BranchEnd end = BranchEnd::kRunning;
  std::string end_message;
};

class Continuation {
 public:
  // `monitor` may be null. `start` need not lie exactly on the branch: it is corrected at its
  // lambda first. `step_size` chooses the steps; null means StepSizeController::Create(
  // options.step). Throws InvalidInput on invalid options, std::invalid_argument on sizes that
  // do not fit the problem.
  Continuation(const NonlinearSystem& problem, const Monitor* monitor, ContinuationOptions options,
               Eigen::VectorXd start, std::unique_ptr<StepSizeController> step_size = nullptr);
  ~Continuation();

  // Computes the next accepted point (the corrected start on the first call), with every
  // special point located on the way. Returns false once the branch has ended.
  bool Step();
  Branch Run();
  const Branch& branch() const { return branch_; }

 private:
  struct State;
  // The parts of Step, in order; each returns false once the branch has ended.
  bool Start();              // the corrected start, the first point
  bool PredictAndCorrect();  // the next point, the step shortened until the corrector converges
  bool HeadsTheAskedWay();  // from a start on a fold, where the first step shows the way
  bool LeavesTheStartOnThePositiveSides();  // of the terminal functions that are zero at the start
  bool RecordEvents();       // the special points between the last point and the next, located
  bool ClosesTheLoop();      // if the step passes the start again, the step onto the start instead
  bool Accept();             // the next point becomes the last; the next step size
  bool End(BranchEnd why, std::string message);  // returns false
  void Report() const;       // the progress callback, if any, at the last point

  std::unique_ptr<State> state_;
  Branch branch_;
};

}  // namespace stickslip
