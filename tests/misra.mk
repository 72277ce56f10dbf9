# misra.mk — static analysis of libtfit (docs/misra.md).
#
#   check-misra  cppcheck's MISRA C:2012 addon (and cppcheck's own checks)
#                and clang-tidy (target/.clang-tidy) over target/src/*.c and
#                the headers they include, in the portable and the Armv7E-M
#                configuration (tests/misra/analyse.sh); every finding must
#                be in the deviation record docs/misra.md, rule by rule and
#                file by file with its count, and the record must hold no
#                more (tests/misra/judge.py); tests/misra/suppressions.txt
#                must be the record's cppcheck suppressions.  The judge is
#                first shown a planted goto, if without braces and second
#                return, a stale record and an unlisted disabled check
#                (tests/misra/selftest.sh), and must name each.
#   misra-rows   the findings as the record's tables (to update docs/misra.md)

DEBS_CHECK += cppcheck clang-tidy python3

MISRA_T := $(T)/misra

.PHONY: check-misra misra-rows
CHECKS += check-misra
check-misra: | deps-check
	@echo "== MISRA C:2012 (cppcheck's addon) and clang-tidy over libtfit: every finding in docs/misra.md =="
	@echo "tools: $$(cppcheck --version), $$(clang-tidy --version | grep -o 'LLVM version [0-9.]*')" \
	  "(docs/misra.md records their findings; other versions find other things)"
	@tests/misra/analyse.sh . $(MISRA_T)/findings
	@tests/misra/selftest.sh $(MISRA_T)/selftest $(MISRA_T)/findings/findings.txt
	@tests/misra/judge.py suppressions docs/misra.md | diff -u tests/misra/suppressions.txt - \
	  >$(MISRA_T)/suppressions.diff || { cat $(MISRA_T)/suppressions.diff; echo "tests/misra/suppressions.txt" \
	  "is not docs/misra.md's record: regenerate it (docs/misra.md, 'When check-misra fails')"; exit 1; }
	@echo "tests/misra/suppressions.txt is the record's cppcheck suppressions: ok"
	@tests/misra/judge.py check $(MISRA_T)/findings/findings.txt docs/misra.md target/.clang-tidy
	@echo "ok: $$(wc -l <$(MISRA_T)/findings/findings.txt) findings over $$(ls target/src/*.c | wc -l) sources," \
	  "each recorded in docs/misra.md; a planted violation is caught"

misra-rows: | deps-check
	@tests/misra/analyse.sh . $(MISRA_T)/findings
	@tests/misra/judge.py rows $(MISRA_T)/findings/findings.txt
