# cmake.mk — libtfit as a CMake package (docs/firmware.md §11, docs/versions.md).
#
#   check-cmake  `make install` into a temporary prefix (with the Cortex-M4F
#                and M7 libraries), then the consumer projects of tests/cmake/
#                built outside the tree's build: find_package(tfit) natively
#                and with the installed arm-none-eabi-m4f.cmake and -m7.cmake
#                toolchains under QEMU, add_subdirectory(target) natively and
#                for Cortex-M4F;
#                block48's golden vectors bit-exact in each, a planted
#                mismatch caught in each, the consumers' flags, the
#                fast-memory placement, tfit_generate_header()'s rebuilds,
#                the version requests the package accepts, -ffast-math
#                refused; and docs/versions.md's table against the versions
#                the Makefile and tfit.h state (tests/cmake/check_versions.sh)

# gcc-arm-none-eabi and qemu-system-arm are in DEBS_CHECK already (Makefile, linker/firmware.mk).
DEBS_CHECK += cmake

CMAKE_T := $(T)/cmake

.PHONY: check-cmake
CHECKS += check-cmake
check-cmake: $(B)/bin/tissuefit $(B)/lib/libtfit.a $(B)/cortex-m4f/libtfit.a $(B)/cortex-m7/libtfit.a $(PY_PKG_LIBS) | deps-check
	@echo "== libtfit as a CMake package: find_package(tfit) natively and on Cortex-M4F and M7 (QEMU), add_subdirectory(target) =="
	@tests/cmake/check_versions.sh $(VERSION)
	@rm -rf $(CMAKE_T) && mkdir -p $(CMAKE_T)
	@$(MAKE) --no-print-directory install PREFIX=$(abspath $(CMAKE_T))/prefix INSTALL_CORES="cortex-m4f cortex-m7" \
	  >$(CMAKE_T)/install.log 2>&1 || { cat $(CMAKE_T)/install.log; exit 1; }
	@CMAKE_JOBS=$(NPROC) tests/cmake/check_consumers.sh $(abspath $(CMAKE_T)) $(VERSION)
	@echo "ok: libtfit $(VERSION) through find_package and add_subdirectory: golden vectors bit-exact natively and on Cortex-M4F and M7, a planted mismatch caught"
