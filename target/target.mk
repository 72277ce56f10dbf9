# target.mk — the freestanding evaluator, built for several machines.
#
# Each build compiles target/src/*.c with the target flags, combines the
# objects into one relocatable object (ld -r: the archive then has no
# references between members, so `nm -u` lists only what the library needs
# from outside — nothing) and archives it.  -ffunction-sections keeps unused
# functions removable by the firmware's --gc-sections.

TARGET_SRC := $(wildcard target/src/*.c)
TARGET_HDR := $(wildcard target/src/*.h target/include/*.h) target/target.mk
# The fixed-point evaluator alone, for cores without an FPU (tfit_q31.h).
TARGET_Q31_SRC := $(wildcard target/src/tfit_q31_*.c) target/src/tfit_crc_word.c
TARGET_CFLAGS := $(TARGET_STRICT) -Itarget/include -ffunction-sections -fdata-sections

# $(call tfit_lib,NAME,CC,FLAGS,BINUTILS-PREFIX,DEPS[,LIB,SOURCES])
#   ->  $(B)/NAME/LIB.a (default libtfit.a from every source)
define tfit_lib
$(B)/$(1)/obj/%.o: target/src/%.c $(TARGET_HDR) | deps-$(5)
	$(Q)$$(call made,CC)$(2) $(TARGET_CFLAGS) $(3) -c $$< -o $$@
$(B)/$(1)/$(or $(6),libtfit).a: $(patsubst target/src/%.c,$(B)/$(1)/obj/%.o,$(or $(7),$(TARGET_SRC)))
	$$(call say,AR)
	$(Q)$(4)ld -r $$^ -o $(B)/$(1)/$(or $(6),libtfit).o
	$(Q)rm -f $$@ && $(4)ar rcs $$@ $(B)/$(1)/$(or $(6),libtfit).o
endef

# The native library that `make` ships.
$(eval $(call tfit_lib,native,$(CC),-O2 -g,,build))
$(B)/lib/libtfit.a: $(B)/native/libtfit.a
	@mkdir -p $(@D)
	$(Q)cp $< $@

# The same, position-independent: inside the Python module's shared
# library (host/host.mk) and the evaluators it compiles from generated
# headers (python/tissuefit/header.py).
$(eval $(call tfit_lib,native-pic,$(CC),-O2 -g -fPIC,,build))

# Cross builds: the freestanding proof, and the libraries the firmware images
# link (linker/firmware.mk).  The STM32H743 has a double-precision FPU; the
# library is float-only, so fpv5-d16 and fpv5-sp-d16 give the same code.
M7_FLAGS := -mcpu=cortex-m7 -mthumb -mfpu=fpv5-d16 -mfloat-abi=hard
# -fstack-usage: the frame of every function, for `make firmware`'s stack table.
$(eval $(call tfit_lib,cortex-m4f,$(ARM)gcc,$(M4F_FLAGS) -O2 -fstack-usage,$(ARM),check))
$(eval $(call tfit_lib,cortex-m7,$(ARM)gcc,$(M7_FLAGS) -O2 -fstack-usage,$(ARM),check))
# The portable C path on the same cores (-DTFIT_PORTABLE: no assembly), the
# reference the assembly is checked against under QEMU (check-qemu).
$(eval $(call tfit_lib,cortex-m4f-portable,$(ARM)gcc,$(M4F_FLAGS) -O2 -DTFIT_PORTABLE,$(ARM),check))
$(eval $(call tfit_lib,cortex-m7-portable,$(ARM)gcc,$(M7_FLAGS) -O2 -DTFIT_PORTABLE,$(ARM),check))
$(eval $(call tfit_lib,cortex-m4f-O0,$(ARM)gcc,$(M4F_FLAGS) -O0,$(ARM),check))
$(eval $(call tfit_lib,cortex-m4f-Os,$(ARM)gcc,$(M4F_FLAGS) -Os,$(ARM),check))
$(eval $(call tfit_lib,cortex-m4f-O3,$(ARM)gcc,$(M4F_FLAGS) -O3,$(ARM),check))
$(eval $(call tfit_lib,riscv64,$(RV)gcc,$(RV64_FLAGS) -O2,$(RV),check))
$(eval $(call tfit_lib,riscv64-O0,$(RV)gcc,$(RV64_FLAGS) -O0,$(RV),check))

# Cores without an FPU: the Q31 evaluator only (soft-float ABI, but no float
# code: check-q31 proves with nm -u that nothing, soft float included, is
# pulled in).
M3_FLAGS := -mcpu=cortex-m3 -mthumb -mfloat-abi=soft
M0P_FLAGS := -mcpu=cortex-m0plus -mthumb -mfloat-abi=soft
$(eval $(call tfit_lib,cortex-m3,$(ARM)gcc,$(M3_FLAGS) -O2 -fstack-usage,$(ARM),check,libtfit_q31,$(TARGET_Q31_SRC)))
$(eval $(call tfit_lib,cortex-m0plus,$(ARM)gcc,$(M0P_FLAGS) -O2 -fstack-usage,$(ARM),check,libtfit_q31,$(TARGET_Q31_SRC)))

# The bit-exact compiler matrix (acceptance: gcc -O0/-O2/-O3 -march=native, clang -O2).
$(eval $(call tfit_lib,bitexact-gcc-O0,$(CC),-O0,,check))
$(eval $(call tfit_lib,bitexact-gcc-O2,$(CC),-O2,,check))
$(eval $(call tfit_lib,bitexact-gcc-O3-native,$(CC),-O3 -march=native,,check))
$(eval $(call tfit_lib,bitexact-clang-O2,$(CLANG),-O2,,check))

# Under the sanitizers, for the host unit tests that call the target.
$(eval $(call tfit_lib,asan,$(CC),-O1 -g $(SANITIZE),,check))
