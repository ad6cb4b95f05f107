#!/bin/sh
# valgrind memcheck of `compatmesh triangulate` on a few pairs (default
# options, remeshing included), an OBJ input and a bad input, and of
# `compatmesh batch` (its job processes too: valgrind follows fork, and a
# job that valgrind faults exits 99, an internal failure of the batch): no
# memory errors and no definite or indirect leaks in any run (exit 99
# otherwise).
#   memcheck_cli.sh COMPATMESH WORK_DIR
set -eu
cli=$1 work=$2
command -v valgrind >/dev/null || { echo "valgrind not found: install the Debian package valgrind" >&2; exit 1; }
rm -rf "$work" && mkdir -p "$work" && cd "$work"
printf '0 0\n4 0\n4 4\n0 4\n' > square.xy
printf '0 0\n5 -1\n6 3\n1 2\n' > kite.xy
printf '0 0\n2 0\n2 1\n1 1\n1 2\n2 2\n2 3\n0 3\n' > c.xy
printf '0 0\n2 0\n2 3\n1 3\n1 2\n0 2\n0 1.5\n0 0.5\n' > l.xy
printf 'v 0 0\nv 2 0\nv 2.5 2\nv 1 3\nv -0.5 2\nl 1 2 3 4 5 1\n' > pent.obj
printf 'v 0 0\nv 3 0\nv 3 3\nv 1.5 1\nv 0 3\nl 1 2 3 4 5 1\n' > dart.obj
printf '0 0\n4 4\n4 0\n0 4\n' > bowtie.xy
memcheck() {
  expected=$1; shift
  set +e
  valgrind -q --error-exitcode=99 --leak-check=full --errors-for-leak-kinds=definite,indirect \
    --show-leak-kinds=definite,indirect "$cli" "$@" >/dev/null 2>valgrind.log
  status=$?
  set -e
  if [ "$status" -ne "$expected" ]; then
    cat valgrind.log
    echo "compatmesh $*: exit $status, expected $expected (99: valgrind found errors or leaks)"
    exit 1
  fi
  echo "compatmesh $*: exit $status, valgrind clean"
}
memcheck 0 triangulate square.xy kite.xy --out-dir out1
memcheck 0 triangulate c.xy l.xy --out-dir out2 --format obj
memcheck 0 triangulate pent.obj dart.obj --out-dir out3 --format ply --method overlay
memcheck 2 triangulate square.xy bowtie.xy --out-dir out4
memcheck 2 triangulate square.xy missing.xy --out-dir out5
memcheck 1 triangulate square.xy kite.xy --out-dir square.xy/out
printf 'square.xy kite.xy\npair: c.xy l.xy\n' > jobs.txt
printf 'square.xy kite.xy\nsquare.xy bowtie.xy\n' > some_bad.txt
printf 'square.xy missing.xy\n' > malformed.txt
memcheck 0 batch jobs.txt --out-dir out7 --jobs 2
memcheck 2 batch some_bad.txt --out-dir out8 --jobs 2
memcheck 2 batch malformed.txt --out-dir out9
