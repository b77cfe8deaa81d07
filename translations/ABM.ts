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
        <source>{label}: validation report {page}</source>
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
        <source>validation cancelled: nothing written</source>
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
        <source>{file}: not imported: its program loads tools by number, and no tool table was chosen (a LinuxCNC tool table, or the FreeCAD document that posted the program)</source>
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
        <source>“{typed}” is not a length: {hint}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>type a number, with a unit if you like (12 mm, 0.5 in)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>“{typed}” is not an angle: {hint}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>type a number, with a unit if you like (10°, 0.2 rad)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>“{typed}” is not a number: {hint}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>type a number without a unit (4, 2.5)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>“{typed}” has a “{other}”: decimals take a “{point}” (12{point}5), thousands no separator (1000)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>“{typed}” is too large a number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>“{typed}” is too small a number: it would be taken as 0</source>
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
        <source>the toolpath's ToolTable property</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the toolpath's ToolTableUnits property</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the toolpath's Operation property</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the helix angle β</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the engagement's StockModel property</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a toolpath linked to the CAM Job</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a machine file (not read by the GUI yet)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>work offsets (not read by the GUI yet)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the wall model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the y window</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cutting forces</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the CL points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No such file or directory</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Permission denied</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Is a directory</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not a directory</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No space left on device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read-only file system</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>File exists</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>File name too long</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Too many levels of symbolic links</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>set the toolpath's ToolTable property (</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>choose one in the toolpath's Operation property</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>say them in the toolpath's ToolTableUnits property (mm or inch)</source>
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
        <source>The wall model {model} applies to a solid stock (STEP, BREP or FCStd), not to {stock}.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The y window {window} applies to a solid stock (STEP, BREP or FCStd), not to {stock}.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The y window must start below its end: {start} mm to {end} mm.</source>
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
        <source>{field}: the field is empty: {hint}.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{field} is required: the field is empty.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{field}: the engagement object holds angles within [{low}, {high}]°, got {value}°.</source>
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
        <source>ABM against booleans</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Helical edges (β = {helix}°), flute 1 of {flutes}, ABM against booleans</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CL points {listed} of the pass, numbered 0..{last} here.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the paper's quintic walls (JSON)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>in-process: the stock minus what earlier cutting moves of the program removed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>initial: the stock as given ({why})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>initial: the stock as given</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>pass CL {cl}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>exact walls</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>quintic walls</source>
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
    <message>
        <source>chosen</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>largest error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>deepest</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>shallowest</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>middle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CL points shown: {listed}. Shaded: the engagement segments (ABM).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>bull-nose mill D {diameter} mm, corner radius {corner} mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{checked} of {count}: {spans} (the statistics, comparison.csv and segments.csv are over these; the engine computed all {count})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ABM {abm_low}–{abm_high} mm, boolean {low}–{high} mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CL points shown: {listed} (the first {count} of {total}). Shaded: the engagement segments (ABM).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>flat end mill D {diameter} mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ball-end mill D {diameter} mm (R {corner} mm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>all {count} (the statistics are over every instant)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>changed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>swept pieces near</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>angles changed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>max l, stock as given (ABM)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>max l, in-process (ABM)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>max l, in-process (boolean)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>max |Δl| (mm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>instants</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>relative</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>max |rel. error|</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>mean |rel. error|</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>max |ΔLEP| (mm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>max |ΔUEP| (mm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>mismatched</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>max |Δ end| (mm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>end mismatched</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Job</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Error by UEP surface, whole pass</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The paper (Siemens NX reference): negligible error with the UEP on a top or a straight wall, below 6 % with the UEP on a curved wall.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Length of cut along the pass</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Depth of cut along the pass</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Length of cut and cut area over φ</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Shape of the cut</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Error per engagement segment</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Error over the pass</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Timings</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Files</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>largest |relative error| over {count} instants</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>mean |relative error|</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>largest |l_ABM − l_ref|, all instants</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>largest |Δ end edge| over {count} instants</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ABM {abm} s vs boolean {boolean} s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{path}: {count} CL points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CL points checked</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>rotation angles</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>φ {start}..{end}° step {step}°: {count} angles, {instants} instants</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>tool</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cutting</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>parameters [from]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>stock model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{swept} ({gauged} by the exact test)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Error of the length of cut as the paper defines it: relative, (l&lt;sub&gt;ABM&lt;/sub&gt; − l&lt;sub&gt;ref&lt;/sub&gt;)/l&lt;sub&gt;ref&lt;/sub&gt;, with l&lt;sub&gt;ref&lt;/sub&gt; from the OpenCASCADE boolean of the cutting edges with the stock solid. Where l&lt;sub&gt;ref&lt;/sub&gt; &amp;lt; {tiny} mm (the edge grazes the stock) the absolute difference l&lt;sub&gt;ABM&lt;/sub&gt; − l&lt;sub&gt;ref&lt;/sub&gt; in mm is used instead; those instants are counted apart. LEP/UEP: largest difference along the edge (mm). Mismatched: instants where only one method finds engagement. End edge: the largest |end&lt;sub&gt;ABM&lt;/sub&gt; − end&lt;sub&gt;ref&lt;/sub&gt;| of the end cutting edge's engaged length (tip to the corner, in the tip plane) over the instants where both give it, and the instants where only one finds it in the stock.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>segment</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>UEP on</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>section</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>wall</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Every CL point: &lt;code&gt;segments.csv&lt;/code&gt;.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>model test {number} {low}–{high} mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>This job is model test {number}.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Depth of cut over the pass (highest UEP z − lowest LEP z per CL point): {ours}. The paper's passes: {papers}.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ABM engine, whole pass</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{time} µs per instant</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>boolean reference (OpenCASCADE)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{time} s per CL point</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>boolean / ABM</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>stock solid and staircase (read, build or recognise)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>paper, {name}, 53 CC points (MATLAB, i7 2.7 GHz)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>angle step not stated</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>one row per instant the boolean checked: cl, phi_deg, l_abm, l_ref, difference, error, error_kind, LEP and UEP of both, pieces of both, segment, uep_surface, end_abm, end_ref, end_difference (the end edge's engaged length; against the in-process stock also l_initial: ABM in the stock as given)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>error per CL point and engagement segment</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>error per kind of UEP surface</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>depth of cut per CL point, both methods, and checked (1 where the boolean checked it; against the in-process stock also changed: whether earlier moves changed the CL point, and swept: the swept pieces the boolean sectioned)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>depth of cut (ABM); paper {low}–{high} mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>depth of cut (ABM); paper: not a model test</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{stock} ({walls}; y window {low}..{high} mm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{tool}, {flutes} flutes, flute length {length} mm, helix {helix}°</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{tool}, {flutes} flutes, flute length {length} mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>feed {feed} mm/tooth, inclination {inclination}°, {speed} rpm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>feed {feed} mm/tooth, inclination {inclination}°</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{count} of the swept pieces that meet the tool's edges (summed over the checked CL points) are moves OpenCASCADE has no reliable solids for (a bull-nose mill's moves within 5.74° of the plane across its axis, whose solids have nearly degenerate faces its booleans misjudge; oblique moves of a tool shorter than its corner radius): the reference decides where the edges lie in those with an exact inside test of its own (the tool's distance function minimised along the move, every crossing isolated to 10⁻¹⁰ mm), independent of the engine (column &lt;code&gt;gauged&lt;/code&gt; of &lt;code&gt;depth.csv&lt;/code&gt;).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>In-process stock</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>For this ball mill the cutting edge is the corner arc (radius {radius} mm, sectioned by the boolean as a true circular arc) followed by the straight side: l is the arc length along both, LEP and UEP are heights along the tool axis above the tip (mm).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>For this bull-nose mill the cutting edge is the corner arc (radius {radius} mm, sectioned by the boolean as a true circular arc) followed by the straight side: l is the arc length along both, LEP and UEP are heights along the tool axis above the tip (mm).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>peak resultant force over the pass</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{force} N at CL {cl}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>mean resultant force, pass average</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>peak torque</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fig.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>yes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Both the engine and the boolean reference work on the &lt;b&gt;in-process stock&lt;/b&gt;: at each CL point, the stock minus the volumes swept by the cutting moves that end before it. The boolean reference sections each cutting-edge line with the stock solid and with exact solids of the volumes swept by the earlier moves that can reach the tool, and keeps what lies in the stock and in none of them. The pictures show the top of that in-process stock around the tool, found the same way along vertical lines. Earlier moves changed {changed} of {count} CL points ({instants} instants by more than {tiny} mm; {engaged} of the changed CL points still engage). Per instant, &lt;code&gt;comparison.csv&lt;/code&gt; has the length in the stock as given (&lt;code&gt;l_initial&lt;/code&gt;) beside both in-process lengths; &lt;code&gt;depth.csv&lt;/code&gt; says which CL points changed.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>peak spindle power</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Linear edge-force model (docs/FORCES.md) on the ABM engagement, global frame, summed over the flutes cutting at each angle of flute 1; over φ at CL {shown} (dotted in the first plot). Also &lt;a href='forces.png'&gt;&lt;code&gt;forces.png&lt;/code&gt;&lt;/a&gt;.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>whole pass</source>
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
<context>
    <name>ABM_messages</name>
    <message>
        <source>phi_deg must be finite angles of shape (p,), got shape {shape}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a boolean result edge lies on no cutting edge (nearest {distance_k} mm away)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>corner_lengths_in_process is for tools with a corner radius; flat-end mills have profile_boolean.flat_lengths_in_process</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the move from {point_c0} to {point_c1} mm has no exact solids here</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>OpenCASCADE did not split the corner's torus along its silhouette for the move {point_m} mm (axis {point_w})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a 2.5D stock has horizontal tops and vertical walls</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the edge {ends_edge} has no 3D curve, so its extent cannot be found</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the edge {ends_edge} lies on {value}, which has no exact B-spline form, so its extent cannot be found exactly</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}{name}: a vertical wall on {error}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>an OffsetSurface ({OffsetValue} mm) of {described_basis}: its offset has no exact form the walls take (offsets of planes, cylinders and extrusions of lines and circles are taken)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>an OffsetSurface that shrinks a cylinder to its axis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>slanted top: a plane tilted {tilt}° from horizontal</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>overhang: a plane facing down, tilted {tilt}° from horizontal</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>wall not vertical: leans {value}°</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>curved top: not a horizontal plane</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>overhang: faces down</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>wall not vertical</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{value}, which has no exact B-spline form for the walls</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}{name}: curved top: not a horizontal plane: a {type} whose control points span z {z_min} to {z_max}, near x = {pole_0}, y = {pole_1}; {RULE}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}{name}: wall not vertical: leans up to {value}° near x = {row_0}, y = {row_1} (a {type} whose control points drift {drift_k} mm sideways over {rise_k} mm of height); {RULE}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>FreeCAD is not importable from {executable} ({error}). Install the Debian package freecad-python3 (apt-get install freecad-python3) and run the system interpreter /usr/bin/python3.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>flutes must be indices in 0..{z_1}, got {flutes}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a boolean result edge lies on no flute helix (nearest {distance} mm away)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the {n} CL points are found {size} times in the pass of {count}; the in-process reference needs them once</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a boolean result edge lies on no cutting edge (nearest {distance} mm away)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>flat_lengths_by_boolean is for flat-end mills; use profile_lengths_by_boolean</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>flat_lengths_in_process is for flat-end mills; use corner_inprocess.corner_lengths_in_process</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a boolean result edge lies on no end edge (nearest {distance_j} mm away)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{path}: unknown file type; expected .step, .stp, .brep, .brp or .FCStd</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{path}: no such file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{path}: the {kind} file holds no shape</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{path}: several solids ({join_names}); choose one with --solid NAME</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{path}: no solid named {name} in the {kind} file (its solids: none)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{path}: no solid named {name} in the {kind} file (its solids: {listed})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{path}: damaged {kind}: {value} of the shape's {count} vertices are not finite numbers (NaN or infinite coordinates)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{path}: damaged or unreadable {kind} (no shape after {timeout} s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot read as {kind}: {value}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the reader ended with exit status {returncode} and no shape</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{path}: damaged or unreadable {kind} ({detail})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}the cutting edges sweep y {s0} to {s1} mm, beyond the y window {w0} to {w1} mm that the stock was recognised over: widen the window</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{path}: cannot open as a FreeCAD document: {error}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{path}: {found} object with a solid named {name} (objects with solids: {names})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no object holds a solid</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>several solids ({names}); choose one with --solid NAME</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>walls must be 'exact' or 'quintic', got {walls}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>wall_points must be 'chebyshev' or 'even', got {wall_points}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}the solid has no top face facing +z</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}not a closed solid: an open shell, {free_edges_shape}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}holds no solid (a {ShapeType} of {count} faces)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}holds {count} solids; a stock is one solid</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}holds {value} faces outside its solid</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}not a closed solid: {free_edges_shape}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}the solid is not valid (shape.check() says why)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{listed} has an edge bordering no other face</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{listed} have edges bordering no other face</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}y_window ({y0}, {y1}) must be increasing and inside the stock's y range [{y_min}, {y_max}]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}{name}: overhang: faces downwards at z = {z}, above the base (z = {limits_4}); a staircase stands on its base</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}{label}: wall has no top edge along a top face</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}{label}: wall has more than one x for y = {points_0_1} (its top edge runs along x there, from x = {x_values_min} to {x_values_max}); {_ALONG_X}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}{label}: wall has more than one x for y = {at_1} (its top edge turns back by {back} mm in y near x = {at_0}); {_ALONG_X}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}{label}: wall has more than one x for y = {value} (two of its top edges overlap in y from {low} to {high}); {_ALONG_X}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}{label}: wall does not run across the y window [{y0}, {y1}]: no x at y = {value} (its top edges leave a gap from {high} to {low})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}{label}: wall does not run across the y window [{y0}, {y1}]: no x at y = {y} (its top edge spans y {y_low} to {y_high}); {_ALONG_X}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a staircase's walls run across y with one x for each y</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}{value}: top face at z = {z} does not reach y = {y_probe}: a section must have one top across the y window</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>more than one top face: {listed}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no top face</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}section {j} (x {x_probe_j} to {x_probe_j_1} at y = {y_probe}) has {what}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}{join_wall_faces}: wall between sections {j_1} and {j} spans z {wall_z_range_0} to {wall_z_range_1}, but the tops beside it are at {low} and {high}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the B-spline wall spans y {start} to {end}, not all of [{y_lo}, {y_hi}]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>fusing the {count} sections gave {count_2} solids, expected 1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the fused staircase solid is not valid</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{error} (the paper's quintic walls need a staircase stock)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no wall face</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}slab {k}: the section at z = {z} near x = {x}, y = {y} lies on {found}; expected one vertical wall</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}slab {k}: the section's curve ending at x = {end_0}, y = {end_1} ({face}) does not continue: the walls do not close</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}slab {k}: the curve recognised on {face} passes {distance} mm from it near x = {x}, y = {y}: not recognised</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}slab {k} (z {z_bottom} to {z_top}): the region recognised has area {found} mm² but the solid's section {expected} mm²: not recognised</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the terraced stock gave no solid</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the terraced solid is not valid</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}: no such file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}: cannot open as a FreeCAD document: {error}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{path}: no FreeCAD CAM Job in the document</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{path}: several CAM Jobs ({listed}): choose one with --cam-job NAME</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{path}: {value} CAM Job named {name} (its Jobs: {listed_or_none})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{os_fspath_path}: the CAM Job {Label} has no Stock: give the stock (--stock)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}: T{number}: the tool controllers {owners_number} and {Label} give tool {number_2} different tools ({value}, {tool_describe})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>feed has {size} values, {operation_label} {size_2} CL points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{Label}: {Label_2} has {count} commands now, the schedule {count_2}: the operation changed since its feeds were scheduled; schedule again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{source}: the document is open in FreeCAD: add the dressup there, or close it first</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{source}: FreeCAD's CAM workbench cannot be imported here, and the document saved without it would lose its CAM objects' behaviour</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where_line}: {name}: not a G-code command</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{source}: toolbit {Label} of shape {shape}: a shape the reader does not know; its kind is unknown</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name} must be a {expected}, got {type}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>side must be 'left' or 'right', not {side}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>centre, d and w must all be (N, 3), got {shape}, {shape_2} and {shape_3}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>engage is for straight edges; the tool has a helix angle of {helix} deg: use flute_engagement</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>origins {shape} and directions {shape_2} must have the same shape (N, 3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>tool axes must have shape (m, 3), got {shape}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>tool axis {axes_i_tolist} is zero or not finite</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>flute must be in 0..{self_flutes_1}, got {flute}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>immersion must be (start, end) in degrees, got {immersion}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>immersion {start}:{end} must be finite and not decreasing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>B-spline wall: dy/du vanishes on span {j}; a helical edge needs a wall with bounded curvature</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name} must have shape {shape}, got {shape_2}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}{value} is not a finite number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>line must have shape ({n},), got {shape}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>row {j} (line {line_j}): tool axis {axis_j_tolist} is not a unit vector</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cutting must have shape ({n},), got {shape}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>row {j} (line {line_j}): {name} must be positive, got {values_j}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>row {j} (line {line_j}): corner_radius must be within [0, radius {self_radius_j}], got {corner_j}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>row {j} (line {line_j}): the tool axis turns by 180° in one cutting move</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>rotation must be an orthonormal 3×3 matrix</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>tolerance must be positive, got {tolerance}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{n} edge lines are not a whole number of CL points of {p} angles</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>program_index must have shape ({m},), got {shape}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>spacing must be positive, got {spacing}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>centre, bound, move and floor must have one row per ball</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the balls must come in program order (move non-decreasing)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{m} CL points × {p} angles need {n} lines; got {n_rows} rows of intervals, {origins_shape_0} origins and {value} directions</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>an interval ends at l = {value} mm, beyond the flute length {flute_length} mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name} must have shape (K,) like rows, got {shape}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>rows must be non-decreasing within 0..{self_n_rows_1}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name} must be a number, got {type} {value}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name} must be a finite number, got {value}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name} must be positive, got {value}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name} must be at most {largest} in size, got {number}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name} must be an array of numbers, got {type}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name} must be an array of numbers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name} must have shape {expected}, got {shape}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}{list_index} is not a finite number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>flutes must be a whole number, got {flutes}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>helix must be within [-{MAX_HELIX}, {MAX_HELIX_2}] degrees (flat-end mills have helix angles up to about {MAX_HELIX_3}°), got {helix}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>corner_radius must be within [0, {value}] mm (half the diameter: a ball), got {corner}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>helical flutes on a corner are not computed: a tool with a corner radius needs straight flutes (helix 0)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>x_min ({x_min}) must be below x_max ({x_max})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>y_min ({y_min}) must be below y_max ({y_max})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a staircase needs at least one section</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>sections[{j}]: z_top {z_top_j} must be above base_z {base_z}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{size} sections need {z_top_size_1} walls, got {points_shape_0}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>wall_curves must be {count} Wall or SplineWall objects</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>sections[{j}].wall: x = {x_k} at y = {y_k} is not beyond {previous_name} ({previous_k}); walls must be ordered along +x inside [y_min, y_max]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>sections[{count}].wall: x = {previous_k} at y = {y_k} is not below x_max ({x_max})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a toolpath needs at least one CL point</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name} = {angles_i} must be within [-{limit}, {limit_2}] degrees</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>inclination = {inclination_i} must be within [-90, 90] degrees</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>inclination must be within (-90, 90) degrees, got {inclination}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>phi range {phi_start}:{phi_end} must not be decreasing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>phi range / phi step gives more than 10^6 angles</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>stock must be a Staircase or a TerracedStock, got {type}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>in_process_runs is for tools with a corner radius; a flat-end tool's edges are lines (in_process_lengths)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>origins and directions must both be (N, 3), got {shape} and {shape_2}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>slab {k}: an odd number of boundary crossings on a line</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>engage_terraced is for straight edges; the tool has a helix angle of {helix} deg</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name} must be a finite [x, y] point, got {value}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>line from {value} to {self_end_tolist} has no length</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>sweep must be non-zero and at most 2π in size, got {sweep}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>degree must be a whole number, got {degree}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>control must be (n, 2) with n ≥ degree + 1 = {degree_1}, got {shape}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>knots must have n + degree + 1 = {n_degree_1} values, got {shape}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>knots and control points must be finite</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>knots must be non-decreasing with knots[n] &gt; knots[degree]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>weights must be {n} positive numbers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a loop needs at least one curve</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>curves[{c}] must be a PlanLine, PlanArc or PlanSpline, got {type}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>curves[{c}] ends at {value} but the next curve starts {gap} mm away: a loop must be closed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>z_top {z_top} must be above z_bottom {z_bottom}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a slab needs one or more Loop objects</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a terraced stock needs at least one slab</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>slabs[{k}] must be a Slab, got {type}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>slabs[{k}] starts at z {z_bottom} but slabs[{k_1}] ends at {z_top}: slabs must be stacked without gaps</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not a plan curve: {type}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{face}: the B-spline runs over y {wall_span_y_0} to {wall_span_y_1}, not across the window {y_min} to {y_max}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a wall needs six [x, y] points, shape (6, 2); got {shape}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>wall points must be finite numbers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>wall points need six distinct y values, got {y_tolist}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>B-spline wall: {poles_shape_0} poles of degree {p} need {value} knots</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>B-spline wall: weights must be positive, one per pole</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>B-spline wall: y must be strictly monotone along the curve</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>grid {grid} mm gives {nx} x {ny} cells, more than {MAX_CELLS}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the Z-map samples a straight edge; the tool has a helix angle of {helix} deg</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the Z-map samples a flat-end mill's edge; the tool has a corner radius of {corner_radius} mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>edge_step {step} mm gives {p_n_1} samples per CL point, more than {MAX_SAMPLES}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name} must be a number, got {value}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name} must be a positive number of mm, got {value}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{prop} {path} is missing; using {moved}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no document: open or create a FreeCAD document first (FreeCAD.newDocument())</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> (property {prop})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>WallModel {walls} applies to a solid stock (.step, .stp, .brep, .brp, .FCStd), not to {value}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{source}: earlier moves of the program already removed all the material this operation's tool would meet (StockModel initial computes it against the stock as given)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{source}: the tool never touches the stock: no CL point of the pass engages it (are the toolpath and {value} in the same frame?)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{Label}: {value} (property {prop}).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>results in the document not read ({error})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{path}: not the results saved with the document (recomputed since?)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{path}: {size} instants, the object says {Instants}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{path}: no force columns, but Forces is on</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{path}: not computed against the stock model {StockModelUsed}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>results not restored ({error}); recompute to compute them</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{Label}: {role} must link an ABM {role_2} object</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>YWindow {YWindow} applies to a solid stock (.step, .stp, .brep, .brp, .FCStd), not to {value}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{Label}: YWindowMin ({low} mm) must be below YWindowMax ({high} mm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{value}: y window {low}..{high} mm misses the stock's y range {YMin}..{YMax} mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot write results: {error}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>create_engagement: unknown setting {unknown_0} (known: {join_SETTINGS})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>walls must be one of {WALL_CHOICES}, got {walls}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>y_window must be auto, whole, swept or (y0, y1), got {y_window}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{Label}: Engagement must link an ABM Engagement object</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{Label}: CLPoint {CLPoint} is not a CL point of {Label_2} (0..{len_rows_1})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{outlined} of the {count} earlier pieces near CL point {CLPoint} are moves of a tool with a corner: they are cut as the hull of the flat-end cylinder of their radius, which holds their volume, so the view shows less stock beside the corner than is left (the engine and validate take their exact volumes)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{Label}: the linked object has no shape</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{Label}: no stock source: set SourceObject or SourceFile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>walls must be one of {WALL_MODELS}, got {walls}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>wall_points must be one of {WALL_POINTS}, got {wall_points}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}: {size} rows are not the same number of angles for each of {m} CL points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}: rows are not in CL point order with {p} angles each</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}: not a results file: missing column {missing_0}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}: column {column}: unknown value {unknown_0}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}: force columns without {missing_0}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}: a force column has an empty or non-finite field</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{summary}: no column 'changed', but {name} has length_initial</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}: not a results archive ({error})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}: not a results archive: no {value}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{Label}: no toolpath file: set File</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{Label}: the CAM operation {operation} is not in the program of {Label_2} (inactive, or no moves)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{Label}: {path} holds several operations ({listing}): set the toolpath's Operation property to the number of the one to compute</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ktc must be positive, got {ktc}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unknown material {name} (known: {value})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>immersion {start}:{end} must satisfy 0 &lt;= start &lt; end &lt;= 180 degrees</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>flute {k_1}: {size} angles instead of {size_2}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>feed per tooth must be a number or have shape ({m},), got {np_shape_feed}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>feed per tooth must be finite and not negative at every CL point</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>lengths must have shape (Z, m, {size}), got {shape}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>rotation must have shape ({lengths_shape_1}, 3, 3), got {shape}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>lengths must be finite and not negative</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>rotation must have shape ({m}, 3, 3), got {shape}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name} must be EdgeIntervals (engine.intervals), got {type}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name} must have {n_rows} rows (CL points × angles), got {n_rows_2}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>rotation must have shape (m, 3, 3), got {shape}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>runs must hold one EdgeIntervals per flute ({flutes}), got {count}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>runs must be finite</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>coefficients must be Coefficients (forces.material(name), or your own), got {type}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>lengths_at and runs_at are for straight flutes only</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>give lengths_at or runs_at, not both</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the forces of a ball mill need each flute's engaged runs along its corner, not only its lengths of cut: lengths_at (such as the in-process stock's) cannot give them; pass runs_at instead</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the forces of a bull-nose mill need each flute's engaged runs along its corner, not only its lengths of cut: lengths_at (such as the in-process stock's) cannot give them; pass runs_at instead</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}: {stripped} is not a finite number (digits 0-9, optional sign, '.' and exponent)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}: {stripped} is not a number (digits 0-9, optional sign, '.' and exponent)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}: {number} is too large (at most {MAX_MAGNITUDE} in magnitude)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>an output path is empty; give a file name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{text}: is a folder; give a file name for the output</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{text}: is a symbolic link (to {os_readlink_text}); it would be replaced by the output: give the file's own path</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{text}: is {value}, not a file; it would be replaced by the output: give a file name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{text}: the file name is {count} bytes long; at most {longest} are allowed here</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>give the input file itself</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>give the stock file itself</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>give the toolpath file itself</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>give the job file itself</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>give the tool table file itself</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>give the machine file itself</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>give the work offsets file itself</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>give the results archive file itself</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}: cannot read: {value}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}: is {kind_mode}, not a file; {give}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a folder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a FIFO (named pipe)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a socket</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a character device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a block device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a special file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}: is {value}, not a file; give the input file itself</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>reading its {st_size} bytes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{os_fspath_path}: not UTF-8 text ({reason} at byte {start})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}: JSON nested {depth} deep; at most {MAX_JSON_DEPTH} levels are read</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}:{lineno}:{colno}: invalid JSON: {msg}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}:{value}: duplicate key {key} in one object</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}: expected a JSON object {...}, got {type}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}: must be a number, got {json_dumps_value}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}: an integer of {length} characters is too large (at most {MAX_MAGNITUDE} in magnitude)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}: must be a finite number, got {value}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}: unknown keys {names} (allowed: {allowed})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}: unknown key {names} (allowed: {allowed})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}: missing key {missing_0}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>every GOTO is a rapid move or a canned-cycle hole</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no GOTO record</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}:{last_line}: end of file and no cutting move ({reason})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}:{value}: GOTO: {detail}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>every feed per tooth written to an APT file must be positive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}: the chordal tolerance must be at least {MIN_TOLERANCE} mm, got {tolerance} mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}: the step along arcs and curves must be at least {MIN_TOLERANCE} mm, got {step} mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>module {__name__} has no attribute {name}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>give a coarser --tolerance or --step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>at least {more} CL points (the program's arcs and curves so far: {so_far})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{more} CL points (the program's arcs and curves so far: {so_far})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>interpolating it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{so_far} CL points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the circle's axis is zero</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the arc's start or end point lies on the circle's axis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}:{value}: tool axis (0, 0, 0) is zero</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{source}:{value}: tool {kind} is none of {join_KINDS}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>its axes are not unit vectors square to each other</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>it is a reflection, not a rotation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}:{start}: the record ends with the continuation mark '$' but the file ends before it is continued</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}:{line}: record {statement} has no major word before '/'</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the knots decrease</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the knots leave the curve no parameter range</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>knot {knot} is repeated more often than the degree {degree}: the curve breaks there</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{count} knots and {count_2} control points fit no B-spline of degree 1 to {MAX_DEGREE} (knots = control points + degree + 1, or the end knots written once: control points - degree + 1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{words}, degree {degree}: {reason}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>its knots give no curve ({listed})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the curve bends too sharply to be interpolated (its second derivative is not finite)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{source}:{first_line}: {self_label}: no cutting moves</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a milling tool the ABM engine does not compute yet (it computes flat-end, bull-nose and ball-end mills)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a turning program, not milling</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not a milling tool (the ABM engine computes flat-end, bull-nose and ball-end mills)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>operation {number}: {what}: {reason}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>operation {number}: no cutting moves ({holes} canned-cycle hole positions)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>operation {number}: no cutting moves</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{source}: operation {n}: the program has operations 1 to {count}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{source}: no operation: the file has no moves</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{count} milling operations; choose one with --operation N</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no operation the engine can run: {refusals}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{source}: {reason}; operations: {listing}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{value}; the record is skipped (the engine does not need it)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>argument {position} {arg} is not a number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>argument {position} is empty</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>argument {position} {arg} is not a number of at most {MAX_MAGNITUDE} in magnitude</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>argument {position} {arg} is neither a number nor a word</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>tool axis (0, 0, 0) is zero</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>takes x,y,z or x,y,z,i,j,k, got {count} number(s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the arc of the CIRCLE on line {circle_line} has no start point (no move before it)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the arc of the CIRCLE on line {circle_line}: {error}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the arc's {label} point is {off} mm off the circle of radius {radius} mm; the arc follows the points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>needs xc,yc,zc,i,j,k[,r], got {count} number(s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected numbers and one direction (CLOCKWISE or COUNTERCLOCKWISE), got {value}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the circle's axis (0, 0, 0) is zero</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a relative move needs a position before it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>takes d or dx,dy,dz, got {count} number(s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{word_upper}: a number above {MAX_MAGNITUDE} in magnitude</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a control point needs x,y,z[,w], got {count} number(s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the NURBS block has no CNTRL records</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a rational NURBS (control points of different weights) is not read</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the control points mix x,y,z and x,y,z,w</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the curve ({words}, degree {degree}) starts {gap} mm from the tool's position; the tool moves there in a straight line</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{join_record_args} gives no axis i,j,k; the axis is kept</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{join_record_args} gives no feed rate; the feed is kept</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>feed rate must be positive, got {numbers_0}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>surface speed {speed} {surface} for {value} gives no spindle speed in rpm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected MM or INCHES, got {join_record_args}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{join_record_args}: cutter compensation in the control; the CL points are taken as the tool tip's centre as written (an offset the control adds, such as wear, is left out)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{join_record_args} gives no diameter; not read</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>diameter must be positive, got {numbers_0}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{join_record_args} is no flute length; not read</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>needs 9 numbers (origin, X axis, Y axis), got {count}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>needs 12 numbers (a 3 x 4 matrix, row by row), got {count}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not a frame: {frame}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{join_record_args} gives no angle; the table is kept</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>angles read in radians, as CAMWorks writes them ({numbers_0} rad = {angle} deg)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the table's angle {angle}° is beyond ±{MAX_ANGLE}°</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no GOTO follows: the circle is not a move</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>operation {number} mixes feeds per minute and per revolution; its feeds are reported as written, each in its own kind</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{source}: only a CL (APT) program can be written back with new feeds</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>feed has {size} values, operation {number} {size_2} cutting CL points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>every feed written back must be positive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{source}:{line}: {op_label}: the feed {exact} {unit} rounds down to 0 at the {decimals} decimals this file writes its feeds with</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}: not a FreeCAD document (an FCStd is a zip file)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}: binary content, not a CL file (APT / CLSF text) or toolpath CSV</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}: empty file: no CL records and no toolpath CSV header</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}: unknown content: neither G-code, APT / CL records (WORD/...) nor a toolpath CSV header (x,y,z,...)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>frame must be one of {FRAMES}, got {frame}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>strings[{index}] = {value} holds a NUL character</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name} must be a 1-D array (n,), got shape {shape}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name} must be integers within int64, got dtype {dtype}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}:{number}: {value}: a comment '(' is not closed on its line</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}:{number}: ): a ')' closes no comment</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}:{number}: {match_group}: the number is above {MAX_MAGNITUDE} in magnitude</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}:{number}: {match_group}: O-words (subroutines, loops, conditions) are not read; only a program number alone on its line</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>parameters and expressions (#, [ ]) are not read</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>assignments (X=…) are not read: write a letter and a number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not a G-code word (a letter and a number)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a letter without a number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{letter} is needed: with G90.1 the centre is written whole</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>an R arc needs an end other than its start (a full circle is written with I J K)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>radius {abs_radius} mm does not fit: the ends are {length} mm apart, more than its diameter</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the centre is the start point</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the end is {last} mm from the centre, the start {first} mm: the arc does not fit (at most {RADIUS_TOLERANCE} mm apart)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>coordinate offsets set by the program (G92) are not read: use G54-G59 and an offsets table</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>subprogram calls are not read</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>subprogram returns are not read</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not a G code this reader knows (docs/GCODE.md)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{groups_group} and {text} in one block: both set the {group}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not an M code this reader knows (docs/GCODE.md)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the letter {letter} is not read (axes X Y Z and A B C; no U V W, E)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{letter} is given twice in one block</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{source}:{first_line}: operation {number} mixes feeds per minute and per revolution; its feeds are reported as written, each in its own kind</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>an incremental R (G91) from a height not known yet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>an incremental Z (G91) needs R first</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a hole whose X Y is not known yet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>L: the repeats must be a whole number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>an arc needs its end: the axis words of its plane (the start's, for a full circle)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>an axis word with no motion in force (G0, G1, G2, G3 or a hole cycle)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>needs a {letter} word</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a feed cannot be negative</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a surface speed with a tool of unknown diameter gives no spindle speed in rpm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no T word has selected a tool to load</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{code} loads tool {number}, and no tool table names it: give the tool table (--tool-table FILE: a LinuxCNC tool table, or the FreeCAD document that posted the program)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{code} loads tool {number}, which {tools_source} does not name (its tools: {known})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cutter compensation in the control; the moves are taken as the tool tip's path as written</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>L{kind} is not read (only L2: a work offset written whole)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>P{number}: the work coordinate systems are P1 (G54) to P9 (G59.3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>an incremental move (G91) from a {letter} position not known yet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a rotary axis word, and no machine file names the kinematics: give --machine FILE (docs/GCODE.md)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the machine {kinematics} has no {letter} axis (its rotary axes: {value})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the {letter} axis at {angles_letter}° is beyond ±{MAX_ANGLE}°</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>TCP off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the {kinematics} machine turns the tool about its pivot: the tool's length is needed (Z in the tool table, or tool_length in {source})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a feed move to a point whose {join_unknown} is not known yet (no {unknown_0} word since the start or the last G28 / G30)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>an arc that also turns a rotary axis is not read</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>an arc from a position not known yet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{normal} is along the normal of the plane G{plane}: it gives no centre</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>needs its centre (I J K) or its radius (R)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>P{value}: the turns must be a whole number from 1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>inverse time feed (G93) needs an F word on every feed move</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>hole cycles are read in the XY plane (G17) only</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}: missing key 'kinematics' (one of {join_KINEMATICS})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}: kinematics: expected one of {join_KINEMATICS}, got {kind}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}: tool_length: must not be negative, got {tool_length}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}: {key}: must be a list of {size} numbers (mm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}:{number}: expected 'parameter value' (LinuxCNC parameter file), got {raw_strip}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}:{number}: {fields_1}: not a number of at most {MAX_MAGNITUDE} in magnitude</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}: {key} is not a work coordinate system ({join_SYSTEMS})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}: {key}: must be [x, y, z] or [x, y, z, a, b, c] (mm, degrees)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}: --{option_replace} applies to {words_kinds_0}, and this file is {value}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a CL file or toolpath CSV</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the program works in inches, and {files} {value} lengths in the machine's units, which LinuxCNC does not write in the file: say them (--machine-units mm or inch)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}:{number}: {shown}: not a tool table word (T P X Y Z A B C U V W D I J Q and a number)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}:{number}: {letter}: given twice on the line</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}:{number}: {match_group}: the number is above {MAX_MAGNITUDE}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}:{number}: no T word: each line of a tool table describes tool T&lt;n&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}:{number}: T{tool}: the table describes tool {tool_2} twice</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>toolpath has {count} CL points, the engagement {value}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}: empty file; expected a results header {value},...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}:1: a column named twice in the header</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}:{number}: expected {count} fields, got {count_2}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}:{number}: a line of {count} characters; at most {MAX_LINE} are read</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}:{number}: a field of {longest} characters; at most {MAX_FIELD} are read</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}:{row}: column {column}: {field} is not a valid int</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>chunk columns {list_columns} differ from the first chunk's {value}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>column {key}: {dtype} {shape}, expected {dtype_2} (rows,)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>chunk columns {list_columns} differ from the first chunk's {list_self_dtypes}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}: not an ABM results archive (no 'format' member saying {FORMAT})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}: not a results archive: no array {prefix_missing_0}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}: unknown array {prefix_unknown_0} in a results archive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}: not a results archive (an .npz file is a zip file, and this is not one)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}: not a results archive: {count} members (at most {MAX_MEMBERS})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}: not a results archive: damaged ({error})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}: not a results archive: member {filename} is not an .npy array</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}: not a results archive: member {filename}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where} is compressed; the archives written here store their arrays uncompressed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where} claims {file_size} bytes in a file of {size}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>npy version {version}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}: not an .npy header ({type}: {error})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}: holds {dtype} values, which are not read (no pickled objects)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}: not a results archive: array {value}: shape {shape}; a results array is 1-D or a scalar</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}: shape {shape} of {dtype} needs {value} bytes; the member holds {body}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}: cut short</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}: array {key}: {dtype} of shape {shape}, expected {dtype_2} of shape {rows}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}: array {key}: no labels ({LABELS_column}: a 1-D str array)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}: array {key}: row {bad_0}: code {values_bad_0} has no label (labels 0..{names_size_1})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}: array {key}: row {bad_0}: {values_bad_0} is too large (at most {MAX_MAGNITUDE} in magnitude)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}: missing key 'format' (a staircase file starts with "format": "{FORMAT}")</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}: format must be {FORMAT}, got {value}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}: units must be 'mm', got {value}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}: sections must be a non-empty list of sections, got {value}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}: sections[{j}]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}: expected an object {"z_top": ...}, got {value}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}: the first section starts at x_min and must not have a wall</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}: a wall needs six [x, y] points, got {got}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}[{k}]: expected an [x, y] pair, got {json_dumps_point}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>zip member {name} reserved twice</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>zip member {name}: size {size} &lt; 0</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>zip member {value}: {value_2} bytes given, {size} reserved</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>zip member {value}: {written} of {size} bytes written</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}: must be {what}, got {json_dumps_value}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}: expected an [x, y] pair, got {json_dumps_value}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}: expected a curve object {"type": ...}, got {json_dumps_data}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}.type: must be "line", "arc" or "spline", got {json_dumps_kind}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}.face: must be a string, got {json_dumps_face}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a list of numbers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a list of [x, y] points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}.degree: must be a whole number, got {value}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a non-empty list of slabs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}: slabs[{k}]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}: expected an object {"z_top": ..., "loops": [...]}, got {json_dumps_slab}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a non-empty list of loops</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a non-empty list of curves</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}: encloses no area ({area} mm²): a loop must bound a region</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}.loops[{i}]: the same contour as loops[{seen_key}]; by the even-odd rule the two cancel and bound no region</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}: empty file; expected a header such as {_EXAMPLE}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}: no CL points: the file has a header but no rows</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}:{numbers_bad_0}: column {column}: {values_bad_0} is not a whole number of at least {low}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{source}: operation {operation}: the file has one pass (no operation column)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{source}: {count} operations; choose one with --operation N; operations: {listing}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{source}: no operation {operation}; the file has operations {value}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}: a line of {count} characters; at most {MAX_LINE} are read</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}: not a CSV line: {error}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}: a field of {longest} characters; at most {MAX_FIELD} are read</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}: duplicate column {duplicate_0}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}: unknown columns {names}; known columns: {listed}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}: unknown column {names}; known columns: {listed}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}: give the tool orientation as theta_a, theta_b or as i, j, k, not both</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}: missing column {missing_0} of the {label} ({join_group})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{where}: expected {count} fields ({join_header}), got {count_2}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>is empty: give CL indices such as 0,27,80-100</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>item {position} {item} is not a CL index or a range A-B (such as 0,27,80-100)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>item {position} {item} runs backwards (write {high}-{low})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>item {position}: CL point {index} is not in the pass (0..{m_1})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>must be a positive whole number of CL points, got {every}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{source}:{line}: {word}: record not understood, ignored ({count} times)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{source}:{line}: {word}: record not understood, ignored</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{source}: records that carry nothing the engine needs, ignored: {records}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}: unknown stock file type; expected .json, .step, .stp, .brep, .brp or .FCStd</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}: y window {y_window_0}..{y_window_1} mm misses the stock's y range {YMin}..{YMax} mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}: the stock is 2.5D along ({value}) in the part, {angle}° from the z of the operation's frame: the operation must be computed in its frame turned to the stock (abm engage, validate and schedule do)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}: the operation's frame is turned against the part's, and a stock JSON can only be moved, not turned: give the stock as a solid (STEP, BREP, FCStd)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}: {key}: must be a string</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{name}: {key}: must be [start, end] in degrees, e.g. [0, 180]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{what}: its {holes} canned-cycle holes are not in the in-process stock (holes are not swept)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{what}: the file gives no diameter, so its {count} cutting moves are not in the in-process stock</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the tool's length in the file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the program's extent</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{what}: the file gives no flute length: in the in-process stock it removes material with its whole length, {length} mm ({whence})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{what}: swept as a flat-end cylinder of its diameter in the in-process stock</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{source}: the in-process stock cannot sweep the program: {error}; the stock model initial (the stock as given) can</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{toolpath}: give the stock (--stock): only a FreeCAD CAM Job's document (FCStd) holds its own</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>is required for the forces: give a material or the coefficients ktc, krc and kac</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>applies to a solid stock (.step, .stp, .brep, .brp, .FCStd), not to {stock}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>y window must be whole, swept or (y0, y1), got {window}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected CL indices such as 0,22,40, got {text}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CL point {index} is not in the pass (0..{m_1})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>must be a number, got {json_dumps_value}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>must be a number, got {value}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>must be a finite number, got {number}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>must be at most {MAX_MAGNITUDE} in size, got {number}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>must be a whole number, got {number}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>must be {self_range_text}, got {number}{shown}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>must not be below the first rotation angle {start}°, got {end}°</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>gives more than {MAX_ANGLES} angles from {start}° to {end}°; take a larger step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>must be at most half the tool diameter ({value} mm: a ball-end mill), got {corner} mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>must be above the start of immersion {low}°, got {high}°</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{source} gives {name} {file_value}, {where} {other}: using {file_value_2}, the value the toolpath was made for</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>is {helix}°, but helical flutes on a corner are not computed: a tool with a corner radius ({corner} mm) needs straight flutes (helix 0)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>needs a staircase stock: the helix solver does not take a general 2.5D stock yet (use straight flutes, helix 0)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>must be one of {value}, got {stock_model}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a helical tool</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the Z-map method</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>in-process is not available with {missing} yet: use initial</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the in-process stock is not available with {missing} yet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>must be a positive number of mm, got {sweep_tolerance}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the in-process stock sweeps the program's {curved} arcs and curves as the chords between their CL points, each within {tolerance} mm of the arc (at most {step} mm long)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>give a larger --sweep-tolerance or --stock-model initial (the stock as given)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>give --stock-model initial (the stock as given)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the in-process stock</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the in-process stock would sweep the program's cutting moves into {value} pieces and bounding balls</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>its sweep ({value} pieces, {count_text_balls} bounding balls)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>give a larger --phi-step or a shorter --phi-range</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{count_text_m} CL points x {count_text_p} angles = {value} instants</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the {command} run</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>would check {many} CL points x {angles} angles x {flutes} flutes = {total} instants</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>would check {many} CL points x {angles} angles = {total} instants</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the boolean reference</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>check fewer CL points (--check, --check-every) or give a larger --phi-step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{grid} mm gives the stock {cells} Z-map cells, more than the Z-map holds ({MAX_CELLS}): give a larger --grid</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the Z-map's {cells} cells</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>give a larger --grid</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>an edge step of {edge_step} mm samples the {length} mm flute at {along} points, {p} angles x {along_2} = {each} per CL point, more than the Z-map takes ({MAX_SAMPLES}): give a larger {option} or --phi-step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>an edge step of {edge_step} mm samples the {length} mm flute at {along} points (the edge step is the grid's unless --edge-step is given), {p} angles x {along_2} = {each} per CL point, more than the Z-map takes ({MAX_SAMPLES}): give a larger {option} or --phi-step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the Z-map would sample {samples} edge points ({m} CL points x {p} angles x {along} along the edge)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the Z-map would sample {samples} edge points ({m} CL points x {p} angles x {along} along the edge) (the edge step is the grid's unless --edge-step is given)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>give a larger {option} or --phi-step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the Z-map baseline needs a staircase stock; {source} is a general 2.5D stock</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{toolpath}: the tool never touches the stock: no CL point of the pass engages it (are the toolpath and {stock} in the same frame?)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{path}: cannot write: {folder} is not a folder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{path}: written twice (as {seen_key} too); choose another name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{path}: is an input and would be overwritten by an output</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>must be a folder, and {report} is a file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{report}: folder holds files but no report (index.html); it would be replaced as a whole: choose a new or empty folder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> and {len_foreign_1} more</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{report}: folder holds {foreign_0}{more}, which no report writes; an older report there is replaced as a whole, which would delete it: choose a new or empty folder, or move it away</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{inside_0}: lies inside the report folder {report}, which is replaced as a whole</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>must end in .FCStd, got {fcstd}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>applies to the Z-map method (zmap), not to abm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>must be 0 (all cores) or a positive number of processes, got {workers}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected a Dask scheduler address such as tcp://127.0.0.1:8786, got {scheduler}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>applies to the abm method: the Z-map updates its stock CL point by CL point</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>must be a positive number of mm, got {value}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>needs the abm method</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the Z-map baseline samples a flat-end mill's edge; this ball mill (corner radius {corner} mm) is computed by the ABM engine only</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the Z-map baseline samples a flat-end mill's edge; this bull-nose mill (corner radius {corner} mm) is computed by the ABM engine only</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the Z-map method: {error}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{toolpath}: earlier moves of the program already removed all the material this operation's tool would meet (--stock-model initial computes it against the stock as given)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>must be 1..{flutes} (the tool has {flutes_2} flutes), got {flute}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>is not available with helical edges (--helix, --flute) yet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{toolpath}: {model_note}; validating against the stock as given</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{stock}: the boolean reference cannot build the stock's solid ({type}: {error})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>in-process is not available for validate with --flute (the helix boolean) yet: use initial</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>must be a positive number, got {limit}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>must be a positive feed per tooth (mm), got {min_feed}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>must end in .apt, .cls, .csv or (for a FreeCAD CAM Job) .FCStd, got {out}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a FreeCAD document (.FCStd) is written for a FreeCAD CAM Job's program only, not for {toolpath}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{model_note}: the feeds are scheduled against the stock as given</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> and {value} more</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{count} CL points cannot keep the force at or under {limit} N at any feed from the minimum feed up; they get the minimum feed: {shown}{more}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{count} CL points cannot keep the area at or under {limit} mm² at any feed from the minimum feed up; they get the minimum feed: {shown}{more}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{toolpath}: {operation_label}: the dressup's feeds are per minute and need a spindle speed (its tool controller's, or give the spindle speed)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{source}: {operation_label}: feeds per minute need a spindle speed (SPINDL, or give the spindle speed)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{why}: {shown} (more than the {most} a run takes without confirmation): {remedy}, or give --allow-large to run it anyway</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{why}: {shown} (more than the {most} a run takes without confirmation): give --allow-large to run it anyway</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{why}: {what} would need about {size} of memory, and this process may use {free}: {remedy}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{why}: {what} would need about {size} of memory, and this process may use {free}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{why}: {os_fspath_path} would take about {size_text_needed}, and {folder} has {size_text_space} free; give --allow-large to try anyway</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>job {job}, CL points {start}..{last}: {name}: {cause}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CL points {start}..{last}: {name}: {cause}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>workers must be a whole number &gt;= 0 (0 = all cores), got {workers}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>chunk of CL points {start}..{start_n_1}: {name} differs from the first chunk's</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{filled} of {m} CL points added</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>could not start {workers} worker processes ({value}; a limit on processes?)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Dask scheduler address must look like tcp://host:port, got {address}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Dask scheduler {address}: no answer within {SCHEDULER_TIMEOUT} s ({type}: {error})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>kind must be one of {LIMITS}, got {kind}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the force limit must be a positive number, got {limit}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the area limit must be a positive number, got {limit}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the minimum feed must be finite and not negative</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>feeds in {unit} need the spindle speed to give a feed per tooth</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a reference for a tool with a corner must give lep_xyz and uep_xyz</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>reference[{name}] must have shape {m_p}, got {shape}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no CL point of the pass engages the stock</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cls must be distinct CL indices in 0..{m_1}, at least one; got {list_cls}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>flute {flute} was not checked; checked: {list_self_flutes}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>flutes must be indices in 0..{tool_flutes_1}, got {flutes}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no CL point of the pass engages the stock with the checked flutes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>stopped with {value} of {count} tasks unanswered</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a worker process ended without answering task {index} (exit code {exitcode})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the worker process ended without answering (exit code {exitcode})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>positive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>above {low}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>at least {low}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>below {high}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>at most {high}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>within {interval}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>is required: the toolpath file does not give it</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>ABM_parameters</name>
    <message>
        <source>tool diameter</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>number of flutes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>flute length</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>corner radius</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>helix angle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>feed per tooth</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>spindle speed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>inclination angle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>first rotation angle φ</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>last rotation angle φ</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>step of φ</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ktc (tangential cutting coefficient)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Krc (radial cutting coefficient)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Kac (axial cutting coefficient)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Kte (tangential edge coefficient)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Kre (radial edge coefficient)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Kae (axial edge coefficient)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>start of immersion</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>end of immersion</source>
        <translation type="unfinished"></translation>
    </message>
</context>
</TS>
