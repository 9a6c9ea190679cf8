# Quick start: `make demo` and `make test`. Both install missing Debian packages first.
PRESET ?= release
BUILD_DIR := $(if $(filter release,$(PRESET)),build,build-$(PRESET))
TWINPATH := $(BUILD_DIR)/bin/twinpath
OUT ?= out/demo

.PHONY: all deps test-deps configure build demo demo-notice test test-notice bench format clean
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
# The notices give the times measured in a fresh root (README, scripts/fresh_machine_check.sh).
demo: demo-notice configure
	cmake --build --preset $(PRESET) --target twinpath
	scripts/demo.sh $(TWINPATH) $(OUT)
demo-notice:
	@echo "twinpath: the first make demo on a fresh Debian 12 takes about 5 minutes on 2 idle cores"
	@echo "twinpath: (15 when they are busy): install some 370 packages (324 MB), build, render, compare"

# Configures again with the tests switched on: a build tree that make demo configured has
# them off, and the test-only programs (chromium, spirv-val) were not installed then.
test: test-notice test-deps
	cmake --preset $(PRESET) -DTWINPATH_TESTS=ON
	cmake --build --preset $(PRESET)
	ctest --preset $(PRESET)
test-notice:
	@echo "twinpath: the first make test after make demo takes about 8 minutes on 2 idle cores"
	@echo "twinpath: (23 when they are busy): install Catch2 and Chromium, build the tests, run them"

bench: build
	$(TWINPATH) bench

format:
	git ls-files '*.cpp' '*.h' '*.hpp' | xargs clang-format -i

clean:
	rm -rf $(BUILD_DIR)
