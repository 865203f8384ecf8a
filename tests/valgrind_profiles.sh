#!/usr/bin/env bash
# Memcheck on the paths that read a bat's profile or dimensions: `sweetspot modes` and `sweetspot impact` on
# good, edge-case and bad profiles, each with the exit status it must have. Any memory error
# (valgrind's exit status 99) or another status fails the test. The program allocates through
# mimalloc (CMakeLists.txt), whose malloc and free memcheck replaces as it does glibc's; its
# operator delete[] is free under another name, so memcheck cannot tell delete[] from free there.
# Usage: valgrind_profiles.sh SWEETSPOT STUDIES_BATS_DIR
set -euo pipefail
program=$1
bats=$2
command -v valgrind >/dev/null || { echo "valgrind is missing: run scripts/setup"; exit 1; }
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT

# A bat file of length 0.84 m over a profile of N rows (slice centres (i + 1/2) L/N).
profile() {
  local name=$1 rows=$2
  printf 'name = "%s"\nlength = 0.84\nprofile = "%s.csv"\n[material]\ndensity = 649\nyoungs_modulus = 1.814e10\nshear_modulus = 1.05e9\n' \
    "$name" "$name" > "$dir/$name.toml"
  awk -v n="$rows" 'BEGIN { print "z_center_m,outer_diameter_m"; for (i = 0; i < n; i++) printf "%.9g,0.06\n", (i + 0.5) * 0.84 / n }' \
    > "$dir/$name.csv"
}
profile one_row 1
profile three_rows 3
profile four_rows 4
profile too_many 4097
cp "$bats/r161.toml" "$bats/r161_profile.csv" "$dir/"
printf 'z_center_m,outer_diameter_m\n0.21,0.06\n0.63,abc\n' > "$dir/not_a_number.csv"
sed 's/"one_row.csv"/"not_a_number.csv"/' "$dir/one_row.toml" > "$dir/not_a_number.toml"
# Named dimensions: a cupped end (repeated knots) and a bat they make impossible.
cp "$bats/maple_271.toml" "$dir/"
sed 's/^barrel_diameter = .*/barrel_diameter = 0.02/' "$bats/maple_271.toml" > "$dir/thin_barrel.toml"

failures=0
memcheck=(valgrind --quiet --error-exitcode=99 --soname-synonyms=somalloc='*mimalloc*' --show-mismatched-frees=no)
expect() {
  local status=$1; shift
  local actual=0
  "${memcheck[@]}" "$program" "$@" > "$dir/out" 2>&1 || actual=$?
  if [ "$actual" != "$status" ]; then
    echo "FAILED (exit $actual, expected $status): sweetspot $*"; cat "$dir/out"; failures=$((failures + 1))
  else
    echo "ok (exit $actual): sweetspot $*"
  fi
}
impact=(--z 0.84 --ball-speed 40 --center 0.1 --omega 50 --integrator exact)
expect 0 modes "$dir/r161.toml" --count 3
expect 0 modes "$dir/four_rows.toml" --count 2
expect 0 impact --bat "$dir/four_rows.toml" "${impact[@]}" --pivot --modes 0
expect 0 impact --bat "$dir/four_rows.toml" "${impact[@]}" --modes all
expect 0 impact --bat "$dir/r161.toml" "${impact[@]}" --slices 5 --modes 4
expect 2 impact --bat "$dir/one_row.toml" "${impact[@]}" --pivot --modes 0
expect 2 modes "$dir/one_row.toml"
expect 2 modes "$dir/three_rows.toml"
expect 2 modes "$dir/too_many.toml"
expect 2 modes "$dir/not_a_number.toml"
expect 0 modes "$dir/maple_271.toml" --count 3
expect 2 modes "$dir/thin_barrel.toml"
[ "$failures" -eq 0 ]
