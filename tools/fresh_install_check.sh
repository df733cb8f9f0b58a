#!/usr/bin/env bash
# The set-up as a newcomer meets it: a clean Debian 12 root, a clean clone, tools/run.sh, then
# tools/test.sh, each timed. Not in the test suite (it downloads Debian and builds from nothing).
set -euo pipefail

usage() {
  cat <<'EOF'
Usage: tools/fresh_install_check.sh TARGET
       tools/fresh_install_check.sh --help

Measures the set-up on a fresh Debian 12 machine: builds a clean bookworm root in TARGET with
mmdebstrap (the default variant: the priority required and important packages, as debootstrap
installs), puts a clean git clone of this repository's committed HEAD in its /root/stickslip
(uncommitted changes are not in it), and there, as root with a minimal environment, runs
tools/run.sh and then tools/test.sh. Prints the wall time of each, split into install, build and
run (or test) as the scripts report it.

TARGET    a new or empty directory; it is left in place afterwards (its logs are
          TARGET/root/run.log and TARGET/root/test.log); remove it with rm -rf when done.

Needs root, mmdebstrap (apt-get install mmdebstrap), git, and a Debian mirror at
http://deb.debian.org. /proc, /sys, /dev, /dev/pts and a /dev/shm of its own are mounted in the
root while it runs and unmounted on any exit. On a shared machine run it under
`nice -n 19 ionice -c3`; the times are then upper bounds.
Exit: 0 both scripts passed, 1 one failed or the root could not be built, 2 bad arguments.
EOF
}

# fail <status> <message>: the message on stderr, then exit.
fail() {
  echo "fresh_install_check.sh: $2" >&2
  exit "$1"
}

# The mirrors of a fresh Debian 12 machine: the release, its updates and its security updates.
MIRRORS=(
  "deb http://deb.debian.org/debian bookworm main"
  "deb http://deb.debian.org/debian bookworm-updates main"
  "deb http://deb.debian.org/debian-security bookworm-security main"
)
# What a root login leaves set; nothing of this machine's environment goes in.
ROOT_ENVIRONMENT=(HOME=/root PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin
  LANG=C.UTF-8 TERM=dumb USER=root LOGNAME=root SHELL=/bin/bash)

# check_target <dir>: a new or empty directory, or exit 2.
check_target() {
  [ -n "$1" ] || fail 2 "TARGET '' is empty (valid: a new or empty directory)"
  if [ -e "$1" ] && { [ ! -d "$1" ] || [ -n "$(ls -A "$1")" ]; }; then
    fail 2 "TARGET '$1' exists and is not an empty directory (valid: a new or empty directory)"
  fi
}

# check_tools: root and the programs used here, or exit 1 saying what is missing.
check_tools() {
  [ "$(id -u)" -eq 0 ] || fail 1 "must run as root (it builds a root and mounts into it)"
  local tool
  for tool in mmdebstrap git chroot mount umount mountpoint; do
    command -v "$tool" > /dev/null || fail 1 "needs $tool on PATH (mmdebstrap: apt-get install mmdebstrap)"
  done
}

MOUNTS=()  # mounted points inside the root, in mounting order

# mount_into <root> <point> <mount arguments...>: mounts and records it for unmount_all.
mount_into() {
  local point=$1/$2
  shift 2
  mkdir -p "$point"
  mount "$@" "$point"
  MOUNTS+=("$point")
}

# stop_processes_in <root>: ends the processes this run left inside the root (an MPI daemon, a
# test still running when interrupted), by id; only this run uses the root.
stop_processes_in() {
  local root proc pids=()
  root=$(readlink -f "$1")
  for proc in /proc/[0-9]*; do
    [ "$(readlink "$proc/root" 2> /dev/null)" = "$root" ] && pids+=("${proc#/proc/}")
  done
  [ ${#pids[@]} -eq 0 ] && return 0
  echo "== ending processes left in the root: ${pids[*]}" >&2
  kill "${pids[@]}" 2> /dev/null || true
  sleep 2
  kill -9 "${pids[@]}" 2> /dev/null || true
}

# unmount_all: the mounts in reverse order; a busy one is detached lazily, so that removing
# TARGET afterwards never reaches into the host's /dev, /proc or /sys.
unmount_all() {
  local i point
  for ((i = ${#MOUNTS[@]} - 1; i >= 0; i--)); do
    point=${MOUNTS[i]}
    umount "$point" 2> /dev/null || umount -l "$point" ||
      echo "fresh_install_check.sh: could not unmount $point: do not remove TARGET before it is" >&2
  done
  MOUNTS=()
}

# in_root <root> <log> <command>: runs the command in the clone inside the root, as root with a
# minimal environment, its output shown and kept in the log.
in_root() {
  env -i "${ROOT_ENVIRONMENT[@]}" chroot "$1" /bin/bash -c "cd /root/stickslip && $3" < /dev/null 2>&1 | tee "$1/root/$2"
}

# timed_step <root> <log> <command>: in_root, then its wall time and the phases the script printed;
# the exit status is the command's.
timed_step() {
  local started=$SECONDS status=0 phases
  in_root "$@" || status=$?
  phases=$(sed -n 's/^== .* wall time: //p' "$1/root/$2" | tail -n 1)
  REPORT+=("$3: $((SECONDS - started)) s wall${phases:+ ($phases)}$([ "$status" -eq 0 ] || echo ", FAILED with exit $status")")
  return "$status"
}

REPORT=()  # one line a step, printed at the end
ROOT=""    # TARGET, for the exit trap

main() {
  case "${1:-}" in
    -h | --help) usage; exit 0 ;;
    -*) fail 2 "unknown option '$1' (valid: --help, or TARGET)" ;;
  esac
  [ $# -eq 1 ] || fail 2 "takes one TARGET, got $# arguments (valid: TARGET, or --help)"
  local target=$1 repo commit started status=0
  check_target "$target"
  ROOT=$target
  check_tools
  repo=$(git -C "$(dirname "$0")" rev-parse --show-toplevel)
  commit=$(git -C "$repo" rev-parse HEAD)
  trap 'stop_processes_in "$ROOT"; unmount_all; print_report' EXIT

  started=$SECONDS
  mmdebstrap --mode=root bookworm "$target" "${MIRRORS[@]}" || fail 1 "mmdebstrap could not build the root"
  REPORT+=("clean Debian 12 root (mmdebstrap, not part of the set-up): $((SECONDS - started)) s")
  [ -s "$target/etc/resolv.conf" ] || cp /etc/resolv.conf "$target/etc/resolv.conf"
  git clone --quiet --no-checkout "$repo" "$target/root/stickslip"
  git -C "$target/root/stickslip" checkout --quiet --detach "$commit"
  REPORT+=("clone of $commit")

  mount_into "$target" proc -t proc proc
  mount_into "$target" sys --bind -o ro /sys
  mount_into "$target" dev --bind /dev
  mount_into "$target" dev/pts --bind /dev/pts
  mount_into "$target" dev/shm -t tmpfs -o mode=1777 tmpfs  # Open MPI's shared memory

  timed_step "$target" run.log tools/run.sh || status=1
  [ "$status" -eq 0 ] && { timed_step "$target" test.log tools/test.sh || status=1; }
  return "$status"
}

print_report() {
  [ ${#REPORT[@]} -eq 0 ] && return 0
  echo "== fresh-install check ($(nproc) cores, $(date -u '+%Y-%m-%d %H:%M UTC'))"
  printf '   %s\n' "${REPORT[@]}"
}

main "$@"
