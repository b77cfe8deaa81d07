# One obvious way to run things. FreeCAD's Python is the system interpreter: never the
# `python3` that happens to be first on PATH.
PYTHON := /usr/bin/python3
DEBS := freecad-python3 freecad python3-numpy python3-scipy python3-matplotlib python3-pytest python3-hypothesis python3-dask python3-distributed xvfb xauth qttools5-dev-tools
OUT := build

.PHONY: translations figures deps model-test-1 model-test-2 model-test-4 model-test-5 validate-model-test-5-in-process validate-model-test-1 validate-model-test-2 validate-model-test-4 validate-model-test-3 test benchmark scaling models install screenshots compare-peers

# Install the Debian packages that are missing (as root, or through sudo).
deps:
	@missing=$$(for p in $(DEBS); do dpkg -s $$p >/dev/null 2>&1 || echo $$p; done); \
	if [ -n "$$missing" ]; then \
	  sudo=$$([ "$$(id -u)" -eq 0 ] || echo sudo); \
	  echo "installing:" $$missing; \
	  $$sudo apt-get update && DEBIAN_FRONTEND=noninteractive $$sudo apt-get install -y --no-install-recommends $$missing; \
	fi

# The main job: model test 1, headless, to a results CSV, its summary and a plot.
model-test-1 model-test-2 model-test-4: model-test-%: deps
	$(PYTHON) -m abm_workbench engage --job resources/models/model_test_$*/job.json \
	  --stock resources/models/model_test_$*/stock.json --toolpath resources/models/model_test_$*/toolpath.csv \
	  --out $(OUT)/model_test_$*/results.csv --plot $(OUT)/model_test_$*/results.png

# Model test N against OpenCASCADE booleans on its STEP solid (true contour walls): HTML report
# and annotated FreeCAD document. Model tests 1 and 2 are the paper's single passes, checked on the
# stock as given, about a minute (the boolean costs ~1 s per CL point): the engine finds that none
# of their CL points meets material the pass's own earlier moves removed, which the in-process
# boolean would take 10 s and more per CL point to confirm. In model test 4, 4 CL points meet such
# material (CL points 46-49), so it is checked on the in-process stock, CL 47 shown (several minutes).
STOCK_MODEL_1 := initial
STOCK_MODEL_2 := initial
STOCK_MODEL_4 := in-process
SHOWN_CL_1 := 0,22,40
SHOWN_CL_2 := 0,22,40
SHOWN_CL_4 := 0,22,47
validate-model-test-1 validate-model-test-2 validate-model-test-4: validate-model-test-%: deps
	$(PYTHON) -m abm_workbench validate --job resources/models/model_test_$*/job.json \
	  --stock resources/models/model_test_$*/stock.step --toolpath resources/models/model_test_$*/toolpath.csv \
	  --report $(OUT)/model_test_$*/validation --fcstd $(OUT)/model_test_$*/validation.FCStd --cl $(SHOWN_CL_$*) \
	  --stock-model $(STOCK_MODEL_$*)

# Model test 3 (a whole program) against OpenCASCADE booleans on the in-process stock: a report and an
# annotated document per operation (operation 1's later passes meet what its first passes removed,
# operation 2 what operation 1 removed). The boolean sections the earlier moves' swept solids, seconds
# to a minute per CL point, so it checks a handful of CL points of each operation (--check; the shown
# one, --cl, among them; the engine computes all), at φ step 3°: about 8 minutes on 2 cores
# (docs/VALIDATION.md).
VALIDATE_3 = $(PYTHON) -m abm_workbench validate --job resources/models/model_test_3/job.json \
  --stock resources/models/model_test_3/stock.step --toolpath resources/models/model_test_3/program.apt \
  --stock-model in-process --phi-step 3 --workers 2
validate-model-test-3: deps
	$(VALIDATE_3) --operation 1 --check 0,27,80,100,109,130,150,164 --cl 130 \
	  --report $(OUT)/model_test_3/validation_op1 --fcstd $(OUT)/model_test_3/validation_op1.FCStd
	$(VALIDATE_3) --operation 2 --check 30,50,54,75,100,109 --cl 50 \
	  --report $(OUT)/model_test_3/validation_op2 --fcstd $(OUT)/model_test_3/validation_op2.FCStd

# Model test 5 (docs/MODEL_TESTS.md): a D16 R3 bull-nose mill semi-finishing a z-level-roughed two-bump part in a
# five-axis raster of 7 passes, as NX writes it (toolpath.cls: TLDATA/MILL with the corner radius, MSYS, GOTO with
# tilted axes; 518 CL points), against OpenCASCADE on the stock as given: corner arcs, sides and end edges of every
# other CL point (and the shown ones) at phi step 3 deg, 2 worker processes, a report and an annotated document, and
# the estimate of what earlier passes removed at every 37th CL point. Through the Python API
# (tests/cad/run_model_test_5.py), for that estimate; `abm validate --job resources/models/model_test_5/job.json ...`
# checks the same files without it. About 10 minutes on 2 quiet cores. validate-model-test-5-in-process checks three CL
# points against the in-process stock instead (what the earlier passes removed, on both sides; the reference decides
# the mill's nearly flat five-axis sub-steps with its exact inside test, docs/VALIDATION.md): about 7 minutes.
model-test-5: deps
	$(PYTHON) -m tests.cad.run_model_test_5 --report $(OUT)/model_test_5/validation \
	  --fcstd $(OUT)/model_test_5/validation.FCStd --cl 40,150,268,440 --check-every 2 --phi-step 3 --workers 2 \
	  --removed-every 37

validate-model-test-5-in-process: deps
	$(PYTHON) -m abm_workbench validate --job resources/models/model_test_5/job.json \
	  --stock resources/models/model_test_5/stock.step --toolpath resources/models/model_test_5/toolpath.cls \
	  --stock-model in-process --phi-step 3 --workers 2 --check 150,268,440 --cl 268 \
	  --report $(OUT)/model_test_5/validation_in_process

test: deps
	$(PYTHON) -m pytest -q tests

benchmark: deps
	$(PYTHON) benchmarks/engine_throughput.py

# ABM against an independent peer (benchmarks/peer_raycast.py: the STEP solid tessellated by
# OpenCASCADE, ray-cast with Embree through trimesh) on both model tests; a few minutes, to
# build/benchmarks/compare_peers.csv. The peer's packages go into a virtual environment that sees
# the system's FreeCAD, numpy and scipy (pinned, installed without their dependencies, so that the
# system's numpy stays the one imported); the project itself never needs them.
PEERS_VENV := $(OUT)/peers-venv
PEER_PACKAGES := trimesh==5.2.0 embreex==4.4.0.post1 manifold3d==3.5.4

$(PEERS_VENV)/ready: Makefile
	@dpkg -s python3-venv >/dev/null 2>&1 || $(MAKE) deps DEBS=python3-venv
	rm -rf $(PEERS_VENV)
	$(PYTHON) -m venv --system-site-packages $(PEERS_VENV)
	$(PEERS_VENV)/bin/python -m pip install --quiet --no-deps $(PEER_PACKAGES)
	test "$$($(PEERS_VENV)/bin/python -c 'import numpy; print(numpy.__file__)')" = \
	  "$$($(PYTHON) -c 'import numpy; print(numpy.__file__)')"
	$(PEERS_VENV)/bin/python -c 'import trimesh.ray.ray_pyembree, embreex, manifold3d'
	touch $@

compare-peers: deps $(PEERS_VENV)/ready
	$(PEERS_VENV)/bin/python benchmarks/compare_methods.py --peers

# Time and peak memory from 10^3 to 10^7 instants: engine, command line, local workers, Dask
# (docs/SCALING.md); a few minutes, to build/benchmarks/scaling.{csv,png}.
scaling: deps
	$(PYTHON) benchmarks/scaling.py

# Re-make the bundled model tests from their design surfaces (JSON and CSV, then STEP solids).
models: deps
	$(PYTHON) resources/models/make_model_tests.py
	$(PYTHON) resources/models/make_model_solids.py
	$(PYTHON) resources/models/make_model_test_4.py

# Development install: link the checkout into FreeCAD's user Mod folder.
install:
	mkdir -p $(HOME)/.local/share/FreeCAD/Mod
	ln -sfn $(CURDIR) $(HOME)/.local/share/FreeCAD/Mod/ABM

# The docs' drawn figures (docs/images/frames_feed.png ...), from the engine's own frames.
figures: deps
	$(PYTHON) docs/make_figures.py docs/images

# The GUI's translations: the template translations/ABM.ts from the sources, each translations/ABM_<language>.ts
# brought up to date with it, and compiled to the ABM_<language>.qm that FreeCAD loads (Qt's lrelease,
# from qttools5-dev-tools). The .qm files are committed, so an install needs no Qt tools.
LRELEASE := $(shell command -v lrelease 2>/dev/null || echo /usr/lib/qt5/bin/lrelease)
translations: deps
	$(PYTHON) -m abm_workbench.gui.i18n
	for ts in translations/ABM_*.ts; do QT_SELECT=qt5 $(LRELEASE) -silent $$ts -qm $${ts%.ts}.qm || exit 1; done

# The README's GUI screenshots (docs/images/gui_*.png): model test 1 in the FreeCAD GUI under Xvfb.
screenshots: deps
	$(PYTHON) -m abm_workbench.gui.screenshots docs/images
