<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de">
<context>
    <name>ABM</name>
    <message>
        <source>diameter</source>
        <translation>Durchmesser</translation>
    </message>
    <message>
        <source>flutes</source>
        <translation>Schneidenzahl</translation>
    </message>
    <message>
        <source>flute length</source>
        <translation>Schneidenlänge</translation>
    </message>
    <message>
        <source>feed per tooth</source>
        <translation>Vorschub pro Zahn</translation>
    </message>
    <message>
        <source>select a FreeCAD CAM Job, or operations of one</source>
        <translation>einen FreeCAD-CAM-Job oder Operationen eines Jobs auswählen</translation>
    </message>
    <message>
        <source>no operation has moves</source>
        <translation>keine Operation hat Bewegungen</translation>
    </message>
    <message>
        <source>{job}: no operation the engine computes ({reasons})</source>
        <translation>{job}: keine Operation, die der Rechenkern berechnet ({reasons})</translation>
    </message>
    <message>
        <source>{operation}: no tool controller</source>
        <translation>{operation}: kein Werkzeugcontroller</translation>
    </message>
    <message>
        <source>{operation}: {controller} gives no {value} (set it in its toolbit, or in Edit → Preferences → ABM)</source>
        <translation>{operation}: {controller} gibt keinen Wert für {value} an (im Toolbit festlegen oder unter Bearbeiten → Einstellungen → ABM)</translation>
    </message>
    <message>
        <source>{operation}: not in the program of {job} (inactive, or no moves)</source>
        <translation>{operation}: nicht im Programm von {job} (inaktiv oder ohne Bewegungen)</translation>
    </message>
    <message>
        <source>Import stock</source>
        <translation>Rohteil importieren</translation>
    </message>
    <message>
        <source>Import toolpath</source>
        <translation>Werkzeugbahn importieren</translation>
    </message>
    <message>
        <source>millimetres (mm)</source>
        <translation>Millimeter (mm)</translation>
    </message>
    <message>
        <source>inches (in)</source>
        <translation>Zoll (in)</translation>
    </message>
    <message>
        <source>{program} works in inches, and the tool table {table} gives its lengths in the machine's units, which LinuxCNC does not write in the table. Which units is the machine set up in (LINEAR_UNITS of its INI file)? (the toolpath's ToolTableUnits; change it later in the property editor)</source>
        <translation>{program} arbeitet in Zoll, und die Werkzeugtabelle {table} gibt ihre Längen in den Einheiten der Maschine an, die LinuxCNC nicht in die Tabelle schreibt. In welchen Einheiten ist die Maschine eingerichtet (LINEAR_UNITS ihrer INI-Datei)? (ToolTableUnits der Werkzeugbahn; später im Eigenschafteneditor änderbar)</translation>
    </message>
    <message>
        <source>stock</source>
        <translation>Rohteil</translation>
    </message>
    <message>
        <source>stocks</source>
        <translation>Rohteile</translation>
    </message>
    <message>
        <source>toolpath</source>
        <translation>Werkzeugbahn</translation>
    </message>
    <message>
        <source>toolpaths</source>
        <translation>Werkzeugbahnen</translation>
    </message>
    <message>
        <source>engagement</source>
        <translation>Eingriff</translation>
    </message>
    <message>
        <source>engagements</source>
        <translation>Eingriffe</translation>
    </message>
    <message>
        <source>Tool table of {file}</source>
        <translation>Werkzeugtabelle zu {file}</translation>
    </message>
    <message>
        <source>Tool table (*.tbl *.FCStd);;All files (*)</source>
        <translation>Werkzeugtabelle (*.tbl *.FCStd);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>{file} holds several operations: choose the one to compute (the toolpath's Operation; change it later in the property editor)</source>
        <translation>{file} enthält mehrere Operationen: die zu berechnende wählen (Operation der Werkzeugbahn; später im Eigenschafteneditor änderbar)</translation>
    </message>
    <message>
        <source>{count} {nouns} selected: select one {noun}</source>
        <translation>{count} {nouns} ausgewählt: nur ein Objekt vom Typ {noun} auswählen</translation>
    </message>
    <message>
        <source>no {noun} in the document: import one first</source>
        <translation>kein Objekt vom Typ {noun} im Dokument: zuerst eines importieren</translation>
    </message>
    <message>
        <source>{count} {nouns} in the document: select the one to use</source>
        <translation>{count} {nouns} im Dokument: das zu verwendende auswählen</translation>
    </message>
    <message>
        <source>Validating {label} at {count} CL points against booleans…</source>
        <translation>{label} wird an {count} CL-Punkten gegen boolesche Operationen validiert…</translation>
    </message>
    <message>
        <source>Computing model test 1…</source>
        <translation>Modelltest 1 wird berechnet…</translation>
    </message>
    <message>
        <source>Reading the toolpath…</source>
        <translation>Werkzeugbahn wird gelesen…</translation>
    </message>
    <message>
        <source>Computing the engagement of the CAM job…</source>
        <translation>Eingriff des CAM-Jobs wird berechnet…</translation>
    </message>
    <message>
        <source>Validate engagement</source>
        <translation>Eingriff validieren</translation>
    </message>
    <message>
        <source>CL points to check (all, or e.g. 0,22,40; about 1 s each):</source>
        <translation>Zu prüfende CL-Punkte (all oder z. B. 0,22,40; je etwa 1 s):</translation>
    </message>
    <message>
        <source>{label}: compute it first (recompute the document)</source>
        <translation>{label}: zuerst berechnen (Dokument neu berechnen)</translation>
    </message>
    <message>
        <source>{file}: not imported: it works in inches, and the units of the tool table {table} were not said</source>
        <translation>{file}: nicht importiert: es arbeitet in Zoll, und die Einheiten der Werkzeugtabelle {table} wurden nicht angegeben</translation>
    </message>
    <message>
        <source>not for the engine</source>
        <translation>nicht für den Rechenkern</translation>
    </message>
    <message>
        <source>Folder for the validation report</source>
        <translation>Ordner für den Validierungsbericht</translation>
    </message>
    <message>
        <source>{label}: validation report {page}</source>
        <translation>{label}: Validierungsbericht {page}</translation>
    </message>
    <message>
        <source>{file}: not imported: its program loads tools by number, and no tool table was chosen (a LinuxCNC tool table, or the FreeCAD document that posted the program)</source>
        <translation>{file}: nicht importiert: das Programm lädt Werkzeuge per Nummer, und es wurde keine Werkzeugtabelle gewählt (eine LinuxCNC-Werkzeugtabelle oder das FreeCAD-Dokument, aus dem das Programm erzeugt wurde)</translation>
    </message>
    <message>
        <source>validation cancelled: nothing written</source>
        <translation>Validierung abgebrochen: nichts geschrieben</translation>
    </message>
    <message>
        <source>length of cut</source>
        <translation>Schnittlänge</translation>
    </message>
    <message>
        <source>cut area</source>
        <translation>Spanungsquerschnitt</translation>
    </message>
    <message>
        <source>resultant cutting force</source>
        <translation>resultierende Schnittkraft</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <source>top</source>
        <translation>Deckfläche</translation>
    </message>
    <message>
        <source>straight wall</source>
        <translation>gerade Wand</translation>
    </message>
    <message>
        <source>curved wall</source>
        <translation>gekrümmte Wand</translation>
    </message>
    <message>
        <source>flute end</source>
        <translation>Schneidenende</translation>
    </message>
    <message>
        <source>stock side</source>
        <translation>Rohteilseite</translation>
    </message>
    <message>
        <source>immersion end</source>
        <translation>Eingriffsende</translation>
    </message>
    <message>
        <source>bottom</source>
        <translation>Boden</translation>
    </message>
    <message>
        <source>flute start</source>
        <translation>Schneidenanfang</translation>
    </message>
    <message>
        <source>machined</source>
        <translation>bearbeitet</translation>
    </message>
    <message>
        <source>peak |F| over φ</source>
        <translation>Spitze |F| über φ</translation>
    </message>
    <message>
        <source>mean |F| over φ</source>
        <translation>Mittel |F| über φ</translation>
    </message>
    <message>
        <source>in-process stock: {count} CL points changed by earlier moves of the program</source>
        <translation>Zwischenrohteil: {count} CL-Punkte durch frühere Bewegungen des Programms verändert</translation>
    </message>
    <message>
        <source>stock as given</source>
        <translation>Rohteil wie gegeben</translation>
    </message>
    <message>
        <source>changed by earlier moves: longest length of cut in-process {now} mm / initial {before} mm</source>
        <translation>durch frühere Bewegungen verändert: größte Schnittlänge am Zwischenrohteil {now} mm / am Ausgangsrohteil {before} mm</translation>
    </message>
    <message>
        <source>ABM engagement</source>
        <translation>ABM-Eingriff</translation>
    </message>
    <message>
        <source>Engagement</source>
        <translation>Eingriff</translation>
    </message>
    <message>
        <source>Forces</source>
        <translation>Kräfte</translation>
    </message>
    <message>
        <source>; peak force {force} N</source>
        <translation>; Kraftspitze {force} N</translation>
    </message>
    <message>
        <source>length of
cut (mm)</source>
        <translation>Schnitt-
länge (mm)</translation>
    </message>
    <message>
        <source>cut area
(mm²)</source>
        <translation>Spanungs-
fläche (mm²)</translation>
    </message>
    <message>
        <source>h (mm)</source>
        <translation>h (mm)</translation>
    </message>
    <message>
        <source>CL {cl} over the tool rotation angle φ</source>
        <translation>CL {cl} über dem Drehwinkel φ des Werkzeugs</translation>
    </message>
    <message>
        <source>φ (deg)</source>
        <translation>φ (Grad)</translation>
    </message>
    <message>
        <source>CL point</source>
        <translation>CL-Punkt</translation>
    </message>
    <message>
        <source>mm</source>
        <translation>mm</translation>
    </message>
    <message>
        <source>Pass progression</source>
        <translation>Verlauf über die Bahn</translation>
    </message>
    <message>
        <source>force (N)</source>
        <translation>Kraft (N)</translation>
    </message>
    <message>
        <source>CL {cl}: peak |F| {peak} N, mean {mean} N</source>
        <translation>CL {cl}: Spitze |F| {peak} N, Mittel {mean} N</translation>
    </message>
    <message>
        <source>Resultant force along the pass</source>
        <translation>Resultierende Kraft entlang der Bahn</translation>
    </message>
    <message>
        <source>not changed by earlier moves</source>
        <translation>nicht durch frühere Bewegungen verändert</translation>
    </message>
    <message>
        <source>Colour by</source>
        <translation>Einfärben nach</translation>
    </message>
    <message>
        <source>&lt;b&gt;{label}&lt;/b&gt;: {m} CL points × {p} angles φ; depth of cut {low}–{high} mm</source>
        <translation>&lt;b&gt;{label}&lt;/b&gt;: {m} CL-Punkte × {p} Winkel φ; Schnitttiefe {low}–{high} mm</translation>
    </message>
    <message>
        <source>no forces: turn Cutting forces on in the engagement's task panel and recompute</source>
        <translation>keine Kräfte: Schnittkräfte in der Aufgabenansicht des Eingriffs einschalten und neu berechnen</translation>
    </message>
    <message>
        <source>depth of cut</source>
        <translation>Schnitttiefe</translation>
    </message>
    <message>
        <source>max length of cut</source>
        <translation>größte Schnittlänge</translation>
    </message>
    <message>
        <source>engagement segment (UEP surface)</source>
        <translation>Eingriffssegment (UEP-Fläche)</translation>
    </message>
    <message>
        <source>{label}: no results (recompute it)</source>
        <translation>{label}: keine Ergebnisse (neu berechnen)</translation>
    </message>
    <message>
        <source>No engagement: select one and use Inspect engagement</source>
        <translation>Kein Eingriff: einen auswählen und „Eingriff untersuchen“ verwenden</translation>
    </message>
    <message>
        <source>CL {cl}: depth of cut {depth} mm, max length of cut {length} mm; segments</source>
        <translation>CL {cl}: Schnitttiefe {depth} mm, größte Schnittlänge {length} mm; Segmente</translation>
    </message>
    <message>
        <source>CL {cl}: the tool does not engage the stock here</source>
        <translation>CL {cl}: das Werkzeug greift hier nicht in das Rohteil ein</translation>
    </message>
    <message>
        <source>segment: UEP surface</source>
        <translation>Segment: UEP-Fläche</translation>
    </message>
    <message>
        <source>UEP surface of the engagement segment:</source>
        <translation>UEP-Fläche des Eingriffssegments:</translation>
    </message>
    <message>
        <source>In-process stock at CL {cl}</source>
        <translation>Zwischenrohteil bei CL {cl}</translation>
    </message>
    <message>
        <source>In-process stock (computing CL {cl}…)</source>
        <translation>Zwischenrohteil (CL {cl} wird berechnet…)</translation>
    </message>
    <message>
        <source>Computing the in-process stock of {label} at CL {cl}…</source>
        <translation>Zwischenrohteil von {label} bei CL {cl} wird berechnet…</translation>
    </message>
    <message>
        <source>In-process stock at CL {cl} (program row {row}): {volume} mm³ removed by earlier moves near it, in {seconds} s</source>
        <translation>Zwischenrohteil bei CL {cl} (Programmzeile {row}): {volume} mm³ durch frühere Bewegungen in der Nähe abgetragen, in {seconds} s</translation>
    </message>
    <message>
        <source>Show in-process stock: inspect an engagement first (Inspect engagement), then choose its CL point in the dock</source>
        <translation>Zwischenrohteil zeigen: zuerst einen Eingriff untersuchen („Eingriff untersuchen“), dann seinen CL-Punkt im Dock wählen</translation>
    </message>
    <message>
        <source>In-process stock at CL {cl}: cancelled</source>
        <translation>Zwischenrohteil bei CL {cl}: abgebrochen</translation>
    </message>
    <message>
        <source>Tool diameter</source>
        <translation>Werkzeugdurchmesser</translation>
    </message>
    <message>
        <source>Flutes</source>
        <translation>Schneiden</translation>
    </message>
    <message>
        <source>Flute length</source>
        <translation>Schneidenlänge</translation>
    </message>
    <message>
        <source>Feed per tooth</source>
        <translation>Vorschub pro Zahn</translation>
    </message>
    <message>
        <source>Inclination α</source>
        <translation>Neigung α</translation>
    </message>
    <message>
        <source>φ step</source>
        <translation>φ-Schritt</translation>
    </message>
    <message>
        <source>ABM</source>
        <translation>ABM</translation>
    </message>
    <message>
        <source>New engagement: tool and cut (0: ask)</source>
        <translation>Neuer Eingriff: Werkzeug und Schnitt (0: nachfragen)</translation>
    </message>
    <message>
        <source>Results</source>
        <translation>Ergebnisse</translation>
    </message>
    <message>
        <source>beside the document</source>
        <translation>neben dem Dokument</translation>
    </message>
    <message>
        <source>Validation reports in</source>
        <translation>Validierungsberichte in</translation>
    </message>
    <message>
        <source>Colour map</source>
        <translation>Farbskala</translation>
    </message>
    <message>
        <source>one per core</source>
        <translation>einer pro Kern</translation>
    </message>
    <message>
        <source>Processes computing the boolean reference of a validation, beside FreeCAD's own (which stays free to draw): 0 one per core</source>
        <translation>Prozesse, die die Boolesche Referenz einer Validierung berechnen, neben FreeCADs eigenem (der frei zum Zeichnen bleibt): 0 einer je Kern</translation>
    </message>
    <message>
        <source>Validation workers</source>
        <translation>Validierungsprozesse</translation>
    </message>
    <message>
        <source>Program CL {index} of {count}: operation {number}{name}, {tool}, its CL {cl}</source>
        <translation>Programm-CL {index} von {count}: Operation {number}{name}, {tool}, ihr CL {cl}</translation>
    </message>
    <message>
        <source>Every CL point of the whole program, operation after operation: moved into another operation, the dock goes there once it rests</source>
        <translation>Alle CL-Punkte des ganzen Programms, Operation für Operation: in eine andere Operation bewegt, wechselt das Dock dorthin, sobald der Regler ruht</translation>
    </message>
    <message>
        <source>Choose operation</source>
        <translation>Operation wählen</translation>
    </message>
    <message>
        <source>Program</source>
        <translation>Programm</translation>
    </message>
    <message>
        <source>no engagement of operation {number} of {job}: select the Job and use Engage CAM job</source>
        <translation>kein Eingriff für Operation {number} von {job}: den Job auswählen und „CAM-Job eingreifen lassen“ verwenden</translation>
    </message>
    <message>
        <source>not computed: {reason}</source>
        <translation>nicht berechnet: {reason}</translation>
    </message>
    <message>
        <source>going there once the slider rests…</source>
        <translation>wird angezeigt, sobald der Regler ruht…</translation>
    </message>
    <message>
        <source>Computing operation {number} of the program…</source>
        <translation>Operation {number} des Programms wird berechnet…</translation>
    </message>
    <message>
        <source>not shown: {reason}</source>
        <translation>nicht angezeigt: {reason}</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Diameter</source>
        <translation>Durchmesser</translation>
    </message>
    <message>
        <source>Corner radius</source>
        <translation>Eckenradius</translation>
    </message>
    <message>
        <source>Helix angle β</source>
        <translation>Drallwinkel β</translation>
    </message>
    <message>
        <source>Spindle speed (rpm)</source>
        <translation>Drehzahl (1/min)</translation>
    </message>
    <message>
        <source>φ start</source>
        <translation>φ Anfang</translation>
    </message>
    <message>
        <source>φ end</source>
        <translation>φ Ende</translation>
    </message>
    <message>
        <source>y window from</source>
        <translation>y-Fenster von</translation>
    </message>
    <message>
        <source>y window to</source>
        <translation>y-Fenster bis</translation>
    </message>
    <message>
        <source>Tool</source>
        <translation>Werkzeug</translation>
    </message>
    <message>
        <source>Cut</source>
        <translation>Schnitt</translation>
    </message>
    <message>
        <source>Tool rotation angles φ</source>
        <translation>Drehwinkel φ des Werkzeugs</translation>
    </message>
    <message>
        <source>Stock model</source>
        <translation>Rohteilmodell</translation>
    </message>
    <message>
        <source>Cutting forces</source>
        <translation>Schnittkräfte</translation>
    </message>
    <message>
        <source>Immersion from</source>
        <translation>Eingriff von</translation>
    </message>
    <message>
        <source>Immersion to</source>
        <translation>Eingriff bis</translation>
    </message>
    <message>
        <source>Engagement: tool and cut</source>
        <translation>Eingriff: Werkzeug und Schnitt</translation>
    </message>
    <message>
        <source>Stock</source>
        <translation>Rohteil</translation>
    </message>
    <message>
        <source>Toolpath</source>
        <translation>Werkzeugbahn</translation>
    </message>
    <message>
        <source>Wall model</source>
        <translation>Wandmodell</translation>
    </message>
    <message>
        <source>y window</source>
        <translation>y-Fenster</translation>
    </message>
    <message>
        <source>Computing the engagement…</source>
        <translation>Eingriff wird berechnet…</translation>
    </message>
    <message>
        <source>Fixed by the toolpath file, the values it was made for:</source>
        <translation>Durch die Werkzeugbahndatei festgelegt, die Werte, für die sie erstellt wurde:</translation>
    </message>
    <message>
        <source>Input files missing: choose the folder that holds them</source>
        <translation>Eingabedateien fehlen: den Ordner wählen, der sie enthält</translation>
    </message>
    <message>
        <source>Missing:</source>
        <translation>Fehlend:</translation>
    </message>
    <message>
        <source>{document}: input files missing, not re-pointed:</source>
        <translation>{document}: Eingabedateien fehlen, nicht neu zugeordnet:</translation>
    </message>
    <message>
        <source>{label}: {file} is not in {folder}</source>
        <translation>{label}: {file} ist nicht in {folder}</translation>
    </message>
    <message>
        <source>{done} of {total} CL points, about {left} left</source>
        <translation>{done} von {total} CL-Punkten, noch etwa {left}</translation>
    </message>
    <message>
        <source>{done} of {total} steps, about {left} left</source>
        <translation>{done} von {total} Schritten, noch etwa {left}</translation>
    </message>
    <message>
        <source>{minutes} min {seconds} s</source>
        <translation>{minutes} min {seconds} s</translation>
    </message>
    <message>
        <source>{seconds} s</source>
        <translation>{seconds} s</translation>
    </message>
    <message>
        <source>Reading and recognising the stock…</source>
        <translation>Rohteil wird gelesen und erkannt…</translation>
    </message>
    <message>
        <source>Computing the in-process stock…</source>
        <translation>Zwischenrohteil wird berechnet…</translation>
    </message>
</context>
<context>
    <name>ABM_ComputeEngagement</name>
    <message>
        <source>Compute engagement</source>
        <translation>Eingriff berechnen</translation>
    </message>
    <message>
        <source>Compute where the cutter engages the stock along the toolpath: select a stock and a toolpath (or have only one of each), then set the tool and cut in the task panel</source>
        <translation>Berechnen, wo der Fräser entlang der Werkzeugbahn in das Rohteil eingreift: ein Rohteil und eine Werkzeugbahn wählen (oder nur je eines haben), dann Werkzeug und Schnitt in der Aufgabenansicht einstellen</translation>
    </message>
</context>
<context>
    <name>ABM_EngageCamJob</name>
    <message>
        <source>Engage CAM job</source>
        <translation>CAM-Job eingreifen lassen</translation>
    </message>
    <message>
        <source>Compute where the cutter engages the stock in a FreeCAD CAM Job: select the Job (every operation the engine computes) or some of its operations; the results follow the Job when it recomputes</source>
        <translation>Berechnen, wo der Fräser in einem FreeCAD-CAM-Job in das Rohteil eingreift: den Job (jede Operation, die der Rechenkern berechnet) oder einige seiner Operationen wählen; die Ergebnisse folgen dem Job, wenn er neu berechnet wird</translation>
    </message>
</context>
<context>
    <name>ABM_ImportStock</name>
    <message>
        <source>Import stock…</source>
        <translation>Rohteil importieren…</translation>
    </message>
    <message>
        <source>Add a staircase stock from the selected solid, or from a STEP, BREP or FCStd solid (recognised, exact walls) or a staircase JSON</source>
        <translation>Ein Treppen-Rohteil aus dem gewählten Volumenkörper hinzufügen, oder aus einem STEP-, BREP- oder FCStd-Körper (erkannt, exakte Wände) oder einer Treppen-JSON-Datei</translation>
    </message>
</context>
<context>
    <name>ABM_ImportToolpath</name>
    <message>
        <source>Import toolpath…</source>
        <translation>Werkzeugbahn importieren…</translation>
    </message>
    <message>
        <source>Add a toolpath from the selected CAM Job or operation, or from a CSV (x,y,z,theta_a,theta_b or x,y,z,i,j,k), an APT / CL file, G-code or an FCStd holding a CAM Job</source>
        <translation>Eine Werkzeugbahn aus dem gewählten CAM-Job oder der gewählten Operation hinzufügen, oder aus einer CSV-Datei (x,y,z,theta_a,theta_b oder x,y,z,i,j,k), einer APT-/CL-Datei, G-Code oder einer FCStd-Datei mit einem CAM-Job</translation>
    </message>
</context>
<context>
    <name>ABM_InspectEngagement</name>
    <message>
        <source>Inspect engagement</source>
        <translation>Eingriff untersuchen</translation>
    </message>
    <message>
        <source>Open the engagement dock for the selected engagement: choose a CL point (highlighted on the model), colour by segment, length of cut or cut area, and see the plots</source>
        <translation>Das Eingriffsfenster für den gewählten Eingriff öffnen: einen CL-Punkt wählen (am Modell hervorgehoben), nach Segment, Schnittlänge oder Spanungsquerschnitt einfärben und die Diagramme sehen</translation>
    </message>
</context>
<context>
    <name>ABM_OpenModelTest</name>
    <message>
        <source>Open model test 1</source>
        <translation>Modelltest 1 öffnen</translation>
    </message>
    <message>
        <source>New document with model test 1 (after Hendriko 2020): the STEP stock with exact walls, the toolpath and the engagement with job.json's tool and cut, computed</source>
        <translation>Neues Dokument mit Modelltest 1 (nach Hendriko 2020): das STEP-Rohteil mit exakten Wänden, die Werkzeugbahn und der Eingriff mit Werkzeug und Schnitt aus job.json, berechnet</translation>
    </message>
</context>
<context>
    <name>ABM_ShowInProcessStock</name>
    <message>
        <source>Show in-process stock</source>
        <translation>Zwischenrohteil zeigen</translation>
    </message>
    <message>
        <source>Show the stock as it is at the dock's chosen CL point: the stock minus what the program's earlier moves near it removed (OpenCASCADE booleans, a few seconds); it follows the CL point chosen in the dock</source>
        <translation>Das Rohteil so zeigen, wie es am im Eingriffsfenster gewählten CL-Punkt ist: das Rohteil ohne das, was frühere Bewegungen des Programms in seiner Nähe entfernt haben (boolesche Operationen von OpenCASCADE, einige Sekunden); es folgt dem im Eingriffsfenster gewählten CL-Punkt</translation>
    </message>
</context>
<context>
    <name>ABM_ValidateEngagement</name>
    <message>
        <source>Validate engagement…</source>
        <translation>Eingriff validieren…</translation>
    </message>
    <message>
        <source>Check the selected engagement's length of cut against OpenCASCADE booleans at all or chosen CL points (about 1 s per CL point; cancellable) and open the HTML report</source>
        <translation>Die Schnittlänge des gewählten Eingriffs an allen oder gewählten CL-Punkten gegen boolesche Operationen von OpenCASCADE prüfen (etwa 1 s pro CL-Punkt; abbrechbar) und den HTML-Bericht öffnen</translation>
    </message>
</context>
</TS>
