# fuzz.mk — libFuzzer targets over the ways text and files enter a scene:
# the scene reader (tests/fuzz/fuzz_scene.c), `--set` values on block48
# (fuzz_set.c), a load-history table file (fuzz_history.c), the `cuts:`
# section of a box scene and the shape functions it cuts (fuzz_cuts.c), and
# an organ's surface mesh file (fuzz_mesh.c).  All are built with clang,
# AddressSanitizer and UndefinedBehaviorSanitizer over a clang build of the
# host library; a crash, leak, undefined behaviour or an input slower than
# FUZZ_TIMEOUT seconds is a finding, written to $(FZ)/artifacts/.
#
#   check-fuzz   (make check) first, every registered law solved by every
#                registered solver on a small box over the same clang
#                library (tests/fuzz/ubsan_solve.c); then the five targets,
#                FUZZ_CHECK_SECONDS each, two at a time (one core each:
#                three rounds of wall time), from the seeds and the
#                regression inputs (tests/fuzz/regress/TARGET/: inputs that
#                found bugs; they must stay harmless); one result line per
#                target, in order.  10 s (60 s in make check-full) is a
#                short real run (the inputs executed and coverage reached
#                are in docs/architecture.md, "Errors and outputs"); the
#                campaign is make fuzz's
#   make fuzz    each target FUZZ_SECONDS (default 1800 s), one after the
#                other, corpus kept in $(FZ)/corpus between runs
#
# Seeds: the shipped and test scenes (scene), tests/fuzz/seeds/TARGET/ (the
# others).  Inputs are at most 4 KiB, 8 KiB for a mesh (FUZZ_MAX_LEN).

FZ := $(B)/fuzz
FUZZ_CHECK_SECONDS ?= $(call check_len,60,10)
FUZZ_SECONDS ?= 1800
FUZZ_TIMEOUT ?= 20
FUZZ_SAN := -fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=all \
            -fno-omit-frame-pointer
# clang has no -fno-tree-slp-vectorize (a GCC workaround, host.mk).
FUZZ_HOST_CFLAGS := $(filter-out -fno-tree-slp-vectorize,$(HOST_CFLAGS)) -O1 $(TEST_G) $(FUZZ_SAN)
FUZZ_TARGETS := scene set history cuts mesh
FUZZ_SEEDS_scene := coeffs/block48.yaml tests/solver/block48_seed.yaml coeffs/cantilever.yaml \
                    tests/solver/patch.yaml tests/solver/inclusion_bar.yaml \
                    $(wildcard tests/fit/scenes/*.yaml)
$(foreach t,set history cuts mesh,$(eval FUZZ_SEEDS_$(t) := $(wildcard tests/fuzz/seeds/$(t)/*)))
FUZZ_MAX_LEN = $(if $(filter mesh,$(1)),8192,4096)
DEBS_CHECK += libclang-rt-14-dev libomp-dev

$(FZ)/host/%.o: host/%.c $(HOST_HDR) | deps-check
	$(Q)$(call made,CLANG)$(CLANG) $(FUZZ_HOST_CFLAGS) -c $< -o $@
# Only what the fuzz targets and ubsan_solve link: none of them reaches
# api/, cli/, emit/, tradeoff/, verify/ or report/ (36 files, about 12 s of
# make check's CPU to compile); a target that comes to need one fails to
# link.
FUZZ_HOST_SRC := $(filter-out $(foreach l,api cli emit tradeoff verify report,host/$(l)/%),$(HOST_SRC))
$(FZ)/libtissuefit-host.a: $(FUZZ_HOST_SRC:host/%.c=$(FZ)/host/%.o)
	$(call say,AR)
	$(Q)rm -f $@ && ar rcs $@ $^

$(FZ)/fuzz_%: tests/fuzz/fuzz_%.c $(FZ)/libtissuefit-host.a $(B)/native/libtfit.a | deps-check
	$(call say,LINK)
	$(Q)$(CLANG) $(FUZZ_HOST_CFLAGS) -fsanitize=fuzzer $< $(FZ)/libtissuefit-host.a \
	  $(B)/native/libtfit.a $(HOST_LIBS) -o $@

# A small solve of every (law, solver) pair over the same clang library
# (tests/fuzz/ubsan_solve.c): the fuzzers never solve, and GCC's UBSan
# (check-sanitize) lacks clang's null-pointer-offset check.
$(FZ)/ubsan_solve: tests/fuzz/ubsan_solve.c $(FZ)/libtissuefit-host.a $(B)/native/libtfit.a | deps-check
	$(call say,LINK)
	$(Q)$(CLANG) $(filter-out -fsanitize=fuzzer-no-link%,$(FUZZ_HOST_CFLAGS)) \
	  -fsanitize=address,undefined $< $(FZ)/libtissuefit-host.a $(B)/native/libtfit.a $(HOST_LIBS) -o $@

# $(call fuzz_run,TARGET,SECONDS,CORPUS-DIR): the seeds and regression
# inputs first, then SECONDS of fuzzing; prints one result line and fails
# on a finding.  A run that outlives its time by far is killed and fails
# too (libFuzzer's own timeout report can hang when the alarm interrupts
# the allocator).
define fuzz_run
mkdir -p $(3) $(FZ)/artifacts; \
cp -n $(FUZZ_SEEDS_$(1)) $(wildcard tests/fuzz/regress/$(1)/*) $(3)/; \
if ! timeout -k 10 $$(( $(2) + 3 * $(FUZZ_TIMEOUT) + 120 )) $(FZ)/fuzz_$(1) $(3) -dict=tests/fuzz/$(1).dict -max_total_time=$(2) \
     -timeout=$(FUZZ_TIMEOUT) -rss_limit_mb=2048 -max_len=$(call FUZZ_MAX_LEN,$(1)) \
     -print_final_stats=1 -artifact_prefix=$(FZ)/artifacts/$(1)- >$(FZ)/$(1).log 2>&1; then \
  grep -E -A12 'ERROR|runtime error|Timeout|out-of-memory|fuzz_$(1):' $(FZ)/$(1).log | head -40; \
  echo "fuzz_$(1): FINDING (input in $(FZ)/artifacts/, log $(FZ)/$(1).log)"; exit 1; fi; \
runs=$$(sed -n 's/^stat::number_of_executed_units: *//p' $(FZ)/$(1).log); \
cov=$$(grep -o 'cov: [0-9]*' $(FZ)/$(1).log | tail -1); \
echo "ok: fuzz_$(1): $(2) s, $$runs inputs, $$cov, $$(ls $(3) | wc -l) in the corpus, no finding"
endef

# $(call fuzz_lane,TARGETS): check-fuzz's targets one after the other, each
# result in $(FZ)/check-TARGET.out; fails when any of them found something.
fuzz_lane = r=0; $(foreach t,$(1),( $(call fuzz_run,$(t),$(FUZZ_CHECK_SECONDS),$(FZ)/check-corpus/$(t)) ) \
  >$(FZ)/check-$(t).out 2>&1 || r=1;) exit $$r

.PHONY: check-fuzz fuzz
CHECKS += check-fuzz
check-fuzz: $(FUZZ_TARGETS:%=$(FZ)/fuzz_%) $(FZ)/ubsan_solve
	@echo "== every law solved by every solver under clang ASan + UBSan =="
	@ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 $(FZ)/ubsan_solve
	@echo "== fuzzing $(FUZZ_TARGETS) (ASan + UBSan, $(FUZZ_CHECK_SECONDS) s each, two at a time) =="
	@rm -rf $(FZ)/check-corpus $(FUZZ_TARGETS:%=$(FZ)/check-%.out)
	@# two lanes, one core each (3 and 2 targets); the lines printed in order
	@r=0; ( $(call fuzz_lane,scene history mesh) ) & p=$$!; \
	( $(call fuzz_lane,set cuts) ) || r=1; wait $$p || r=1; \
	cat $(FUZZ_TARGETS:%=$(FZ)/check-%.out); exit $$r

fuzz: $(FUZZ_TARGETS:%=$(FZ)/fuzz_%)
	@echo "== fuzzing $(FUZZ_TARGETS) (ASan + UBSan, $(FUZZ_SECONDS) s each) =="
	@$(foreach t,$(FUZZ_TARGETS),$(call fuzz_run,$(t),$(FUZZ_SECONDS),$(FZ)/corpus/$(t)) && ) true
