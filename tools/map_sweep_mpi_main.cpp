// stickslip-mpi map-sweep: the brute-force map across the ranks of an MPI job, with the options
// of `stickslip map-sweep` but --shard and --merge (the ranks split the rows). Rank r computes the
// rows j with j mod N = r (the shards of stickslip's --shard, each rank on --threads threads); rank 0 gathers the ranks' maps, merges them as --merge does and
// writes the file whole: the same bytes as one process writes, for any number of ranks. MPI stays
// here: the library knows nothing of it.
//
//   mpirun -np 4 stickslip-mpi map-sweep --preset paper-6 --first omega ... --output map.csv
//   mpirun -np 4 stickslip-mpi map-sweep --model chain.toml --first omega --second F_s ... --output map.csv
//   (as root: mpirun --allow-run-as-root; more ranks than cores: --oversubscribe)
#include <mpi.h>

#include <algorithm>
#include <exception>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "cli_common.hpp"
#include "map_sweep_command.hpp"
#include "progress_line.hpp"
#include "stickslip/invalid_input.hpp"
#include "stickslip/io/atomic_file.hpp"
#include "stickslip/io/command_options.hpp"

namespace stickslip::cli {
namespace {

constexpr int kChunk = 1 << 30;  // bytes per message (MPI counts are int)

void SendText(const std::string& text, int to) {
  const unsigned long long size = text.size();
  MPI_Send(&size, 1, MPI_UNSIGNED_LONG_LONG, to, 0, MPI_COMM_WORLD);
  for (std::size_t at = 0; at < text.size(); at += kChunk) {
    const int count = static_cast<int>(std::min<std::size_t>(kChunk, text.size() - at));
    MPI_Send(text.data() + at, count, MPI_CHAR, to, 1, MPI_COMM_WORLD);
  }
}

std::string ReceiveText(int from) {
  unsigned long long size = 0;
  MPI_Recv(&size, 1, MPI_UNSIGNED_LONG_LONG, from, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  std::string text(size, '\0');
  for (std::size_t at = 0; at < text.size(); at += kChunk) {
    const int count = static_cast<int>(std::min<std::size_t>(kChunk, text.size() - at));
    MPI_Recv(text.data() + at, count, MPI_CHAR, from, 1, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  }
  return text;
}

int RunAcrossRanks(const MapSweepPlan& plan, int rank, int ranks) {
  // Checked on rank 0, which writes; every rank learns the outcome.
  std::string refused;
  if (rank == 0) {
    try {
      CheckMapOutputFile(plan.output, "output", plan.force);
    } catch (const InvalidInput& e) {
      refused = e.what();
    }
  }
  int ok = refused.empty() ? 1 : 0;
  MPI_Allreduce(MPI_IN_PLACE, &ok, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
  if (!ok) {
    if (rank == 0) fmt::print(stderr, "error: {}\n", refused);
    return kExitBadInput;
  }
  ProgressLine line("map-sweep (rank 0)");
  const MapFile mine = plan.compute(rank + 1, ranks, rank == 0 ? line.Callback() : ProgressCallback{});
  line.Clear();
  if (rank != 0) {
    SendText(mine.text, 0);
    return kExitOk;
  }
  std::vector<std::string> texts = {mine.text};
  std::vector<std::string> names = {"rank 0"};
  for (int r = 1; r < ranks; ++r) {
    names.push_back(fmt::format("rank {}", r));
    texts.push_back(ReceiveText(r));
  }
  const MapFile merged = MergeMapFiles(texts, names, plan.output);
  WriteFileAtomically(plan.output, merged.text);
  fmt::print("{} rank(s): {}", ranks, merged.summary);
  return kExitOk;
}

}  // namespace
}  // namespace stickslip::cli

int main(int argc, char** argv) {
  using namespace stickslip::cli;
  MPI_Init(&argc, &argv);
  int rank = 0, ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  CLI::App app(
      "stickslip-mpi: the brute-force map of stickslip map-sweep across the ranks of an MPI job; rank 0 writes "
      "the file, the same bytes for any number of ranks and threads. Exit codes: 0 success, 1 failure, 2 bad "
      "input (nothing written).",
      "stickslip-mpi");
  app.require_subcommand(1);
  // A flag takes no value (--force=2 is bad input, not a count), as in stickslip.
  app.option_defaults()->disable_flag_override();
  const Command command =
      AddMapSweepCommand(app, [rank, ranks](const MapSweepPlan& plan) { return RunAcrossRanks(plan, rank, ranks); },
                         /*shards=*/false, ranks);
  int code = kExitFailure;
  try {
    app.parse(argc, argv);
    code = command.run();
  } catch (const CLI::CallForHelp& e) {
    code = rank == 0 ? app.exit(e) : 0;
  } catch (const CLI::ParseError& e) {
    if (rank == 0) fmt::print(stderr, "error: {}\n", e.what());
    code = kExitBadInput;
  } catch (const stickslip::InvalidInput& e) {  // the same on every rank: the options are the same
    if (rank == 0) fmt::print(stderr, "error: {}\n", stickslip::OnCommandLine(e).what());
    code = kExitBadInput;
  } catch (const std::exception& e) {  // this rank only: the others may wait for it
    fmt::print(stderr, "error: rank {}: {}\n", rank, e.what());
    MPI_Abort(MPI_COMM_WORLD, kExitFailure);
  }
  MPI_Finalize();
  return code;
}
