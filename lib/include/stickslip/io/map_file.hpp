// The brute-force map's file (analysis/brute_force_map.hpp, and a model's:
// analysis/model_brute_force_map.hpp): one writer, one reader, and the merge of shards. A CSV
// table, one row per section point of each attractor of each cell:
//
//   i,j,ni,nj,<first>,<second>,section_phase,run,attractors,attractor,status,period,stops_per_period,
//   sticks_per_period,starts,signature,k,x1,x2,v1,v2                  (the paper's model)
//   ...,starts,amplitude:<q_c>,k,<the state by the model's names>     (a model of the user's)
//
// i, j the cell (ni, nj cells along each axis); <first>, <second> the two parameters' names and
// their values in the cell; run the map's fingerprint (16 hexadecimal digits, MapRunFingerprint:
// the same in the shards of one map); attractors the number found in the cell, attractor its
// index (from 0); status periodic, not-settled or incomplete; starts the runs that ended on it; signature its
// orbit type (empty if none was read); k = 0..period-1 its section points (one row, k = 0, the
// last state, when not periodic). Numbers in shortest round-trip form, so a file read and written
// again is the same bytes, and the file does not depend on threads, shards or ranks.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "stickslip/analysis/brute_force_map.hpp"

namespace stickslip {

struct ModelBruteForceMap;  // analysis/model_brute_force_map.hpp

std::string BruteForceMapCsv(const BruteForceMap& map);
std::string BruteForceMapCsv(const ModelBruteForceMap& map);
// Whether `line` is a header BruteForceMapCsv writes (for any model and two parameters): the mark
// of a file that map-sweep may replace.
bool IsBruteForceMapCsvHeader(std::string_view line);
// Whether `text` starts with a model's map header (else it is taken as the paper's model's).
bool IsModelBruteForceMapCsv(std::string_view text);

// The map of a file written by BruteForceMapCsv; `name` (the file's path) starts every message.
// Throws InvalidInput naming the file, the line and the column of the first problem.
BruteForceMap ReadBruteForceMapCsv(std::string_view text, const std::string& name);
// A model's map: its parameters, contact and state columns by the header's names; their values
// finite (the model's ranges are checked where its run file is read).
ModelBruteForceMap ReadModelBruteForceMapCsv(std::string_view text, const std::string& name);
// Reads `text` as the map file of its kind (IsModelBruteForceMapCsv), throwing as its reader does.
void CheckBruteForceMapCsv(std::string_view text, const std::string& name);

// The shards of one map (computed with shard = 1..N of N, in any order) as the one map: every cell
// once, by j then i. Throws InvalidInput naming "merge" when the shards are of different grids
// (parameters, cell counts, values or section phase) or runs (the run fingerprint) or a cell is missing or in two shards; the
// message names the shard (`names[s]` for shards[s]) and the cell.
BruteForceMap MergeBruteForceMaps(const std::vector<BruteForceMap>& shards, const std::vector<std::string>& names);
ModelBruteForceMap MergeBruteForceMaps(const std::vector<ModelBruteForceMap>& shards, const std::vector<std::string>& names);

}  // namespace stickslip
