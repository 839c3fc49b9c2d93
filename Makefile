# Copyright (C) 2026 the vsph developers.
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE).
# vsph: one non-recursive Makefile (STYLE B11). `make check` and `make report`
# work as the first command on a fresh machine: they install what is missing.

CC       ?= gcc
# The library's packages; the program's add cmark-gfm (the report's page).
LIBPKGS  := gsl fftw3 yaml-0.1 libcjson zlib
PKGS     := $(LIBPKGS) libcmark-gfm
TESTPKGS := check
BUILD    ?= build
WARN     := -Wall -Wextra -Wpedantic -Wshadow -Wstrict-prototypes \
            -Wmissing-prototypes -Wdouble-promotion -Wformat=2
ifdef CI
WARN     += -Werror
endif
OPT      ?= -O3
# AVX2 and FMA where the CPU has it (the pair and kernel loops vectorise 4
# wide); `make ARCH=` builds for any x86-64. The program and the tests
# are built for the machine that builds them; the installed library runs
# on any x86-64 (below, "the library": a baseline copy, and this one
# where the loader picks it). No -ffast-math and no FMA
# contraction (-std=c11), but the right-hand side's sums are reduced lane
# by lane and the exponential uses fma() where the target has it: builds
# with and without ARCH agree to rounding, not bitwise. Within one build
# the thread count never changes a result.
# The cores make check builds on (one job each), unless make was given
# its own -j (its jobserver then rules).
NPROC    := $(shell nproc 2>/dev/null || echo 1)
JOBS      = $(if $(findstring -j,$(MAKEFLAGS)),,-j$(NPROC))
ARCH     ?= $(shell grep -qw avx2 /proc/cpuinfo 2>/dev/null && echo -march=x86-64-v3)
CFLAGS   ?= $(OPT) $(ARCH) -g
# -fno-math-errno: nothing reads errno after a math call, and without it
# sqrt cannot be vectorised.
# -ffp-contract=off: no multiply-add fused behind the code's back (GCC's
# -std=c11 already says so; clang fuses by default): the candidate test's
# SIMD lanes (solver/pair_x86.c) and the portable loop compute s^2 alike.
# -fPIC: the program, libvsph.a and libvsph.so share one set of objects
# (measured: the same results bit for bit and the same speed, docs/speed.md);
# -fno-semantic-interposition lets the library's calls to its own
# functions stay direct; -fvisibility=hidden: libvsph.so exports only what
# the public headers mark VSPH_API (common/api.h).
ALLCFLAGS = -std=c11 -D_POSIX_C_SOURCE=200809L -fopenmp -fno-math-errno \
            -ffp-contract=off \
            -fPIC -fno-semantic-interposition -fvisibility=hidden \
            $(WARN) $(CFLAGS) \
            $(SAN) $(shell pkg-config --cflags $(PKGS) 2>/dev/null)
LDLIBS    = $(shell pkg-config --libs $(PKGS) 2>/dev/null) -lcmark-gfm-extensions -lm
LIBLDLIBS = $(shell pkg-config --libs $(LIBPKGS) 2>/dev/null) -lm
TESTLIBS  = $(shell pkg-config --libs $(TESTPKGS) 2>/dev/null)

# Layers, lowest first: common <- kernels <- solver <- analysis <- io <-
# runs <- reports <- cli. The library, libvsph, is the lower five layers
# (common to io); runs, reports and cli are the program that uses it, as
# examples/ do: through the public headers (public-check) and linked
# against libvsph.a. The tests link the program's objects but
# cli/main.o, and the same archive.
CORE_SRC := $(wildcard common/*.c kernels/*.c solver/*.c solver/scenes/*.c \
              solver/forms/*.c analysis/*.c io/*.c)
PROG_SRC := $(wildcard runs/*.c reports/*.c)
PROG_OBJ := $(PROG_SRC:%.c=$(BUILD)/%.o)
ALL_SRC  := $(CORE_SRC) $(PROG_SRC)
CLI_SRC  := $(wildcard cli/*.c)
TEST_SRC := $(wildcard tests/*.c)
ALL_OBJ  := $(ALL_SRC:%.c=$(BUILD)/%.o)
# A hash of every source file, linked in as vsph_source_hash_id: the
# report's cache keys include it, so any change to the code reruns.
TEXT_SRC := $(sort $(wildcard reports/text/*.md reports/claims/*.md))
SRC_ALL  := $(sort $(wildcard vsph.h common/*.[ch] kernels/*.[ch] solver/*.[ch] \
              solver/scenes/*.c solver/forms/*.[ch] analysis/*.[ch] io/*.[ch] runs/*.[ch] reports/*.[ch] \
              cli/*.[ch])) $(TEXT_SRC)
HASH_OBJ := $(BUILD)/gen/source_hash.o
# The report's prose (reports/text/*.md) and claims (reports/claims/*.md),
# compiled in.
TEXT_OBJ := $(BUILD)/gen/text_blocks.o
CLI_OBJ  := $(CLI_SRC:%.c=$(BUILD)/%.o)
# The library's static archive (below, "the library"), which the program
# and the tests link.
LIBA     := $(BUILD)/libvsph.a
TEST_OBJ := $(TEST_SRC:%.c=$(BUILD)/%.o)
CLI_LIB  := $(filter-out $(BUILD)/cli/main.o,$(CLI_OBJ))

.PHONY: all deps deps-build check test report baseline bench peer-pysph archive full-sitting full-report asan valgrind-check prefix-check public-check \
        lib doc install uninstall \
        format format-check mutate fuzz slurm-check fresh-check \
        fresh-check-tests paraview-check optional-checks reference clean

all: deps-build $(BUILD)/vsph

# Idempotent: returns at once when every package is present. Building and
# installing (make, make lib, make install) need the compiler and the
# libraries alone; the tests and the report need Check and gnuplot too.
deps:
	@scripts/install-deps
deps-build:
	@scripts/install-deps --build

# The compiler and its flags, kept in a file that changes only when they
# do: every object depends on it, so a change of flags (this Makefile's
# or CFLAGS=...) rebuilds everything, and nothing else does.
$(BUILD)/gen/cflags: FORCE
	@mkdir -p $(dir $@)
	@printf '%s\n' '$(CC) $(ALLCFLAGS)' > $@.tmp
	@if cmp -s $@.tmp $@; then rm -f $@.tmp; else mv -f $@.tmp $@; fi

$(BUILD)/%.o: %.c $(BUILD)/gen/cflags
	@mkdir -p $(dir $@)
	$(CC) $(ALLCFLAGS) -MMD -MP -c $< -o $@

# The library's layers again for the x86-64 baseline (the installed
# libvsph.a and libvsph.so; see "the library").
PORT       := $(BUILD)/x86-64
PORTCFLAGS  = $(subst $(CFLAGS),$(OPT) -g,$(ALLCFLAGS))
$(PORT)/gen/cflags: FORCE
	@mkdir -p $(dir $@)
	@printf '%s\n' '$(CC) $(PORTCFLAGS)' > $@.tmp
	@if cmp -s $@.tmp $@; then rm -f $@.tmp; else mv -f $@.tmp $@; fi

$(PORT)/%.o: %.c $(PORT)/gen/cflags
	@mkdir -p $(dir $@)
	$(CC) $(PORTCFLAGS) -MMD -MP -c $< -o $@

# With it, the commit the sources were at when they changed last (git's
# short id, "-dirty" when they differed from it; "unknown" outside git):
# run.json records it beside the source hash, never in a key.
# Made at every make (the commit it names moves without the sources: a
# build after a commit that changed no source must not keep the older
# commit's name), but replaced only when its text changes, so that nothing
# is rebuilt for nothing.
$(BUILD)/gen/source_hash.c: FORCE
	@mkdir -p $(dir $@)
	@printf '/* generated: hash of the sources */\nconst char vsph_source_hash_id[] = "%s";\nconst char vsph_commit_id[] = "%s";\n' \
	  "$$(cat $(SRC_ALL) | sha1sum | cut -c1-16)" \
	  "$$(git describe --always --dirty --abbrev=12 2>/dev/null | tr -cd '0-9a-z-' || true)" > $@.tmp
	@if cmp -s $@.tmp $@; then rm -f $@.tmp; else mv -f $@.tmp $@; fi

.PHONY: FORCE
FORCE:

$(HASH_OBJ): $(BUILD)/gen/source_hash.c
	$(CC) -std=c11 -fPIC -c $< -o $@

$(BUILD)/gen/text_blocks.c: $(TEXT_SRC) scripts/embed-text
	@mkdir -p $(dir $@)
	@scripts/embed-text $(TEXT_SRC) > $@.tmp && mv $@.tmp $@

$(TEXT_OBJ): $(BUILD)/gen/text_blocks.c reports/text.h
	$(CC) -std=c11 -fPIC -I. $(SAN) -c $< -o $@

# The archive last: the linker takes from it what the objects before it
# name (the source hash included).
$(BUILD)/vsph: $(PROG_OBJ) $(CLI_OBJ) $(TEXT_OBJ) $(LIBA)
	$(CC) $(ALLCFLAGS) -o $@ $^ $(LDLIBS)

$(BUILD)/check_vsph: $(PROG_OBJ) $(CLI_LIB) $(TEST_OBJ) $(TEXT_OBJ) $(LIBA)
	$(CC) $(ALLCFLAGS) -o $@ $^ $(TESTLIBS) $(LDLIBS)

# The FULL report's runs that ended, kept compact in reports/full (see
# docs/usage.md: vsph report archive); the commit named for runs of these
# sources is HEAD's.
archive: deps $(BUILD)/vsph
	scripts/source-commits $(BUILD)/history $(HISTORY_N) $(wildcard reports/full/entries.md)
	VSPH_ARCHIVE_HISTORY=$(BUILD)/history \
	VSPH_COMMIT="$$(git describe --always --dirty --abbrev=12 2>/dev/null \
	  | tr -cd '0-9a-z-')" $(BUILD)/vsph report archive \
	  --out reports/out-full reports/full

# One sitting of the FULL report's runs: the costliest runs that do not
# stand in reports/full and fit BUDGET (default 150m), niced, two at a
# time, checkpointed, into reports/out-full; then `make archive` keeps the
# ones that ended (docs/usage.md: vsph report --budget, --skip-archived).
# BUDGET reaches vsph through the environment, as one argument that no
# shell reads (vsph refuses what is not a time); the history as for
# make report.
BUDGET ?= 150m
export BUDGET
full-sitting: deps $(BUILD)/vsph
	@$(HISTORY); VSPH_ARCHIVE_HISTORY=$$h $(BUILD)/vsph report --full \
	  --out reports/out-full --budget "$$BUDGET" --skip-archived reports/full

# The FULL report assembled into reports/out-full from its own runs and
# the ones that stand in reports/full (docs/usage.md: --from-archive); then
# reports/full/summary.md holds its claims and convergence tables.
full-report: deps $(BUILD)/vsph
	@$(HISTORY); VSPH_ARCHIVE_HISTORY=$$h $(BUILD)/vsph report assemble \
	  --full --out reports/out-full --from-archive reports/full

# ------------------------------------------------------------ the library
# libvsph, static and shared: the lower five layers (common, kernels,
# solver, analysis, io) and the source hash, from the program's own
# objects; runs/, reports/ and cli/ stay in the program. The public headers (the front door, vsph.h, and
# what it includes) install under include/vsph/ with their folders; a
# program links it through pkg-config (vsph.pc), as examples/regression
# shows (docs/library.md).
VERSION := $(shell sed -n 's/^\#define VSPH_VERSION "\(.*\)"/\1/p' common/consts.h)
SOVER   := 0
LIBSO   := $(BUILD)/libvsph.so.$(VERSION)
PUB_HDR := vsph.h common/api.h common/consts.h common/status.h common/params.h \
           common/sysinfo.h \
           kernels/kernel.h solver/particles.h solver/cells.h solver/pair.h \
           solver/viscous.h solver/equations.h solver/walls.h solver/scene.h \
           solver/run.h solver/lattice.h solver/integrate.h solver/materials.h \
           solver/diagnostics.h solver/forms/brookshaw.h solver/forms/er.h \
           solver/forms/morris.h solver/forms/stress.h solver/forms/takeda.h \
           solver/forms/zheng.h analysis/moments.h analysis/fields.h \
           analysis/scaling.h analysis/dissipation.h analysis/references.h \
           analysis/series.h analysis/contact.h analysis/laplacian.h \
           io/files.h io/csv.h io/json.h io/plot.h io/vtk.h
LIB_ALL := $(CORE_SRC:%.c=$(BUILD)/%.o) $(HASH_OBJ)

$(LIBA): $(LIB_ALL)
	@rm -f $@
	ar rcs $@ $^

$(LIBSO): $(LIB_ALL)
	$(CC) $(ALLCFLAGS) -shared -Wl,-soname,libvsph.so.$(SOVER) -o $@ $^ $(LIBLDLIBS)

# The installed library runs on any x86-64. Where this build is for
# x86-64-v3 (AVX2 and FMA, the default on a CPU that has them), the
# install holds two copies of libvsph.so: the x86-64 baseline's in lib/
# and this build's in lib/glibc-hwcaps/x86-64-v3/, which the loader
# (glibc 2.33 and later) picks on a CPU that has x86-64-v3, the
# baseline's elsewhere: the dispatch is at run time, by the loader, and
# each CPU gets the fastest copy it can run. libvsph.a is the baseline's
# (a static link cannot choose). Any other ARCH (say -march=native, the
# opt-in for a library only this machine runs) installs this build's
# alone. The two copies agree to rounding, not bitwise (their sums are
# reduced 4 and 2 lanes wide). The program is installed the same way.
ifeq ($(strip $(ARCH)),-march=x86-64-v3)
HWCAPS   := x86-64-v3
PORT_ALL := $(CORE_SRC:%.c=$(PORT)/%.o) $(HASH_OBJ)
LIB_INST := $(PORT)/libvsph.a $(PORT)/libvsph.so.$(VERSION)
$(PORT)/libvsph.a: $(PORT_ALL)
	@rm -f $@
	ar rcs $@ $^
$(PORT)/libvsph.so.$(VERSION): $(PORT_ALL)
	$(CC) $(PORTCFLAGS) -shared -Wl,-soname,libvsph.so.$(SOVER) -o $@ $^ $(LIBLDLIBS)
# The program likewise: the baseline's in bin/, this build's in
# libexec/vsph/x86-64-v3/, which the baseline's starts where the CPU has
# x86-64-v3 (cli/main.c, faster_copy).
LIB_INST += $(PORT)/vsph
$(PORT)/vsph: $(PROG_SRC:%.c=$(PORT)/%.o) $(CLI_SRC:%.c=$(PORT)/%.o) \
              $(TEXT_OBJ) $(PORT)/libvsph.a
	$(CC) $(PORTCFLAGS) -o $@ $^ $(LDLIBS)
endif
INSTALL_LIB = $(if $(HWCAPS),--hwcaps $(HWCAPS) $(PORT))

# The manual page, vsph(1), from the program's own --help texts.
$(BUILD)/vsph.1: $(BUILD)/vsph scripts/make-man
	scripts/make-man $(BUILD)/vsph > $@.tmp && mv $@.tmp $@

lib: deps-build
	@$(MAKE) --no-print-directory $(LIBA) $(LIBSO) $(LIB_INST) $(BUILD)/vsph.1 doc

# The reference manual of the public headers (docs/Doxyfile), by Debian's
# doxygen (scripts/install-deps); skipped with a note where it is absent.
# A warning fails it (WARN_AS_ERROR): the warnings are shown and no
# manual is kept, so the next make tries again.
doc: $(BUILD)/doc/html/index.html
$(BUILD)/doc/html/index.html: docs/Doxyfile $(PUB_HDR)
	@if command -v doxygen > /dev/null; then \
	  rm -rf $(BUILD)/doc && mkdir -p $(BUILD)/doc && \
	  if { cat docs/Doxyfile; echo "INPUT = $(PUB_HDR)"; \
	       echo "OUTPUT_DIRECTORY = $(BUILD)/doc"; \
	       echo "WARN_LOGFILE = $(BUILD)/doc/warnings.log"; } | doxygen - && \
	     ! [ -s $(BUILD)/doc/warnings.log ]; then \
	    echo "doc: the reference manual in $(BUILD)/doc/html"; \
	  else \
	    cat $(BUILD)/doc/warnings.log >&2; rm -rf $(BUILD)/doc/html; \
	    echo "doc: doxygen warned (above): document every parameter, or" \
	      "mend the comment" >&2; exit 1; \
	  fi; \
	else echo "doc: skipped (no doxygen; scripts/install-deps installs it)"; fi

# make install [PREFIX=/usr/local] [DESTDIR=]: the program, the libraries,
# the headers, vsph.pc and vsph(1), each file listed in
# PREFIX/share/vsph/manifest, which `make uninstall` reads: it removes
# what the manifest lists and nothing else (scripts/install).
PREFIX  ?= /usr/local
install: lib
	scripts/install $(INSTALL_LIB) "$(DESTDIR)" "$(PREFIX)" "$(VERSION)" \
	  "$(SOVER)" $(BUILD) $(PUB_HDR)
uninstall:
	scripts/install --uninstall "$(DESTDIR)" "$(PREFIX)"

# Every test, through the single Check runner (STYLE B10), started twice at
# once on two lanes of suites (scripts/check-lanes). The library's
# test links examples/regression against a copy installed under
# $(BUILD)/stage (VSPH_STAGE).
check: deps
	@$(MAKE) --no-print-directory $(JOBS) $(BUILD)/vsph $(BUILD)/check_vsph
	@# after, not beside: lib's own make builds libvsph.a, which the
	@# program links (two makes writing it at once broke a -j2 link)
	@$(MAKE) --no-print-directory $(JOBS) lib
	@rm -rf $(BUILD)/stage
	@scripts/install $(INSTALL_LIB) "" "$(abspath $(BUILD)/stage)" \
	  "$(VERSION)" "$(SOVER)" $(BUILD) $(PUB_HDR) > /dev/null
	@$(MAKE) --no-print-directory prefix-check public-check format-check
	VSPH_BIN=$(BUILD)/vsph VSPH_STAGE=$(abspath $(BUILD)/stage) OMP_NUM_THREADS=2 \
	  GOMP_SPINCOUNT=1000 scripts/check-lanes $(BUILD)/check_vsph $(BUILD)

test: check

# How many commits back the archive's runs are traced to the commit that
# made them (scripts/source-commits), at least: it also goes back to the
# oldest commit reports/full/entries.md names, so no archived run falls
# out of the window as commits pile up.
HISTORY_N = 400

# The main job: the whole report into reports/out/ (quick; FULL=1 for the
# paper's resolutions and end times).
# The history that judges the archive's runs (scripts/source-commits) into
# shell variable h; when it cannot be made (outside a git clone, say), its
# own reason is said, h stays empty and the archive's older runs unjudged.
HISTORY = if scripts/source-commits $(BUILD)/history $(HISTORY_N) $(wildcard reports/full/entries.md) >/dev/null; \
	  then h=$(BUILD)/history; else h=; echo "make: reports/full's older \
	  runs stay unjudged (no history: above)"; fi

# The quick report shows beside its figures the paper-resolution runs of
# reports/full (when there is one), judged with that history, and reads
# from there the runs it shares with the FULL plan that stand (docs/usage.md:
# --from-archive); FRESH=1 makes them here instead (FRESH=0 or unset:
# read).
report: deps
	@$(MAKE) --no-print-directory $(BUILD)/vsph
	@$(HISTORY); VSPH_ARCHIVE_HISTORY=$$h $(BUILD)/vsph report \
	  --out reports/out $(if $(FULL),--full,$(if $(wildcard \
	  reports/full),--beside reports/full $(if $(filter-out 0,$(FRESH)),, \
	  --from-archive reports/full)))

# Re-record the regression baseline (tests/check_baseline.c) after an
# intended change to the numerics; commit reports/baseline.csv with a reason.
baseline: deps
	@$(MAKE) --no-print-directory $(BUILD)/vsph
	$(BUILD)/vsph report --out reports/out --only scenes
	cp reports/out/baseline.csv reports/baseline.csv

# Timings (never in the tests): quadrature, particle sums, operators.
bench: deps
	@$(MAKE) --no-print-directory $(BUILD)/vsph
	$(BUILD)/vsph bench --processes 5 --csv $(BUILD)/bench.csv

# The second peer timed in the same sitting as vsph's rows: Debian's PySPH
# (installed by the script: install-deps pysph) on its Taylor-Green
# example at vsph's bench size and neighbours, one thread, against vsph's
# square step and MGF force (scripts/peer-pysph; two to three minutes).
# A timing, not a check: not part of `make check` or optional-checks.
peer-pysph:
	scripts/peer-pysph

# `vsph report submit` on a real Slurm: installs slurm-wlm and munge,
# starts a one-node cluster on this machine (its own slurm.conf and munge
# key in a temporary folder), checks the Slurm report against a local one
# and that a cancelled task is all a second submission reruns, and stops
# every daemon it started. Not part of `make check` (a few minutes).
slurm-check: deps
	scripts/slurm-check

# The README's two commands on a truly fresh machine: a minimal Debian 12
# (debootstrap, cached outside the repository in /var/cache/vsph-fresh),
# a new copy of it each time, only make and git installed, a clone of
# HEAD, then `make check` and `make report` there, each timed with the
# load (scripts/fresh-check). Needs root. fresh-check-tests runs
# `make check` alone (.ci/run does, after the tests here).
fresh-check:
	scripts/fresh-check
fresh-check-tests:
	scripts/fresh-check --tests

# The snapshots as ParaView sees them: installs Debian's ParaView and xvfb,
# runs a short 2-D and a short 3-D run into a temporary folder and opens
# each snapshots.pvd with pvpython (scripts/paraview-check.py): the arrays,
# their components, no NaN, and the times against energy.csv. Not part of
# `make check` (ParaView is large).
paraview-check:
	scripts/paraview-check

# Every optional check above that this machine can install, one after
# another, each timed, with a line per check at the end (passed, failed,
# skipped and why); 20-30 minutes (scripts/optional-checks).
optional-checks:
	scripts/optional-checks

# The finite-volume references the report reads from reference/data
# (OpenFOAM v1912: the stretching square by interFoam, the cavity by
# icoFoam; reference/README.md): each case run again in build/reference
# (an interrupted one resumes there) and compared with the committed files
# to REFERENCE_TOL of each column's largest magnitude. Hours on two cores;
# REFERENCE_CASES picks some (scripts/reference --list). Not part of
# `make check` or `make report`.
REFERENCE_TOL ?= 1e-6
REFERENCE_CASES ?=
reference:
	@scripts/install-deps openfoam
	scripts/reference --tol $(REFERENCE_TOL) $(REFERENCE_CASES)

# Each coefficient of each physical term mutated in turn (scripts/mutate):
# a test must fail for every one. Slow (one rebuild per mutation); not part
# of `make check`. Works on a scratch copy of the committed sources.
mutate: deps
	scripts/mutate

# libFuzzer (clang) on the parameter file parser, the argument parser and
# the run-folder contract (random folder contents, then a run: a refusal
# changes nothing, a run ends sealed ok): FUZZ_RUNS executions each, at
# most FUZZ_SECONDS each, from the seeds in tests/fuzz/corpus (new inputs
# go to build-fuzz/corpus). Not part of `make check`. A crash leaves its
# input as crash-* in the current folder.
FUZZ_RUNS    ?= 1000000
FUZZ_SECONDS ?= 600
FUZZ_SAN     := -fsanitize=fuzzer-no-link,address,undefined
fuzz:
	@scripts/install-deps fuzz
	@$(MAKE) --no-print-directory BUILD=build-fuzz CC=clang OPT=-O1 \
	  SAN="$(FUZZ_SAN)" build-fuzz/fuzz_params build-fuzz/fuzz_args \
	  build-fuzz/fuzz_folder
	@mkdir -p build-fuzz/corpus/params build-fuzz/corpus/args \
	  build-fuzz/corpus/folder
	build-fuzz/fuzz_params -runs=$(FUZZ_RUNS) -max_total_time=$(FUZZ_SECONDS) \
	  -close_fd_mask=2 -print_final_stats=1 \
	  build-fuzz/corpus/params tests/fuzz/corpus/params
	build-fuzz/fuzz_args -runs=$(FUZZ_RUNS) -max_total_time=$(FUZZ_SECONDS) \
	  -close_fd_mask=2 -print_final_stats=1 \
	  build-fuzz/corpus/args tests/fuzz/corpus/args
	build-fuzz/fuzz_folder -runs=$(FUZZ_RUNS) -max_total_time=$(FUZZ_SECONDS) \
	  -close_fd_mask=2 -print_final_stats=1 -timeout=20 \
	  build-fuzz/corpus/folder tests/fuzz/corpus/folder

$(BUILD)/fuzz_%: tests/fuzz/fuzz_%.c $(PROG_OBJ) $(CLI_LIB) $(TEXT_OBJ) $(LIBA)
	$(CC) $(ALLCFLAGS) -fsanitize=fuzzer -o $@ $^ $(LDLIBS)

asan: deps
	@$(MAKE) --no-print-directory BUILD=build-asan OPT=-O1 \
	  SAN="-fsanitize=address,undefined -fno-omit-frame-pointer" \
	  build-asan/vsph build-asan/check_vsph
	VSPH_BIN=build-asan/vsph CK_FORK=no OMP_NUM_THREADS=2 \
	  ASAN_OPTIONS=detect_leaks=1 build-asan/check_vsph

valgrind-check: deps
	@$(MAKE) --no-print-directory $(BUILD)/vsph $(BUILD)/check_vsph
	VSPH_BIN=$(BUILD)/vsph CK_FORK=no OMP_NUM_THREADS=1 \
	  valgrind --error-exitcode=1 --leak-check=full \
	  --suppressions=tests/valgrind.supp $(BUILD)/check_vsph

# REBOUND-style name rule: every defined global symbol of <dir>/<file>.o
# starts with vsph_<file>_ (main excepted in cli/main.o; a named OpenMP
# critical section's lock, .gomp_critical_user_NAME, follows the rule by
# its NAME); and a prefix belongs to one file: two files of one name in
# two folders (runs/x.c and io/x.c) would share theirs, so the names of
# the objects must differ across folders.
prefix-check: $(ALL_OBJ) $(CLI_OBJ)
	@bad=0; dup=$$(for o in $(ALL_OBJ) $(CLI_OBJ); do basename $$o; done | \
	  sort | uniq -d); for d in $$dup; do \
	  echo "prefix-check: two files named $${d%.o}.c share the prefix vsph_$${d%.o}_:" \
	    $$(for o in $(ALL_OBJ) $(CLI_OBJ); do case $$o in */$$d) echo $$o ;; esac; done); \
	  bad=1; done; \
	for o in $(ALL_OBJ) $(CLI_OBJ); do \
	  base=$$(basename $$o .o); \
	  for s in $$(nm -g --defined-only $$o | awk '{print $$3}'); do \
	    case $$s in vsph_$${base}_*|.gomp_critical_user_vsph_$${base}_*) ;; main) [ $$base = main ] || { echo "$$o: $$s"; bad=1; } ;; \
	      *) echo "prefix-check: $$o exports $$s (want vsph_$${base}_*)"; bad=1 ;; esac; \
	  done; \
	done; [ $$bad -eq 0 ] && echo "prefix-check: ok"

# The program (runs/, reports/, cli/) uses libvsph as examples/ do: of
# the library's layers it includes only the public headers (PUB_HDR), so
# what it needs is on the public face, refusing bad arguments, documented,
# installed. And a public header includes only public headers (an
# installed one would not find the others).
PROG_FILES = $(wildcard runs/*.[ch] reports/*.[ch] cli/*.[ch])
INCLUDES = sed -n 's|^[[:space:]]*\#[[:space:]]*include[[:space:]]*"\([^"]*\)".*|\1|p'
public-check:
	@bad=0; pub=" $(PUB_HDR) "; \
	for f in $(PROG_FILES); do \
	  for h in $$($(INCLUDES) $$f); do \
	    case $$h in ../common/*|../kernels/*|../solver/*|../analysis/*|../io/*) \
	      case "$$pub" in *" $${h#../} "*) ;; *) bad=1; \
	        echo "public-check: $$f includes $${h#../}, not a public header (PUB_HDR)" ;; \
	      esac ;; \
	    esac; \
	  done; \
	done; \
	for f in $(PUB_HDR); do \
	  for h in $$($(INCLUDES) $$f); do \
	    r=$$(realpath -m --relative-to=. $$(dirname $$f)/$$h); \
	    case "$$pub" in *" $$r "*) ;; *) bad=1; \
	      echo "public-check: the public $$f includes $$r, not a public header" ;; \
	    esac; \
	  done; \
	done; [ $$bad -eq 0 ] && echo "public-check: ok"

FMT_SRC = $(wildcard vsph.h common/*.[ch] kernels/*.[ch] solver/*.[ch] \
            solver/scenes/*.[ch] solver/forms/*.[ch] analysis/*.[ch] io/*.[ch] \
            runs/*.[ch] reports/*.[ch] cli/*.[ch] tests/*.[ch] tests/fuzz/*.[ch] \
            examples/*/*.[ch])
# The C files git tracks that FMT_SRC leaves out (none in a checkout
# without git): format-check fails on them, so a new folder is not
# silently unchecked.
FMT_MISSED = $(filter-out $(FMT_SRC),$(shell git ls-files '*.[ch]' 2> /dev/null))
format:
	clang-format -i $(FMT_SRC)
format-check:
	@if [ -n "$(FMT_MISSED)" ]; then \
	  echo "format-check: FMT_SRC (Makefile) leaves out $(FMT_MISSED)"; exit 1; fi
	@if command -v clang-format > /dev/null; then \
	  clang-format --dry-run --Werror $(FMT_SRC) && echo "format-check: ok"; \
	else echo "format-check: skipped (no clang-format)"; fi

clean:
	rm -rf build build-asan build-fuzz

-include $(ALL_OBJ:.o=.d) $(CLI_OBJ:.o=.d) $(TEST_OBJ:.o=.d) \
  $(ALL_SRC:%.c=$(PORT)/%.d) $(CLI_SRC:%.c=$(PORT)/%.d)
