# Top-level entry points. `make demo` and `make test` work on a fresh Debian 12
# machine with only git and make: they install what is missing first.
BUILD_DIR ?= build
JOBS ?= 2
# The page of --html is built with npm (three.js from its registry). A node
# that brings its own npm (NodeSource's) is kept: Debian's npm conflicts
# with it.
NPM_PACKAGES := $(if $(shell command -v npm),,nodejs npm)
DEB_PACKAGES := cmake g++ python3 llvm-dev llvm-14-tools libfmt-dev \
                nlohmann-json3-dev libcli11-dev help2man libxxhash-dev googletest libgtest-dev libgmock-dev parallel \
                pkg-config pybind11-dev python3-dev python3-numpy python3-pandas \
                python3-dask python3-distributed python3-pytest librsvg2-bin python3-pil \
                chromium $(NPM_PACKAGES)
SUDO := $(shell [ "$$(id -u)" = 0 ] || echo sudo)

.PHONY: all deps install-missing build install demo test test-asan test-tsan fuzz bench difftest \
        check-format \
        format clean

all: build

# `make bench` adds its contenders: LinuxCNC's rs274 and valgrind.
BENCH_PACKAGES := linuxcnc-uspace valgrind libbenchmark-dev
# The tests' oracles: LinuxCNC's rs274, a locale with a decimal comma (the
# toolpath's numbers must not follow the C locale), and Neovim, a real
# editor's LSP client for mbc lsp.
TEST_PACKAGES := linuxcnc-uspace locales-all neovim

deps:
	@$(MAKE) --no-print-directory install-missing PACKAGES="$(DEB_PACKAGES)"

install-missing:
	@missing=""; \
	for p in $(PACKAGES); do \
	  dpkg-query -W -f='$${Status}' $$p 2>/dev/null | grep -q 'install ok installed' \
	    || missing="$$missing $$p"; \
	done; \
	if [ -n "$$missing" ]; then \
	  echo "installing:$$missing"; \
	  $(SUDO) apt-get update && \
	  DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y --no-install-recommends $$missing; \
	fi

$(BUILD_DIR)/CMakeCache.txt:
	cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=Release

build: deps $(BUILD_DIR)/CMakeCache.txt
	cmake --build $(BUILD_DIR) -j$(JOBS)

# mbc, the runtime library and header, and the CMake package
# (docs/embedding.md) under PREFIX.
PREFIX ?= /usr/local
install: build
	cmake --install $(BUILD_DIR) --prefix $(PREFIX)

demo: build
	@echo "== mbc run examples/bolt_circle.nc (toolpath, DPRNT, variables) =="
	$(BUILD_DIR)/mbc run examples/bolt_circle.nc --toolpath $(BUILD_DIR)/demo.toolpath.jsonl \
	  --vars-out $(BUILD_DIR)/demo.vars.json --gcode $(BUILD_DIR)/demo.flat.nc \
	  --svg $(BUILD_DIR)/demo.svg
	@echo "== toolpath ($(BUILD_DIR)/demo.toolpath.jsonl) =="
	@cat $(BUILD_DIR)/demo.toolpath.jsonl
	@echo "== variables ($(BUILD_DIR)/demo.vars.json) =="
	@cat $(BUILD_DIR)/demo.vars.json; echo
	@echo "== flattened G-code ($(BUILD_DIR)/demo.flat.nc) =="
	@cat $(BUILD_DIR)/demo.flat.nc
	@echo "== drawing: open $(BUILD_DIR)/demo.svg in a browser =="
	@# The 3D page needs the page npm fetched at build time: said if missing.
	@if why=$$($(BUILD_DIR)/mbc run examples/bolt_circle.nc --html $(BUILD_DIR)/demo.html \
	     --dprnt /dev/null 2>&1 >/dev/null | grep 'error:'); then echo "$$why"; \
	 else echo "== 3D view: open $(BUILD_DIR)/demo.html in a browser =="; fi

test: build
	@$(MAKE) --no-print-directory install-missing PACKAGES="$(TEST_PACKAGES)"
	cd $(BUILD_DIR) && ctest --output-on-failure -j$(JOBS)

# Not part of `make test`: timings need a quiet machine (bench/README.md).
bench: build
	@$(MAKE) --no-print-directory install-missing PACKAGES="$(BENCH_PACKAGES)"
	cmake -S . -B $(BUILD_DIR) -DMBC_MICRO_BENCH=ON
	cmake --build $(BUILD_DIR) -j$(JOBS) --target mbc_micro
	python3 bench/run.py --mbc $(BUILD_DIR)/mbc --micro $(BUILD_DIR)/bench/mbc_micro \
	  --out bench/RESULTS.md

# The whole suite built with AddressSanitizer and UndefinedBehaviorSanitizer;
# any report fails its test. A Debug build: assertions on, and the IR
# verified after every pass of every compile (toolchain/ir_pipeline.cpp).
ASAN_BUILD_DIR ?= build-asan
# The threads under ThreadSanitizer: the toolpath's writer thread and
# mbc batch's workers, in a build of their own (mbc only).
TSAN_BUILD_DIR ?= build-tsan
test-tsan: deps
	cmake -S . -B $(TSAN_BUILD_DIR) -DCMAKE_BUILD_TYPE=Debug -DMBC_SANITIZE=thread
	cmake --build $(TSAN_BUILD_DIR) -j$(JOBS) --target mbc
	cd $(TSAN_BUILD_DIR) && ctest --output-on-failure -j$(JOBS) -R '^(writer|batch)/'

test-asan: deps
	@$(MAKE) --no-print-directory install-missing PACKAGES="$(TEST_PACKAGES)"
	cmake -S . -B $(ASAN_BUILD_DIR) -DCMAKE_BUILD_TYPE=Debug \
	  -DMBC_SANITIZE=address,undefined
	cmake --build $(ASAN_BUILD_DIR) -j$(JOBS)
	cd $(ASAN_BUILD_DIR) && ctest --output-on-failure -j$(JOBS)

# libFuzzer targets (tests/fuzz) built with clang-14, coverage and the
# sanitizers, run for SECONDS each (tools/fuzz.sh); corpora grow in
# $(FUZZ_BUILD_DIR)/fuzz-corpus, failing inputs land in fuzz-crashes.
FUZZ_BUILD_DIR ?= build-fuzz
FUZZ_PACKAGES := clang-14 libclang-rt-14-dev
SECONDS ?= 60
fuzz: deps
	@$(MAKE) --no-print-directory install-missing PACKAGES="$(FUZZ_PACKAGES)"
	CC=clang-14 CXX=clang++-14 cmake -S . -B $(FUZZ_BUILD_DIR) \
	  -DCMAKE_BUILD_TYPE=RelWithDebInfo -DMBC_FUZZ=ON
	cmake --build $(FUZZ_BUILD_DIR) -j$(JOBS) --target fuzz_frontend fuzz_pipeline fuzz_profile fuzz_lsp \
	  fuzz_lsp_server
	tools/fuzz.sh $(FUZZ_BUILD_DIR) $(SECONDS)

# Random programs under every engine against the interpreter
# (tools/difftest.py), then the machine model's oracles on as many seeds
# (tools/oracles.py); a difference or a violation is reduced and written
# to $(BUILD_DIR).
N ?= 1000
SEED ?= 1
difftest: build
	@$(MAKE) --no-print-directory install-missing PACKAGES="$(TEST_PACKAGES)"
	python3 tools/difftest.py --mbc $(BUILD_DIR)/mbc \
	  --engines $(BUILD_DIR)/tests/difftest_engines -n $(N) --seed $(SEED) \
	  --jobs $(JOBS) --out $(BUILD_DIR)
	python3 tools/oracles.py --mbc $(BUILD_DIR)/mbc -n $(N) --seed $(SEED) \
	  --jobs $(JOBS) --out $(BUILD_DIR)

# Debian 12's clang-format (14), the version the tree is formatted with.
check-format:
	@$(MAKE) --no-print-directory install-missing PACKAGES=clang-format-14
	clang-format-14 --dry-run -Werror $$(git ls-files '*.cpp' '*.h')

format:
	@$(MAKE) --no-print-directory install-missing PACKAGES=clang-format-14
	clang-format-14 -i $$(git ls-files '*.cpp' '*.h')

clean:
	rm -rf $(BUILD_DIR)
