# SPDX-License-Identifier: Apache-2.0
# Sourced by the bench scripts.

# The median of the numbers on stdin (the mean of the middle two for an even count).
median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

# bench_setup [ALPHAPOCKET]: sets root (the repository), exe (the given
# executable, default build/apps/alphapocket), reps (REPS, default 3) and
# scratch (a folder removed on exit).
bench_setup() {
  root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
  exe=$(realpath "${1:-$root/build/apps/alphapocket}")
  reps=${REPS:-3}
  [[ -x $exe ]] || { echo "$exe: not an executable (build alphapocket first)" >&2; exit 1; }
  scratch=$(mktemp -d)
  trap 'rm -rf "$scratch"' EXIT
}

# write_random_points FILE N SEED: N uniform random points in the unit cube
# (Python's random.Random(SEED)), as "x y z" lines.
write_random_points() {
  python3 - "$@" <<'PY'
import random, sys
path, n, seed = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
r = random.Random(seed)
with open(path, "w") as f:
    for _ in range(n):
        f.write("%.17g %.17g %.17g\n" % (r.random(), r.random(), r.random()))
PY
}
