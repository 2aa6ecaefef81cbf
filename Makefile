# raybook's front door. Every target installs what is missing, configures and builds, so any of
# them works as the first command on a fresh clone: make demo, make chapterN, make rt, make test.
BUILD      ?= build
JOBS       ?= $(shell nproc)
# The written chapters: one scene each, scenes/chapterNN-<slug>.lua.
CHAPTERS   := $(sort $(patsubst 0%,%,$(shell ls scenes 2>/dev/null | sed -n 's/^chapter\([0-9][0-9]\)-.*\.lua$$/\1/p')))
CHAPTERS   := $(shell echo $(CHAPTERS) | tr ' ' '\n' | sort -n | tr '\n' ' ')
LAST       := $(lastword $(CHAPTERS))
CHAPTER_TARGETS := $(addprefix chapter,$(CHAPTERS))
# ninja-build: make test's assignments round trip builds its exports with Ninja (assignment.py
# use_ninja); everything else builds with CMake's Makefiles.
DEBS       := g++ cmake make pkg-config libglm-dev libstb-dev catch2 liblua5.4-dev doxygen graphviz libjs-mathjax python3 libnanovdb-dev ccache \
              ninja-build
BENCH_DEBS := povray libembree-dev hyperfine gnuplot-nox blender
# Open MPI, for rendering on many processes (mpirun -np N ./rt scene.lua): make mpi installs it,
# and so does make test, so that the MPI tests always run.
MPI_DEBS   := openmpi-bin libopenmpi-dev
# make fuzz: libFuzzer and the sanitizers come with clang; the targets run one after the other.
FUZZ_DEBS    := clang libclang-rt-14-dev libomp-14-dev
FUZZ_BUILD   ?= build-fuzz
FUZZ_SECONDS ?= 60
FUZZ_TARGETS := obj lua_scene options journal stats compare vdb
SUDO       := $(shell [ "$$(id -u)" = 0 ] || echo sudo)

.PHONY: deps bench-deps mpi-deps mpi configure rt test test-exercises test-assignments assignment grade \
        test-sanitize sanitize-ctest sanitize-build soak demo docs golden-update bench charts fuzz web web-bundle clean \
        $(CHAPTER_TARGETS)

# Install the Debian packages that are missing (nothing when all are present).
deps:
	@missing=$$(for p in $(DEBS); do dpkg-query -W -f='$${Status}' $$p 2>/dev/null | grep -q 'ok installed' || echo $$p; done); \
	if [ -n "$$missing" ]; then \
	  echo "installing:" $$missing; \
	  $(SUDO) apt-get update -qq && DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq $$missing; \
	fi

bench-deps:
	@$(MAKE) --no-print-directory deps DEBS="$(BENCH_DEBS)"

mpi-deps:
	@$(MAKE) --no-print-directory deps DEBS="$(MPI_DEBS)"

$(BUILD)/CMakeCache.txt: CMakeLists.txt
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release

configure: deps $(BUILD)/CMakeCache.txt

# make chapterN: ./rt built from chapters 1..N and nothing later. (A static pattern rule: GNU
# Make never searches plain pattern rules for .PHONY targets.)
$(CHAPTER_TARGETS): chapter%: configure
	cmake --build $(BUILD) -j $(JOBS) --target rt_ch$*
	@cp -f $(BUILD)/rt_ch$* rt.tmp && mv -f rt.tmp rt
	@./rt --version

# A chapter that is not written yet.
chapter%:
	@echo "make: chapter $* is planned but not written yet; the written chapters are $(CHAPTERS)" >&2
	@exit 1

rt: chapter$(LAST)

# make mpi: install Open MPI, configure again so that CMake finds it, and build ./rt with it;
# then mpirun -np N ./rt scene.lua renders on N processes (docs/many-machines.md).
mpi: mpi-deps configure
	cmake -S . -B $(BUILD) >/dev/null
	@$(MAKE) --no-print-directory rt

# Every test: the unit tests, golden images, scenes, bad input, MPI runs and the docs' live
# panels (CTest; Open MPI is installed first and CMake configured again to find it; before the
# whole-book suites, make web installs emscripten and Chromium and builds rt as WebAssembly, and
# make docs the pages with their live panels, which CMake, configured again, then tests), then the chapter
# ladder the way a student climbs it (make chapterN for each N), which leaves ./rt the newest,
# then the assignments' round trip and grading (make test-assignments). The round trip is also
# the check that the tests notice every exercise region: each region's stub must redden its
# row, and each blank, planted in the solved chapter, its own row. The mutation check (make
# test-exercises) proves less with the same builds (a blank makes some test of the chapter
# fail), so make test leaves it out.
#
# The loop after a change: the unit tests and golden images always run. The slower checks carry
# content-hash stamps (tests/exercises/stamps.py, under BUILD/stamps/) and run again only when
# the files they depend on changed: a chapter's round trip and ladder rung when
# that chapter's own files, core or the tools changed; the whole-book CTest suites (scenes,
# determinism, bad input, MPI, batch, docs) when anything outside the chapter modules changed.
# A skipped check says so. FULL=1, and CI (CI=true), drop the stamps and run everything.
FULL ?= $(if $(filter true,$(CI)),1)
STAMPS_PY := python3 tests/exercises/stamps.py
# Each stage says how long it took ("make test: the build took 212 s").
STAGE_START = @date +%s >$(BUILD)/stage-start
stage_took = @echo "make test: $(1) took $$(($$(date +%s) - $$(cat $(BUILD)/stage-start))) s"
test: mpi-deps configure
	cmake -S . -B $(BUILD) >/dev/null
	$(STAGE_START)
	cmake --build $(BUILD) -j $(JOBS)
	$(call stage_took,the build)
	$(if $(FULL),rm -rf $(BUILD)/stamps)
	$(STAGE_START)
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS) -L 'unit|golden'
	$(call stage_took,the unit tests and golden images)
	$(STAGE_START)
	@if $(STAMPS_PY) stale $(BUILD) suite suite; then \
	  $(MAKE) --no-print-directory web docs && cmake -S . -B $(BUILD) >/dev/null && \
	  (cd $(BUILD) && ctest --output-on-failure -j $(JOBS) -LE 'unit|golden') && \
	  $(STAMPS_PY) record $(BUILD) suite suite; \
	else \
	  echo "skip the whole-book CTest suites: nothing outside the chapter modules changed since they passed (make test FULL=1 runs them)"; \
	fi
	$(call stage_took,make web and docs and the whole-book suites)
	$(STAGE_START)
	LADDER_STAMPS=1 bash tests/ladder.sh "$(MAKE) --no-print-directory BUILD=$(BUILD)" $(BUILD) "$(CHAPTERS)"
	$(call stage_took,the chapter ladder)
	$(STAGE_START)
	$(MAKE) --no-print-directory test-assignments ROUNDTRIP_STAMPS=1
	$(call stage_took,the assignments' round trip and grading)

# The tests prove they can fail: each exercise region, blanked one at a time, must make one of
# its chapter's tests fail (only the test program is rebuilt, and only that chapter's tests run).
# Quicker than the round trip while writing a chapter's tests (regions.py mutate --only ID);
# make test relies on the round trip, which checks this and more.
test-exercises: configure
	cmake --build $(BUILD) -j $(JOBS) --target raybook_tests
	python3 tests/exercises/regions.py mutate $(BUILD)

# Assignments (tests/exercises/assignment.py): make assignment N [DIR=...] writes chapters 1..N
# as a project of its own, chapter N's exercise regions replaced by stubs; make grade DIR=...
# checks one such project, or a folder of them, and writes a CSV. `make assignment 5` works as
# written: the number after "assignment" is its argument, not a target.
ifeq (assignment,$(firstword $(MAKECMDGOALS)))
  N ?= $(word 2,$(MAKECMDGOALS))
  ifneq ($(word 2,$(MAKECMDGOALS)),)
    $(eval $(word 2,$(MAKECMDGOALS)):;@:)
  endif
endif
assignment:
	@[ -n "$(N)" ] || { echo "usage: make assignment N [DIR=assignment-chNN]" >&2; exit 2; }
	python3 tests/exercises/assignment.py export $(N) \
	  $(or $(DIR),assignment-ch$(shell printf %02d $(N) 2>/dev/null))

grade:
	@[ -n "$(DIR)" ] || { echo "usage: make grade DIR=project-or-folder [CSV=grades.csv] [PARALLEL=P]" >&2; \
	  exit 2; }
	python3 tests/exercises/assignment.py grade $(DIR) $(if $(CSV),--csv $(CSV)) \
	  $(if $(PARALLEL),--parallel $(PARALLEL))

# The assignments' round trip (every chapter: export, make check fails every exercise; restore
# the regions one at a time, and after each its row and the earlier ones pass, the later ones
# fail; solved, everything passes; each exercise's blank planted as a bug reddens its own row
# and only rows that need it) and make grade over an untouched, a solved and a buggy project,
# and the Monte Carlo goldens' planted solutions (tests/exercises/test_assignments.sh: the last
# two run beside the round trip, each into its own log, since none of the three keeps the cores
# busy alone). Each project builds in its own build/ folder, as make check does, through ccache
# (raybook's own build's cache: a file an export did not change is not compiled again); without
# ccache through objcache.py, in BUILD/objcache.
test-assignments: export RB_OBJCACHE = $(abspath $(BUILD))/objcache
test-assignments:
	bash tests/exercises/test_assignments.sh $(BUILD) $(if $(ROUNDTRIP_STAMPS),--stamps)

# The same CTest suite (unit tests, golden images, bad input, scenes, batch, interrupt, MPI)
# built with AddressSanitizer and UndefinedBehaviorSanitizer, in its own build folder (no
# benchmarks; the ladder is left out, since it rebuilds ./rt, and so are the two docs tests,
# which run Doxygen and no raybook code, and the determinism and golden-all tests, which check
# pictures the sanitizers cannot change, with code scenes_smoke runs there too). Any report fails its test:
#   halt_on_error, -fno-sanitize-recover=all  the first report ends the program;
#   exitcode=66                               ... with an exit code no test expects;
#   detect_leaks=1                            LeakSanitizer checks the heap at exit;
#   allocator_may_return_null=1               an allocation too large for memory throws
#                                             std::bad_alloc, as in the normal build (rt says
#                                             "out of memory"), instead of a sanitizer abort;
#   print_stacktrace=1                        UBSan prints where, not only what.
SANITIZE_BUILD ?= build-sanitize
SANITIZER_ENV  := ASAN_OPTIONS=halt_on_error=1:exitcode=66:detect_leaks=1:allocator_may_return_null=1 \
                  UBSAN_OPTIONS=halt_on_error=1:exitcode=66:print_stacktrace=1
#
# SANITIZE_CTEST picks the tests and the parallelism (ctest options, default -j JOBS: all of
# them); CI runs the unit tests and golden images beside make test and the rest after it
# (.ci/run). make sanitize-ctest runs them without building first.
SANITIZE_CTEST ?= -j $(JOBS)
test-sanitize: sanitize-build
	$(MAKE) --no-print-directory sanitize-ctest

sanitize-ctest:
	cd $(SANITIZE_BUILD) && $(SANITIZER_ENV) ctest --output-on-failure $(SANITIZE_CTEST)

# The instrumented tree alone (make test-sanitize builds it first; .ci/run builds it beside make
# test at the lowest priority: make test leaves src/ as it is, its round trip plants stubs and
# bugs in exported copies; make test-exercises, which plants them in src/, must not run beside
# it).
sanitize-build: deps
	cmake -S . -B $(SANITIZE_BUILD) -DCMAKE_BUILD_TYPE=Release -DRB_SANITIZE=ON
	cmake --build $(SANITIZE_BUILD) -j $(JOBS)

# make soak (issue 40): SOAK_N random legal scenes of every chapter, of seed SOAK_SEED, rendered
# by the sanitizer tree's rt on one thread and on two under a random --max-memory and
# --time-limit, their films checked for NaN in-process (tests/soak/README.md). Never part of
# make test: about 4 s a scene on two cores under a heavy load (2,000 took 51 minutes as up to four
# workers side by side, soak.sh FIRST).
SOAK_N    ?= 300
SOAK_SEED ?= 1
soak: sanitize-build
	cmake --build $(SANITIZE_BUILD) -j $(JOBS) --target soak_film
	$(SANITIZER_ENV) bash tests/soak/soak.sh $(SANITIZE_BUILD) $(SOAK_N) $(SOAK_SEED)
	@# The MPI chaos test at full size (make test runs it with 3 kills at 64x48): 12 random
	@# SIGKILLs under mpirun -np 3, each followed by --resume on 1-3 ranks (docs/many-machines.md).
	@if [ -x $(SANITIZE_BUILD)/rt_ch$(LAST) ] && command -v mpirun >/dev/null; then \
	  $(SANITIZER_ENV) python3 tests/mpi/chaos.py $(SANITIZE_BUILD)/rt_ch$(LAST) $(SANITIZE_BUILD)/soak-chaos \
	    --kills 12 --size 192x128; \
	fi

demo: rt
	./rt --features=all scenes/showcase.lua
	@echo "demo image: $$(pwd)/showcase.png"

# make docs EDITION=student: the student edition, every exercise region's code replaced by its
# stub in the listings (tests/exercises/student_docs.py), into docs/student/html, for an
# instructor to publish.
#
# With emscripten installed (make web installs it), make docs also builds the chapter pages'
# live panels: rt as WebAssembly, and src/web/bundle.py's docs/html/live/raybook-live.js.
docs: configure
ifeq ($(EDITION),student)
	cmake --build $(BUILD) --target docs-student
	@if command -v emcc >/dev/null; then $(MAKE) --no-print-directory web-bundle WEB_OUT=docs/student/html/live; \
	  else echo "docs: without the live panels (emscripten is not installed; make web installs it)"; fi
	@echo "docs (student edition): $$(pwd)/docs/student/html/index.html"
else ifeq ($(EDITION),)
	cmake --build $(BUILD) --target docs
	@if command -v emcc >/dev/null; then $(MAKE) --no-print-directory web-bundle; else \
	  echo "docs: without the live panels (emscripten is not installed; make web installs it)"; fi
	@echo "docs: $$(pwd)/docs/html/index.html"
else
	@echo "make docs: EDITION=$(EDITION) is not an edition; leave it out (the full docs) or use EDITION=student" >&2
	@exit 2
endif

# Regenerate every golden image deliberately (the chapter scenes, each by its own chapter's
# binary, and the seed scenes by the newest); say why in the commit message.
golden-update: configure
	cmake --build $(BUILD) -j $(JOBS)
	@for s in scenes/chapter[0-9][0-9]-*.lua; do \
	  n=$$(basename $$s | cut -c8-9 | sed 's/^0//'); \
	  bash tests/golden/run_golden.sh $(BUILD)/rt_ch$$n $$s golden $(BUILD)/golden-report --update || exit 1; \
	done
	@for s in scenes/seeds/[0-9][0-9][0-9]-*.lua; do \
	  bash tests/golden/run_golden.sh $(BUILD)/rt_ch$(LAST) $$s golden $(BUILD)/golden-report --update || exit 1; \
	done

# Benchmarks against POV-Ray and Embree (not a test: CI never gates on timings).
bench: bench-deps mpi-deps configure
	cmake -S . -B $(BUILD) >/dev/null
	cmake --build $(BUILD) -j $(JOBS)
	bash tests/perf/bench.sh $(BUILD)
	@# The live panels' cost (issue 25): the bundle's size, and each chapter's scene at 160x120 in
	@# headless Chromium against native rt on one thread; with emscripten installed.
	@if command -v emcc >/dev/null; then $(MAKE) --no-print-directory docs && \
	  python3 tests/perf/web/bench_live.py --bundle docs/html/live/raybook-live.js \
	    --rt $(BUILD)/rt_ch$(LAST) --out $(BUILD)/bench-live.md; \
	else echo "bench: no live-panel numbers (emscripten is not installed; make web installs it)"; fi

# Charts for the chapter pages, into docs/charts/.
charts: bench-deps configure
	cmake --build $(BUILD) -j $(JOBS)
	bash tests/perf/charts.sh $(BUILD)

# Fuzz each reader of untrusted bytes (OBJ, scene scripts, the command line, --resume's
# journal, .stats files, --compare's images, NanoVDB grids), FUZZ_SECONDS each (60 by
# default; make fuzz FUZZ_SECONDS=600 for longer), built with clang, libFuzzer, ASan and UBSan
# in their own folder. Never part of make test, which replays the corpus instead.
fuzz:
	@$(MAKE) --no-print-directory deps DEBS="$(DEBS) $(FUZZ_DEBS)"
	@[ -f $(FUZZ_BUILD)/CMakeCache.txt ] || CC=clang CXX=clang++ cmake -S . -B $(FUZZ_BUILD) \
	  -DCMAKE_BUILD_TYPE=RelWithDebInfo -DRB_FUZZ=ON -DBUILD_TESTING=OFF
	cmake --build $(FUZZ_BUILD) -j $(JOBS) --target $(addprefix fuzz_,$(FUZZ_TARGETS))
	bash tests/fuzz/run.sh $(FUZZ_BUILD) $(FUZZ_SECONDS) $(FUZZ_TARGETS)

# make web: rt as WebAssembly (src/web/README.md), for the docs' live panels: Debian's
# emscripten builds build-web/rt_web.js from the same sources, and the page's Lua (wasmoon, from
# the npm registry, the version pinned in src/web/package.json) goes to build-web/npm. emcc
# needs NODE_PATH to find Debian's acorn (DESIGN section 10).
WEB_BUILD ?= build-web
# Node.js and npm come with the machine (emscripten needs Node.js; Debian's npm would replace it).
WEB_DEBS  := emscripten chromium
web:
	@$(MAKE) --no-print-directory deps DEBS="$(WEB_DEBS)"
	@[ -f $(WEB_BUILD)/CMakeCache.txt ] || NODE_PATH=/usr/share/nodejs emcmake cmake -S . -B $(WEB_BUILD) \
	  -DCMAKE_BUILD_TYPE=Release
	NODE_PATH=/usr/share/nodejs cmake --build $(WEB_BUILD) -j $(JOBS) --target rt_web
	@command -v npm >/dev/null || { echo "make web: npm is missing (it comes with Node.js)" >&2; exit 1; }
	@mkdir -p $(WEB_BUILD)/npm
	@cmp -s src/web/package-lock.json $(WEB_BUILD)/npm/package-lock.json || { \
	  cp src/web/package.json src/web/package-lock.json $(WEB_BUILD)/npm/ && \
	  (cd $(WEB_BUILD)/npm && npm ci --silent --no-audit --no-fund); }

# The live panels' one script, from rt_web.js, the page's Lua and the chapter scenes.
WEB_OUT ?= docs/html/live
web-bundle: web
	python3 src/web/bundle.py --rt $(WEB_BUILD)/rt_web.js --lua-host src/web/lua_host.js \
	  --wasmoon $(WEB_BUILD)/npm/node_modules/wasmoon --out $(WEB_OUT)

clean:
	rm -rf $(BUILD) $(FUZZ_BUILD) $(SANITIZE_BUILD) $(WEB_BUILD) rt
