#!/bin/sh
# Runs the CLI on every benchmark pair and writes bench/RESULTS.md, then
# bench/remesh_bench.py, which writes bench/REMESH.md.
#   bench/run_bench.sh BUILD_DIR
# Inputs go to BUILD_DIR/bench_run/input, each run to BUILD_DIR/bench_run/PAIR/
# (not BUILD_DIR/bench: CMake owns that folder).
# Every pair must succeed: failures are listed and the exit code is 1.
# CM_BENCH_TIMEOUT (seconds, default 900) bounds one pair's run.
set -u

if [ $# -ne 1 ]; then
    echo "usage: $0 BUILD_DIR" >&2
    exit 2
fi
build=$(cd "$1" 2>/dev/null && pwd) || { echo "bench: no build directory $1" >&2; exit 2; }
src=$(cd "$(dirname "$0")/.." && pwd)
cli=$build/bin/compatmesh
gen=$build/bin/cm_gen_pairs
python=/usr/bin/python3
limit=${CM_BENCH_TIMEOUT:-900}
for tool in "$cli" "$gen"; do
    if [ ! -x "$tool" ]; then
        echo "bench: $tool is missing: build first (cmake --build $build)" >&2
        exit 2
    fi
done

bench=$build/bench_run
input=$bench/input
rm -rf "$bench"
mkdir -p "$bench"
"$gen" --out "$input" --set bench || { echo "bench: cm_gen_pairs failed" >&2; exit 1; }

# status.tsv: pair, exit code, wall seconds; make_results.py reads it.
status=$bench/status.tsv
: >"$status"
failed=""
count=$(wc -l <"$input/pairs.txt")
i=0
while read -r name files; do
    [ -n "$name" ] || continue
    i=$((i + 1))
    set --
    for f in $files; do set -- "$@" "$input/$f"; done
    start=$(date +%s.%N)
    timeout "$limit" "$cli" triangulate "$@" --out-dir "$bench/$name" \
        </dev/null >"$bench/$name.log" 2>&1
    code=$?
    end=$(date +%s.%N)
    wall=$(echo "$start $end" | awk '{ printf "%.3f", $2 - $1 }')
    printf '%s\t%s\t%s\n' "$name" "$code" "$wall" >>"$status"
    if [ "$code" -eq 0 ]; then
        echo "[$i/$count] $name ok (${wall} s)"
    else
        [ "$code" -eq 124 ] && echo "timed out after $limit s" >>"$bench/$name.log"
        echo "[$i/$count] $name FAILED (exit $code), log: $bench/$name.log" >&2
        sed 's/^/    /' "$bench/$name.log" | head -n 20 >&2
        failed="$failed $name"
    fi
done <"$input/pairs.txt"

# The price of compatibility: every polygon meshed alone by CGAL at the
# same angle bound (cgal.tsv: pair, file, CGAL's output line).
cgal=$build/bin/cm_cgal_single
if [ -x "$cgal" ]; then
    while read -r name files; do
        [ -n "$name" ] || continue
        for f in $files; do
            line=$(timeout "$limit" "$cgal" "$input/$f" 25 </dev/null 2>/dev/null) || line="failed"
            printf '%s\t%s\t%s\n' "$name" "$f" "$line" >>"$bench/cgal.tsv"
        done
    done <"$input/pairs.txt"
else
    echo "bench: $cgal not built (CGAL missing): no comparison with single-polygon meshing" >&2
fi

# The correspondence bound: the largest smallest angle any compatible
# triangulation of the pair can have (bound.tsv: pair, bound line), from
# the bound cache remesh_bench.py shares (computed where missing).
"$python" "$src/bench/cached_bounds.py" "$cli" "$input" "$bench/bound.tsv" "$limit" ||
    { echo "bench: cached_bounds.py failed" >&2; exit 1; }

# Each polygon alone (paired with itself): what remeshing reaches without
# the correspondence to honour (alone.tsv: pair, file, smallest angle).
while read -r name files; do
    [ -n "$name" ] || continue
    for f in $files; do
        out=$bench/alone/$name/${f%.*}
        mkdir -p "$out"
        cp "$input/$f" "$out/a.xy" && cp "$input/$f" "$out/b.xy"
        if timeout "$limit" "$cli" triangulate "$out/a.xy" "$out/b.xy" --out-dir "$out/result" \
            </dev/null >/dev/null 2>&1; then
            angle=$("$python" -c 'import json, sys; print(json.load(open(sys.argv[1]))["meshes"][0]["min_angle_deg"])' "$out/result/report.json")
        else
            angle=failed
        fi
        printf '%s\t%s\t%s\n' "$name" "$f" "$angle" >>"$bench/alone.tsv"
    done
done <"$input/pairs.txt"

# The paper's Table 1 (smoothing methods), appended by make_results.py.
"$build/bin/cm_table1" "$bench/table1.md" >/dev/null || { echo "bench: cm_table1 failed" >&2; exit 1; }

"$python" "$src/bench/make_results.py" "$bench" "$src/bench/RESULTS.md" || exit 1
echo "bench: wrote $src/bench/RESULTS.md"

# The remesher judged against what each pair allows (bench/REMESH.md): the
# hard family and the bench set, both correspondence modes, CGAL alongside.
"$python" "$src/bench/remesh_bench.py" --compatmesh "$cli" --modes index,auto \
    --timeout "$limit" --json "$bench/remesh.json" --out "$src/bench/REMESH.md" ||
    failed="$failed (remesh_bench.py)"
if [ -n "$failed" ]; then
    echo "bench: FAILED pairs:$failed" >&2
    exit 1
fi
