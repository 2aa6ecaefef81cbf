# raybook's front door. `make demo` and `make test` install what is missing, configure and build.
BUILD      ?= build
JOBS       ?= $(shell nproc)
CHAPTERS   := 1 2 3 4 5 6 7
LAST       := $(lastword $(CHAPTERS))
DEBS       := g++ cmake make pkg-config libglm-dev libstb-dev catch2 liblua5.4-dev doxygen graphviz libjs-mathjax
BENCH_DEBS := povray libembree-dev hyperfine gnuplot-nox
SUDO       := $(shell [ "$$(id -u)" = 0 ] || echo sudo)

.PHONY: deps bench-deps configure rt test demo docs golden-update bench charts clean $(addprefix chapter,$(CHAPTERS))

# Install the Debian packages that are missing (nothing when all are present).
deps:
	@missing=$$(for p in $(DEBS); do dpkg-query -W -f='$${Status}' $$p 2>/dev/null | grep -q 'ok installed' || echo $$p; done); \
	if [ -n "$$missing" ]; then \
	  echo "installing:" $$missing; \
	  $(SUDO) apt-get update -qq && DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq $$missing; \
	fi

bench-deps:
	@$(MAKE) --no-print-directory deps DEBS="$(BENCH_DEBS)"

$(BUILD)/CMakeCache.txt: CMakeLists.txt
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release

configure: deps $(BUILD)/CMakeCache.txt

# make chapterN: ./rt built from chapters 1..N.
chapter%: configure
	cmake --build $(BUILD) -j $(JOBS) --target rt_ch$*
	cp $(BUILD)/rt_ch$* ./rt

rt: chapter$(LAST)

test: configure
	cmake --build $(BUILD) -j $(JOBS)
	cp $(BUILD)/rt_ch$(LAST) ./rt
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

demo: rt
	./rt --features=all scenes/showcase.lua
	@echo "demo image: $$(pwd)/showcase.png"

docs: configure
	cmake --build $(BUILD) --target docs
	@echo "docs: $$(pwd)/docs/html/index.html"

# Regenerate every golden image deliberately; say why in the commit message.
golden-update: configure
	cmake --build $(BUILD) -j $(JOBS)
	@for s in scenes/chapter[0-9][0-9]-*.lua; do \
	  n=$$(basename $$s | cut -c8-9 | sed 's/^0//'); \
	  bash tests/golden/run_golden.sh $(BUILD)/rt_ch$$n $$s golden $(BUILD)/golden-report $(BUILD)/tests/rb_imgdiff --update || exit 1; \
	done

# Benchmarks against POV-Ray and Embree (not a test: CI never gates on timings).
bench: bench-deps configure
	cmake -S . -B $(BUILD) >/dev/null
	cmake --build $(BUILD) -j $(JOBS)
	bash tests/perf/bench.sh $(BUILD)

# Charts for the chapter pages, into docs/charts/.
charts: bench-deps configure
	cmake --build $(BUILD) -j $(JOBS)
	bash tests/perf/charts.sh $(BUILD)

clean:
	rm -rf $(BUILD) rt
