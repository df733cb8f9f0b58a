// The speed-up of the brute-force map from 1 to 2 MPI ranks: the wall time of the whole command
//   mpirun -np N stickslip-mpi map-sweep --threads 1 ... --output <temporary file>
// (--allow-run-as-root as root, --oversubscribe), that is mpirun's launch of the ranks, MPI_Init,
// the options, the cells, the gather on rank 0, the merge, the file written and MPI_Finalize, for
// N = 1 and 2 on the same grid, measured in one run of this program (tools/benchmark.sh interleaves
// the repetitions at random, so that a load that comes and goes meets both alike). The grid is the
// section 6 map of the continuation benchmark's MapCellsPerCore (omega 0.55 to 0.6, u_r 1.2 to 1.5,
// the command line's defaults: 500 + 24 periods, rest, the neighbour and 4 more starts per cell),
// refined to 24 x 20 cells (480), so that the work is about ten times the launch (about 1 s on 2
// cores); the same command on a grid of one cell measures what every run pays besides its cells
// (the launch overhead).
//
//   build/release/tests/mpi_benchmark --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
//
// Built only with the MPI front end; the programs' paths are compiled in (STICKSLIP_MPI, MPIEXEC).
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

extern char** environ;

namespace {

// Runs `args` (args[0] found on PATH or given as a path) with stdout on /dev/null; returns the exit
// status of waitpid, or -1 when it could not be started.
int RunCommand(const std::vector<std::string>& args) {
  std::vector<char*> argv;
  for (const std::string& arg : args) argv.push_back(const_cast<char*>(arg.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  const int spawned = posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) return -1;
  int status = 0;
  if (waitpid(pid, &status, 0) != pid) return -1;
  return status;
}

// range(0) ranks, a grid of (range(1) + 1) x (range(2) + 1) cells.
void MpiMapSweep(benchmark::State& state) {
  const auto ranks = state.range(0), first_steps = state.range(1), second_steps = state.range(2);
  const std::filesystem::path output =
      std::filesystem::temp_directory_path() / ("stickslip-mpi-benchmark-" + std::to_string(getpid()) + ".csv");
  std::vector<std::string> command = {MPIEXEC};
  if (geteuid() == 0) command.push_back("--allow-run-as-root");
  command.insert(command.end(), {"--oversubscribe", "-np", std::to_string(ranks), STICKSLIP_MPI, "map-sweep",
                                 "--preset", "paper-6", "--first", "omega", "--first-from", "0.55", "--first-to",
                                 "0.6", "--first-steps", std::to_string(first_steps), "--second", "u_r",
                                 "--second-from", "1.2", "--second-to", "1.5", "--second-steps",
                                 std::to_string(second_steps), "--threads", "1", "--output", output.string()});
  for (auto _ : state) {
    const int status = RunCommand(command);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
      state.SkipWithError("mpirun stickslip-mpi map-sweep failed");
      break;
    }
  }
  std::filesystem::remove(output);
  state.counters["ranks"] = static_cast<double>(ranks);
  state.counters["cells"] = static_cast<double>((first_steps + 1) * (second_steps + 1));
}
BENCHMARK(MpiMapSweep)
    ->ArgNames({"ranks", "first_steps", "second_steps"})
    ->Args({1, 23, 19})
    ->Args({2, 23, 19})
    ->Args({1, 0, 0})
    ->Args({2, 0, 0})
    ->Iterations(1)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace

int main(int argc, char** argv) {
  // Shared-memory messages copied through a buffer rather than across address spaces (CMA), which
  // containers that restrict ptrace refuse (as tests/cli/map_sweep_test.sh does).
  setenv("OMPI_MCA_btl_vader_single_copy_mechanism", "none", 0);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
