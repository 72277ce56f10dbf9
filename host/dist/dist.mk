# dist.mk — the MPI build (issue 18, docs/scaling.md): build/bin/tissuefit-mpi,
# the same host library as the tool with dist/ and an MPI main on top.
# `make mpi` or `make MPI=1` builds it; the default build needs no MPI.

DEBS_MPI := libopenmpi-dev openmpi-bin
.PHONY: deps-mpi mpi
deps-mpi: ; $(call ensure_debs,$(DEBS_MPI))

# Evaluated when a recipe runs, after deps-mpi has installed mpicc.
MPI_CFLAGS = $(shell mpicc --showme:compile)
MPI_LIBS = $(shell mpicc --showme:link) -pthread

DIST_SRC := $(sort $(wildcard host/dist/*.c)) host/cli/main_mpi.c
DIST_OBJ := $(DIST_SRC:host/%.c=$(B)/mpi/host/%.o)

$(B)/mpi/host/%.o: host/%.c $(HOST_HDR) | deps-build deps-mpi
	@mkdir -p $(@D)
	$(call say,CC)
	$(Q)$(CC) $(HOST_CFLAGS) -O2 -g -pthread $(MPI_CFLAGS) -c $< -o $@

$(B)/bin/tissuefit-mpi: $(DIST_OBJ) $(B)/native/libtissuefit-host.a $(B)/native/libtfit.a
	@mkdir -p $(@D)
	$(call say,LINK)
	$(Q)$(CC) $^ $(HOST_LIBS) $(MPI_LIBS) -o $@

mpi: $(B)/bin/tissuefit-mpi
ifeq ($(MPI),1)
all: $(B)/bin/tissuefit-mpi
endif
