# layers.mk — the structure of host/ (issue 12).
#
#   check-host-layers  host/ holds only layer folders (HOST_LAYERS, host.mk)
#                      and host.mk; no file includes a later layer; no include
#                      cycle between files; no mutable global or static
#                      state in any host object except cli/main.o; no
#                      (char *err, size_t errlen) pair: fallible functions
#                      take tf_ctx *ctx first (tests/layers/check_errors.sh).  Each
#                      checker is first shown broken copies and objects and
#                      must reject them for the right reason
#                      (tests/layers/selftest.sh).

LAYERS_T := $(T)/layers

.PHONY: check-host-layers
CHECKS += check-host-layers

$(LAYERS_T)/%.o: tests/layers/%.c | deps-build
	@mkdir -p $(@D)
	$(call say,CC)
	$(Q)$(CC) $(HOST_CFLAGS) -O2 -c $< -o $@

HOST_OBJ_NATIVE := $(HOST_SRC:host/%.c=$(B)/native/host/%.o)

check-host-layers: $(HOST_OBJ_NATIVE) $(LAYERS_T)/fixture_mutable.o $(LAYERS_T)/fixture_const.o
	@echo "== host/ layers: include structure and global state =="
	@tests/layers/selftest.sh "$(HOST_LAYERS)" $(LAYERS_T)/fixture_mutable.o \
	  $(LAYERS_T)/fixture_const.o
	@tests/layers/check_includes.sh host "$(HOST_LAYERS)"
	@tests/layers/check_errors.sh host
	@tests/layers/check_globals.sh $(HOST_OBJ_NATIVE)
