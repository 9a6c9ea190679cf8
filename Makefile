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

demo: build
	scripts/demo.sh $(TWINPATH) $(OUT)

test: test-deps build
	ctest --preset $(PRESET)

bench: build
	$(TWINPATH) bench

format:
	git ls-files '*.cpp' '*.h' '*.hpp' | xargs clang-format -i

clean:
	rm -rf $(BUILD_DIR)
