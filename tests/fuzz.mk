# fuzz.mk — libFuzzer targets over the two ways text enters a scene
# (issue 19): the scene reader (tests/fuzz/fuzz_scene.c) and `--set`
# values on block48 (tests/fuzz/fuzz_set.c).  Both are built with clang,
# AddressSanitizer and UndefinedBehaviorSanitizer over a clang build of the
# host library; a crash, leak, undefined behaviour or an input slower than
# FUZZ_TIMEOUT seconds is a finding, written to $(FZ)/artifacts/.
#
#   check-fuzz   (make check) both targets at once, FUZZ_CHECK_SECONDS (25 s), from the
#                seeds and the regression inputs (tests/fuzz/regress/: inputs
#                that found bugs; they must stay harmless).  25 s is a short
#                real run: on the 2-core machine each target executes well
#                over 10^5 inputs and reaches about 97 % of the coverage 60 s
#                reached (docs/architecture.md, "make check's time"); the
#                campaign is make fuzz's; first, every registered law solved
#                by every registered solver on a small box over the same
#                clang library (tests/fuzz/ubsan_solve.c)
#   make fuzz    each target FUZZ_SECONDS (default 1800 s), corpus kept in
#                $(FZ)/corpus between runs
#
# Seeds: the shipped and test scenes, and tests/fuzz/seeds/set/.

FZ := $(B)/fuzz
FUZZ_CHECK_SECONDS ?= 25
FUZZ_SECONDS ?= 1800
FUZZ_TIMEOUT ?= 20
FUZZ_SAN := -fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=all \
            -fno-omit-frame-pointer
# clang has no -fno-tree-slp-vectorize (a GCC workaround, host.mk).
FUZZ_HOST_CFLAGS := $(filter-out -fno-tree-slp-vectorize,$(HOST_CFLAGS)) -O1 -g $(FUZZ_SAN)
FUZZ_SCENE_SEEDS := coeffs/block48.yaml tests/solver/block48_seed.yaml coeffs/cantilever.yaml tests/solver/patch.yaml \
                    $(wildcard tests/fit/scenes/*.yaml)
DEBS_CHECK += libclang-rt-14-dev libomp-dev

$(FZ)/host/%.o: host/%.c $(HOST_HDR) | deps-check
	@mkdir -p $(@D)
	$(call say,CLANG)
	$(Q)$(CLANG) $(FUZZ_HOST_CFLAGS) -c $< -o $@
$(FZ)/libtissuefit-host.a: $(HOST_SRC:host/%.c=$(FZ)/host/%.o)
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
# on a finding.
define fuzz_run
mkdir -p $(3) $(FZ)/artifacts; \
if [ $(1) = scene ]; then cp -n $(FUZZ_SCENE_SEEDS) tests/fuzz/regress/scene/* $(3)/; \
else cp -n tests/fuzz/seeds/set/* tests/fuzz/regress/set/* $(3)/; fi; \
if ! $(FZ)/fuzz_$(1) $(3) -dict=tests/fuzz/$(1).dict -max_total_time=$(2) \
     -timeout=$(FUZZ_TIMEOUT) -rss_limit_mb=2048 -max_len=4096 -print_final_stats=1 \
     -artifact_prefix=$(FZ)/artifacts/$(1)- >$(FZ)/$(1).log 2>&1; then \
  grep -E -A12 'ERROR|runtime error|Timeout|out-of-memory' $(FZ)/$(1).log | head -40; \
  echo "fuzz_$(1): FINDING (input in $(FZ)/artifacts/, log $(FZ)/$(1).log)"; exit 1; fi; \
runs=$$(sed -n 's/^stat::number_of_executed_units: *//p' $(FZ)/$(1).log); \
cov=$$(grep -o 'cov: [0-9]*' $(FZ)/$(1).log | tail -1); \
echo "ok: fuzz_$(1): $(2) s, $$runs inputs, $$cov, $$(ls $(3) | wc -l) in the corpus, no finding"
endef

.PHONY: check-fuzz fuzz
CHECKS += check-fuzz
check-fuzz: $(FZ)/fuzz_scene $(FZ)/fuzz_set $(FZ)/ubsan_solve
	@echo "== every law solved by every solver under clang ASan + UBSan =="
	@ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 $(FZ)/ubsan_solve
	@echo "== fuzzing the scene reader and --set values (ASan + UBSan, $(FUZZ_CHECK_SECONDS) s each) =="
	@rm -rf $(FZ)/check-corpus
	@# the two targets at once, one core each; their lines printed in order
	@r=0; ( $(call fuzz_run,scene,$(FUZZ_CHECK_SECONDS),$(FZ)/check-corpus/scene) ) \
	  >$(FZ)/check-scene.out 2>&1 & p=$$!; \
	( $(call fuzz_run,set,$(FUZZ_CHECK_SECONDS),$(FZ)/check-corpus/set) ) >$(FZ)/check-set.out 2>&1 || r=1; \
	wait $$p || r=1; cat $(FZ)/check-scene.out $(FZ)/check-set.out; exit $$r

fuzz: $(FZ)/fuzz_scene $(FZ)/fuzz_set
	@echo "== fuzzing the scene reader and --set values (ASan + UBSan, $(FUZZ_SECONDS) s each) =="
	@$(call fuzz_run,scene,$(FUZZ_SECONDS),$(FZ)/corpus/scene)
	@$(call fuzz_run,set,$(FUZZ_SECONDS),$(FZ)/corpus/set)
