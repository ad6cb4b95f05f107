# Thin wrapper around CMake. `make demo` and `make test` work on a fresh
# Debian 12 machine: they install the Debian packages they need first.
BUILD ?= build
JOBS ?= $(shell nproc)

# Debian packages the build, the tests, the demo and the bench need.
DEBIAN_PACKAGES = build-essential cmake pkg-config libgmp-dev liblbfgs-dev libfreetype-dev \
  fonts-dejavu-core fonts-urw-base35 fonts-freefont-ttf fonts-liberation fonts-noto-core python3 python3-numpy python3-pytest python3-meshio python3-shapely \
  libopenmesh-dev libeigen3-dev pybind11-dev python3-dev \
  meshlab dpkg-dev qtbase5-dev libqt5opengl5-dev libqt5xmlpatterns5-dev \
  libglew-dev xvfb xauth \
  libsuitesparse-dev libgmsh-dev gmsh gmsh-doc python3-gmsh python3-scipy \
  clang libclang-rt-14-dev valgrind libcairo2-dev python3-pil libjansson-dev librsvg2-bin \
  libdouble-conversion-dev libpng-dev fontconfig calculix-ccx

# Only `make bench` needs these: CGAL meshes each polygon alone, to compare;
# Gmsh's and OpenCASCADE's STL models give the benches real sections
# (bench/stl_sections.py, bench/section_soak.py).
BENCH_PACKAGES = libcgal-dev gmsh-doc occt-misc

.PHONY: all deps bench-deps build demo test bench fuzz soak clean install-meshlab-plugin

all: build

deps:
	@missing=$$(for p in $(DEBIAN_PACKAGES); do \
	    dpkg-query -W -f='$${Status}\n' $$p 2>/dev/null | grep -q '^install ok installed' || echo $$p; \
	  done); \
	if [ -n "$$missing" ]; then \
	  echo "installing Debian packages:" $$missing; \
	  SUDO=$$( [ "$$(id -u)" -eq 0 ] || echo sudo ); \
	  $$SUDO apt-get update -qq && \
	  DEBIAN_FRONTEND=noninteractive $$SUDO apt-get install -y -qq $$missing; \
	fi

build: deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo
	cmake --build $(BUILD) -j $(JOBS)

test: build
	ctest --test-dir $(BUILD) --output-on-failure -j $(JOBS)

demo: build
	bash examples/demo.sh $(BUILD)

bench-deps:
	@$(MAKE) --no-print-directory deps DEBIAN_PACKAGES="$(BENCH_PACKAGES)"

bench: bench-deps build
	bash bench/run_bench.sh $(BUILD)

# Puts the MeshLab plugin where the MeshLab GUI loads plugins from.
install-meshlab-plugin: build
	cmake --install $(BUILD) --component meshlab_plugin

# Longer fuzzing: every harness FUZZ_SECONDS, in the clang sanitizer tree.
FUZZ_SECONDS ?= 600
fuzz: build
	sh tests/sanitize/sanitizer_tree.sh . $(BUILD)/sanitize $(JOBS)
	for h in read_xy read_obj read_ply pipeline; do \
	  sh tests/fuzz/run_fuzzer.sh $(BUILD)/sanitize/bin/fuzz_$$h tests/fuzz/corpus/$$h \
	    $(BUILD)/fuzz-long/$$h $(FUZZ_SECONDS) || exit 1; \
	done

# 100,000 random pairs through the default pipeline, then FONT_SOAK_PAIRS
# real glyph pairs of the fonts above (the construction, then 1,000 of them
# remeshed and morphed), every result checked exactly.
SOAK_PAIRS ?= 100000
FONT_SOAK_PAIRS ?= 20000
soak: build
	$(BUILD)/bin/soak $(SOAK_PAIRS)
	$(BUILD)/bin/cm_font_soak --pairs $(FONT_SOAK_PAIRS) --no-remesh
	$(BUILD)/bin/cm_font_soak --first $(FONT_SOAK_PAIRS) --pairs 1000 --morph

clean:
	rm -rf $(BUILD)
