// Export of a run's results to AUTO-07p's bifurcation (b.), solution (s.) and diagnostics (d.)
// files, so that AUTO's own tools (its Python parsers, @pp, PyPLAUT) read stickslip's branches.
//
// b.: one line per branch point, "BR PT TY LAB" and then the continuation parameter, the measures
// (amplitude:x1, amplitude:x2, peak-to-peak:x2, stick-fraction, stops, sticks, friction-work,
// equivalent-damping: branch.csv's names),
// x10, x20, v10, phi, d1..dn; AUTO's default axes (columns 0 and 1) thus draw max |x1| against
// the parameter. PT is negative where the orbit is stable, as AUTO marks it. TY uses AUTO's
// codes: LP 2, BP 1, UZ -4, EP 9, PD 7, TR 8. stickslip's orbit-type changes (GR, T0, S0, NS, SK)
// have no AUTO code and are written as user points (-4); their type stays in special-points.csv.
// s.: for each labelled point, the orbit over one period at `samples` times (t scaled to
// [0, 1], U = x1, x2, x1', x2'), PAR(1..5) = chi, eta, omega, u_s, u_r and PAR(11) = the period;
// for a run file's [model] U = its whole state (sampled by its exact simulator from the stored
// start; the model read from the run file summary.json names), PAR(1..4) = omega, F_k, F_s, v_b.
// Any model's b. columns are the summary's: the parameter, the measures, the start state, phi, d1..dn.
// d.: one block per branch point, as AUTO's parseD reads it: BR, PT, the Newton iterations the
// corrector took (IT; AUTO lists each iteration, stickslip keeps their count), the parameter and
// the step that reached the point (0 at the start and at located points), the Floquet multipliers
// ("Multiplier k re im"), and for a labelled point its TY and LAB.
#pragma once

#include <filesystem>
#include <string>

namespace stickslip {

struct AutoFiles {
  std::string b;
  std::string s;
  std::string d;
};

// Reads results/<run>/ (ReadRunFiles). Throws InvalidInput naming the file, as the reader does.
AutoFiles ExportAuto(const std::filesystem::path& run_directory, int samples = 101);

}  // namespace stickslip
