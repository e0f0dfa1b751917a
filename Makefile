# dynx: one entry point for everything.
#   make run    install missing packages, build, run the default deck, say where results are
#   make test   unit tests (debug build) and regression tests (release build)
#   make bench  benchmarks (recorded in docs/performance.md)
#   make studies  error-against-run-time studies (docs/studies/)
#   make fuzz   N (default 10000) mutated decks and restart dumps through the in-process harness
#               bin/dynx-fuzz-debug, then NPROC (1000) through bin/dynx-debug processes (docs/errors.md)
#   make restart-long  interrupt-and-continue on every scene deck, 20 kill -9 on the full Taylor impact
#   make kill9-sweep   kill -9 at every write/rename/fsync/unlink of a short run (plot crash safety)
#   make mpi-sweep     every regression deck serially and at NP 2, 3, 4: bitwise equal (about 15 min)
#   make public-decks  the public LS-DYNA deck corpus (tests/public/): runs / exit 2 / wrong table,
#                      written to docs/public-decks.md (a few minutes; not part of make test)
SHELL := /bin/sh
FC := h5pfc
SRC_DIRS := base linalg parallel model materials materials/eos build deck elements rigid contact loads io engine solvers
# src/tools/: dynx_*.f90 are the tool programs, dx_*.f90 their modules (in the library)
LIB_SRC := $(foreach d,$(SRC_DIRS),$(wildcard src/$(d)/*.f90)) $(wildcard src/tools/dx_*.f90)
PROG_SRC := src/main/dynx.f90 $(wildcard src/tools/dynx_*.f90)
# the main program's own modules (dx_cli), linked into bin/dynx only
MAIN_SRC := $(filter-out src/main/dynx.f90,$(wildcard src/main/*.f90))
ALL_SRC := $(LIB_SRC) $(MAIN_SRC) $(PROG_SRC)
TEST_SRC := $(wildcard tests/unit/*.f90)
# h5pfc moves archives (libdynx.a) after the -l flags; --no-as-needed keeps libmetis.so
# linked so libdynx.a can resolve METIS symbols from it
LIBS := -Wl,--no-as-needed -lmetis -ldmumps -lmumps_common -larpack -llapack -lblas
COMMON := -I/usr/include -ffree-line-length-132
REL_FLAGS := $(COMMON) -O3 -march=native -funroll-loops
# the element and material kernels work on fixed chunks of nv_chunk elements: their
# temporaries go on the stack (small, bounded); everything else keeps heap temporaries, so
# model-sized arrays (1e5-1e6 nodes) never overflow the 8 MB default stack
KERNEL_OBJ := $(addprefix build/release/,dx_hex8.o dx_hex8_geometry.o dx_tet4.o \
              $(notdir $(patsubst %.f90,%.o,$(wildcard src/materials/*.f90 src/materials/eos/*.f90))))
$(KERNEL_OBJ): REL_FLAGS += -fstack-arrays
DBG_FLAGS := $(COMMON) -O0 -g -std=f2008 -Wall -Wextra -Wimplicit-interface -fcheck=all \
             -ffpe-trap=invalid,zero,overflow -fbacktrace -Wno-unused-dummy-argument \
             -Wno-maybe-uninitialized -Wno-compare-reals -Wno-function-elimination
# the fuzz build: debug flags plus AddressSanitizer and UBSan (gfortran 12 supports both)
ASAN_FLAGS := $(DBG_FLAGS) -fsanitize=address,undefined -fno-omit-frame-pointer
DEFAULT_DECK := decks/taylor_bar/deck.k
OUT := out

PROGS := bin/dynx $(patsubst src/tools/%.f90,bin/%,$(wildcard src/tools/dynx_*.f90))
PROGS := $(subst _,-,$(PROGS))

.PHONY: all deps run test unit regression bench studies clean debug fuzz restart-long kill9-sweep mpi-sweep public-decks
all: $(PROGS)

deps:
	@sh scripts/install-deps.sh

build/deps.mk: $(ALL_SRC) $(TEST_SRC) scripts/f90deps.py
	@mkdir -p build
	@python3 scripts/f90deps.py $(ALL_SRC) $(TEST_SRC) > $@.tmp
	@mv $@.tmp $@

OBJ := build/release
include build/deps.mk
OBJ := build/debug
include build/deps.mk
OBJ := build/asan
include build/deps.mk
# the record-buffer template is included, not compiled: its instances rebuild with it
$(addsuffix /dx_deck_buffers.o,build/release build/debug build/asan): src/deck/dx_deck_buffer.inc

REL_LIB_OBJ := $(patsubst %.f90,build/release/%.o,$(notdir $(LIB_SRC)))
DBG_LIB_OBJ := $(patsubst %.f90,build/debug/%.o,$(notdir $(LIB_SRC)))
vpath %.f90 $(addprefix src/,$(SRC_DIRS) main tools) tests/unit

build/release/%.o: %.f90 | build/release
	$(FC) $(REL_FLAGS) -Jbuild/release -c $< -o $@
build/debug/%.o: %.f90 | build/debug
	$(FC) $(DBG_FLAGS) -Jbuild/debug -c $< -o $@
build/asan/%.o: %.f90 | build/asan
	$(FC) $(ASAN_FLAGS) -Jbuild/asan -c $< -o $@
build/release build/debug build/asan bin:
	@mkdir -p $@

build/release/libdynx.a: $(REL_LIB_OBJ)
	ar rcs $@ $^
build/debug/libdynx.a: $(DBG_LIB_OBJ)
	ar rcs $@ $^

bin/dynx: build/release/dynx.o $(MAIN_SRC:src/main/%.f90=build/release/%.o) build/release/libdynx.a | bin
	$(FC) $(REL_FLAGS) -o $@ $^ $(LIBS)
bin/dynx-debug: build/debug/dynx.o $(MAIN_SRC:src/main/%.f90=build/debug/%.o) build/debug/libdynx.a | bin
	$(FC) $(DBG_FLAGS) -o $@ $^ $(LIBS)
build/asan/libdynx.a: $(patsubst %.f90,build/asan/%.o,$(notdir $(LIB_SRC)))
	ar rcs $@ $^
bin/dynx-asan: build/asan/dynx.o $(MAIN_SRC:src/main/%.f90=build/asan/%.o) build/asan/libdynx.a | bin
	$(FC) $(ASAN_FLAGS) -o $@ $^ $(LIBS)
# the fuzz harness (src/tools/dynx_fuzz.f90) in the debug build (-fcheck=all, FPE traps): the
# campaign's binary (make fuzz); and with the sanitizers too (FUZZ_BIN=bin/dynx-fuzz-asan)
bin/dynx-fuzz-debug: build/debug/dynx_fuzz.o build/debug/libdynx.a | bin
	$(FC) $(DBG_FLAGS) -o $@ $^ $(LIBS)
bin/dynx-fuzz-asan: build/asan/dynx_fuzz.o build/asan/libdynx.a | bin
	$(FC) $(ASAN_FLAGS) -o $@ $^ $(LIBS)
bin/dynx-%: build/release/dynx_%.o build/release/libdynx.a | bin
	$(FC) $(REL_FLAGS) -o $@ $^ $(LIBS)
# FFTW is linked into the one tool that calls it (through src/tools/dx_fft.f90, the only
# module that includes fftw3.f03: scripts/check_layers.py) and its unit test
FFTW_LIBS := -lfftw3
bin/dynx-thist: build/release/dynx_thist.o build/release/libdynx.a | bin
	$(FC) $(REL_FLAGS) -o $@ $^ $(LIBS) $(FFTW_LIBS)

UNIT_TESTS := $(patsubst tests/unit/%.f90,build/debug/tests/%,$(filter tests/unit/test_%,$(TEST_SRC)))
MPI_TESTS := build/debug/tests/mpi_par_test build/debug/tests/mpi_par_model_test build/debug/tests/mpi_fail_test \
             build/debug/tests/mpi_repro_test build/debug/tests/mpi_mumps_test
MPI_BENCH := build/release/bench/mpi_shared_bench build/release/bench/repro_sum_bench
build/release/bench/%: build/release/%.o build/release/libdynx.a
	@mkdir -p build/release/bench
	$(FC) $(REL_FLAGS) -o $@ $^ $(LIBS)
build/debug/tests/%: build/debug/%.o build/debug/dx_assert.o build/debug/libdynx.a
	@mkdir -p build/debug/tests
	$(FC) $(DBG_FLAGS) -o $@ $^ $(LIBS)
build/debug/tests/test_fft: build/debug/test_fft.o build/debug/dx_assert.o build/debug/libdynx.a
	@mkdir -p build/debug/tests
	$(FC) $(DBG_FLAGS) -o $@ $^ $(LIBS) $(FFTW_LIBS)

debug: bin/dynx-debug

run: deps
	@$(MAKE) --no-print-directory all
	@bin/dynx -i $(DEFAULT_DECK) -o $(OUT)/taylor_bar
	@echo "dynx: results of $(DEFAULT_DECK) are in $(OUT)/taylor_bar/ (open $(OUT)/taylor_bar/d3plot.xdmf in ParaView)"

unit: $(UNIT_TESTS)
	@sh scripts/run_unit_tests.sh $(UNIT_TESTS)

regression: all bin/dynx-debug bin/dynx-fuzz-debug
	@sh scripts/run_regression.sh

test: deps
	@$(MAKE) --no-print-directory all debug bin/dynx-asan bin/dynx-fuzz-debug $(UNIT_TESTS) $(MPI_TESTS)
	@sh scripts/test_suites.sh $(UNIT_TESTS) -- $(MPI_TESTS)

# long interrupt-and-continue and kill -9 checks: every scene deck in decks/, every mode
restart-long: deps
	@$(MAKE) --no-print-directory all
	@sh scripts/restart_long.sh

# kill -9 at every pwrite64, write, rename, fsync and unlink of a run (strace fault injection;
# 763 kill points, 0 failures: docs/design.md, "Crash-safe plot output")
kill9-sweep: deps
	@$(MAKE) --no-print-directory all
	@python3 scripts/kill9_sweep.py
	@python3 scripts/kill9_resume_sweep.py states
	@python3 scripts/kill9_resume_sweep.py h5

# serial vs MPI bit for bit on every regression deck that runs to a normal end (docs/design.md,
# "Every regression deck under MPI"); then every `expect` case (bad input, run failures) at
# NP 2 and 3: mpirun's exit code and the message equal the serial run's (mpi_expect_decks.sh)
mpi-sweep: deps
	@$(MAKE) --no-print-directory all
	@sh scripts/mpi_all_decks.sh 2 3 4
	@sh scripts/mpi_expect_decks.sh 2 3

# the deck-reader and restart-dump fuzzer through the sanitized debug build: N mutants
# (default 1e4; the issue-15 campaign is make fuzz N=100000), a mutant over 10 s is a hang
# (bin/dynx-asan: the debug flags, -ffpe-trap=invalid,zero,overflow included, plus the
# sanitizers); SEED= repeats a campaign, JOBS= parallel runs (default 2)
N ?= 10000
JOBS ?= 2
SEED ?=
# N inputs through the in-process harness (bin/dynx-fuzz-debug: one process per batch of
# 500, debug build with the FPE traps); then NPROC inputs (default 1000, half of them
# mutated restart dumps that run their cycles) each through its own bin/dynx-debug process
NPROC ?= 1000
FUZZ_BIN ?= bin/dynx-fuzz-debug
fuzz: deps
	@$(MAKE) --no-print-directory bin/dynx-debug $(FUZZ_BIN)
	@python3 scripts/fuzz_decks.py --count $(N) --jobs $(JOBS) --watchdog 10 $(if $(SEED),--seed $(SEED)) \
	   --harness $(FUZZ_BIN) --dynx bin/dynx-debug --workdir build/fuzz
	@python3 scripts/fuzz_decks.py --count $(NPROC) --jobs $(JOBS) --watchdog 10 $(if $(SEED),--seed $(SEED)) \
	   --restart-share 0.5 --dynx bin/dynx-debug --workdir build/fuzz-proc

bench: deps
	@$(MAKE) --no-print-directory all $(MPI_BENCH)
	@sh scripts/bench.sh
	@sh scripts/bench_compare.sh
	@sh scripts/bench_shared_sum.sh
	@sh scripts/bench_repro_sum.sh
	@sh scripts/bench_contact.sh
	@python3 scripts/bench_scaling.py   # MPI: speed-up, memory per rank, weak scaling, ulimit (BIG= skips 1e6)
	@sh scripts/bench_par_contact.sh
	@sh scripts/bench_implicit.sh
	@python3 scripts/bench_shell_scenes.py --plate $(if $(PLATE),$(PLATE),40) --post $(if $(POST),$(POST),12) --out docs/performance.md

studies: deps
	@$(MAKE) --no-print-directory all
	@sh scripts/studies.sh
	@sh scripts/studies_contact.sh
	@/usr/bin/python3 scripts/studies_emc.py
	@sh scripts/studies_scenes.sh
	@sh scripts/studies_lamina.sh
	@sh scripts/studies_spall.sh
	@sh scripts/studies_hirate.sh
	@/usr/bin/python3 scripts/studies_order.py
	@/usr/bin/python3 scripts/studies_order_seed.py
	@/usr/bin/python3 scripts/studies_order_more.py
	@/usr/bin/python3 scripts/doc_numbers.py --update

# each deck of tests/public/index.tsv: --check, a --walltime-capped run, a physics check
public-decks: all
	@/usr/bin/python3 scripts/public_decks.py --self-test
	@/usr/bin/python3 scripts/public_decks.py

clean:
	rm -rf build bin out
