# host.mk — the tissuefit tool.  Every host/**/*.c except cli/main.c goes
# into a static library that the tool and the host tests link; adding a file
# (or a folder) needs no change here.  Includes are written from host/
# ("solvers/solver.h"), so each one names the layer it reaches into.

# The layers, lowest first: a file may include its own layer and the ones
# before it, never a later one (tests/layers/check_includes.sh, in make
# check).  A new folder goes into this list; docs/architecture.md says what
# each holds.
HOST_LAYERS := base numerics materials geometry problem meshfree solvers verify cost model \
               fitting dist emit tradeoff report scene cli api

# dist/ and cli/main_mpi.c need MPI: only the MPI build (host/dist/dist.mk) compiles them.
HOST_SRC := $(filter-out host/cli/main.c host/cli/main_mpi.c host/dist/%,\
                         $(shell find host -name '*.c' | LC_ALL=C sort))
HOST_HDR := $(shell find host -name '*.h') target/include/tfit.h target/include/tfit_q31.h host/host.mk
# -fno-tree-slp-vectorize: GCC 12.2's SLP vectorizer at -O2 drops the
# rounding in `f[i][k] = (double)(float)f[i][k]` for k = 0, 1 of rows of
# three (only k = 2 is rounded; -O1, clang and this flag are right).  The
# host rounds to float to see exactly what the firmware sees, so it is off
# for all host code; tests/unit/fitting/test_toolchain.c fails if it comes back.
HOST_CFLAGS := $(HOST_STRICT) -fno-tree-slp-vectorize -fopenmp -Ihost -Itarget/include \
               -I/usr/include/suitesparse -DTFIT_TOOL_VERSION='"$(VERSION)"'
# gmsh is not linked: host/geometry/gmsh_api.c opens it at its first call.
# LLVM's lld links a sanitized test program in 0.14 s where GNU ld takes
# 0.32 s (make check links about 260 programs against these libraries).
HOST_LIBS := -fuse-ld=lld -fopenmp -lcholmod -lumfpack -lgsl -llapacke -lopenblas -lcyaml -lyaml -lassimp -lz -lm

# $(call host_lib,NAME,FLAGS)  ->  $(B)/NAME/libtissuefit-host.a
define host_lib
$(B)/$(1)/host/%.o: host/%.c $(HOST_HDR) | deps-build
	$(Q)$$(call made,CC)$(CC) $(HOST_CFLAGS) $(2) -c $$< -o $$@
$(B)/$(1)/libtissuefit-host.a: $(HOST_SRC:host/%.c=$(B)/$(1)/host/%.o)
	$$(call say,AR)
	$(Q)rm -f $$@ && ar rcs $$@ $$^
endef

# Position-independent, so that the same objects make the tool and the
# shared library the Python module loads (python/python.mk): one build of
# host/ instead of two.  -fno-semantic-interposition lets GCC inline across
# functions as without -fPIC; the tool is a PIE either way, and no result
# depends on it (check-coeffs regenerates the shipped headers to the byte,
# and the Python tests compare solves with the tool's to the last bit).
$(eval $(call host_lib,native,-O2 -g -fPIC -fno-semantic-interposition))
# -O2 as the tool ships (native): ASan and UBSan instrument either level,
# and the unit tests under them (check-sanitize) run about a third faster
# than at -O1 (docs/architecture.md, "make check's time").
$(eval $(call host_lib,asan,-O2 $(TEST_G) $(SANITIZE)))

# The flat API of host/api/ as a shared library: the API's objects, the
# rest of the host library and a position-independent libtfit (the tool's
# sweep times the target evaluator) inside; it exports tf_api_* only.
HOST_API_OBJ := $(patsubst host/%.c,$(B)/native/host/%.o,$(wildcard host/api/*.c))
$(B)/native/libtissuefit.so: $(HOST_API_OBJ) $(B)/native/libtissuefit-host.a $(B)/native-pic/libtfit.a \
                             host/api/libtissuefit.map
	@mkdir -p $(@D)
	$(call say,LINK)
	$(Q)$(CC) -shared -Wl,--no-undefined -Wl,--version-script=host/api/libtissuefit.map \
	  $(HOST_API_OBJ) $(B)/native/libtissuefit-host.a $(B)/native-pic/libtfit.a $(HOST_LIBS) -o $@

# What `tissuefit eval` compiles a generated header with (host/cli/eval_shim.h):
# the evaluator the Python module compiles too, tfit.h and the position-
# independent libtfit, staged under build/ as `make install` lays them out
# under PREFIX, so that the tool finds them from its own path in both.
EVAL_STAGE := $(B)/share/tfit/tfit_shim.c $(B)/include/tfit.h $(B)/include/tfit_q31.h \
              $(B)/lib/tfit/native-pic/libtfit.a
$(B)/share/tfit/tfit_shim.c: python/tissuefit/tfit_shim.c
$(B)/include/tfit.h: target/include/tfit.h
$(B)/include/tfit_q31.h: target/include/tfit_q31.h
$(B)/lib/tfit/native-pic/libtfit.a: $(B)/native-pic/libtfit.a
$(EVAL_STAGE):
	@mkdir -p $(@D)
	$(Q)cp $< $@

# The tool links the native target library to time it (tissuefit sweep).
$(B)/bin/tissuefit: $(B)/native/host/cli/main.o $(B)/native/libtissuefit-host.a $(B)/native/libtfit.a \
                    | $(EVAL_STAGE)
	@mkdir -p $(@D)
	$(call say,LINK)
	$(Q)$(CC) $^ $(HOST_LIBS) -o $@

include host/dist/dist.mk
