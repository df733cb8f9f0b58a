# Shared by the map-sweep test scripts (sourced after expect.sh).
#
# `map_args KEY VALUE...` sets `args` to a small map's options (the section 6 data, 4 x 5 cells, 30 +
# 6 periods, 2 starts: 5 rows, which 2 and 3 ranks or shards split unevenly, 3 + 2 and 2 + 2 + 1),
# the pairs given replacing or adding options (an option given twice is refused).
map_args() {
  declare -A o=([--preset]=paper-6 [--first]=omega [--first-from]=0.55 [--first-to]=0.6 [--first-steps]=3
                [--second]=u_r [--second-from]=1.2 [--second-to]=1.5 [--second-steps]=4 [--transients]=30
                [--periods]=6 [--starts]=2)
  while [ $# -gt 0 ]; do o[$1]=$2; shift 2; done
  args=(map-sweep)
  for key in "${!o[@]}"; do args+=("$key" "${o[$key]}"); done
}

# `expect_map CODE TEXT KEY VALUE...`: the map of map_args with those pairs, run by $bin (or by the
# command in the array `map_runner` when set: mpirun ... stickslip-mpi), exits with CODE, one line
# holding TEXT on stderr, nothing written (expect.sh's expect), within a timeout.
map_runner=()
expect_map() {
  local code=$1 text=$2
  shift 2
  map_args "$@"
  if [ ${#map_runner[@]} -eq 0 ]; then
    expect "$code" "$text" timeout 60 "$bin" "${args[@]}"
  else
    expect "$code" "$text" "${map_runner[@]}" "${args[@]}"
  fi
}

# `mpi_ready` sets the launcher `mpi` from STICKSLIP_MPI (the stickslip-mpi program) and MPIEXEC
# (mpirun), which tests/CMakeLists.txt passes where the MPI front end is built, and succeeds: mpirun with
# --allow-run-as-root and --oversubscribe, --quiet (a rank's one-line error is then all stderr holds,
# not followed by mpirun's report of the exit code), under a timeout (no check may hang). Without
# them it says why and fails the script when STICKSLIP_REQUIRE_MPI is set (tools/test.sh sets it:
# there Open MPI is installed and the MPI checks must run), else skips them.
mpi_ready() {
  local why=""
  if [ -z "${STICKSLIP_MPI:-}" ]; then
    why="the MPI front end stickslip-mpi is not built (Open MPI: libopenmpi-dev)"
  elif [ ! -x "${MPIEXEC:-}" ]; then
    why="mpirun is not installed (openmpi-bin; MPIEXEC = '${MPIEXEC:-}')"
  fi
  if [ -n "$why" ]; then
    if [ -n "${STICKSLIP_REQUIRE_MPI:-}" ]; then fail "$why, and STICKSLIP_REQUIRE_MPI is set"; else echo "$why: MPI checks skipped"; fi
    return 1
  fi
  # Shared-memory messages copied through a buffer rather than across address spaces (CMA), which
  # containers that restrict ptrace refuse.
  export OMPI_MCA_btl_vader_single_copy_mechanism=none
  mpi=(timeout 300 "$MPIEXEC" --quiet --allow-run-as-root --oversubscribe)
  # Sanitized build: what Open MPI's libraries (not built with the sanitizers) still hold at exit is
  # not a leak of stickslip's; the full unwinding at each allocation lets the suppressions see them.
  # (their statistics, printed to stderr at exit, not shown: a refusal stays one line).
  if [ -n "${STICKSLIP_MPI_LSAN_SUPPRESSIONS:-}" ]; then
    mpi=(env "LSAN_OPTIONS=suppressions=$STICKSLIP_MPI_LSAN_SUPPRESSIONS:fast_unwind_on_malloc=0:print_suppressions=0" "${mpi[@]}")
  fi
  return 0
}
