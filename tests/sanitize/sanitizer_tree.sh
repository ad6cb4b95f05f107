#!/bin/sh
# Configures and builds the clang sanitizer tree (ASan + UBSan + libFuzzer
# coverage): the C library, its C tests and the fuzz harnesses, no bindings.
#   sanitizer_tree.sh SOURCE_DIR BUILD_DIR [JOBS]
set -eu
src=$1 build=$2 jobs=${3:-2}
command -v clang >/dev/null || { echo "clang not found: install the Debian packages clang libclang-rt-14-dev" >&2; exit 1; }
cmake -S "$src" -B "$build" -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCM_SANITIZER_TREE=ON -DCM_WITH_OPENMESH=OFF -DCM_WITH_PYTHON=OFF -DCM_WITH_FREETYPE=OFF \
  -DCM_WITH_MESHLAB=OFF -DCM_WITH_GMSH=OFF >/dev/null
cmake --build "$build" -j "$jobs"
