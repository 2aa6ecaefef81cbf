# The front door of a raybook assignment (written by raybook's make assignment N from
# tests/exercises/assignment.mk). Every target configures and builds what it needs.
BUILD   ?= build
JOBS    ?= $(shell nproc)
CHAPTER := @CHAPTER@
CHAPTERS := $(shell seq 1 $(CHAPTER))
CHAPTER_TARGETS := $(addprefix chapter,$(CHAPTERS))
# raybook's suites that need the whole book (every chapter, the seed scenes, the docs), left out
# of make test here.
WHOLE_BOOK := @WHOLE_BOOK@

.PHONY: configure rt check test docs clean $(CHAPTER_TARGETS)

$(BUILD)/CMakeCache.txt: CMakeLists.txt
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release

configure: $(BUILD)/CMakeCache.txt

# make chapterN: ./rt built from chapters 1..N.
$(CHAPTER_TARGETS): chapter%: configure
	cmake --build $(BUILD) -j $(JOBS) --target rt_ch$*
	@cp -f $(BUILD)/rt_ch$* rt.tmp && mv -f rt.tmp rt
	@./rt --version

chapter%:
	@echo "make: this assignment holds chapters 1 to $(CHAPTER)" >&2
	@exit 1

rt: chapter$(CHAPTER)

# Your progress: chapter $(CHAPTER)'s tests, exercise by exercise, and its golden image.
check:
	python3 tests/exercises/assignment.py check . --build $(BUILD)

# Every test of chapters 1..$(CHAPTER) (unit tests, golden images, determinism).
test: configure
	cmake --build $(BUILD) -j $(JOBS)
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS) -E '^($(WHOLE_BOOK))$$'

# The chapter pages of chapters 1..$(CHAPTER), with chapter $(CHAPTER)'s exercises as stubs in the listings
# and the formulas drawn by MathJax from docs/html/mathjax (Debian's libjs-mathjax; no network).
docs: configure
	cmake --build $(BUILD) --target docs
	@echo "docs: $$(pwd)/docs/html/index.html"

clean:
	rm -rf $(BUILD) rt docs/html
