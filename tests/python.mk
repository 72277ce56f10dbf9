# python.mk — the Python module's tests (docs/python.md).
#
#   check-python  `make install` into build/tests/python/install (PREFIX=/usr),
#                 `import tissuefit` from there in Debian's python3, then
#                 pytest tests/python against that install: block48 solved
#                 equal to `tissuefit solve` bit for bit (nodes, outputs,
#                 points, a cut progress), its VTU read back by meshio with
#                 the tool's point data and cells, a fit equal to the tool's
#                 bytes and its golden vectors, every shipped header's golden
#                 vectors (float and Q31) bit for bit through libtfit, and
#                 the tool's messages as tissuefit.Error (file:line: field
#                 for a broken scene); a flipped bit and a changed status
#                 are shown counted.

PY_T := $(T)/python
PY_SITE_T = $(abspath $(PY_T))/install/usr/$(PYTHON_SITE)

.PHONY: check-python
CHECKS += check-python
check-python: $(B)/bin/tissuefit $(PY_PKG_LIBS) | deps-check
	@echo "== python: the tissuefit module installed, against the tool and the golden vectors =="
	@rm -rf $(PY_T) && mkdir -p $(PY_T)
	@$(MAKE) --no-print-directory install DESTDIR=$(abspath $(PY_T))/install PREFIX=/usr \
	  >$(PY_T)/install.log 2>&1 || { cat $(PY_T)/install.log; exit 1; }
	@cd $(PY_T) && PYTHONPATH=$(PY_SITE_T) $(PYTHON) -c "import tissuefit; print('imported', tissuefit.__file__)"
	@PYTHONDONTWRITEBYTECODE=1 PYTHONPATH=$(PY_SITE_T):tests/python TISSUEFIT_SITE=$(PY_SITE_T) TISSUEFIT_ROOT=$(CURDIR) \
	  TISSUEFIT_TOOL=$(abspath $(B))/bin/tissuefit $(PYTHON) -m pytest -q -p no:cacheprovider \
	  --basetemp=$(abspath $(PY_T))/tmp tests/python 2>&1 | tee $(PY_T)/pytest.log
	@grep -q ' passed' $(PY_T)/pytest.log && ! grep -qE ' (failed|error|skipped)' $(PY_T)/pytest.log
	@echo "ok: tissuefit imported from a make install; $$(grep -oE '[0-9]+ passed' $(PY_T)/pytest.log): solves equal to tissuefit solve bit for bit, VTU via meshio, fit, every shipped header's golden vectors"
