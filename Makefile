# pkmws — the two commands a newcomer needs are `make demo` and `make test`.
# Both install the Debian packages the project needs first (idempotent).

DEB_PACKAGES := cmake g++ make ccache libcgal-dev libgmp-dev libmpfr-dev libeigen3-dev \
                libboost-dev libtbb-dev nlohmann-json3-dev libcli11-dev libgtest-dev \
                libbenchmark-dev python3 python3-dev pybind11-dev python3-pytest python3-numpy python3-shapely \
                python3-ezdxf python3-matplotlib python3-jsonschema librsvg2-bin libopenmpi-dev openmpi-bin \
                libnlopt-cxx-dev
JOBS ?= $(shell nproc 2>/dev/null || echo 2)
PKMWS := build/bin/pkmws
SUDO := $(shell [ "$$(id -u)" = 0 ] || echo sudo)

.PHONY: all deps configure build demo test sanitize bench clean

all: build

deps:
	@missing=$$(for p in $(DEB_PACKAGES); do \
	    dpkg-query -W -f='$${Status}\n' $$p 2>/dev/null | grep -q '^install ok installed' || echo $$p; done); \
	if [ -n "$$missing" ]; then \
	  echo "installing:" $$missing; \
	  $(SUDO) apt-get update -qq && \
	  DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq --no-install-recommends $$missing; \
	else echo "deps: all Debian packages present"; fi

configure:
	@[ -f build/CMakeCache.txt ] || cmake --preset release

build: deps configure
	cmake --build --preset release -j $(JOBS)

demo: build
	bash apps/demo.sh $(PKMWS) out

test: build
	ctest --preset release -j $(JOBS)

# AddressSanitizer + UndefinedBehaviorSanitizer (preset `sanitize`, build-sanitize/):
# every test but those labelled `heavy` (minutes under ASan), the fuzz corpus
# and the generative loader fuzzing included. UBSan stops at the first report;
# tests/sanitize/ubsan.supp holds the one suppression (CGAL, with the reason).
# The Python module is off there: an ASan extension cannot load into a plain
# interpreter. .ci/run runs this after `make test`.
sanitize: deps
	@[ -f build-sanitize/CMakeCache.txt ] || cmake --preset sanitize
	cmake --build --preset sanitize -j $(JOBS)
	ctest --preset sanitize -j $(JOBS)

bench: build
	bash benchmarks/run.sh

clean:
	rm -rf build build-sanitize out
