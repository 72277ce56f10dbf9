# python.mk — the Python module `tissuefit` (python/tissuefit/, docs/python.md):
# installed by `make install` beside the shared library it binds with ctypes
# (libtissuefit.so, host/host.mk), a position-independent libtfit and the
# target headers that its generated-header evaluator compiles against.
#
#   make install PREFIX=/usr/local   also installs the package into
#                                    PREFIX/$(PYTHON_SITE)/tissuefit
#   make python-example              docs/examples/cut_progress.py from a
#                                    staged install: docs/cutting-progress.png
#                                    redrawn as build/python-example/
#                                    cutting-progress.png

# Debian's interpreter: the pyenv python3 first on this machine's PATH lacks
# the Debian packages (numpy, meshio, pytest).
PYTHON ?= /usr/bin/python3
DEBS_PYTHON := python3 python3-numpy python3-meshio python3-pytest
DEBS_CHECK += $(DEBS_PYTHON)
DEBS_BUILD_PYTHON := $(DEBS_BUILD) $(DEBS_PYTHON)

# Where the package goes under PREFIX: the dist-packages folder Debian's
# python3 searches under /usr and under /usr/local alike
# (lib/python3.11/dist-packages on Debian 12).
PYTHON_SITE ?= lib/python$(shell $(PYTHON) -c 'import sys; print("%d.%d" % sys.version_info[:2])' 2>/dev/null || echo 3)/dist-packages
PY_PKG_SRC := $(wildcard python/tissuefit/*.py) python/tissuefit/tfit_shim.c
PY_PKG_LIBS := $(B)/native/libtissuefit.so $(B)/native-pic/libtfit.a

.PHONY: install-python python-example deps-python-example
deps-python-example: ; $(call ensure_debs,$(DEBS_BUILD_PYTHON) gnuplot-nox)
install: install-python
install-python: $(PY_PKG_LIBS)
	$(eval PYDIR := $(DESTDIR)$(PREFIX)/$(PYTHON_SITE)/tissuefit)
	install -d $(PYDIR)/include
	install -m 644 $(PY_PKG_SRC) $(PYDIR)
	install -m 755 $(B)/native/libtissuefit.so $(PYDIR)/libtissuefit.so
	install -m 644 $(B)/native-pic/libtfit.a $(PYDIR)/libtfit_pic.a
	install -m 644 target/include/tfit.h target/include/tfit_q31.h $(PYDIR)/include

# The example runs from a staged install, as a user's script would.
PY_EXAMPLE_T := $(B)/python-example
python-example: $(PY_PKG_LIBS) | deps-python-example
	@rm -rf $(PY_EXAMPLE_T) && mkdir -p $(PY_EXAMPLE_T)
	@$(MAKE) --no-print-directory install-python DESTDIR=$(abspath $(PY_EXAMPLE_T))/stage PREFIX=/usr \
	  >$(PY_EXAMPLE_T)/install.log 2>&1 || { cat $(PY_EXAMPLE_T)/install.log; exit 1; }
	PYTHONPATH=$(abspath $(PY_EXAMPLE_T))/stage/usr/$(PYTHON_SITE) $(PYTHON) docs/examples/cut_progress.py \
	  coeffs/block48_cut.yaml $(PY_EXAMPLE_T)
