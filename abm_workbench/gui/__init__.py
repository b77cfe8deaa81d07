"""The ABM workbench's GUI (imported only when FreeCAD.GuiUp).

- :mod:`.commands`: ``ABM_OpenModelTest``, ``ABM_ImportStock``, ``ABM_ImportToolpath``,
  ``ABM_ComputeEngagement``, ``ABM_EngageCamJob`` (a FreeCAD CAM Job: :mod:`.cam_jobs`),
  ``ABM_InspectEngagement``, ``ABM_ValidateEngagement``, each inside a document transaction (undo
  works), errors to the report view in plain words.
- :mod:`.task_panel`: the engagement's tool and cut, with units, checked as typed; its numbers
  read and shown in each field's declared unit by :mod:`.numbers`.
- :mod:`.dock`: the engagement dock: CL point slider, colour by and legend, plots.
- :mod:`.view_providers`: icons, styles, the engaged surface as one mesh (:mod:`.surface_mesh`,
  :mod:`.colouring`), the highlighted CL point; :func:`.view_providers.attach` and a document
  observer for restored objects.
- :mod:`.state`: what the dock, task panel and view providers tell each other (no imports
  between them); :mod:`.reporting`: errors in the GUI's plain words, checked recomputes.
- :mod:`.progress`, :mod:`.validate`: progress and cancel; validation and its HTML report.
- :mod:`.worker`: the engine in a worker thread during a recompute, with progress and Cancel.
- :mod:`.screenshots`: the README's pictures under Xvfb (``make screenshots``).

docs/GUI.md describes what the user sees.
"""
