# vlbe -- build, test, benchmark.  GNU make + a C99 compiler.
#
#   make test           header checks, the C blocks of the docs (check-docs),
#                       the first program in double and float (check-first),
#                       every tests/test_*.c in three builds
#                       (double -O2, float -O1, ASan+UBSan -O0; TEST_CFGS)
#                       and run, the double -O2 binaries of VALGRIND_SUITES
#                       under valgrind when it is installed, make check-m4;
#                       all through make's job server (-j<cores + 1> unless -j
#                       is given), each binary under a time limit; then the
#                       measured numbers of the test comments against their
#                       logs and the summary
#   make vg-cover       the library lines each suite executes (gcov), and
#                       those the valgrind set leaves (tests/vgcover.sh)
#   make demo           build the examples and run the paper scenes (out/demo/),
#                       then the work-precision charts (out/wp_*.svg, every
#                       bench/wp_*.c at -O2)
#   make bench          build and run bench/*.c (-O3 -march=native), out/bench/;
#                       where LAPACKE is installed also bench_lu beside
#                       LAPACK's band LU (build/bench/bench_lu_lapacke)
#   make bench-scale    time per step of a clamped chain, 4 .. 1024 elements, dense vs banded
#   make examples       build examples/*.c with the full warning set
#   make check-headers  each header alone, twice, as C++, in float mode
#   make check-docs     every C block of README.md and docs/*.md compiled, their
#                       links and quoted names checked (tests/doc_blocks.sh)
#   make check-m4       the tests/m4 programs built for a Cortex-M4F (float,
#                       hard FPU) and run under qemu-system-arm -M mps2-an386,
#                       each output against the host float run; no double
#                       arithmetic in the images, image sizes, stack per
#                       public function (build/m4/; make m4-tools installs
#                       the ARM toolchain and QEMU with apt-get as root)
#   make measured-update  rerun the tests and rewrite the measured numbers
#                       quoted in test comments (tests/measured.sh) from them
#   make lint           cppcheck
#   make cmocka         make sure cmocka is usable (installs it with apt-get
#                       when run as root on Debian)
#   make fuzz           build the libFuzzer harnesses fuzz/fuzz_*.c with clang
#                       (ASan + UBSan) and run each for FUZZ_TIME seconds
#                       (default 600 / number of harnesses) from its seed
#                       corpus fuzz/corpus/<name>/; new inputs and crash
#                       files go to build/fuzz/ (FUZZ_SEEDS=<dir pattern>,
#                       % = harness name, to start from other seeds)
#   make fuzz-build     build them only; make fuzz-clang: the clang check
#   make mutate         apply each edit of tests/mutations.txt to a copy of the
#                       tree and run its suites; MUTATIONS=<ids> for a subset
#                       (report: build/mutate/report.txt)
#   make clean
#
# cmocka from somewhere else: make test CMOCKA_CFLAGS=-I/opt/cmocka/include \
#                                       CMOCKA_LIBS="-L/opt/cmocka/lib -lcmocka"

ifeq ($(origin CC),default)
CC = cc
endif
ifeq ($(origin CXX),default)
CXX = c++
endif
CSTD = -std=c99
WARN = -Wall -Wextra -Wpedantic -Wshadow -Wstrict-prototypes -Wmissing-prototypes \
       -Wcast-qual -Wvla -Wdouble-promotion -Wfloat-conversion -Werror
CXXWARN = -Wall -Wextra -Werror
CMOCKA_CFLAGS ?=
CMOCKA_LIBS ?= -lcmocka
VALGRIND ?= valgrind
CPPCHECK ?= cppcheck

BUILD = build
OUT = out

HEADERS := $(wildcard vlbe.h ancf_ale.h rancf.h corot2d.h integrators.h)
reverse = $(if $(1),$(call reverse,$(wordlist 2,$(words $(1)),$(1))) $(firstword $(1)))

# -- scenes: the scene set-ups, run drivers, closed forms and the chart
# writer that examples, tests and benchmarks share (scenes/*.h) ------------
SCENE_DIR = scenes
SCENE_HDRS := $(wildcard $(SCENE_DIR)/*.h)

# -- tests: one binary per tests/test_*.c and build configuration ----------
TEST_DIR = tests
TEST_SRCS := $(wildcard $(TEST_DIR)/test_*.c)
TEST_NAMES := $(basename $(notdir $(TEST_SRCS)))
# tests include the scene headers: they are dependencies too;
# tests/test_fuzz_corpus.c includes the fuzz harnesses
TEST_DEPS = $(HEADERS) $(wildcard $(TEST_DIR)/*.h) $(SCENE_HDRS) $(wildcard fuzz/*.c fuzz/*.h)
# the corpus replay marks its snapshots defined for valgrind (fuzz/fuzz_util.h)
# where valgrind's client-request header is installed
MEMCHECK_DEF := $(if $(wildcard /usr/include/valgrind/memcheck.h),-DVLBE_FUZZ_MEMCHECK)
# The builds make test runs.  dbl-O0 (double, unoptimised) is defined but
# not among them: the sanitizer build is double at -O0 too, and its logs are
# those of dbl-O0 line for line (every value, every measured number), so it
# runs the unoptimised code with the checks on top; make test
# TEST_CFGS="dbl dbl-O0 flt san" runs it as well.
TEST_CFGS ?= dbl flt san
CFG_dbl := -O2
CFG_dbl-O0 := -O0
# float at -O1: the build is there for the precision, and -O1 computes the
# same values as -O2 (ISO C mode: no contraction into FMA, no fast-math;
# every line of the float suites' logs is the same at both levels) for 60 % of the
# compile time; -O2's optimiser and its warnings on the same code are the
# dbl build's, and float at -O2 is what make check-m4 compiles
CFG_flt := -O1 -DVLBE_USE_FLOAT
# The sanitizer build is -O0.  Its point is the checks: ASan and UBSan
# instrument the program as gcc sees it before optimising, and at -O0 every
# load, store and operation of the source keeps its check (-O1 drops those of
# the accesses it folds away); the optimised code is what the dbl and flt
# builds run, and valgrind.  What -O0 gives up is UBSan's object-size check,
# which needs the optimiser to know sizes; out-of-bounds accesses are still
# ASan's (between objects) and -fsanitize=bounds' (indices of declared
# arrays).  gcc 12, 36 suites, one core: -O0 -g compiles in ~110 s of CPU,
# -O1 -g in ~600 s (variable tracking and register allocation of the
# instrumented code); the runs take ~100 s instead of ~45 s.  Both count as
# slow builds (tu_slow_run), so the same test variants run, and the measured
# numbers of the san build agree.
CFG_san := -O0 -g -fsanitize=address,undefined -fno-sanitize-recover=all
TEST_BINS := $(foreach c,$(TEST_CFGS),$(addprefix $(BUILD)/$(c)/,$(TEST_NAMES)))

# -- examples and benchmarks ------------------------------------------------
EXAMPLE_DIR = examples
EXAMPLE_SRCS := $(wildcard $(EXAMPLE_DIR)/*.c)
EXAMPLE_NAMES := $(basename $(notdir $(EXAMPLE_SRCS)))
EXAMPLE_BINS := $(addprefix $(BUILD)/examples/,$(EXAMPLE_NAMES))
EXAMPLE_DEPS := $(HEADERS) $(SCENE_HDRS)
# first_chain.c is the README's first program, not a paper scene (make
# check-first runs it)
DEMO_SCENES ?= $(filter-out first_chain,$(EXAMPLE_NAMES))

BENCH_SRCS := $(wildcard bench/*.c)
BENCH_NAMES := $(basename $(notdir $(BENCH_SRCS)))
BENCH_FLAGS = -O3 -march=native
BENCH_PORTABLE_FLAGS = -O2
BENCH_BINS := $(addprefix $(BUILD)/bench/,$(BENCH_NAMES))
BENCH_PORTABLE_BINS := $(addprefix $(BUILD)/bench/portable/,$(BENCH_NAMES))
# bench files include the scene headers (the problem definitions)
BENCH_DEPS := $(HEADERS) $(wildcard bench/*.h) $(SCENE_HDRS)
# the work-precision runs of `make demo` (every bench/wp_*.c): portable
# flags, the examples' warnings
DEMO_WP_NAMES := $(basename $(notdir $(wildcard bench/wp_*.c)))
DEMO_WP_FLAGS = -O2
DEMO_WP_BINS := $(addprefix $(BUILD)/demo/,$(DEMO_WP_NAMES))
# benchmarks that take an output directory rather than a file tag: the wp_*
BENCH_DIR_ARG := $(DEMO_WP_NAMES)
# bench_lu side by side with LAPACK's band LU, built only where LAPACKE is
# installed (Debian: liblapacke-dev); never required
LAPACKE_H := $(wildcard /usr/include/lapacke.h)
BENCH_LAPACKE_BINS := $(if $(LAPACKE_H),$(BUILD)/bench/bench_lu_lapacke)

.PHONY: all check test check-headers check-first cmocka test-build examples demo bench \
        bench-portable bench-scale lint clean fuzz fuzz-build fuzz-clang measured-update mutate \
        check-m4 m4-tools test-run vg-cover FORCE

all: test examples

check: test

# -- header hygiene ---------------------------------------------------------
check-headers:
	@set -e; for h in $(HEADERS); do \
	  echo "check-headers: $$h (C99 twice, C++11, float)"; \
	  printf '#include "%s"\n#include "%s"\n' $$h $$h | $(CC) $(CSTD) $(WARN) -I. -x c -fsyntax-only -; \
	  printf '#include "%s"\n' $$h | $(CXX) -std=c++11 $(CXXWARN) -I. -x c++ -fsyntax-only -; \
	  printf '#include "%s"\n#include "%s"\n' $$h $$h | $(CC) $(CSTD) $(WARN) -DVLBE_USE_FLOAT -I. -x c -fsyntax-only -; \
	done
	@echo "check-headers: all together, reverse order:$(call reverse,$(HEADERS))"
	@printf '#include "%s"\n' $(call reverse,$(HEADERS)) | $(CC) $(CSTD) $(WARN) -I. -x c -fsyntax-only -
	@printf '#include "%s"\n' $(call reverse,$(HEADERS)) | $(CC) $(CSTD) $(WARN) -DVLBE_USE_FLOAT -I. -x c -fsyntax-only -
	@printf '#include "%s"\n' $(call reverse,$(HEADERS)) | $(CXX) -std=c++11 $(CXXWARN) -I. -x c++ -fsyntax-only -
	@echo "check-headers: $(SCENE_DIR)/svgplot.h (C99 twice, C++11)"
	@printf '#include "$(SCENE_DIR)/svgplot.h"\n#include "$(SCENE_DIR)/svgplot.h"\n' | $(CC) $(CSTD) $(WARN) -I. -x c -fsyntax-only -
	@printf '#include "$(SCENE_DIR)/svgplot.h"\n' | $(CXX) -std=c++11 $(CXXWARN) -I. -x c++ -fsyntax-only -

# every ```c block of README.md and docs/*.md compiled and linked, double
# and float (tests/doc_blocks.sh says how fragments and mirrors of
# examples/*.c are compiled); relative links and quoted names checked
.PHONY: check-docs
check-docs:
	@CC='$(CC)' CSTD='$(CSTD)' WARN='$(WARN)' BUILD='$(BUILD)' MIRRORS_BUILT=first_chain.c \
	  sh tests/doc_blocks.sh

# -- cmocka -------------------------------------------------------------------
CMOCKA_PROBE = printf '\#include <stdarg.h>\n\#include <stddef.h>\n\#include <setjmp.h>\n\#include <stdint.h>\n\#include <cmocka.h>\nint main(void) { print_message("%%s", ""); return 0; }\n' | \
  $(CC) $(CMOCKA_CFLAGS) -x c - -o $(BUILD)/.cmocka-probe $(CMOCKA_LIBS) >/dev/null 2>&1

cmocka:
	@mkdir -p $(BUILD)
	@if $(CMOCKA_PROBE); then exit 0; fi; \
	if [ "$$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then \
	  echo "cmocka: not found, installing libcmocka-dev with apt-get"; \
	  { apt-get update && DEBIAN_FRONTEND=noninteractive apt-get -o DPkg::Lock::Timeout=600 install -y libcmocka-dev; } || true; \
	fi; \
	if $(CMOCKA_PROBE); then exit 0; fi; \
	echo "vlbe tests need cmocka (Debian: apt-get install libcmocka-dev; or set CMOCKA_CFLAGS/CMOCKA_LIBS)" >&2; \
	exit 1

# -- tests ------------------------------------------------------------------
# $(1) = configuration: the rule that builds build/$(1)/test_x from tests/test_x.c
define TEST_RULE
$(BUILD)/$(1)/%: $(TEST_DIR)/%.c $(TEST_DEPS) | cmocka
	@mkdir -p $$(@D)
	$$(CC) $$(CSTD) $$(WARN) $$(CFG_$(1)) $$(MEMCHECK_DEF) -I. $$(CMOCKA_CFLAGS) $$< -o $$@ $$(CMOCKA_LIBS) -lm
endef
$(foreach c,$(TEST_CFGS),$(eval $(call TEST_RULE,$(c))))

test-build: $(TEST_BINS)

# make test runs through make's job server: every build and every run is a
# target of its own, so on N cores N jobs go at once and a suite runs as
# soon as its binary exists.  `make test` alone re-invokes make with
# -j$(TEST_JOBS) (default: the number of cores) unless -j was given, and
# with -Otarget, so each target's output comes out whole when it finishes.
#
# Each run (target BUILD/<cfg>/<suite>.log; valgrind runs
# BUILD/dbl/<suite>.vg.log) has VLBE_TEST_REPORT=1 (the logs carry the
# MEASURED lines that tests/measured.sh checks against the comments) and a
# time limit: TEST_TIMEOUT seconds per binary, TEST_VG_TIMEOUT under
# valgrind, so a hang fails the run and names the suite.  The log is kept
# next to its binary, printed whole when the run ends (without the MEASURED
# lines), followed by a FAILED line when it failed; the exit status goes to
# <log>.rc.  A failing run leaves the others running.  make check-m4 runs
# beside them into BUILD/m4/check-m4.log.  When everything has run:
# tests/measured.sh (when every run passed), then cmocka's closing lines
# "[  PASSED  ] N test(s).", "[  SKIPPED ] N test(s)" and "[  FAILED  ] N
# test(s)" summed per build and in total, then the check-m4 log; the exit
# status is non-zero on any failure.
#
# Order: make starts the jobs of a target list from its left, so the lists
# below put the costly suites first (CPU seconds on one core, gcc 12 -O2:
# compile up to ~8 s, the longest runs ~20 s in the san build and ~15 s
# under valgrind); the short ones fill in at the end.  From a clean clone on
# two cores (gcc 12), one core's CPU seconds: the builds dbl ~210, flt
# (-O1) ~115, san ~125; check-m4 ~45, check-docs and check-first ~32; the
# runs dbl 17, flt 8, san ~105, valgrind ~59.
TEST_TIMEOUT ?= 300
TEST_VG_TIMEOUT ?= 1200
# one job more than cores: a job that links, starts or waits on its log
# leaves its core to the spare one (clean clone, 2 cores: 5 min 33 s with 3
# jobs against 5 min 41 s to 6 min 3 s with 2)
TEST_JOBS ?= $(shell n=$$(nproc 2>/dev/null || getconf _NPROCESSORS_ONLN 2>/dev/null || echo 2); echo $$((n + 1)))
TEST_SUMMARY = awk '{ b = FILENAME; sub(/\/[^\/]*$$/, "", b); sub(/.*\//, "", b); \
    if (FILENAME ~ /\.vg\.log$$/) b = b "+valgrind"; if (!(b in seen)) { seen[b] = 1; order[++nb] = b } } \
  /^\[  PASSED  \] [0-9]+ test/ { p[b] += $$4; P += $$4 } \
  /^\[  SKIPPED \] [0-9]+ test/ { s[b] += $$4; S += $$4 } \
  /^\[  FAILED  \] [0-9]+ test/ { f[b] += $$4; F += $$4 } \
  END { for (i = 1; i <= nb; ++i) printf "  %-14s %4d passed, %d failed, %d skipped\n", order[i], p[order[i]], f[order[i]], s[order[i]]; \
    if (F == 0 && fail != 0) F = 1; printf "tests: %d passed, %d failed, %d skipped\n", P, F, S }'

# the suites by falling cost of build and run; the others follow
TEST_COSTLY = test_scenes_band test_scenes_spin test_sliding_xcheck test_fuzz_corpus \
  test_spin_damping test_chain_ale test_scenes_shaft test_scenes_sliding test_katz \
  test_scenes_cable test_scenes_ale test_scenes_semicircle test_scenes_torsion \
  test_contract_chain test_scenes_moving3d test_contract_elem
TEST_ORDER := $(filter $(TEST_NAMES),$(TEST_COSTLY)) $(filter-out $(TEST_COSTLY),$(TEST_NAMES))

# Valgrind (memcheck) runs what it adds over ASan+UBSan, which run every
# suite: the use of uninitialised values, and the -O2 code.  Both are about
# the library's lines that a run executes, so the set below is chosen by
# line coverage: every suite built with --coverage (-O0, whose runs take the
# same slow-build variants as a run under valgrind) and the lines of vlbe.h,
# ancf_ale.h, rancf.h, corot2d.h and integrators.h that each executes
# (tests/vgcover.sh, make vg-cover).  All 44 suites execute 7365 lines; the
# 24 suites below execute 7351 of them, at ~49 s of valgrind CPU time
# (one core, gcc 12 -O2) instead of ~550 s (each of them executes lines no
# other one of the set does).  They leave 14 lines: vlbe_dae_stats_add
# (integrators.h, sums two counter records; run by test_scenes_sliding,
# test_scenes_band, test_sliding_xcheck).  The eigen-solvers, the
# linearisation and vlbe_dae_project are test_eig's, test_lin's and
# test_dae_project's (~2 s together); test_rancf_chain (~1 s) is the
# fastest of the suites that run vlbe_ale_chain_length to its end.  The
# suites left out are long integrations that go over the same lines again
# (test_scenes_spin, test_scenes_band and test_sliding_xcheck alone take
# ~210 s), the Campbell scenes of test_modal (~19 s) and the load-stepped
# beams of test_static_cr2d (~71 s), whose eigen-solver, linearisation and
# static-solver lines the suites above run, and test_katz, which checks
# the examples' reference solutions and executes no library line.
# VALGRIND_SUITES=all runs every suite under valgrind.
VALGRIND_SUITES ?= test_chain_ale test_integrators test_bdf test_ale3 \
  test_ale_inv test_rancf test_contract_core test_dae_band test_vlbe test_corot2d \
  test_chain_band test_contract_elem test_contract_chain \
  test_cr2d_band test_static test_band test_cr2d_trans test_loads test_chain_con3 test_prestress \
  test_eig test_lin test_dae_project test_rancf_chain
VG_NAMES := $(if $(filter all,$(VALGRIND_SUITES)),$(TEST_ORDER),$(filter $(TEST_NAMES),$(VALGRIND_SUITES)))
HAVE_VALGRIND := $(shell command -v $(VALGRIND) 2>/dev/null || true)
TEST_LOGS := $(foreach c,$(TEST_CFGS),$(addprefix $(BUILD)/$(c)/,$(addsuffix .log,$(TEST_NAMES))))
VG_LOGS := $(if $(HAVE_VALGRIND),$(addprefix $(BUILD)/dbl/,$(addsuffix .vg.log,$(VG_NAMES))))
M4_LOG = $(BUILD)/m4/check-m4.log
# the order the jobs start in: check-m4 (its own builds through the job
# server), the valgrind runs, then the builds by their longest runs
TEST_RUN_CFGS := $(filter $(TEST_CFGS),san dbl-O0 dbl flt) $(filter-out san dbl-O0 dbl flt,$(TEST_CFGS))
TEST_SCHEDULE := $(M4_LOG) $(VG_LOGS) \
  $(foreach c,$(TEST_RUN_CFGS),$(addprefix $(BUILD)/$(c)/,$(addsuffix .log,$(TEST_ORDER))))

# $(1) time limit, $(2) log, $(3) command: the run, its log, its verdict
exe_path = $(if $(filter /%,$(1)),$(1),./$(1))
TEST_RUN = rm -f $(2).rc; rc=0; \
  VLBE_TEST_REPORT=1 timeout -k 10 $(1) $(3) > $(2) 2>&1 < /dev/null || rc=$$?; \
  echo "== $(3)"; grep -v '^MEASURED ' $(2); \
  if [ $$rc -eq 124 ] || [ $$rc -eq 137 ]; then echo "FAILED (time limit $(1) s exceeded): $(3)"; \
  elif [ $$rc -ne 0 ]; then echo "FAILED (exit $$rc): $(3)"; fi; \
  echo $$rc > $(2).rc

define TEST_RUN_RULE
$(BUILD)/$(1)/%.log: $(BUILD)/$(1)/% FORCE
	@$$(call TEST_RUN,$(TEST_TIMEOUT),$$@,$$(call exe_path,$$<))
endef
$(foreach c,$(TEST_CFGS),$(eval $(call TEST_RUN_RULE,$(c))))

$(BUILD)/dbl/%.vg.log: $(BUILD)/dbl/% FORCE
	@$(call TEST_RUN,$(TEST_VG_TIMEOUT),$@,$(VALGRIND) -q --error-exitcode=1 --leak-check=full $(call exe_path,$<))

# after cmocka: both may install packages, and two apt-get runs at once
# collide on dpkg's lock on a fresh machine
$(M4_LOG): FORCE | cmocka
	@mkdir -p $(@D); rm -f $@.rc; rc=0; \
	$(MAKE) --no-print-directory check-m4 > $@ 2>&1 < /dev/null || rc=$$?; echo $$rc > $@.rc

FORCE:

test:
	@+$(MAKE) --no-print-directory $(if $(filter -j%,$(MAKEFLAGS)),,-j$(TEST_JOBS)) -Otarget test-run

# (the binaries named too: built through the logs' pattern rule they would
# count as intermediate files and be deleted)
test-run: check-headers check-docs check-first $(TEST_SCHEDULE) $(TEST_BINS) $(addprefix $(BUILD)/dbl/,$(VG_NAMES))
	@set -u; fail=0; \
	if [ -z "$(TEST_NAMES)" ]; then echo "test: no $(TEST_DIR)/test_*.c yet"; fi; \
	for l in $(TEST_LOGS) $(VG_LOGS); do [ "$$(cat $$l.rc 2>/dev/null)" = 0 ] || fail=1; done; \
	if [ $$fail = 0 ] && [ -n "$(TEST_NAMES)" ]; then echo "== sh $(TEST_DIR)/measured.sh $(BUILD)"; \
	  sh $(TEST_DIR)/measured.sh $(BUILD) || { echo "FAILED: measured numbers in test comments (make measured-update rewrites them)"; fail=1; }; fi; \
	$(if $(HAVE_VALGRIND),,echo "test: valgrind not found, valgrind runs skipped";) \
	if [ -n "$(strip $(TEST_LOGS) $(VG_LOGS))" ]; then $(TEST_SUMMARY) fail=$$fail $(TEST_LOGS) $(VG_LOGS); \
	else echo "tests: 0 passed, 0 failed, 0 skipped"; fi; \
	echo "== make check-m4"; cat $(M4_LOG); \
	[ "$$(cat $(M4_LOG).rc 2>/dev/null)" = 0 ] || { echo "FAILED: make check-m4"; fail=1; }; \
	exit $$fail

# the line coverage behind VALGRIND_SUITES (tests/vgcover.sh): per header the
# library lines all suites execute and those the valgrind set executes, and
# each line the set leaves
vg-cover: cmocka
	@CC='$(CC)' CFLAGS='$(CSTD) $(WARN) $(CFG_dbl-O0) $(MEMCHECK_DEF) -I. $(CMOCKA_CFLAGS)' \
	  LIBS='$(CMOCKA_LIBS) -lm' BUILD='$(BUILD)' sh $(TEST_DIR)/vgcover.sh $(VG_NAMES)

# Runs the double and float builds with VLBE_TEST_REPORT=1 and rewrites every
# measured number of a test comment that no longer agrees with its log.
measured-update: test-build
	@set -u; for c in $(TEST_CFGS); do for t in $(TEST_NAMES); do \
	  echo "== $(BUILD)/$$c/$$t"; \
	  VLBE_TEST_REPORT=1 timeout -k 10 $(TEST_TIMEOUT) ./$(BUILD)/$$c/$$t > $(BUILD)/$$c/$$t.log 2>&1 || \
	    echo "($(BUILD)/$$c/$$t failed: its numbers are left as they are)"; \
	done; done; sh $(TEST_DIR)/measured.sh --update $(BUILD)

# -- examples and demo ------------------------------------------------------
$(BUILD)/examples/%: $(EXAMPLE_DIR)/%.c $(EXAMPLE_DEPS)
	@mkdir -p $(@D)
	$(CC) $(CSTD) $(WARN) -O2 -I. $< -o $@ -lm

examples: $(EXAMPLE_BINS)
	@echo "examples: $(words $(EXAMPLE_BINS)) built$(if $(EXAMPLE_BINS),: $(EXAMPLE_NAMES))"

# The README's first program, built as a user would (the warning set, -O2)
# in double and in float, and run: each must finish (exit 0), and the two
# tips at t = 1 s agree to 1e-3 relative (float carries about 2e-4 there,
# make check-m4's cantilever)
FIRST_BINS = $(BUILD)/first/first_chain-dbl $(BUILD)/first/first_chain-flt
$(BUILD)/first/first_chain-dbl: $(EXAMPLE_DIR)/first_chain.c $(HEADERS)
	@mkdir -p $(@D)
	$(CC) $(CSTD) $(WARN) -O2 -I. $< -o $@ -lm
$(BUILD)/first/first_chain-flt: $(EXAMPLE_DIR)/first_chain.c $(HEADERS)
	@mkdir -p $(@D)
	$(CC) $(CSTD) $(WARN) -O2 -DVLBE_USE_FLOAT -I. $< -o $@ -lm

check-first: $(FIRST_BINS)
	@set -e; for b in $(FIRST_BINS); do echo "== $$b"; $$b > $$b.txt || { cat $$b.txt; echo "FAILED: $$b"; exit 1; }; cat $$b.txt; done; \
	awk '/^t = 1.0 s/ { y[++n] = $$8 + 0 } END { d = y[1] - y[2]; if (d < 0) d = -d; s = y[1] < 0 ? -y[1] : y[1]; \
	  if (n != 2 || !(s > 0) || !(d <= 1e-3 * s)) { print "FAILED: first_chain tip, double " y[1] " mm, float " y[2] " mm"; exit 1 } \
	  printf "check-first: tip at t = 1 s, double %s mm, float %s mm\n", y[1], y[2] }' $(BUILD)/first/first_chain-dbl.txt $(BUILD)/first/first_chain-flt.txt

# Each example prints, besides its own report, comparison rows
#   ROW|<scene>|<quantity [unit]>|<published>|<computed>|<relative error>|<cpu seconds>
# (svgp_compare_row() in scenes/svgplot.h writes one; "-" for no value); the
# demo collects them into one table, out/demo/table.txt.  Examples run from
# the repository root and write their charts to out/<name>*.svg.
DEMO_TABLE = awk -F'|' '{ n++; for (i = 2; i <= 7; i++) { c[n, i] = $$i; if (length($$i) > w[i]) w[i] = length($$i) } } \
  END { split("scene|quantity|published|vlbe|rel.err|cpu [s]", h, "|"); \
    for (i = 2; i <= 7; i++) if (length(h[i - 1]) > w[i]) w[i] = length(h[i - 1]); \
    for (r = 0; r <= n; r++) { line = ""; \
      for (i = 2; i <= 7; i++) { v = r ? c[r, i] : h[i - 1]; \
        line = line (i > 2 ? "  " : "") sprintf("%" (i <= 3 ? "-" : "") w[i] "s", v) } \
      print line } }'

$(BUILD)/demo/%: bench/%.c $(BENCH_DEPS)
	@mkdir -p $(@D)
	$(CC) $(CSTD) $(WARN) $(DEMO_WP_FLAGS) -DVLBE_BENCH_FLAGS='"$(DEMO_WP_FLAGS)"' -I. $< -o $@ -lm

demo: examples $(DEMO_WP_BINS)
	@mkdir -p $(OUT)/demo
	@set -e; : > $(OUT)/demo/rows.txt; \
	if [ -z "$(strip $(DEMO_SCENES))" ]; then echo "demo: no examples yet ($(EXAMPLE_DIR)/*.c)"; fi; \
	for s in $(DEMO_SCENES); do \
	  echo "== $$s"; \
	  $(BUILD)/examples/$$s > $(OUT)/demo/$$s.txt 2>&1 || { cat $(OUT)/demo/$$s.txt; echo "demo: $$s failed"; exit 1; }; \
	  grep -v '^ROW|' $(OUT)/demo/$$s.txt || true; \
	  grep '^ROW|' $(OUT)/demo/$$s.txt >> $(OUT)/demo/rows.txt || true; \
	done; \
	echo; echo "== comparison with the published numbers (all scenes)"; \
	$(DEMO_TABLE) $(OUT)/demo/rows.txt | tee $(OUT)/demo/table.txt; \
	for w in $(DEMO_WP_NAMES); do \
	  echo; echo "== $$w: work-precision ($(DEMO_WP_FLAGS))"; \
	  $(BUILD)/demo/$$w $(OUT) > $(OUT)/demo/$$w.txt 2>&1 || \
	    { cat $(OUT)/demo/$$w.txt; echo "demo: $$w failed"; exit 1; }; \
	  cat $(OUT)/demo/$$w.txt; \
	done; \
	echo "demo: tables in $(OUT)/demo/, charts in $(OUT)/"

# -- benchmarks ---------------------------------------------------------------
$(BUILD)/bench/%: bench/%.c $(BENCH_DEPS)
	@mkdir -p $(@D)
	$(CC) $(CSTD) $(WARN) $(BENCH_FLAGS) -DVLBE_BENCH_FLAGS='"$(BENCH_FLAGS)"' -I. $< -o $@ -lm

$(BUILD)/bench/portable/%: bench/%.c $(BENCH_DEPS)
	@mkdir -p $(@D)
	$(CC) $(CSTD) $(WARN) $(BENCH_PORTABLE_FLAGS) -DVLBE_BENCH_FLAGS='"$(BENCH_PORTABLE_FLAGS)"' -I. $< -o $@ -lm

$(BUILD)/bench/bench_lu_lapacke: bench/bench_lu.c $(BENCH_DEPS)
	@mkdir -p $(@D)
	$(CC) $(CSTD) $(WARN) $(BENCH_FLAGS) -DVLBE_BENCH_FLAGS='"$(BENCH_FLAGS)"' -DVLBE_BENCH_LAPACKE -I. $< -o $@ -llapacke -lm

bench: $(BENCH_BINS) $(BENCH_LAPACKE_BINS)
	@mkdir -p $(OUT)/bench
	@set -e; for b in $(BENCH_NAMES); do echo "== $$b ($(BENCH_FLAGS))"; \
	  case " $(BENCH_DIR_ARG) " in *" $$b "*) $(BUILD)/bench/$$b $(OUT)/bench;; *) $(BUILD)/bench/$$b;; esac; \
	done
	@set -e; for b in $(BENCH_LAPACKE_BINS); do echo "== $$b ($(BENCH_FLAGS), LAPACKE)"; $$b; done

# time per step of a clamped chain, 4 .. 1024 elements, dense and banded
bench-scale: $(BUILD)/bench/bench_scale
	@mkdir -p $(OUT)/bench
	$(BUILD)/bench/bench_scale $(OUT)/bench

# the same benchmarks built without -march=native; files get the tag "portable"
bench-portable: $(BENCH_PORTABLE_BINS)
	@mkdir -p $(OUT)/bench
	@set -e; for b in $(BENCH_NAMES); do echo "== $$b ($(BENCH_PORTABLE_FLAGS))"; \
	  case " $(BENCH_DIR_ARG) " in *" $$b "*) $(BUILD)/bench/portable/$$b $(OUT)/bench/portable;; \
	  *) $(BUILD)/bench/portable/$$b portable;; esac; \
	done

# -- fuzzing -----------------------------------------------------------------
# One libFuzzer binary per fuzz/fuzz_<name>.c (clang: -fsanitize=fuzzer needs
# its libclang_rt.fuzzer).  Each runs FUZZ_TIME seconds, one after the other
# (never -fork/-jobs), on a scratch copy of the seeds: the committed corpus
# is read, new inputs land in build/fuzz/work/<name>/, crashes in
# build/fuzz/artifacts/<name>/.  The summary counts a harness that stopped on
# "FUZZ VIOLATION" (a failed contract check, fuzz/fuzz_util.h) as a
# contract violation and any other stop (sanitizer report, signal, timeout)
# as a crash; any finding makes the target fail.
FUZZ_CC ?= clang
FUZZ_FLAGS = -g -O1 -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all
FUZZ_SRCS := $(wildcard fuzz/fuzz_*.c)
FUZZ_NAMES := $(patsubst fuzz_%,%,$(basename $(notdir $(FUZZ_SRCS))))
FUZZ_BINS := $(addprefix $(BUILD)/fuzz/fuzz_,$(FUZZ_NAMES))
FUZZ_TIME ?= $(shell n=$(words $(FUZZ_NAMES)); [ $$n -gt 0 ] && echo $$((600 / n)) || echo 60)
FUZZ_SEEDS ?= fuzz/corpus/%
FUZZ_OPTS ?= -timeout=20 -rss_limit_mb=2048
FUZZ_PROBE = printf '\#include <stdint.h>\n\#include <stddef.h>\nint LLVMFuzzerTestOneInput(const uint8_t *d, size_t n);\nint LLVMFuzzerTestOneInput(const uint8_t *d, size_t n) { (void)d; (void)n; return 0; }\n' | \
  $(FUZZ_CC) $(FUZZ_FLAGS) -x c - -o $(BUILD)/.fuzz-probe >/dev/null 2>&1

fuzz-clang:
	@mkdir -p $(BUILD)
	@if $(FUZZ_PROBE); then exit 0; fi; \
	if [ "$$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then \
	  echo "fuzz: $(FUZZ_CC) with libFuzzer not usable, installing clang with apt-get"; \
	  { apt-get update && DEBIAN_FRONTEND=noninteractive apt-get -o DPkg::Lock::Timeout=600 install -y clang; } || true; \
	fi; \
	if $(FUZZ_PROBE); then exit 0; fi; \
	echo "make fuzz needs clang with libFuzzer and the ASan/UBSan runtimes (Debian: apt-get install clang," >&2; \
	echo "which brings libclang_rt.fuzzer; or set FUZZ_CC to such a clang)" >&2; \
	exit 1

$(BUILD)/fuzz/fuzz_%: fuzz/fuzz_%.c $(HEADERS) $(wildcard fuzz/*.h) tests/ale_material.h | fuzz-clang
	@mkdir -p $(@D)
	$(FUZZ_CC) $(FUZZ_FLAGS) -I. $< -o $@ -lm

fuzz-build: $(FUZZ_BINS)

fuzz: fuzz-build
	@set -u; total=0; crashes=0; viol=0; \
	for h in $(FUZZ_NAMES); do \
	  w=$(BUILD)/fuzz/work/$$h; a=$(BUILD)/fuzz/artifacts/$$h; log=$(BUILD)/fuzz/$$h.log; \
	  seeds=$$(echo '$(FUZZ_SEEDS)' | sed "s/%/$$h/g"); \
	  mkdir -p $$w $$a; [ -d "$$seeds" ] || seeds=""; \
	  echo "== fuzz $$h ($(FUZZ_TIME) s, seeds: $${seeds:-none})"; \
	  rc=0; ./$(BUILD)/fuzz/fuzz_$$h -max_total_time=$(FUZZ_TIME) -print_final_stats=1 $(FUZZ_OPTS) \
	    -artifact_prefix=$$a/ $$w $$seeds > $$log 2>&1 || rc=$$?; \
	  ex=$$(sed -n 's/^stat::number_of_executed_units: *//p' $$log | tail -1); ex=$${ex:-0}; \
	  total=$$((total + ex)); \
	  if [ $$rc -ne 0 ]; then \
	    if grep -q '^FUZZ VIOLATION' $$log; then viol=$$((viol + 1)); what="contract violation"; \
	    else crashes=$$((crashes + 1)); what="crash"; fi; \
	    echo "   $$h: $$ex executions, STOPPED on a $$what (log $$log):"; \
	    grep -m3 -E '^FUZZ VIOLATION|ERROR: |runtime error|Test unit written' $$log | sed 's/^/     /'; \
	  else echo "   $$h: $$ex executions, no finding"; fi; \
	done; \
	echo "fuzz: $$total executions, $$crashes crashes, $$viol contract violations"; \
	[ $$crashes -eq 0 ] && [ $$viol -eq 0 ]

# -- mutation testing ------------------------------------------------------
# tests/mutate.sh: every entry of tests/mutations.txt (or the ids in
# MUTATIONS) applied alone to a copy of the tree in build/mutate/tree, the
# suites it names built there by this Makefile (build/dbl/test_x) and run;
# the table goes to build/mutate/report.txt.  Fails on a survivor that
# mutations.txt does not explain, a stale or a non-compiling entry.
MUTATIONS ?=

mutate: cmocka
	@MAKE='$(MAKE)' sh tests/mutate.sh $(MUTATIONS)

# -- Cortex-M4F under QEMU ------------------------------------------------------
# make check-m4 builds every program of M4_NAMES (tests/m4/m4_*.c) twice:
# for a Cortex-M4F with its single-precision FPU (float build, the WARN set,
# -O2, no FMA contraction; newlib with rdimon semihosting; startup and
# memory map in tests/m4/) and for the host in float with the same flags.
# Then, failing on any miss:
#   - runs each image under qemu-system-arm -M mps2-an386 (M4_TIMEOUT
#     seconds each) and the host build, both must exit 0;
#   - compares each M4 output with the host's (tests/m4/compare.awk: a
#     value is bit-identical or within M4_TOL FLT_EPSILON times the largest
#     magnitude of its group; counts and statuses equal);
#   - checks that no image links a __aeabi_d* symbol (double arithmetic);
#   - prints the size of each image and of an LU-only image (default
#     VLBE_ASSERT, no crt0) that must link neither __assert_func, printf
#     nor malloc;
#   - prints the worst-case stack of every public function (tests/m4/stack.awk
#     over gcc's -fstack-usage -fcallgraph-info=su of one unit of all headers
#     compiled with -DVLBE_API=): at most 1 kB, 2 kB for element kernels,
#     or the figure in tests/m4/stack_exceptions.txt; a recursion counts as
#     over the limit unless listed there.  Table in build/m4/stack.md.
# Outputs, images and tables in build/m4/.
M4_CC ?= arm-none-eabi-gcc
M4_NM ?= arm-none-eabi-nm
M4_SIZE ?= arm-none-eabi-size
M4_QEMU ?= qemu-system-arm
M4_TIMEOUT ?= 60
M4_TOL ?= 16
# the float cantilever's tip against the double run, relative (make check-m4)
M4_DBL_TOL ?= 1e-3
M4_DIR = tests/m4
M4_ARCH = -mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard
M4_FLAGS = -DVLBE_USE_FLOAT -O2 -ffp-contract=off
M4_LD = -T $(M4_DIR)/mps2_an386.ld $(M4_DIR)/startup.S
M4_NAMES = m4_base m4_lu m4_ale m4_ale3 m4_rancf m4_cr2d m4_hht m4_bdf
M4_ELFS := $(addprefix $(BUILD)/m4/,$(addsuffix .elf,$(M4_NAMES)))
M4_HOST_BINS := $(addprefix $(BUILD)/m4/host/,$(M4_NAMES))
M4_DEPS = $(HEADERS) $(M4_DIR)/m4_out.h $(SCENE_DIR)/pendulum.h $(SCENE_DIR)/ex_run.h
M4_KERNEL_RE = ^vlbe_(ale|ale3|rancf|cr2d)_
M4_SYSTEM_RE = _(chain|beam|inv_sys)_|_inv_chain_
M4_PROBE = printf 'int main(void) { return 0; }\n' | \
  $(M4_CC) $(M4_ARCH) --specs=rdimon.specs -x c - -o $(BUILD)/.m4-probe >/dev/null 2>&1
M4_MISSING = m=""; \
  if ! command -v $(M4_CC) >/dev/null 2>&1; then m="$$m gcc-arm-none-eabi"; \
  elif ! $(M4_PROBE); then m="$$m libnewlib-arm-none-eabi"; fi; \
  command -v $(M4_QEMU) >/dev/null 2>&1 || m="$$m qemu-system-arm"

m4-tools:
	@mkdir -p $(BUILD)
	@$(M4_MISSING); if [ -z "$$m" ]; then exit 0; fi; \
	if [ "$$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then \
	  echo "m4-tools: missing:$$m; installing with apt-get"; \
	  { apt-get update && DEBIAN_FRONTEND=noninteractive apt-get -o DPkg::Lock::Timeout=600 install -y $$m; } || true; \
	  $(M4_MISSING); if [ -z "$$m" ]; then exit 0; fi; \
	fi; \
	echo "make check-m4 needs the Debian packages:$$m (apt-get install$$m;" >&2; \
	echo "or set M4_CC, M4_NM, M4_SIZE, M4_QEMU to an arm-none-eabi toolchain with newlib and a QEMU)" >&2; \
	exit 1

$(BUILD)/m4/%.elf: $(M4_DIR)/%.c $(M4_DEPS) $(M4_DIR)/startup.S $(M4_DIR)/mps2_an386.ld | m4-tools
	@mkdir -p $(@D)
	$(M4_CC) $(M4_ARCH) $(CSTD) $(WARN) $(M4_FLAGS) --specs=rdimon.specs $(M4_LD) $< -o $@ -lm

# the footprint image: no crt0, no stdio (startup.S with M4_BARE)
$(BUILD)/m4/m4_lu_only.elf: $(M4_DIR)/m4_lu_only.c vlbe.h $(M4_DIR)/startup.S $(M4_DIR)/mps2_an386.ld | m4-tools
	@mkdir -p $(@D)
	$(M4_CC) $(M4_ARCH) $(CSTD) $(WARN) $(M4_FLAGS) -DM4_BARE -nostartfiles $(M4_LD) $< -o $@ -lm

$(BUILD)/m4/host/%: $(M4_DIR)/%.c $(M4_DEPS)
	@mkdir -p $(@D)
	$(CC) $(CSTD) $(WARN) $(M4_FLAGS) $< -o $@ -lm

# the HHT cantilever in double on the host: the float runs' tip against it
$(BUILD)/m4/host-dbl/m4_hht: $(M4_DIR)/m4_hht.c $(M4_DEPS)
	@mkdir -p $(@D)
	$(CC) $(CSTD) $(WARN) -O2 -DM4_HOST_DOUBLE $< -o $@ -lm

# one unit of all headers, public functions external (-DVLBE_API=)
$(BUILD)/m4/stack/vlbe_all.ci: $(HEADERS) | m4-tools
	@mkdir -p $(@D)
	@printf '#include "%s"\n' $(HEADERS) > $(@D)/vlbe_all.c
	$(M4_CC) $(M4_ARCH) $(CSTD) $(WARN) $(M4_FLAGS) -DVLBE_API= -fstack-usage -fcallgraph-info=su \
	  -I. -c $(@D)/vlbe_all.c -o $(@D)/vlbe_all.o

check-m4: $(M4_ELFS) $(M4_HOST_BINS) $(BUILD)/m4/host-dbl/m4_hht $(BUILD)/m4/m4_lu_only.elf \
          $(BUILD)/m4/stack/vlbe_all.ci
	@set -u; fail=0; d=$(BUILD)/m4; \
	echo "== check-m4: $(M4_NAMES) under $(M4_QEMU) -M mps2-an386 and on the host (float)"; \
	for p in $(M4_NAMES); do \
	  rc=0; timeout -k 5 $(M4_TIMEOUT) $(M4_QEMU) -M mps2-an386 -nographic -semihosting \
	    -kernel $$d/$$p.elf < /dev/null > $$d/$$p.m4.txt 2>&1 || rc=$$?; \
	  hrc=0; timeout -k 5 $(M4_TIMEOUT) $$d/host/$$p > $$d/$$p.host.txt 2>&1 || hrc=$$?; \
	  if [ $$rc -eq 124 ] || [ $$rc -eq 137 ]; then echo "FAILED (time limit $(M4_TIMEOUT) s): $$p under QEMU"; fail=1; \
	  elif [ $$rc -ne 0 ]; then echo "FAILED (exit $$rc): $$p under QEMU"; grep '^FAIL' $$d/$$p.m4.txt; fail=1; fi; \
	  if [ $$hrc -ne 0 ]; then echo "FAILED (exit $$hrc): $$p on the host"; fail=1; fi; \
	  awk -v tol=$(M4_TOL) -v prog=$$p -f $(M4_DIR)/compare.awk $$d/$$p.host.txt $$d/$$p.m4.txt || fail=1; \
	done; \
	hrc=0; timeout -k 5 $(M4_TIMEOUT) $$d/host-dbl/m4_hht > $$d/m4_hht.dbl.txt 2>&1 || hrc=$$?; \
	if [ $$hrc -ne 0 ]; then echo "FAILED (exit $$hrc): m4_hht in double on the host"; fail=1; fi; \
	for f in host m4; do \
	  awk -v tol=$(M4_DBL_TOL) -v what="m4_hht $$f float" -f $(M4_DIR)/vs_double.awk \
	    $$d/m4_hht.dbl.txt $$d/m4_hht.$$f.txt || fail=1; \
	done; \
	rc=0; timeout -k 5 $(M4_TIMEOUT) $(M4_QEMU) -M mps2-an386 -nographic -semihosting \
	  -kernel $$d/m4_lu_only.elf < /dev/null > $$d/m4_lu_only.m4.txt 2>&1 || rc=$$?; \
	if [ $$rc -ne 0 ]; then echo "FAILED (exit $$rc): m4_lu_only under QEMU"; fail=1; fi; \
	for e in $(M4_ELFS) $$d/m4_lu_only.elf; do \
	  s=$$($(M4_NM) $$e | awk '$$NF ~ /^__aeabi_d/ { printf " %s", $$NF }'); \
	  if [ -n "$$s" ]; then echo "FAILED: $$e links double arithmetic:$$s"; fail=1; fi; \
	done; \
	s=$$($(M4_NM) $$d/m4_lu_only.elf | awk '$$NF ~ /^(__assert_func|_?_?v?i?printf|_.*printf_r|malloc|_malloc_r)$$/ { printf " %s", $$NF }'); \
	if [ -n "$$s" ]; then echo "FAILED: the LU-only image links$$s"; fail=1; fi; \
	echo; echo "== check-m4: image sizes (bytes, $(M4_SIZE); text = code + read-only data)"; \
	base=$$($(M4_SIZE) $$d/m4_base.elf | awk 'NR == 2 { print $$1 }'); \
	echo "| image | text | text - m4_base | data | bss |"; echo "|---|---:|---:|---:|---:|"; \
	for e in $(M4_ELFS) $$d/m4_lu_only.elf; do \
	  $(M4_SIZE) $$e | awk -v n=$$(basename $$e .elf) -v b=$$base \
	    'NR == 2 { printf "| %s | %d | %s | %d | %d |\n", n, $$1, n == "m4_lu_only" ? "-" : (n == "m4_base" ? "0" : $$1 - b), $$2, $$3 }'; \
	done; \
	echo "(text - m4_base: what vlbe and the program's set-up add to the startup, crt0, stdio and output"; \
	echo " helper of m4_base; m4_lu_only: vlbe.h's dense and band LU with the default VLBE_ASSERT, no crt0"; \
	echo " and no stdio: no __assert_func, printf or malloc linked)"; \
	echo; echo "== check-m4: stack per public function (bytes; float, $(M4_ARCH) -O2)"; \
	awk -v headers="$(HEADERS)" -v kernel_re='$(M4_KERNEL_RE)' -v system_re='$(M4_SYSTEM_RE)' \
	  -v exceptions=$(M4_DIR)/stack_exceptions.txt -f $(M4_DIR)/stack.awk $$d/stack/vlbe_all.ci \
	  > $$d/stack.md 2> $$d/stack.sum || fail=1; \
	cat $$d/stack.md $$d/stack.sum; \
	grep -E '^\| [a-z0-9_]+\.h \| vlbe_' docs/embedded.md > $$d/stack_readme.txt || true; \
	grep -E '^\| [a-z0-9_]+\.h \| vlbe_' $$d/stack.md > $$d/stack_run.txt || true; \
	if ! diff $$d/stack_readme.txt $$d/stack_run.txt > $$d/stack_readme.diff; then \
	  echo "FAILED: docs/embedded.md's stack table differs from this run (diff in $$d/stack_readme.diff)"; fail=1; \
	else echo "stack: docs/embedded.md's table equals this run"; fi; \
	if [ $$fail = 0 ]; then echo "check-m4: ok"; else echo "check-m4: FAILED"; fi; \
	exit $$fail

# -- lint ---------------------------------------------------------------------
# -D__unix__: the hosted configuration (VLBE_ASSERT is assert, which cppcheck
# knows ends the path; the bare-metal trap it does not)
LINT_OPTS = --enable=warning,performance,portability --error-exitcode=1 --inline-suppr -q \
  --std=c99 --suppress=missingIncludeSystem -I. -D__unix__
LINT_FILES := $(HEADERS) $(wildcard bench/*.h bench/*.c tests/*.h tests/*.c $(SCENE_DIR)/*.h examples/*.c)
# twice, double and float: cppcheck otherwise mixes both configurations of
# vlbe_real in its whole-program (ctu) checks and reports false overruns
lint:
	$(CPPCHECK) $(LINT_OPTS) -UVLBE_USE_FLOAT $(LINT_FILES)
	$(CPPCHECK) $(LINT_OPTS) -DVLBE_USE_FLOAT $(LINT_FILES)

clean:
	rm -rf $(BUILD) $(OUT)
