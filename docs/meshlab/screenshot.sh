#!/bin/sh
# Regenerates docs/meshlab_dialog.png: MeshLab's GUI under Xvfb with two
# section polylines loaded and the filter's dialog open, captured with
# ImageMagick. Docs tool, not a test; needs xvfb, xdotool, imagemagick and
# a build (BUILD, default build). Menu positions are those of MeshLab
# 2020.09 in a 1280x900 screen without a window manager.
set -e
BUILD=${1:-build}
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
WORK=$(mktemp -d)
trap 'kill $GUI $XVFB 2>/dev/null; rm -rf "$WORK"' EXIT

# MeshLab loads plugins from plugins/ beside its binary.
mkdir -p "$WORK/run/plugins"
cp /usr/bin/meshlab "$WORK/run/"
for f in "$ROOT/$BUILD"/meshlab/plugins/*.so; do ln -s "$(readlink -f "$f")" "$WORK/run/plugins/"; done

/usr/bin/python3 - "$WORK" <<'PY'
import math, sys
def ply(path, pts):
    with open(path, "w") as f:
        f.write("ply\nformat ascii 1.0\nelement vertex %d\nproperty float x\nproperty float y\n"
                "property float z\nelement edge %d\nproperty int vertex1\nproperty int vertex2\n"
                "end_header\n" % (len(pts), len(pts)))
        for p in pts: f.write("%.7g %.7g %.7g\n" % p)
        for i in range(len(pts)): f.write("%d %d\n" % (i, (i + 1) % len(pts)))
star = lambda n, r0, r1, z, sx, sy: [(sx * (r0, r1)[i % 2] * math.cos(2 * math.pi * i / n),
                                      sy * (r0, r1)[i % 2] * math.sin(2 * math.pi * i / n), z) for i in range(n)]
ply(sys.argv[1] + "/section_low.ply", star(16, 1.0, 0.6, 0.0, 1.0, 1.0))
ply(sys.argv[1] + "/section_high.ply", star(22, 1.2, 0.9, 1.5, 1.0, 0.6))
PY

DISPLAY_NUMBER=:$((90 + $$ % 100))
Xvfb $DISPLAY_NUMBER -screen 0 1280x900x24 >/dev/null 2>&1 & XVFB=$!
sleep 1
export DISPLAY=$DISPLAY_NUMBER
cd "$WORK"
LD_LIBRARY_PATH=/usr/lib/x86_64-linux-gnu/meshlab ./run/meshlab section_low.ply section_high.ply >/dev/null 2>&1 & GUI=$!
sleep 6
xdotool mousemove 120 10 click 1; sleep 1                    # Filters
xdotool mousemove 270 165 click 1; sleep 1                   # Remeshing, Simplification and Reconstruction
xdotool mousemove 496 137 click 1; sleep 2                   # Compatible Triangulation of Two Boundaries
import -window root -crop 853x723+0+0 +repage "$ROOT/docs/meshlab_dialog.png"
xdotool mousemove 313 550 click 1; sleep 3                   # Apply
import -window root -crop 853x723+0+0 +repage "$ROOT/docs/meshlab_result.png"
echo "wrote docs/meshlab_dialog.png and docs/meshlab_result.png"
