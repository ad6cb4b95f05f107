#!/bin/sh
# Installs the build into a temporary prefix and uses it as a user would:
# the README's C example (docs/examples/pair.c) built with pkg-config and
# with find_package(compatmesh), the C++ OpenMesh example
# (docs/examples/pair.cc) with find_package, the installed command-line
# tool (a triangulation, and a sweep through Gmsh when built with it) and
# the installed Python module.
#   check_install.sh SOURCE_DIR BUILD_DIR WORK_DIR WITH_GMSH(ON|OFF)
set -eu
src=$1 build=$2 work=$3 with_gmsh=$4
rm -rf "$work"
mkdir -p "$work"
prefix=$work/prefix
cmake --install "$build" --prefix "$prefix" >"$work/install.log"

# pkg-config, the README's command line.
export PKG_CONFIG_PATH="$prefix/lib/pkgconfig"
cc -std=c11 -Wall -Werror -o "$work/pair_pc" "$src/docs/examples/pair.c" \
   $(pkg-config --cflags --libs compatmesh) -Wl,-rpath,"$prefix/lib"
"$work/pair_pc" >"$work/pair_pc.out"
grep -q '^triangle ' "$work/pair_pc.out"

# CMake package: a project of its own.
mkdir -p "$work/project"
cp "$src/docs/examples/pair.c" "$src/docs/examples/pair.cc" "$work/project/"
cat >"$work/project/CMakeLists.txt" <<'CMAKE'
cmake_minimum_required(VERSION 3.18)
project(uses_compatmesh LANGUAGES C CXX)
set(CMAKE_CXX_STANDARD 17)
find_package(compatmesh 0.1 REQUIRED)
add_executable(pair_c pair.c)
target_link_libraries(pair_c PRIVATE compatmesh::compatmesh)
add_executable(pair_cc pair.cc)
target_link_libraries(pair_cc PRIVATE compatmesh::openmesh)
CMAKE
cmake -S "$work/project" -B "$work/project/build" -DCMAKE_PREFIX_PATH="$prefix" \
      -DCMAKE_BUILD_RPATH="$prefix/lib" >"$work/project.log"
cmake --build "$work/project/build" >>"$work/project.log"
"$work/project/build/pair_c" | cmp - "$work/pair_pc.out"
cp "$src/tests/openmesh/data/a.off" "$src/tests/openmesh/data/b.off" "$work/project/build/"
(cd "$work/project/build" && ./pair_cc | grep -q ' triangles$' && test -s a_tri.off && test -s b_tri.off)

# The installed tool and Python module.
"$prefix/bin/compatmesh" --version | grep -q '^compatmesh '
printf '0 0\n4 0\n4 3\n0 3\n' >"$work/a.xy"
printf '0 0\n4 1\n3 4\n-1 2\n' >"$work/b.xy"
"$prefix/bin/compatmesh" triangulate "$work/a.xy" "$work/b.xy" -o "$work/tri" >/dev/null
test -s "$work/tri/a.off" && test -s "$work/tri/preview.png"
# Gmsh is loaded by the installed tool when a sweep writes a Gmsh format.
if [ "$with_gmsh" = ON ]; then
  "$prefix/bin/compatmesh" sweep "$work/a.xy" "$work/b.xy" -o "$work/sweep.msh" >/dev/null
  grep -q '^\$MeshFormat' "$work/sweep.msh"
fi
PYTHONPATH="$prefix/lib/python3/dist-packages" /usr/bin/python3 -c \
  'import compatmesh, numpy as np; r = compatmesh.triangulate([np.array([[0, 0], [4, 0], [4, 3], [0, 3.0]]), np.array([[0, 0], [4, 1], [3, 4], [-1, 2.0]])]); assert len(r.faces) >= 2'
echo "installed into $prefix and used: pkg-config, find_package (C and C++), CLI, Python"
