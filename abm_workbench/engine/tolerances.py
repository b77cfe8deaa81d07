"""Tolerances of the engine, in one place (lengths in mm)."""

#: The root finders stop when a Newton step or the bracket is below this, on the unit interval
#: of a boundary search (Newton converges quadratically, so the root is then good to ~1e-24).
ROOT_TOL = 1e-12
#: Plain Newton steps tried from the secant point before the safeguarded iteration (most
#: crossings are near-linear, so three steps reach ROOT_TOL).
FAST_NEWTON = 3
#: Iteration cap of the safeguarded Newton-bisection root finder.
ROOT_MAX_ITER = 100
#: Pieces of the cutting edge shorter than this (mm) are merged with their neighbours.
LENGTH_EPS = 1e-12
#: A direction component below this counts as zero (edge parallel to a plane).
PARALLEL_EPS = 1e-14
#: Points sampled per wall when checking that walls are ordered and inside the x limits.
WALL_CHECK_SAMPLES = 2049
#: Recognition of solids (mm): a face is horizontal when its points stay within this of one z,
#: a wall vertical when its points over each plan point stay within this in x and y, a plan
#: curve runs one way when it never turns back by more than this, and points, levels and
#: limits closer than this coincide. One tolerance for every decision of abm_workbench.cad.faces,
#: recognise and terraced_recognise.
RECOGNITION_TOL = 1e-6
