#!/bin/sh
# Compatible triangulations of the demo pairs (the letters U and S of the
# paper's Figure 8, a U/S/C triple, stars, a spiral, a comb), then the morph
# and the sweep from U to S.
#   examples/demo.sh BUILD_DIR
# Writes BUILD_DIR/demo/input/*.xy and one folder BUILD_DIR/demo/PAIR/ per
# pair with the meshes, report.json and preview.svg. Exits non-zero if any
# pair fails.
set -u

if [ $# -ne 1 ]; then
    echo "usage: $0 BUILD_DIR" >&2
    exit 2
fi
build=$(cd "$1" 2>/dev/null && pwd) || { echo "demo: no build directory $1" >&2; exit 2; }
cli=$build/bin/compatmesh
gen=$build/bin/cm_gen_pairs
python=/usr/bin/python3
for tool in "$cli" "$gen"; do
    if [ ! -x "$tool" ]; then
        echo "demo: $tool is missing: build first (cmake --build $build)" >&2
        exit 2
    fi
done

demo=$build/demo
input=$demo/input
rm -rf "$input"
mkdir -p "$demo"
"$gen" --out "$input" --set demo >/dev/null || { echo "demo: cm_gen_pairs failed" >&2; exit 1; }

# One line per pair from its report.json.
summary() {
    "$python" -c '
import json, sys
r = json.load(open(sys.argv[1]))
angles = ", ".join(("%.1f" if m["min_angle_deg"] >= 1 else "%.2g") % m["min_angle_deg"]
                   for m in r["meshes"])
print("  n=%d k=%d steiner=%d triangles=%d min angles %s deg, %.3f s" % (
    r["n"], r["k"], r["steiner"], r["triangles"], angles, r["seconds"]["total"]))
' "$1"
}

failed=""
while read -r name files; do
    [ -n "$name" ] || continue
    out=$demo/$name
    set --
    for f in $files; do set -- "$@" "$input/$f"; done
    if "$cli" triangulate "$@" --out-dir "$out" </dev/null >"$demo/$name.log" 2>&1; then
        echo "$name: $out"
        for mesh in "$out"/*.off; do echo "  mesh    $mesh"; done
        echo "  picture $out/preview.svg"
        summary "$out/report.json" || failed="$failed $name"
    else
        echo "$name: FAILED (exit $?), see $demo/$name.log" >&2
        sed 's/^/  /' "$demo/$name.log" >&2
        failed="$failed $name"
    fi
done <"$input/pairs.txt"

# The U of the paper's Figure 8 morphed into its S, and the swept volume
# between them as a finite-element mesh (Gmsh .msh, read by Gmsh and meshio).
us="$input/U_S_a.xy $input/U_S_b.xy"
if "$cli" morph $us --frames 11 --out-dir "$demo/morph_U_S" </dev/null >"$demo/morph.log" 2>&1; then
    echo "morph U -> S: 11 sections in $demo/morph_U_S (frame_000.off ... frame_010.off)"
    echo "  picture $demo/morph_U_S/frames.svg"
else
    echo "morph: FAILED, see $demo/morph.log" >&2
    failed="$failed morph"
fi
if "$cli" sweep $us --sections 11 --height 1 -o "$demo/sweep_U_S.msh" </dev/null >"$demo/sweep.log" 2>&1; then
    echo "sweep U -> S: 6-node prisms in $demo/sweep_U_S.msh"
else
    echo "sweep: FAILED, see $demo/sweep.log" >&2
    failed="$failed sweep"
fi

if [ -n "$failed" ]; then
    echo "demo: failed:$failed" >&2
    exit 1
fi
echo "demo: all pairs done; inputs in $input"
