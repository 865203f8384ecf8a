#!/usr/bin/env bash
# Memcheck on the paths beyond the bat profiles (valgrind_profiles.sh): one impact, a study run
# (without mpirun: MPI's singleton start), killed and resumed from its journal, a tiny
# optimisation, and the Python module's impacts(). Any memory error or definitely lost block
# (valgrind's --error-exitcode=1) or another exit status fails the test. Suppressed: Open MPI's own
# leaks (tests/valgrind/open_mpi.supp, Open MPI's openmpi-valgrind.supp) and CPython's allocator
# (Debian's python3.supp), each suppression saying why; none of sweetspot's. Blocks only "possibly
# lost" (a pointer into their middle still held) are neither shown nor errors. Small scenes
# (--modes 6), a few points: about a minute of CPU on 2 cores.
# Usage: valgrind_paths.sh SWEETSPOT SOURCE_DIR [PYTHON PYTHON_MODULE_DIR]
set -euo pipefail
program=$1
source=$2
python=${3:-}
python_dir=${4:-}
here=$(dirname "$(realpath "$0")")
command -v valgrind >/dev/null || { echo "valgrind is missing: run scripts/setup"; exit 1; }
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cd "$dir"

# The program allocates through mimalloc (CMakeLists.txt): memcheck replaces its malloc and free as
# it does glibc's; its operator delete[] is free under another name, so memcheck cannot tell
# delete[] from free there. The Python module keeps glibc's allocator: its run below checks them.
memcheck_glibc=(valgrind --quiet --error-exitcode=1 --leak-check=full --errors-for-leak-kinds=definite
                --show-leak-kinds=definite --num-callers=40
                --suppressions=/usr/share/openmpi/openmpi-valgrind.supp --suppressions="$here/valgrind/open_mpi.supp")
memcheck=("${memcheck_glibc[@]}" --soname-synonyms=somalloc='*mimalloc*' --show-mismatched-frees=no)
failures=0
# check DESCRIPTION COMMAND...: the command under memcheck must exit 0.
check() {
  local what=$1 status=0
  shift
  "$@" >"$dir/out" 2>&1 || status=$?
  if [ "$status" != 0 ]; then
    echo "FAILED (exit $status): $what: $*"; cat "$dir/out"; failures=$((failures + 1))
  else
    echo "ok: $what"
  fi
}
bat=$source/studies/bats/r161.toml

# One impact, in the pivot rig and swung, with the dense and the adaptive integrators.
check "impact" "${memcheck[@]}" "$program" impact --bat "$bat" --z 0.7 --ball-speed 40 --cm-speed 10 --omega 40 --modes 6
check "impact, pivot, dopri" "${memcheck[@]}" "$program" impact --bat "$bat" --z 0.6 --ball-speed 30 --pivot --center 0.1 \
  --omega 50 --modes 6 --integrator dopri

# A study on 2 OpenMP threads: 2 bats (one by its dimensions) x 3 points x 2 speeds, 6 modes.
cat >study.toml <<STUDY
title = "memcheck"
[scene]
cm_speed = 5
omega = 40
e0 = 0.5
modes = 6
[axes]
bat = ["$bat", "$source/studies/bats/maple_271.toml"]
z = [0.6, 0.7, 0.75]
ball_speed = [30, 40]
STUDY
check "run (2 threads, no mpirun)" env OMP_NUM_THREADS=2 "${memcheck[@]}" "$program" run study.toml -o study.h5 --quiet
[ -f study.h5 ] || { echo "FAILED: run wrote no study.h5"; failures=$((failures + 1)); }

# Killed once its journal holds a record (past the 56-byte header), then resumed under memcheck:
# the journal's reading and the recovered points' path. 150 points in chunks of 8.
cat >long.toml <<STUDY
title = "memcheck, resumed"
[scene]
bat = "$bat"
cm_speed = 5
omega = 40
e0 = 0.5
modes = 6
[axes]
z = { start = 0.50, stop = 0.79, step = 0.01 }
ball_speed = [20, 25, 30, 35, 40]
STUDY
OMP_NUM_THREADS=2 "${memcheck[@]}" "$program" run long.toml -o long.h5 --quiet >"$dir/killed" 2>&1 &
pid=$!
for _ in $(seq 1200); do
  [ "$(stat -c %s long.h5.journal 2>/dev/null || echo 0)" -gt 56 ] && break
  sleep 0.05
done
kill -KILL "$pid" 2>/dev/null || true
wait "$pid" 2>/dev/null || true
if [ -f long.h5 ] || [ ! -f long.h5.journal ]; then
  echo "FAILED: the run to kill ended first or left no journal"; cat "$dir/killed"; failures=$((failures + 1))
fi
check "run --resume" env OMP_NUM_THREADS=2 "${memcheck[@]}" "$program" run long.toml -o long.h5 --resume
grep -q "resuming: [1-9][0-9]* of 150 points already done" "$dir/out" ||
  { echo "FAILED: the resumed run recovered no point"; cat "$dir/out"; failures=$((failures + 1)); }

# A tiny optimisation: the rigid maple 271's density free, 5 evaluations of one point.
cat >opt.toml <<OPT
bat = "$source/studies/bats/maple_271.toml"
[free]
density = { min = 500, max = 900 }
[player]
center = 0.09
omega = 51
ball_speed = 40
swing_exponent = 0.3
[model]
modes = 0
[objective]
maximize = "mean_bbs"
points = [0.7]
weights = [1]
[optimizer]
max_evaluations = 5
OPT
check "optimize (5 evaluations)" "${memcheck[@]}" "$program" optimize opt.toml -o opt.h5 --quiet
[ -f opt_best.toml ] || { echo "FAILED: optimize wrote no opt_best.toml"; failures=$((failures + 1)); }

# The Python module: impacts() of 2 x 2 points over 2 threads. CPython keeps its own allocator
# (pymalloc), whose reads of memory it never wrote Debian's python3.supp suppresses: with
# PYTHONMALLOC=malloc, every object CPython, numpy and pandas never free at exit (hundreds, none
# of the module's) would be a definite leak. The module's C++ allocations are malloc's either way.
if [ -n "$python_dir" ]; then
  check "python impacts" env PYTHONPATH="$python_dir" PYTHONDONTWRITEBYTECODE=1 \
    "${memcheck_glibc[@]}" --suppressions=/usr/lib/valgrind/python3.supp \
    "$python" -c "
import sweetspot
bat = sweetspot.Bat.load('$bat')
ds = sweetspot.impacts(bat, z=[0.6, 0.7], ball_speed=[[30], [40]], cm_speed=10, omega=40, modes=6, threads=2)
assert ds['vf'].shape == (2, 2) and (ds['status'].values == 0).all(), ds
"
fi
[ "$failures" -eq 0 ]
