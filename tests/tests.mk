# tests.mk — everything `make check` runs.
#
#   check-unit         cmocka host unit tests (tests/unit/LAYER/test_*.c, one
#                      folder per host/ layer); make check: the 10 of UNIT_FIRST
#   check-sanitize     the same tests under AddressSanitizer + UBSan;
#                      make check: all but those 10
#   check-freestanding target library for Cortex-M4F and RV64: no undefined
#                      symbols, no mutable statics, no recursion
#   check-bitexact     1000 random models x 4 compiler configurations
#   check-golden       golden vectors of generated headers x 4 configurations
#   check-header       a generated header included from two translation units
#   check-insncount    callgrind: same instruction count for every input
#   check-cli          the command line: help, exit statuses, nothing half-written;
#                      tissuefit eval: every shipped header's golden vectors through
#                      a CSV bit for bit (tests/cli/eval.sh)

# -I.: a test reaches beyond host/ by its path from the top ("tests/...").
TEST_CFLAGS := $(HOST_CFLAGS) -O1 $(TEST_G) -I. -Itests/support -Itests/bitexact
SUPPORT_SRC := $(wildcard tests/support/*.c)
UNIT_SRC := $(shell find tests/unit -name 'test_*.c' | LC_ALL=C sort)
UNIT_NAMES := $(UNIT_SRC:tests/unit/%.c=%)
BITEXACT_CONFIGS := gcc-O0 gcc-O2 gcc-O3-native clang-O2
T := $(B)/tests

# Link line of a host test: $(call host_test_link,VARIANT); a rule that
# uses it lists $(B)/VARIANT/libtest-support.a among its prerequisites.
host_test_link = $(B)/$(1)/libtest-support.a $(B)/$(1)/libtissuefit-host.a $(B)/$(1)/libtfit.a \
                 -lcmocka $(HOST_LIBS)

# tests/support/*.c compiled once per variant into an archive that every
# host test links, rather than once per test program (make check links
# about 150 of them: 62 unit tests twice, and the tools of the other checks).
# $(call test_support_lib,VARIANT,FLAGS)
define test_support_lib
$(B)/$(1)/test-support/%.o: tests/support/%.c $(wildcard tests/support/*.h) $(HOST_HDR) | deps-check
	@mkdir -p $$(@D)
	$$(call say,CC)
	$(Q)$(CC) $(TEST_CFLAGS) $(2) -c $$< -o $$@
$(B)/$(1)/libtest-support.a: $(SUPPORT_SRC:tests/support/%.c=$(B)/$(1)/test-support/%.o)
	$$(call say,AR)
	$(Q)rm -f $$@ && ar rcs $$@ $$^
endef
$(eval $(call test_support_lib,native,))
$(eval $(call test_support_lib,asan,$(SANITIZE)))

$(T)/unit/%: tests/unit/%.c $(B)/native/libtissuefit-host.a $(B)/native/libtest-support.a $(B)/native/libtfit.a | deps-check
	$(Q)$(call made,BUILD)$(CC) $(TEST_CFLAGS) $< $(call host_test_link,native) -o $@
$(T)/asan/%: tests/unit/%.c $(B)/asan/libtissuefit-host.a $(B)/asan/libtest-support.a $(B)/asan/libtfit.a | deps-check
	$(Q)$(call made,BUILD)$(CC) $(TEST_CFLAGS) $(SANITIZE) $< $(call host_test_link,asan) -o $@

.PHONY: check-unit check-sanitize check-freestanding check-bitexact check-golden \
        check-header check-insncount check-cli
CHECKS += check-unit check-sanitize check-freestanding check-bitexact check-golden \
          check-header check-insncount check-cli

# The programs run $(NPROC) at a time (tests/run_tests.sh prints their logs
# in order, then the slowest three), the slowest first so that no core
# waits at the end for one long program (measured: `slowest:` in the log).
UNIT_FIRST := solvers/test_conformance fitting/test_resonant_fit fitting/test_family_conformance \
              scene/test_scene_scaled solvers/test_weak_bc solvers/test_homogeneous scene/test_sites \
              solvers/test_nonlinear fitting/test_prony_pipeline meshfree/test_cut_shape
# make check runs every unit program once: the ten of UNIT_FIRST natively in
# check-unit, every other one under ASan + UBSan in check-sanitize, a
# stricter run of the same program and the same -O2 host library.  They are
# the seven slowest natively (every solver re-solving block48, every family
# refitted: 120 s of CPU natively, about 200 under the sanitizers) and the
# three the sanitizers slow most (the scaled scenes' organ fills 29 s under
# them, 8 s natively; the cut shape functions 14 s and 1 s; the Prony
# pipeline 11 s and 2.5 s).  The scene reader and the cut shape functions
# stay under ASan + UBSan in make check through check-fuzz's targets.
# make check-full runs all of them both ways; make check-quick (UNIT_ALL=1)
# all of them natively, the edit-test loop having no sanitized build.
UNIT_ALL ?=
UNIT_NATIVE = $(if $(or $(filter-out 0,$(CHECK_FULL)),$(UNIT_ALL)),$(UNIT_NAMES),$(UNIT_FIRST))
check-unit: $(UNIT_NATIVE:%=$(T)/unit/%)
	@echo "== host unit tests$(if $(filter $(words $(UNIT_NAMES)),$(words $(UNIT_NATIVE))),, (short: the $(words $(UNIT_FIRST)) slowest; check-sanitize runs the others))) =="
	@tests/run_tests.sh $(NPROC) $(T)/logs/unit $(foreach u,$(UNIT_FIRST),$(T)/unit/$(u)) \
	  $(filter-out $(UNIT_FIRST:%=$(T)/unit/%),$^)
	@echo "ok: $(words $^) of $(words $(UNIT_NAMES)) unit test programs passed"

SANITIZE_NAMES = $(call check_len,$(UNIT_NAMES),$(filter-out $(UNIT_FIRST),$(UNIT_NAMES)))
check-sanitize: $(SANITIZE_NAMES:%=$(T)/asan/%)
	@echo "== host unit tests under ASan + UBSan$(call check_len,, (short: not the $(words $(UNIT_FIRST)) slowest; check-unit runs them natively)) =="
	@ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1 \
	  tests/run_tests.sh $(NPROC) $(T)/logs/asan $(foreach u,$(filter $(UNIT_FIRST),$(SANITIZE_NAMES)),$(T)/asan/$(u)) \
	  $(filter-out $(UNIT_FIRST:%=$(T)/asan/%),$^)
	@echo "ok: $(words $^) of $(words $(UNIT_NAMES)) unit test programs passed under ASan + UBSan"

# --- freestanding -----------------------------------------------------------
$(T)/callgraph: tests/freestanding/callgraph.c | deps-check
	@mkdir -p $(@D)
	$(call say,BUILD)
	$(Q)$(CC) $(HOST_STRICT) -O1 $< -o $@

# The checker must reject a known-bad image, or its "no recursion" means nothing.
$(T)/recursive.elf: tests/freestanding/recursive.c | deps-check
	@mkdir -p $(@D)
	$(call say,BUILD)
	$(Q)$(ARM)gcc $(M4F_FLAGS) -O0 -nostdlib -Wl,-e,pong $< -o $@

check-freestanding: $(T)/callgraph $(T)/recursive.elf \
    $(foreach b,cortex-m4f cortex-m4f-O0 cortex-m4f-Os cortex-m4f-O3 riscv64 riscv64-O0,$(B)/$(b)/libtfit.a)
	@echo "== freestanding target library =="
	@if $(ARM)objdump -d $(T)/recursive.elf | $(T)/callgraph >/dev/null; then \
	  echo "callgraph checker accepted a recursive image"; exit 1; fi
	@set -e; export CALLGRAPH=$(T)/callgraph; \
	for b in cortex-m4f cortex-m4f-O0 cortex-m4f-Os cortex-m4f-O3; do \
	  FLAGS="$(M4F_FLAGS)" tests/freestanding/check.sh $$b $(ARM) $(B)/$$b arm; done; \
	for b in riscv64 riscv64-O0; do \
	  FLAGS="$(RV64_FLAGS)" tests/freestanding/check.sh $$b $(RV) $(B)/$$b; done
	@# the modal rows' table is the one declared indirect call: undeclared, or
	@# declared with a target the image lacks, it must be refused
	@if $(ARM)objdump -d $(B)/cortex-m4f-O0/image.elf | $(T)/callgraph >/dev/null; then \
	  echo "callgraph checker accepted an undeclared indirect call"; exit 1; fi
	@if $(ARM)objdump -d $(B)/cortex-m4f-O0/image.elf | \
	  $(T)/callgraph tfit_modal_rows_asm=tfit_modal_rows_r1,tfit_modal_rows_r9 >/dev/null; then \
	  echo "callgraph checker accepted a declared target that is not in the image"; exit 1; fi
	@echo "ok: 6 target library builds freestanding; the call-graph checker rejects recursion, undeclared indirect calls and missing declared targets"

# --- bit-exact: random models -------------------------------------------------
$(T)/gen_random: tests/bitexact/gen_random.c $(B)/native/libtissuefit-host.a $(B)/native/libtest-support.a $(B)/native/libtfit.a | deps-check
	@mkdir -p $(@D)
	$(call say,BUILD)
	$(Q)$(CC) $(TEST_CFLAGS) $< $(call host_test_link,native) -o $@

$(T)/random.bundle: $(T)/gen_random
	$(call say,GEN)
	$(Q)$< bundle 1000 20261122 $@

$(T)/run_bundle-%: tests/bitexact/run_bundle.c $(B)/bitexact-%/libtfit.a | deps-check
	@mkdir -p $(@D)
	$(call say,BUILD)
	$(Q)$(CC) $(HOST_STRICT) -O1 -Itarget/include -Itests/bitexact $^ -o $@

# The counter-test: the library built so that it contracts a*b + c into
# FMA must mismatch, or bit-exactness is not being measured.  The sources
# forbid contraction themselves (tfit_internal.h's pragma, which holds even
# under -ffp-contract=fast), so the pragma is removed from a copy, as
# check-contract does for the M4F; the copy is built with -mfma
# -ffp-contract=fast.  Its golden bits must differ and its boot self-test
# (tfit_model_check, TFIT_ERR_ARITH) must fail.  It needs a CPU with FMA;
# without one the check fails, it is not skipped.
FMA_PRAGMA := \#pragma GCC optimize("fp-contract=off")
$(T)/fma/libtfit.a: $(TARGET_SRC) $(TARGET_HDR) | deps-check
	$(call say,AR)
	$(Q)rm -rf $(@D) && mkdir -p $(@D)/src $(@D)/obj && cp target/src/*.c target/src/*.h $(@D)/src/
	$(Q)grep -qxF '$(FMA_PRAGMA)' $(@D)/src/tfit_internal.h || \
	  { echo "tfit_internal.h no longer has the line this test removes"; exit 1; }
	$(Q)grep -vxF '$(FMA_PRAGMA)' target/src/tfit_internal.h >$(@D)/src/tfit_internal.h
	$(Q)for f in $(@D)/src/*.c; do $(CC) $(TARGET_CFLAGS) -O2 -mfma -ffp-contract=fast \
	  -I$(@D)/src -c $$f -o $(@D)/obj/$$(basename $${f%.c}).o || exit 1; done
	$(Q)ld -r $(@D)/obj/*.o -o $(@D)/libtfit.o && ar rcs $@ $(@D)/libtfit.o
$(T)/run_bundle-fma: tests/bitexact/run_bundle.c $(T)/fma/libtfit.a | deps-check
	$(call say,BUILD)
	$(Q)$(CC) $(HOST_STRICT) -O1 -Itarget/include -Itests/bitexact $^ -o $@

check-bitexact: $(T)/random.bundle $(BITEXACT_CONFIGS:%=$(T)/run_bundle-%) $(T)/run_bundle-fma
	@echo "== bit-exact: random models, every family, four compiler configurations =="
	@set -e; for c in $(BITEXACT_CONFIGS); do $(T)/run_bundle-$$c $$c $(T)/random.bundle; done
	@grep -qw fma /proc/cpuinfo || { echo "this CPU has no FMA: the FMA counter-test cannot run"; exit 1; }
	@if $(T)/run_bundle-fma fma-contracted $(T)/random.bundle >$(T)/fma.log 2>&1; then \
	  tail -n 1 $(T)/fma.log; echo "the FMA-contracted library matched every golden word"; exit 1; fi; \
	tail -n 1 $(T)/fma.log; \
	n=$$(sed -n 's/.* \([0-9][0-9]*\) mismatches.*/\1/p' $(T)/fma.log); \
	k=$$(sed -n 's/.* \([0-9][0-9]*\) failed checks.*/\1/p' $(T)/fma.log); \
	[ "$${n:-0}" -gt 0 ] || { echo "the FMA build gave no mismatching word"; exit 1; }; \
	[ "$${k:-0}" -gt 0 ] || { echo "the FMA build passed every boot self-test"; exit 1; }
	@echo "ok: 1000 random models bit-exact in $(words $(BITEXACT_CONFIGS)) compiler configurations; a contracted build mismatches and fails its self-test"

# One configuration of check-bitexact, for make check-quick.
BITEXACT_QUICK := $(word 2,$(BITEXACT_CONFIGS))
.PHONY: check-bitexact-quick
check-bitexact-quick: $(T)/random.bundle $(T)/run_bundle-$(BITEXACT_QUICK)
	@echo "== bit-exact: random models, every family, $(BITEXACT_QUICK) only =="
	@$(T)/run_bundle-$(BITEXACT_QUICK) $(BITEXACT_QUICK) $(T)/random.bundle
	@echo "ok: 1000 random models bit-exact in $(BITEXACT_QUICK) (make check-bitexact runs $(words $(BITEXACT_CONFIGS)) configurations and the FMA counter-test)"

# --- generated headers --------------------------------------------------------
$(T)/gen/families.h: $(T)/gen_random
	@mkdir -p $(@D)
	$(call say,GEN)
	$(Q)$< header 7 $@
$(T)/gen/modal_ranks.h: $(T)/gen_random
	@mkdir -p $(@D)
	$(call say,GEN)
	$(Q)$< modal-ranks 14 $@
$(T)/gen/demo.h: $(B)/bin/tissuefit
	@mkdir -p $(@D)
	$(call say,GEN)
	$(Q)$< -q demo-model -o $@

# $(call golden_runner,HEADER-BASE)
define golden_runner
$(T)/golden-$(1)-%: tests/header/run_golden.c $(T)/gen/$(1).h $(B)/bitexact-%/libtfit.a
	$$(call say,BUILD)
	$(Q)$(CC) $(HOST_STRICT) -O1 -Itarget/include -I$(T)/gen -DGOLDEN_H='"$(1)_golden.h"' \
	  -DGOLDEN_SETS=TFIT_$(call upper,$(1))_GOLDEN_SETS \
	  -DTFIT_$(call upper,$(1))_IMPLEMENTATION $$< $(B)/bitexact-$$*/libtfit.a -o $$@
endef
$(eval $(call golden_runner,families))
$(eval $(call golden_runner,demo))
# and the shipped contact regions' headers (GOLDEN_REGIONS: tests/region_target.mk,
# read after coeffs.mk, adds them and their runners as prerequisites)
GOLDEN_HEADERS = families demo $(GOLDEN_REGIONS)

check-golden: $(foreach h,families demo,$(BITEXACT_CONFIGS:%=$(T)/golden-$(h)-%))
	@echo "== golden vectors of generated headers and the shipped contact regions' =="
	@set -e; for h in $(GOLDEN_HEADERS); do for c in $(BITEXACT_CONFIGS); do \
	  $(T)/golden-$$h-$$c $$h/$$c; done; done
	@echo "ok: golden vectors of $(words $(GOLDEN_HEADERS)) headers pass in $(words $(BITEXACT_CONFIGS)) configurations"

$(T)/two_tu: tests/header/tu_main.c tests/header/tu_other.c $(T)/gen/families.h $(B)/native/libtfit.a
	$(call say,BUILD)
	$(Q)$(CC) $(HOST_STRICT) -O1 -Itarget/include -I$(T)/gen $(filter %.c %.a,$^) -o $@

# A stale header: families.h regenerated from another seed (same model names,
# other tables and N_OUT), compiled into one file next to the current one's
# IMPLEMENTATION: the link must fail on the model's CRC-named symbol.
$(T)/gen/stale/families.h: $(T)/gen_random
	@mkdir -p $(@D)
	$(call say,GEN)
	$(Q)$< header 8 $@

check-header: $(T)/two_tu $(T)/gen/stale/families.h tests/header/tu_stale.c
	@echo "== generated header in two translation units; a file compiled against a stale header does not link =="
	@$(T)/two_tu
	@n=$$(nm $(T)/two_tu | grep -c ' tfit_nodal_a_coef$$'); \
	if [ "$$n" != 1 ]; then echo "tfit_nodal_a_coef defined $$n times"; exit 1; fi; \
	echo "tables defined once: ok"
	@if $(CC) $(HOST_STRICT) -O1 -Itarget/include -I$(T)/gen -c tests/header/tu_main.c -o $(T)/tu_main.o && \
	  $(CC) $(HOST_STRICT) -O1 -Itarget/include -I$(T)/gen/stale -c tests/header/tu_stale.c -o $(T)/tu_stale.o && \
	  $(CC) $(T)/tu_main.o $(T)/tu_stale.o $(B)/native/libtfit.a -o $(T)/stale_tu 2>$(T)/stale.err; then \
	  echo "a file compiled against a stale families.h linked"; exit 1; fi; \
	  want=$$(sed -n 's/^#define tfit_nodal_a \(tfit_nodal_a_[0-9a-f]*\) .*/\1/p' $(T)/gen/stale/families.h); \
	  grep -q "undefined reference to .$$want" $(T)/stale.err || { cat $(T)/stale.err; exit 1; }; \
	  echo "stale header (N_OUT $$(sed -n 's/^#define TFIT_NODAL_A_N_OUT \([0-9]*\)u/\1/p' $(T)/gen/stale/families.h) against $$(sed -n 's/^#define TFIT_NODAL_A_N_OUT \([0-9]*\)u/\1/p' $(T)/gen/families.h)): link refused, undefined $$want"
	@echo "ok: the header compiles in two translation units, its tables defined once; a stale one does not link"

# --- fixed instruction count ------------------------------------------------
$(T)/probe: tests/insncount/probe.c $(T)/gen/families.h $(B)/native/libtfit.a
	$(call say,BUILD)
	$(Q)$(CC) $(HOST_STRICT) -O1 -Itarget/include -I$(T)/gen $(filter %.c %.a,$^) -o $@

# modal_ranks.h too: the float modal ranks 1-9 and the modal_q15 models
# (their C path here: branch-free saturation and integer sums)
$(T)/probe-modal_ranks: tests/insncount/probe.c $(T)/gen/modal_ranks.h $(B)/native/libtfit.a
	$(call say,BUILD)
	$(Q)$(CC) $(HOST_STRICT) -O1 -Itarget/include -I$(T)/gen -DGOLDEN_H='"modal_ranks_golden.h"' \
	  -DGOLDEN_SETS=TFIT_MODAL_RANKS_GOLDEN_SETS -DGOLDEN_Q31_SETS=TFIT_MODAL_RANKS_GOLDEN_Q31_SETS \
	  -DTFIT_MODAL_RANKS_IMPLEMENTATION $(filter %.c %.a,$^) -o $@

check-insncount: $(T)/probe $(T)/probe-modal_ranks
	@echo "== instructions per evaluation (callgrind), every golden input =="
	@tests/insncount/run.sh $(T)/probe $(T)/insncount
	@tests/insncount/run.sh $(T)/probe-modal_ranks $(T)/insncount-modal_ranks
	@echo "ok: one instruction count per entry point and model, whatever the input"

# tissuefit eval compiles the header for each call, four per model: make
# check leaves out the heart's and the stomach's, whose golden files are
# 4.5 and 2.3 MB, and liver_tumour's (the liver's is the organ evaluated
# here; liver_tumour's golden vectors run in check-python and check-organs)
# (make check-full: every shipped header).
EVAL_HEADERS = $(call check_len,,$(filter-out coeffs/heart.h coeffs/stomach.h coeffs/liver_tumour.h %_golden.h,$(sort $(wildcard coeffs/*.h))))
check-cli: $(B)/bin/tissuefit
	@echo "== command line =="
	@tests/cli/cli.sh $(B)/bin/tissuefit
	@echo "== tissuefit eval: $(call check_len,every shipped header's,the shipped headers' (short: not the heart's, the stomach's and liver_tumour's)) golden vectors through a CSV, and the refusals =="
	@EVAL_HEADERS="$(EVAL_HEADERS)" tests/cli/eval.sh $(B)/bin/tissuefit
	@echo "== material regions: a two-material bar against its exact solution, Newton with a neo-Hookean sphere, Kelvin and cross-law spheres against their relaxed and instantaneous limits, the VTU material field, the refusals =="
	@tests/solver/inclusions.sh $(B)/bin/tissuefit
