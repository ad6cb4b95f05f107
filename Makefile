# Thin wrapper around CMake. `make demo` and `make test` work on a fresh
# Debian 12 machine: they install the Debian packages they need first.
BUILD ?= build
JOBS ?= $(shell nproc)

# Debian packages the build, the tests, the demo and the bench need.
DEBIAN_PACKAGES = build-essential cmake pkg-config libgmp-dev libfreetype-dev \
  fonts-dejavu-core python3 python3-numpy python3-pytest python3-meshio \
  libopenmesh-dev libeigen3-dev pybind11-dev python3-dev \
  libsuitesparse-dev libgmsh-dev gmsh python3-gmsh

.PHONY: all deps build demo test bench clean

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

bench: build
	bash bench/run_bench.sh $(BUILD)

clean:
	rm -rf $(BUILD)
