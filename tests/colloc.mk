# colloc.mk — the MLS collocation solver (issue 16, seed 004): the Hertz
# test, block48's static limit against the Galerkin solvers, speed.
#
#   check-colloc   a short Hertz run (every indentation within 5 % of the
#                  theory at 4,353 particles) and the thread-determinism of a
#                  full run (1 and 2 threads, same bits)
#   hertz-study    the convergence study over particle counts, block sizes
#                  and options: docs/collocation/ (CSV, tables, PNG plot);
#                  not part of make check
#   bench-colloc   time per explicit step at 6,000 particles beside a
#                  reference operation (make bench)
# Unit tests (tests/unit/test_colloc*.c) run with check-unit and
# check-sanitize.

$(T)/colloc/%: tests/colloc/%.c $(B)/native/libtissuefit-host.a | deps-build
	@mkdir -p $(@D)
	$(call say,BUILD)
	$(Q)$(CC) $(TEST_CFLAGS) -O2 $< $(B)/native/libtissuefit-host.a $(HOST_LIBS) -o $@

DEBS_COLLOC_STUDY := $(DEBS_BUILD) gnuplot-nox
.PHONY: check-colloc hertz-study bench-colloc block48-colloc deps-colloc-study
CHECKS += check-colloc
BENCHES += bench-colloc

deps-colloc-study: ; $(call ensure_debs,$(DEBS_COLLOC_STUDY))

# Acceptance 1 at 4,353 particles (linear law and SVK), on one thread (the
# answer is the same on any: the next check), then the same bits from a
# whole Hertz run on 1 and 2 threads, the solver interface's path against
# the core, and `tissuefit verify hertz`.
check-colloc: $(T)/colloc/hertz $(T)/colloc/block48 $(B)/bin/tissuefit
	@echo "== collocation: Hertz at 4,353 particles, every indentation within 5 % =="
	@OMP_NUM_THREADS=1 $(T)/colloc/hertz --law linear --check 0.05 | tail -3
	@OMP_NUM_THREADS=1 $(T)/colloc/hertz --law svk --indent 0.0001,0.00025 --check 0.05 | tail -3
	@echo "== collocation: a Hertz run on 1 and 2 threads, same bits =="
	@rm -f $(T)/colloc/threads-1.csv $(T)/colloc/threads-2.csv
	@for t in 1 2; do OMP_NUM_THREADS=$$t $(T)/colloc/hertz --cells 6 --levels 3 \
	  --indent 0.001,0.002 --csv $(T)/colloc/threads-$$t.csv > /dev/null; done
	@cut -d, -f1-21 $(T)/colloc/threads-1.csv > $(T)/colloc/threads-1.cut
	@cut -d, -f1-21 $(T)/colloc/threads-2.csv > $(T)/colloc/threads-2.cut
	@test -s $(T)/colloc/threads-1.cut
	@cmp $(T)/colloc/threads-1.cut $(T)/colloc/threads-2.cut && \
	  echo "ok: forces, contact counts and relaxation steps identical to the last bit"
	@echo "== collocation: tissuefit solve (mls-collocation) against the core on block48 =="
	@OMP_NUM_THREADS=1 tests/colloc/solver_path.sh $(B)/bin/tissuefit $(T)/colloc/block48
	@echo "== tissuefit verify hertz =="
	@OMP_NUM_THREADS=1 $(B)/bin/tissuefit -q verify hertz --cells 4 \
	  --csv $(T)/colloc/verify_hertz.csv > /dev/null
	@awk -F, 'NR == 1 && $$1 == "particles" { h = 1 } NR > 1 && $$1 == 713 { n++ } \
	  END { if (!h || n != 4) { print "FAIL: verify hertz CSV"; exit 1 } \
	        print "ok: verify hertz wrote 4 force-indentation pairs at 713 particles" }' \
	  $(T)/colloc/verify_hertz.csv

hertz-study: $(T)/colloc/hertz | deps-colloc-study
	@echo "== collocation: Hertz convergence study (docs/collocation/) =="
	@tests/colloc/hertz_study.sh $(T)/colloc/hertz docs/collocation

block48-colloc: $(T)/colloc/block48 $(T)/solver/node61
	@echo "== collocation: block48 static limit against CalculiX and RPIM Galerkin =="
	@tests/colloc/block48.sh $(T)/colloc/block48 $(T)/solver/node61 docs/collocation

# Passive waiting: on a machine shared with other jobs, spinning OpenMP
# threads burn the cores the others need (measured: 13.6 ms of processor per
# step on 2 threads with the default policy, 1.03 ms passive).
bench-colloc: $(T)/colloc/bench_step
	@OMP_WAIT_POLICY=passive $(T)/colloc/bench_step
