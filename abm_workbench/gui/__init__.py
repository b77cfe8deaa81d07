"""The ABM workbench's GUI: view providers and commands (imported only when FreeCAD.GuiUp).

- :mod:`.view_providers`: icons per object type, the engaged surface coloured per face by the
  UEP surface of its engagement segment, the stock semi-transparent, the toolpath a thick line;
  :func:`.view_providers.attach` and a document observer that attaches them to restored objects.
- :mod:`.commands`: ``ABM_OpenModelTest``, ``ABM_ImportStock``, ``ABM_ImportToolpath``,
  ``ABM_ComputeEngagement``, each inside a document transaction (undo works).

docs/GUI.md describes what the user sees.
"""
