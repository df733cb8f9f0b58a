// Executing a run file: the continuation setup it describes (presets, restart from a labelled
// point of earlier results, choice of unknowns). The files a run produces are result_files.hpp's.
#pragma once

#include <filesystem>

#include "stickslip/branches/orbit_continuation.hpp"
#include "stickslip/io/run_file.hpp"

namespace stickslip {

// The run file's [continuation] keys as the engine's options: direction, range, steps, max_points,
// the detections and continue_past_type_changes (user values are MakeSetup's: they address the
// unknowns).
void SetContinuationOptions(const RunFile& run, ContinuationOptions* options);

// The setup a run file describes. Throws RunFileError naming the file, line and key.
OrbitContinuationSetup MakeSetup(const RunFile& run, const std::filesystem::path& results_root);

}  // namespace stickslip
