// atlas for a run file's [model] (model_table.hpp), as every front end runs it: the options of
// `stickslip atlas` (AtlasCommand, command_options.hpp) read for the model's atlas
// (analysis/model_atlas.hpp) and checked before any work, and the atlas stored as the paper's is
// (atlas_files.hpp), its run file the file, or "(command line)" where `set` changed what it gives.
//
//   const ModelFileStart start = ReadModelFileStart("belt-damped.toml", {});
//   const ModelAtlasOptions options = ModelAtlasOptionsOf(command, start);
//   WriteAtlasFiles("results", StoredModelAtlas(ComputeModelAtlas(start.model, start.parameters, options),
//                                               options, start, "belt-damped.toml", {}, "belt-atlas"));
#pragma once

#include <filesystem>
#include <string>

#include "stickslip/analysis/model_atlas.hpp"
#include "stickslip/io/atlas_files.hpp"
#include "stickslip/io/command_options.hpp"
#include "stickslip/io/model_file_start.hpp"
#include "stickslip/named_values.hpp"

namespace stickslip {

// The command's options for the model's atlas, its brute force's as ModelBruteForceOptionsOf
// (model_map.hpp) reads them. Throws InvalidInput naming the flag (ModelAtlasOptions::Validate,
// WholeNumber), before any simulation.
ModelAtlasOptions ModelAtlasOptionsOf(const AtlasCommand& command, const ModelFileStart& start);

// The atlas's files (RecordModelAtlas) with the slip's natural frequencies (the start's) in every
// trace; its run file `run_file`, or "(command line)" where `set` changed what it gives.
StoredAtlas StoredModelAtlas(const ModelAtlas& atlas, const ModelAtlasOptions& options, const ModelFileStart& start,
                             const std::filesystem::path& run_file, const NamedValues& set, const std::string& output);

}  // namespace stickslip
