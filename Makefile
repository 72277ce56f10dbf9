# tissuefit — the only entry point.  `make help` lists the targets.
#
# Every target that needs Debian packages checks for them first (deps-*):
# as root it installs what is missing with apt-get, otherwise it prints the
# exact apt-get line and stops.

SHELL := /bin/bash
# A failing command inside a pipe fails the recipe (a checker piped into sed
# must not have its verdict swallowed).
.SHELLFLAGS := -o pipefail -c
.DEFAULT_GOAL := all
.DELETE_ON_ERROR:
.SUFFIXES:

VERSION := 0.1.0
# Cores for the parallel parts of `make check` (the builds of each check,
# the unit tests, the two fuzzers).  nproc(1) would return OMP_NUM_THREADS,
# which make check sets to 1 for the programs it runs (below).
NPROC := $(shell env -u OMP_NUM_THREADS -u OMP_THREAD_LIMIT nproc 2>/dev/null || echo 1)
PREFIX ?= /usr/local
B := build

# Quiet by default: one line per built file; `make V=1` shows the commands.
V ?= 0
Q := $(if $(filter 1,$(V)),,@)
# $(call say,WHAT) prints "  WHAT target" unless V=1.
say = $(if $(filter 1,$(V)),,@printf '  %-6s %s\n' '$(1)' '$@')
# $(Q)$(call made,WHAT)COMMAND: the target's folder and the same line in the
# command's own shell, for the rules make check runs about 1,300 times (two
# more shells per object cost about 7 s of its CPU).
made = mkdir -p $(@D) && $(if $(filter 1,$(V)),,printf '  %-6s %s\n' '$(1)' '$@' && )

CC := gcc
CLANG := clang
ARM := arm-none-eabi-
RV := riscv64-unknown-elf-

# GUIDE §4: strict C11, no contraction of a*b+c into an FMA, warnings are errors.
STRICT := -std=c11 -ffp-contract=off -Wall -Wextra -Werror
HOST_STRICT := $(STRICT) -Wshadow -Wstrict-prototypes -Wmissing-prototypes -D_XOPEN_SOURCE=700
TARGET_STRICT := $(STRICT) -Wdouble-promotion -Wconversion -Wpedantic -Wshadow \
                 -Wstrict-prototypes -Wmissing-prototypes -ffreestanding
SANITIZE := -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
# TEST_G: the debug information of the test programs and of the sanitized
# and fuzzed host builds: line tables (-g1) name the file and line of every
# frame a sanitizer or a failed assertion reports, and compile about 14 %
# faster than -g, about 35 s of make check's CPU over its ~300 compiles;
# `make TEST_G=-g` for a debugger's view of the variables.
TEST_G ?= -g1

M4F_FLAGS := -mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard
RV64_FLAGS := -march=rv64imafdc -mabi=lp64d -mcmodel=medany

# ---------------------------------------------------------------------------
# Debian packages
DEBS_BUILD := gcc make binutils pkg-config zlib1g-dev liblapacke-dev libopenblas-dev \
              libsuitesparse-dev libcyaml-dev libyaml-dev libgmsh-dev libassimp-dev libgsl-dev lld
DEBS_CHECK := $(DEBS_BUILD) libcmocka-dev clang valgrind gcc-arm-none-eabi \
              libnewlib-arm-none-eabi gcc-riscv64-unknown-elf
DEBS_DEMO := $(DEBS_BUILD) gnuplot-nox

# $(call ensure_debs,PACKAGES)
# One dpkg-query for the whole list: every check's make runs deps-check,
# and one query per package cost about 20 s of make check's CPU.
define ensure_debs
@if ! command -v dpkg-query >/dev/null 2>&1; then \
  echo "note: not a Debian system; make sure these (or their equivalents) are installed: $(1)"; \
  exit 0; \
fi; \
installed=" $$(dpkg-query -W -f='$${db:Status-Status} $${Package}\n' $(1) 2>/dev/null | \
  sed -n 's/^installed \([^:]*\).*/\1/p' | tr '\n' ' ')"; \
missing=""; \
for p in $(1); do \
  case "$$installed" in *" $$p "*) ;; *) missing="$$missing $$p";; esac; \
done; \
if [ -n "$$missing" ]; then \
  if [ "$$(id -u)" = 0 ]; then \
    echo "installing Debian packages:$$missing"; \
    apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq \
      --no-install-recommends $$missing >/dev/null || exit 1; \
  else \
    echo "error: missing Debian packages. Install them with:"; \
    echo "  sudo apt-get install -y --no-install-recommends$$missing"; \
    exit 1; \
  fi; \
fi
endef

DEBS_BENCH := $(DEBS_BUILD)

.PHONY: deps-build deps-check deps-demo deps-bench
deps-build: ; $(call ensure_debs,$(DEBS_BUILD))
deps-check: ; $(call ensure_debs,$(DEBS_CHECK))
deps-demo: ; $(call ensure_debs,$(DEBS_DEMO))
deps-bench: ; $(call ensure_debs,$(DEBS_BENCH))

# $(call upper,TEXT): TEXT in capitals, for the TFIT_NAME_* macros of a
# header's name.  Pure make: a $(shell ... | tr) here cost two forks per
# call, and the fragments call it about 570 times while make reads them
# (8 s of every make invocation, before any rule ran).
upper = $(subst z,Z,$(subst y,Y,$(subst x,X,$(subst w,W,$(subst v,V,$(subst u,U,$(subst t,T,$(subst s,S,$(subst r,R,$(subst q,Q,$(subst p,P,$(subst o,O,$(subst n,N,$(subst m,M,$(subst l,L,$(subst k,K,$(subst j,J,$(subst i,I,$(subst h,H,$(subst g,G,$(subst f,F,$(subst e,E,$(subst d,D,$(subst c,C,$(subst b,B,$(subst a,A,$(1)))))))))))))))))))))))))))

# Two lengths of the same checks.  `make check` runs every check in its
# short version, under 10 minutes on a 2-core machine: each check still
# runs its kind of test on every area it covers, with fewer repetitions or
# configurations.  `make check-full` runs the same checks at full length
# (CHECK_FULL=1); what each check adds there is listed in
# docs/architecture.md ("Adding a check").  $(call check_len,FULL,SHORT)
# picks the value for the current length.
CHECK_FULL ?=
comma := ,
empty :=
space := $(empty) $(empty)
check_len = $(if $(filter-out 0,$(CHECK_FULL)),$(1),$(2))

# Fragments: each area adds its rules, and appends to CHECKS (run by
# `make check`), BENCHES (run by `make bench`) and the DEBS_* lists.
CHECKS :=
BENCHES :=
include target/target.mk
include host/host.mk
include tests/tests.mk
include $(filter-out target/target.mk host/host.mk tests/tests.mk,$(sort $(wildcard */*.mk)))

# ---------------------------------------------------------------------------
.PHONY: all demo check check-full check-quick bench install clean help

all: $(B)/bin/tissuefit $(B)/lib/libtfit.a

# Each check prints a "== ... ==" heading first and a result line
# "ok: ..." last, once its work is done (tests/check_guard.sh): a check
# whose rule lost its recipe, or that stopped after its heading, must fail
# rather than pass silently.  The guard is first shown such a log.
#
# $(call run_checks,LIST,NAME,INSTALLERS) runs in two phases, after the
# deps-* INSTALLERS the checks of LIST use, one after the other (two apt-get
# runs at once would fight over dpkg's lock).  First one make builds
# every file the checks of LIST depend on (tests/check_files.awk reads
# them from make's database), $(NPROC) jobs at a time, its output in
# $(B)/check/NAME-build.log: make alone sees which files two checks share.
# Then the checks run CHECK_LANES at a time (tests/run_checks.sh), each
# its own make, with its output in $(B)/check/CHECK.log, and "WALL CHECK
# CPU" seconds in $(B)/check/NAME.seconds.  The lanes start with the
# checks measured slowest (CHECK_FIRST), so that no core waits at the end
# for one long check.  A check's make builds what is left $(NPROC) jobs at
# a time, unless make was given -j (then they share its jobserver).
# One lane more than the cores: a check waiting on QEMU's output, MPI's
# start or its own lines then leaves a core idle less often (with NPROC
# lanes the checks used 92 % of the cores, 72 of 926 core-seconds idle;
# with NPROC + 1 94 %; NPROC + 2 gained nothing and cost more CPU).
CHECK_LANES ?= $(shell echo $$(( $(NPROC) + 1 )))
# The checks run one more at a time than there are cores, and their builds
# $(NPROC) jobs at a time: each program gets one OpenMP thread unless a
# check asks for more.  Two threads per program on two busy cores cost CPU
# (libgomp spinning at every barrier: about 30 s of make check's, perf;
# block48_nh's held-out solves 138 s of CPU instead of 100) and wall time
# (a sleeping thread waits for a core at every barrier: a unit test of 1 s
# of CPU took 12.5 s).  The bits do not depend on the thread count, and the
# checks that say so run their two thread counts explicitly
# (test_conformance and test_solver, the collocation's Hertz run,
# check-coeffs' regenerations with two threads, the outputs' interrupted
# writes).
check check-full check-quick: export OMP_NUM_THREADS ?= 1
check check-full check-quick: export OMP_WAIT_POLICY := passive
CHECK_JOBS = $(if $(findstring jobserver,$(MAKEFLAGS)),,-j$(NPROC))
CHECK_FIRST := check-sanitize check-fuzz check-unit check-fit check-stability check-qemu-region \
               check-prony-long check-organs check-cycles check-cli check-misra check-mpi
# The time the first make was started, for the total make check prints.
ifeq ($(MAKE_T0),)
MAKE_T0 := $(shell date +%s)
export MAKE_T0
endif
define run_checks
	@mkdir -p $(B)/check
	@$(MAKE) --no-print-directory -j1 $(3)
	@set -e; s=$$(date +%s); \
	echo "== building what the $(words $(1)) checks need ($(B)/check/$(2)-build.log) =="; \
	files=$$({ $(MAKE) --no-print-directory -pq 2>/dev/null || true; } | awk -v ROOTS="$(1)" -f tests/check_files.awk); \
	[ -n "$$files" ] || { echo "tests/check_files.awk found no files the checks need"; exit 1; }; \
	if ! $(MAKE) --no-print-directory $(CHECK_JOBS) $$files >$(B)/check/$(2)-build.log 2>&1; then \
	  grep -v 'is up to date' $(B)/check/$(2)-build.log | tail -40; echo "FAILED: the build the checks need"; exit 1; fi; \
	times >$(B)/check/$(2)-build.times; \
	echo "built $$(echo $$files | wc -w) files in $$(( $$(date +%s) - s )) s ($$(awk -f tests/times_cpu.awk \
	  $(B)/check/$(2)-build.times) s of CPU)"
	@MAKE_JOBS="$(CHECK_JOBS)" tests/run_checks.sh $(CHECK_LANES) $(B)/check $(2) \
	  $(filter $(CHECK_FIRST),$(1)) $(filter-out $(CHECK_FIRST),$(1))
	@echo "$(2): $$(( $$(date +%s) - $(MAKE_T0) )) s since make started ($(NPROC) cores)"
endef

check: | deps-check
	@mkdir -p $(B)/check
	@printf '== a check that stopped after its heading ==\n' >$(B)/check/guard-selftest.log
	@if tests/check_guard.sh guard-selftest $(B)/check/guard-selftest.log >/dev/null; then \
	  echo "tests/check_guard.sh accepted a log without a result line"; exit 1; fi
	$(call run_checks,$(CHECKS),check,deps-check deps-mpi deps-calculix)
	@echo "== make check$(call check_len,-full,): all passed ($(words $(CHECKS)) checks, each with its result line$(call check_len,, in its short version)) =="

check-full: | deps-check
	@$(MAKE) --no-print-directory check CHECK_FULL=1

# The edit-test loop: every unit test natively (UNIT_ALL=1, tests/tests.mk),
# the layer rule, the freestanding library and one bit-exact configuration
# (`make check` runs them all).
QUICK_CHECKS := check-unit check-host-layers check-freestanding check-bitexact-quick
check-quick: | deps-check
ifeq ($(UNIT_ALL),)
	@$(MAKE) --no-print-directory check-quick UNIT_ALL=1
else
	$(call run_checks,$(QUICK_CHECKS),check-quick,deps-check)
	@echo "== make check-quick: all passed ($(words $(QUICK_CHECKS)) checks; make check runs $(words $(CHECKS))) =="
endif

bench: | deps-bench
	@$(MAKE) --no-print-directory $(BENCHES)

# INSTALL_CORES: cross-built libraries installed beside the native one, as
# lib/tfit/CORE/libtfit.a (the name the linker scripts place by), for
# find_package(tfit) in a cross build (docs/firmware.md §11), e.g.
# `make install PREFIX=/opt/tfit INSTALL_CORES="cortex-m4f cortex-m7"`.
INSTALL_CORES ?=
INSTALL_CORES_KNOWN := cortex-m4f cortex-m7 riscv64
$(if $(filter-out $(INSTALL_CORES_KNOWN),$(INSTALL_CORES)),\
  $(error INSTALL_CORES: unknown core(s) $(filter-out $(INSTALL_CORES_KNOWN),$(INSTALL_CORES)); known: $(INSTALL_CORES_KNOWN)))
INSTALL_CMAKE := $(DESTDIR)$(PREFIX)/lib/cmake/tfit
INSTALL_SHARE := $(DESTDIR)$(PREFIX)/share/tfit

install: all $(INSTALL_CORES:%=$(B)/%/libtfit.a)
	install -d $(DESTDIR)$(PREFIX)/bin $(DESTDIR)$(PREFIX)/lib/pkgconfig $(DESTDIR)$(PREFIX)/include \
	  $(INSTALL_CMAKE) $(INSTALL_SHARE)/cmake $(INSTALL_SHARE)/linker
	install -m 755 $(B)/bin/tissuefit $(DESTDIR)$(PREFIX)/bin/tissuefit
	install -m 644 $(B)/lib/libtfit.a $(DESTDIR)$(PREFIX)/lib/libtfit.a
	install -m 644 target/include/tfit.h $(DESTDIR)$(PREFIX)/include/tfit.h
	install -m 644 target/include/tfit_q31.h $(DESTDIR)$(PREFIX)/include/tfit_q31.h
	install -d $(DESTDIR)$(PREFIX)/lib/tfit/native-pic
	install -m 644 $(B)/native-pic/libtfit.a $(DESTDIR)$(PREFIX)/lib/tfit/native-pic/libtfit.a
	install -m 644 python/tissuefit/tfit_shim.c $(INSTALL_SHARE)/tfit_shim.c
	sed -e 's|@PREFIX@|$(PREFIX)|' -e 's|@VERSION@|$(VERSION)|' target/tfit.pc.in \
	  > $(DESTDIR)$(PREFIX)/lib/pkgconfig/tfit.pc
	chmod 644 $(DESTDIR)$(PREFIX)/lib/pkgconfig/tfit.pc
	install -m 644 cmake/tfitConfig.cmake cmake/tfitTargets.cmake cmake/tfitGenerate.cmake $(INSTALL_CMAKE)
	sed -e 's|@VERSION@|$(VERSION)|g' cmake/tfitConfigVersion.cmake.in > $(INSTALL_CMAKE)/tfitConfigVersion.cmake
	chmod 644 $(INSTALL_CMAKE)/tfitConfigVersion.cmake
	install -m 644 cmake/arm-none-eabi.cmake cmake/arm-none-eabi-m4f.cmake cmake/arm-none-eabi-m7.cmake \
	  $(INSTALL_SHARE)/cmake
	install -m 644 linker/*.ld linker/startup.c linker/startup.h linker/semihost.c linker/semihost.h \
	  $(INSTALL_SHARE)/linker
	$(foreach c,$(INSTALL_CORES),install -d $(DESTDIR)$(PREFIX)/lib/tfit/$(c) && \
	  install -m 644 $(B)/$(c)/libtfit.a $(DESTDIR)$(PREFIX)/lib/tfit/$(c)/libtfit.a;)

clean:
	rm -rf $(B)

help:
	@echo "make            build/bin/tissuefit and build/lib/libtfit.a"
	@echo "make demo       the main job, end to end"
	@echo "make check      every test, each in its short version (installs missing Debian packages when root)"
	@echo "make check-full the same tests at full length (long runs, every thread count and configuration)"
	@echo "make check-quick  unit tests, layers, freestanding, one bit-exact configuration"
	@echo "make bench      speed and size measurements (medians, ratios, instruction counts)"
	@echo "make install    PREFIX=/usr/local: tool, library, tfit.h, pkg-config file, CMake package,"
	@echo "                Python module (docs/python.md; make python-example runs its example)"
	@echo "                (INSTALL_CORES=\"cortex-m4f cortex-m7\": their libraries too)"
	@echo "make clean      remove build/"
