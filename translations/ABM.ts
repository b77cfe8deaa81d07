<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1">
<context>
    <name>ABM</name>
    <message>
        <source>diameter</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>flutes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>flute length</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>feed per tooth</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>select a FreeCAD CAM Job, or operations of one</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no operation has moves</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{job}: no operation the engine computes ({reasons})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{operation}: no tool controller</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{operation}: {controller} gives no {value} (set it in its toolbit, or in Edit → Preferences → ABM)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{operation}: not in the program of {job} (inactive, or no moves)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Import stock</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Import toolpath</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>millimetres (mm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>inches (in)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{program} works in inches, and the tool table {table} gives its lengths in the machine's units, which LinuxCNC does not write in the table. Which units is the machine set up in (LINEAR_UNITS of its INI file)? (the toolpath's ToolTableUnits; change it later in the property editor)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>stock</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>stocks</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>toolpath</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>toolpaths</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>engagement</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>engagements</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tool table of {file}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tool table (*.tbl *.FCStd);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{file} holds several operations: choose the one to compute (the toolpath's Operation; change it later in the property editor)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{count} {nouns} selected: select one {noun}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no {noun} in the document: import one first</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{count} {nouns} in the document: select the one to use</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Validating {label} at {count} CL points against booleans…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Computing model test 1…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reading the toolpath…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Computing the engagement of the CAM job…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Validate engagement</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CL points to check (all, or e.g. 0,22,40; about 1 s each):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{label}: compute it first (recompute the document)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{file}: not imported: it works in inches, and the units of the tool table {table} were not said</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not for the engine</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Folder for the validation report</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{label}: validation report {page}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{file}: not imported: its program loads tools by number, and no tool table was chosen (a LinuxCNC tool table, or the FreeCAD document that posted the program)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>validation cancelled: nothing written</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>length of cut</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cut area</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>resultant cutting force</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>none</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>top</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>straight wall</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>curved wall</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>flute end</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>stock side</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>immersion end</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>bottom</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>flute start</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>machined</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>peak |F| over φ</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>mean |F| over φ</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>in-process stock: {count} CL points changed by earlier moves of the program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>stock as given</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>changed by earlier moves: longest length of cut in-process {now} mm / initial {before} mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ABM engagement</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Engagement</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Forces</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>; peak force {force} N</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>length of
cut (mm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cut area
(mm²)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>h (mm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CL {cl} over the tool rotation angle φ</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>φ (deg)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CL point</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pass progression</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>force (N)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CL {cl}: peak |F| {peak} N, mean {mean} N</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Resultant force along the pass</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not changed by earlier moves</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Colour by</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;b&gt;{label}&lt;/b&gt;: {m} CL points × {p} angles φ; depth of cut {low}–{high} mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no forces: turn Cutting forces on in the engagement's task panel and recompute</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>depth of cut</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>max length of cut</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>engagement segment (UEP surface)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{label}: no results (recompute it)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No engagement: select one and use Inspect engagement</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CL {cl}: depth of cut {depth} mm, max length of cut {length} mm; segments</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CL {cl}: the tool does not engage the stock here</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>segment: UEP surface</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>UEP surface of the engagement segment:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>In-process stock at CL {cl}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>In-process stock (computing CL {cl}…)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Computing the in-process stock of {label} at CL {cl}…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>In-process stock at CL {cl} (program row {row}): {volume} mm³ removed by earlier moves near it, in {seconds} s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show in-process stock: inspect an engagement first (Inspect engagement), then choose its CL point in the dock</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>In-process stock at CL {cl}: cancelled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tool diameter</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Flutes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Flute length</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Feed per tooth</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Inclination α</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>φ step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ABM</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New engagement: tool and cut (0: ask)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Results</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>beside the document</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Validation reports in</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Colour map</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>one per core</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Processes computing the boolean reference of a validation, beside FreeCAD's own (which stays free to draw): 0 one per core</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Validation workers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Program CL {index} of {count}: operation {number}{name}, {tool}, its CL {cl}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Every CL point of the whole program, operation after operation: moved into another operation, the dock goes there once it rests</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Choose operation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no engagement of operation {number} of {job}: select the Job and use Engage CAM job</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not computed: {reason}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>going there once the slider rests…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Computing operation {number} of the program…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not shown: {reason}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Diameter</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Corner radius</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Helix angle β</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Spindle speed (rpm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>φ start</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>φ end</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>y window from</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>y window to</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tool</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cut</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tool rotation angles φ</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stock model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cutting forces</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Immersion from</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Immersion to</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Engagement: tool and cut</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stock</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Toolpath</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Wall model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>y window</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Computing the engagement…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fixed by the toolpath file, the values it was made for:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Input files missing: choose the folder that holds them</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Missing:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{document}: input files missing, not re-pointed:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{label}: {file} is not in {folder}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{done} of {total} CL points, about {left} left</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{done} of {total} steps, about {left} left</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{minutes} min {seconds} s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{seconds} s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reading and recognising the stock…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Computing the in-process stock…</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>ABM_ComputeEngagement</name>
    <message>
        <source>Compute engagement</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Compute where the cutter engages the stock along the toolpath: select a stock and a toolpath (or have only one of each), then set the tool and cut in the task panel</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>ABM_EngageCamJob</name>
    <message>
        <source>Engage CAM job</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Compute where the cutter engages the stock in a FreeCAD CAM Job: select the Job (every operation the engine computes) or some of its operations; the results follow the Job when it recomputes</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>ABM_ImportStock</name>
    <message>
        <source>Import stock…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add a staircase stock from the selected solid, or from a STEP, BREP or FCStd solid (recognised, exact walls) or a staircase JSON</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>ABM_ImportToolpath</name>
    <message>
        <source>Import toolpath…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add a toolpath from the selected CAM Job or operation, or from a CSV (x,y,z,theta_a,theta_b or x,y,z,i,j,k), an APT / CL file, G-code or an FCStd holding a CAM Job</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>ABM_InspectEngagement</name>
    <message>
        <source>Inspect engagement</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open the engagement dock for the selected engagement: choose a CL point (highlighted on the model), colour by segment, length of cut or cut area, and see the plots</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>ABM_OpenModelTest</name>
    <message>
        <source>Open model test 1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New document with model test 1 (after Hendriko 2020): the STEP stock with exact walls, the toolpath and the engagement with job.json's tool and cut, computed</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>ABM_ShowInProcessStock</name>
    <message>
        <source>Show in-process stock</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show the stock as it is at the dock's chosen CL point: the stock minus what the program's earlier moves near it removed (OpenCASCADE booleans, a few seconds); it follows the CL point chosen in the dock</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>ABM_ValidateEngagement</name>
    <message>
        <source>Validate engagement…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Check the selected engagement's length of cut against OpenCASCADE booleans at all or chosen CL points (about 1 s per CL point; cancellable) and open the HTML report</source>
        <translation type="unfinished"></translation>
    </message>
</context>
</TS>
