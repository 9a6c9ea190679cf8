# Quick start: `make demo` and `make test`. Both install missing Debian packages first.
PRESET ?= release
BUILD_DIR := $(if $(filter release,$(PRESET)),build,build-$(PRESET))
TWINPATH := $(BUILD_DIR)/bin/twinpath
OUT ?= out/demo

.PHONY: all deps test-deps configure build demo test bench format clean
all: build

deps:
	@scripts/deps.sh build
test-deps:
	@scripts/deps.sh test

configure: deps
	@test -f $(BUILD_DIR)/build.ninja || cmake --preset $(PRESET)

build: configure
	cmake --build --preset $(PRESET)

# The demo builds only the executable; the tests (and Catch2) are make test's business.
demo: configure
	@echo "twinpath: building the executable (about 5 minutes on 2 cores the first time)"
	cmake --build --preset $(PRESET) --target twinpath
	scripts/demo.sh $(TWINPATH) $(OUT)

# Configures again with the tests switched on: a build tree that make demo configured has
# them off, and the test-only programs (chromium, spirv-val) were not installed then.
test: test-deps
	cmake --preset $(PRESET) -DTWINPATH_TESTS=ON
	cmake --build --preset $(PRESET)
	ctest --preset $(PRESET)

bench: build
	$(TWINPATH) bench

format:
	git ls-files '*.cpp' '*.h' '*.hpp' | xargs clang-format -i

clean:
	rm -rf $(BUILD_DIR)
