"""The CAD layer: solids in and out, staircase recognition, and the boolean reference.

This subpackage is the only place that imports FreeCAD and Part (through
:mod:`.freecad_env`); the engine stays pure numpy. Lengths in mm, angles in degrees.

- :mod:`.solids`: a :class:`~abm_workbench.engine.Staircase` as an exact solid, STEP/BREP export.
- :mod:`.recognise`: a solid (STEP, BREP, FCStd) back into a Staircase.
- :mod:`.boolean`: lengths of cut by OpenCASCADE booleans, the reference the engine is
  checked against (the paper's Siemens NX check).
- :mod:`.profile_edges`, :mod:`.profile_boolean`: the whole cutting edge of any tool (corner arcs as
  true circular arcs, sides, end edges) built from the tool's definition and sectioned with the stock;
  :mod:`.corner_sweep`, :mod:`.corner_inprocess`: exact solids of the volumes a bull-nose or ball-end mill
  sweeps, and that reference against the in-process stock (:mod:`.sweep_membership`, its exact inside test for
  the volumes OpenCASCADE's solids do not give reliably); :mod:`.profile_inprocess`: an estimate of what
  earlier moves took from a corner tool's edges where it is checked against the stock as given;
  :mod:`.hull_solids`, :mod:`.inprocess_boolean`: a flat-end mill's swept volumes and the in-process stock by
  OpenCASCADE.
- :mod:`.annotate`: a FreeCAD document with the stock, the toolpath and the engagement of
  chosen CL points drawn on the model.
"""
