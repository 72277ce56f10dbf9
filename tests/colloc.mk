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

# Acceptance 1 at 4,353 particles (linear law and SVK), then the same bits
# from a whole Hertz run on 1 and 2 threads.
check-colloc: $(T)/colloc/hertz
	@echo "== collocation: Hertz at 4,353 particles, every indentation within 5 % =="
	@$(T)/colloc/hertz --law linear --radius 100 --indent 0.0001,0.00025,0.0004,0.000625 \
	  --check 0.05 | tail -3
	@$(T)/colloc/hertz --law svk --radius 100 --indent 0.0001,0.00025 --check 0.05 | tail -3
	@echo "== collocation: a Hertz run on 1 and 2 threads, same bits =="
	@rm -f $(T)/colloc/threads-1.csv $(T)/colloc/threads-2.csv
	@for t in 1 2; do OMP_NUM_THREADS=$$t $(T)/colloc/hertz --cells 6 --levels 3 \
	  --indent 0.001,0.002 --csv $(T)/colloc/threads-$$t.csv > /dev/null; done
	@cut -d, -f1-21 $(T)/colloc/threads-1.csv > $(T)/colloc/threads-1.cut
	@cut -d, -f1-21 $(T)/colloc/threads-2.csv > $(T)/colloc/threads-2.cut
	@cmp $(T)/colloc/threads-1.cut $(T)/colloc/threads-2.cut && \
	  echo "forces and contact counts identical to the last bit: ok"

hertz-study: $(T)/colloc/hertz | deps-colloc-study
	@echo "== collocation: Hertz convergence study (docs/collocation/) =="
	@tests/colloc/hertz_study.sh $(T)/colloc/hertz docs/collocation

block48-colloc: $(T)/colloc/block48 $(T)/solver/node61
	@echo "== collocation: block48 static limit against CalculiX and RPIM Galerkin =="
	@tests/colloc/block48.sh $(T)/colloc/block48 $(T)/solver/node61 docs/collocation

bench-colloc: $(T)/colloc/bench_step
	@$(T)/colloc/bench_step
