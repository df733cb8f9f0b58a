// stickslip export --auto: a run's results as AUTO-07p's b., s. and d. files.
#include <filesystem>
#include <memory>
#include <string>
#include <system_error>

#include <fmt/format.h>

#include "cli_common.hpp"
#include "commands.hpp"
#include "stickslip/io/atomic_file.hpp"
#include "stickslip/io/auto_export.hpp"
#include "stickslip/invalid_input.hpp"

namespace stickslip::cli {

namespace {

struct ExportArgs {
  std::string directory;
  bool auto07p = false;
  int samples = 101;
  bool force = false;
};

// AUTO's files have no room for a mark of who wrote them, so an existing b., s. or d. file (an
// earlier export, or the user's own) is replaced only with --force; a link at one of those names
// (its target outside the run) never is: the export writes into the run's directory only.
void CheckReplaceable(const std::filesystem::path& file, bool force) {
  std::error_code error;
  if (std::filesystem::is_symlink(file, error)) {
    throw InvalidInput::WithMessage(
        "directory", fmt::format("'{}' is a link: the export writes only into the run's directory (remove the link)",
                                 file.string()));
  }
  if (std::filesystem::exists(file, error) && !force) {
    throw InvalidInput::WithMessage(
        "directory", fmt::format("'{}' exists: an export replaces it only with --force (it may be the user's)",
                                 file.string()));
  }
}

int RunExport(const ExportArgs& args) {
  namespace fs = std::filesystem;
  if (!args.auto07p) throw InvalidInput::WithMessage("format", "format is missing: valid --auto");
  if (args.directory.empty()) {
    throw InvalidInput::WithMessage("directory", "directory = '' is invalid: it is empty: valid results/<run>/ of a run");
  }
  const fs::path dir(args.directory);
  CheckHoldsRun(dir, "directory", fmt::format("{}, or one branch-<k>/ of a trace's directory", kRunDirectory));
  if (args.samples < 2 || args.samples > 100000) {
    throw InvalidInput("samples", args.samples, "2 <= samples <= 100000");
  }
  const std::string run = fs::absolute(dir).lexically_normal().filename().string().empty()
                              ? fs::absolute(dir).lexically_normal().parent_path().filename().string()
                              : fs::absolute(dir).lexically_normal().filename().string();
  constexpr const char* kPrefixes[] = {"b.", "s.", "d."};
  for (const char* prefix : kPrefixes) {
    try {
      CheckOutputFile(dir / (prefix + run), prefix + run);
    } catch (const InvalidInput& e) {
      throw InvalidInput::WithMessage("directory",
                                      fmt::format("directory = '{}' cannot hold the export: {}", dir.string(), e.what()));
    }
  }
  for (const char* prefix : kPrefixes) CheckReplaceable(dir / (prefix + run), args.force);
  const AutoFiles files = ExportAuto(dir, args.samples);  // after the checks: no work for nothing
  // All or none: AUTO reads b., s. and d. together (load(run)), so some of one export beside the rest
  // of another would mislead it.
  WriteFilesAtomically({{dir / ("b." + run), files.b}, {dir / ("s." + run), files.s}, {dir / ("d." + run), files.d}});
  fmt::print("wrote {}, {} and {}\n", (dir / ("b." + run)).string(), (dir / ("s." + run)).string(),
             (dir / ("d." + run)).string());
  return kExitOk;
}

}  // namespace

Command AddExportCommand(CLI::App& app) {
  auto args = std::make_shared<ExportArgs>();
  CLI::App* cmd = app.add_subcommand(
      "export",
      "Export a run's results (results/<run>/) as AUTO-07p's b.<run> (with the measures as columns), s.<run> and "
      "d.<run> (Newton iterations, step, multipliers per point) files, beside them; all three or none.");
  cmd->add_option("directory", args->directory, "results/<run>/ of a continuation run")->required();
  cmd->add_flag("--auto", args->auto07p, "AUTO-07p's bifurcation (b.), solution (s.) and diagnostics (d.) files");
  AddCountOption(*cmd, "--samples", &args->samples, 2, 100000, "orbit samples per labelled solution (2 to 1e5)");
  cmd->add_flag("--force", args->force,
                "replace existing b., s. and d. files (an earlier export, or the user's); without it an existing "
                "one is kept and export exits 2. A link at those names is never written through");
  return {cmd, [args] { return RunExport(*args); }};
}

}  // namespace stickslip::cli
