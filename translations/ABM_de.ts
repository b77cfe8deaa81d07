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
        <translation>wählen Sie einen FreeCAD-CAM-Job oder Operationen eines Jobs aus</translation>
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
        <translation>{operation}: {controller} gibt keinen Wert für {value} an (legen Sie ihn im Toolbit fest oder unter Bearbeiten → Einstellungen → ABM)</translation>
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
        <source>{label}: validation report {page}</source>
        <translation>{label}: Validierungsbericht {page}</translation>
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
        <translation>{file} enthält mehrere Operationen: wählen Sie die zu berechnende (Operation der Werkzeugbahn; später im Eigenschafteneditor änderbar)</translation>
    </message>
    <message>
        <source>{count} {nouns} selected: select one {noun}</source>
        <translation>{count} {nouns} ausgewählt: wählen Sie nur ein Objekt vom Typ {noun} aus</translation>
    </message>
    <message>
        <source>no {noun} in the document: import one first</source>
        <translation>kein Objekt vom Typ {noun} im Dokument: importieren Sie zuerst eines</translation>
    </message>
    <message>
        <source>{count} {nouns} in the document: select the one to use</source>
        <translation>{count} {nouns} im Dokument: wählen Sie das zu verwendende aus</translation>
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
        <translation>{label}: berechnen Sie es zuerst (berechnen Sie das Dokument neu)</translation>
    </message>
    <message>
        <source>validation cancelled: nothing written</source>
        <translation>Validierung abgebrochen: nichts geschrieben</translation>
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
        <source>{file}: not imported: its program loads tools by number, and no tool table was chosen (a LinuxCNC tool table, or the FreeCAD document that posted the program)</source>
        <translation>{file}: nicht importiert: das Programm lädt Werkzeuge per Nummer, und es wurde keine Werkzeugtabelle gewählt (eine LinuxCNC-Werkzeugtabelle oder das FreeCAD-Dokument, aus dem das Programm erzeugt wurde)</translation>
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
        <translation>keine Kräfte: schalten Sie Schnittkräfte in der Aufgabenansicht des Eingriffs ein und berechnen Sie neu</translation>
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
        <translation>{label}: keine Ergebnisse (berechnen Sie es neu)</translation>
    </message>
    <message>
        <source>No engagement: select one and use Inspect engagement</source>
        <translation>Kein Eingriff: wählen Sie einen aus und verwenden Sie „Eingriff untersuchen“</translation>
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
        <translation>Zwischenrohteil zeigen: untersuchen Sie zuerst einen Eingriff („Eingriff untersuchen“), dann wählen Sie seinen CL-Punkt im Dock</translation>
    </message>
    <message>
        <source>In-process stock at CL {cl}: cancelled</source>
        <translation>Zwischenrohteil bei CL {cl}: abgebrochen</translation>
    </message>
    <message>
        <source>“{typed}” is not a length: {hint}</source>
        <translation>„{typed}“ ist keine Länge: {hint}</translation>
    </message>
    <message>
        <source>type a number, with a unit if you like (12 mm, 0.5 in)</source>
        <translation>geben Sie eine Zahl ein, nach Wunsch mit Einheit (12 mm, 0.5 in)</translation>
    </message>
    <message>
        <source>“{typed}” is not an angle: {hint}</source>
        <translation>„{typed}“ ist kein Winkel: {hint}</translation>
    </message>
    <message>
        <source>type a number, with a unit if you like (10°, 0.2 rad)</source>
        <translation>geben Sie eine Zahl ein, nach Wunsch mit Einheit (10°, 0.2 rad)</translation>
    </message>
    <message>
        <source>“{typed}” is not a number: {hint}</source>
        <translation>„{typed}“ ist keine Zahl: {hint}</translation>
    </message>
    <message>
        <source>type a number without a unit (4, 2.5)</source>
        <translation>geben Sie eine Zahl ohne Einheit ein (4, 2.5)</translation>
    </message>
    <message>
        <source>“{typed}” has a “{other}”: decimals take a “{point}” (12{point}5), thousands no separator (1000)</source>
        <translation>„{typed}“ enthält „{other}“: Dezimalstellen werden mit „{point}“ abgetrennt (12{point}5), Tausender ohne Trennzeichen (1000)</translation>
    </message>
    <message>
        <source>“{typed}” is too large a number</source>
        <translation>„{typed}“ ist eine zu große Zahl</translation>
    </message>
    <message>
        <source>“{typed}” is too small a number: it would be taken as 0</source>
        <translation>„{typed}“ ist eine zu kleine Zahl: sie würde als 0 genommen</translation>
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
        <translation>kein Eingriff für Operation {number} von {job}: wählen Sie den Job aus und verwenden Sie „CAM-Job eingreifen lassen“</translation>
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
        <source>the toolpath's ToolTable property</source>
        <translation>die Eigenschaft ToolTable der Werkzeugbahn</translation>
    </message>
    <message>
        <source>the toolpath's ToolTableUnits property</source>
        <translation>die Eigenschaft ToolTableUnits der Werkzeugbahn</translation>
    </message>
    <message>
        <source>the toolpath's Operation property</source>
        <translation>die Eigenschaft Operation der Werkzeugbahn</translation>
    </message>
    <message>
        <source>the helix angle β</source>
        <translation>den Drallwinkel β</translation>
    </message>
    <message>
        <source>the engagement's StockModel property</source>
        <translation>die Eigenschaft StockModel des Eingriffs</translation>
    </message>
    <message>
        <source>a toolpath linked to the CAM Job</source>
        <translation>eine mit dem CAM-Job verknüpfte Werkzeugbahn</translation>
    </message>
    <message>
        <source>a machine file (not read by the GUI yet)</source>
        <translation>eine Maschinendatei (von der Oberfläche noch nicht gelesen)</translation>
    </message>
    <message>
        <source>work offsets (not read by the GUI yet)</source>
        <translation>Nullpunktverschiebungen (von der Oberfläche noch nicht gelesen)</translation>
    </message>
    <message>
        <source>the wall model</source>
        <translation>das Wandmodell</translation>
    </message>
    <message>
        <source>the y window</source>
        <translation>das y-Fenster</translation>
    </message>
    <message>
        <source>Cutting forces</source>
        <translation>Schnittkräfte</translation>
    </message>
    <message>
        <source>the CL points</source>
        <translation>die CL-Punkte</translation>
    </message>
    <message>
        <source>No such file or directory</source>
        <translation>Datei oder Verzeichnis nicht gefunden</translation>
    </message>
    <message>
        <source>Permission denied</source>
        <translation>Keine Berechtigung</translation>
    </message>
    <message>
        <source>Is a directory</source>
        <translation>Ist ein Verzeichnis</translation>
    </message>
    <message>
        <source>Not a directory</source>
        <translation>Ist kein Verzeichnis</translation>
    </message>
    <message>
        <source>No space left on device</source>
        <translation>Kein Speicherplatz mehr auf dem Gerät</translation>
    </message>
    <message>
        <source>Read-only file system</source>
        <translation>Schreibgeschütztes Dateisystem</translation>
    </message>
    <message>
        <source>File exists</source>
        <translation>Datei existiert bereits</translation>
    </message>
    <message>
        <source>File name too long</source>
        <translation>Dateiname zu lang</translation>
    </message>
    <message>
        <source>Too many levels of symbolic links</source>
        <translation>Zu viele Ebenen symbolischer Verknüpfungen</translation>
    </message>
    <message>
        <source>set the toolpath's ToolTable property (</source>
        <translation>setzen Sie die Eigenschaft ToolTable der Werkzeugbahn (</translation>
    </message>
    <message>
        <source>choose one in the toolpath's Operation property</source>
        <translation>wählen Sie eine in der Eigenschaft Operation der Werkzeugbahn</translation>
    </message>
    <message>
        <source>say them in the toolpath's ToolTableUnits property (mm or inch)</source>
        <translation>geben Sie sie in der Eigenschaft ToolTableUnits der Werkzeugbahn an (mm oder inch)</translation>
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
        <source>The wall model {model} applies to a solid stock (STEP, BREP or FCStd), not to {stock}.</source>
        <translation>Das Wandmodell {model} gilt für ein Volumenkörper-Rohteil (STEP, BREP oder FCStd), nicht für {stock}.</translation>
    </message>
    <message>
        <source>The y window {window} applies to a solid stock (STEP, BREP or FCStd), not to {stock}.</source>
        <translation>Das y-Fenster {window} gilt für ein Volumenkörper-Rohteil (STEP, BREP oder FCStd), nicht für {stock}.</translation>
    </message>
    <message>
        <source>The y window must start below its end: {start} mm to {end} mm.</source>
        <translation>Das y-Fenster muss unterhalb seines Endes beginnen: {start} mm bis {end} mm.</translation>
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
        <source>{field}: the field is empty: {hint}.</source>
        <translation>{field}: das Feld ist leer: {hint}.</translation>
    </message>
    <message>
        <source>{field} is required: the field is empty.</source>
        <translation>{field} ist erforderlich: das Feld ist leer.</translation>
    </message>
    <message>
        <source>{field}: the engagement object holds angles within [{low}, {high}]°, got {value}°.</source>
        <translation>{field}: das Eingriffsobjekt fasst Winkel im Bereich [{low}, {high}]°, erhalten: {value}°.</translation>
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
        <source>ABM against booleans</source>
        <translation>ABM gegen boolesche Operationen</translation>
    </message>
    <message>
        <source>Helical edges (β = {helix}°), flute 1 of {flutes}, ABM against booleans</source>
        <translation>Wendelförmige Schneiden (β = {helix}°), Schneide 1 von {flutes}, ABM gegen boolesche Operationen</translation>
    </message>
    <message>
        <source>CL points {listed} of the pass, numbered 0..{last} here.</source>
        <translation>CL-Punkte {listed} des Durchgangs, hier mit 0..{last} nummeriert.</translation>
    </message>
    <message>
        <source>the paper's quintic walls (JSON)</source>
        <translation>die quintischen Wände des Artikels (JSON)</translation>
    </message>
    <message>
        <source>in-process: the stock minus what earlier cutting moves of the program removed</source>
        <translation>Zwischenrohteil: das Rohteil ohne das, was frühere Schnittbewegungen des Programms entfernt haben</translation>
    </message>
    <message>
        <source>initial: the stock as given ({why})</source>
        <translation>Ausgangsrohteil: das Rohteil wie gegeben ({why})</translation>
    </message>
    <message>
        <source>initial: the stock as given</source>
        <translation>Ausgangsrohteil: das Rohteil wie gegeben</translation>
    </message>
    <message>
        <source>pass CL {cl}</source>
        <translation>CL {cl} des Durchgangs</translation>
    </message>
    <message>
        <source>exact walls</source>
        <translation>exakte Wände</translation>
    </message>
    <message>
        <source>quintic walls</source>
        <translation>quintische Wände</translation>
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
    <message>
        <source>chosen</source>
        <translation>gewählt</translation>
    </message>
    <message>
        <source>largest error</source>
        <translation>größter Fehler</translation>
    </message>
    <message>
        <source>deepest</source>
        <translation>tiefster</translation>
    </message>
    <message>
        <source>shallowest</source>
        <translation>flachster</translation>
    </message>
    <message>
        <source>middle</source>
        <translation>Mitte</translation>
    </message>
    <message>
        <source>CL points shown: {listed}. Shaded: the engagement segments (ABM).</source>
        <translation>Gezeigte CL-Punkte: {listed}. Schattiert: die Eingriffssegmente (ABM).</translation>
    </message>
    <message>
        <source>bull-nose mill D {diameter} mm, corner radius {corner} mm</source>
        <translation>Torusfräser D {diameter} mm, Eckenradius {corner} mm</translation>
    </message>
    <message>
        <source>{checked} of {count}: {spans} (the statistics, comparison.csv and segments.csv are over these; the engine computed all {count})</source>
        <translation>{checked} von {count}: {spans} (die Statistik, comparison.csv und segments.csv beziehen sich auf diese; der Rechenkern hat alle {count} berechnet)</translation>
    </message>
    <message>
        <source>ABM {abm_low}–{abm_high} mm, boolean {low}–{high} mm</source>
        <translation>ABM {abm_low}–{abm_high} mm, boolesch {low}–{high} mm</translation>
    </message>
    <message>
        <source>CL points shown: {listed} (the first {count} of {total}). Shaded: the engagement segments (ABM).</source>
        <translation>Gezeigte CL-Punkte: {listed} (die ersten {count} von {total}). Schattiert: die Eingriffssegmente (ABM).</translation>
    </message>
    <message>
        <source>flat end mill D {diameter} mm</source>
        <translation>Schaftfräser D {diameter} mm</translation>
    </message>
    <message>
        <source>ball-end mill D {diameter} mm (R {corner} mm)</source>
        <translation>Kugelfräser D {diameter} mm (R {corner} mm)</translation>
    </message>
    <message>
        <source>all {count} (the statistics are over every instant)</source>
        <translation>alle {count} (die Statistik bezieht sich auf jeden Zeitpunkt)</translation>
    </message>
    <message>
        <source>changed</source>
        <translation>verändert</translation>
    </message>
    <message>
        <source>swept pieces near</source>
        <translation>überstrichene Stücke in der Nähe</translation>
    </message>
    <message>
        <source>angles changed</source>
        <translation>veränderte Winkel</translation>
    </message>
    <message>
        <source>max l, stock as given (ABM)</source>
        <translation>max. l, Rohteil wie gegeben (ABM)</translation>
    </message>
    <message>
        <source>max l, in-process (ABM)</source>
        <translation>max. l, Zwischenrohteil (ABM)</translation>
    </message>
    <message>
        <source>max l, in-process (boolean)</source>
        <translation>max. l, Zwischenrohteil (boolesch)</translation>
    </message>
    <message>
        <source>max |Δl| (mm)</source>
        <translation>max. |Δl| (mm)</translation>
    </message>
    <message>
        <source>instants</source>
        <translation>Zeitpunkte</translation>
    </message>
    <message>
        <source>relative</source>
        <translation>relativ</translation>
    </message>
    <message>
        <source>max |rel. error|</source>
        <translation>max. |rel. Fehler|</translation>
    </message>
    <message>
        <source>mean |rel. error|</source>
        <translation>mittl. |rel. Fehler|</translation>
    </message>
    <message>
        <source>max |ΔLEP| (mm)</source>
        <translation>max. |ΔLEP| (mm)</translation>
    </message>
    <message>
        <source>max |ΔUEP| (mm)</source>
        <translation>max. |ΔUEP| (mm)</translation>
    </message>
    <message>
        <source>mismatched</source>
        <translation>abweichend</translation>
    </message>
    <message>
        <source>max |Δ end| (mm)</source>
        <translation>max. |Δ Stirn| (mm)</translation>
    </message>
    <message>
        <source>end mismatched</source>
        <translation>Stirn abweichend</translation>
    </message>
    <message>
        <source>Job</source>
        <translation>Auftrag</translation>
    </message>
    <message>
        <source>Error by UEP surface, whole pass</source>
        <translation>Fehler nach UEP-Fläche, ganzer Durchgang</translation>
    </message>
    <message>
        <source>The paper (Siemens NX reference): negligible error with the UEP on a top or a straight wall, below 6 % with the UEP on a curved wall.</source>
        <translation>Der Artikel (Referenz Siemens NX): vernachlässigbarer Fehler mit dem UEP auf einer Deckfläche oder einer geraden Wand, unter 6 % mit dem UEP auf einer gekrümmten Wand.</translation>
    </message>
    <message>
        <source>Length of cut along the pass</source>
        <translation>Schnittlänge entlang des Durchgangs</translation>
    </message>
    <message>
        <source>Depth of cut along the pass</source>
        <translation>Schnitttiefe entlang des Durchgangs</translation>
    </message>
    <message>
        <source>Length of cut and cut area over φ</source>
        <translation>Schnittlänge und Spanungsquerschnitt über φ</translation>
    </message>
    <message>
        <source>Shape of the cut</source>
        <translation>Form des Schnitts</translation>
    </message>
    <message>
        <source>Error per engagement segment</source>
        <translation>Fehler je Eingriffssegment</translation>
    </message>
    <message>
        <source>Error over the pass</source>
        <translation>Fehler über den Durchgang</translation>
    </message>
    <message>
        <source>Timings</source>
        <translation>Laufzeiten</translation>
    </message>
    <message>
        <source>Files</source>
        <translation>Dateien</translation>
    </message>
    <message>
        <source>largest |relative error| over {count} instants</source>
        <translation>größter |relativer Fehler| über {count} Zeitpunkte</translation>
    </message>
    <message>
        <source>mean |relative error|</source>
        <translation>mittlerer |relativer Fehler|</translation>
    </message>
    <message>
        <source>largest |l_ABM − l_ref|, all instants</source>
        <translation>größtes |l_ABM − l_ref|, alle Zeitpunkte</translation>
    </message>
    <message>
        <source>largest |Δ end edge| over {count} instants</source>
        <translation>größtes |Δ Stirnschneide| über {count} Zeitpunkte</translation>
    </message>
    <message>
        <source>ABM {abm} s vs boolean {boolean} s</source>
        <translation>ABM {abm} s gegenüber boolesch {boolean} s</translation>
    </message>
    <message>
        <source>{path}: {count} CL points</source>
        <translation>{path}: {count} CL-Punkte</translation>
    </message>
    <message>
        <source>CL points checked</source>
        <translation>geprüfte CL-Punkte</translation>
    </message>
    <message>
        <source>rotation angles</source>
        <translation>Drehwinkel</translation>
    </message>
    <message>
        <source>φ {start}..{end}° step {step}°: {count} angles, {instants} instants</source>
        <translation>φ {start}..{end}° Schritt {step}°: {count} Winkel, {instants} Zeitpunkte</translation>
    </message>
    <message>
        <source>tool</source>
        <translation>Werkzeug</translation>
    </message>
    <message>
        <source>cutting</source>
        <translation>Schnittwerte</translation>
    </message>
    <message>
        <source>parameters [from]</source>
        <translation>Parameter [aus]</translation>
    </message>
    <message>
        <source>stock model</source>
        <translation>Rohteilmodell</translation>
    </message>
    <message>
        <source>{swept} ({gauged} by the exact test)</source>
        <translation>{swept} ({gauged} durch den exakten Test)</translation>
    </message>
    <message>
        <source>Error of the length of cut as the paper defines it: relative, (l&lt;sub&gt;ABM&lt;/sub&gt; − l&lt;sub&gt;ref&lt;/sub&gt;)/l&lt;sub&gt;ref&lt;/sub&gt;, with l&lt;sub&gt;ref&lt;/sub&gt; from the OpenCASCADE boolean of the cutting edges with the stock solid. Where l&lt;sub&gt;ref&lt;/sub&gt; &amp;lt; {tiny} mm (the edge grazes the stock) the absolute difference l&lt;sub&gt;ABM&lt;/sub&gt; − l&lt;sub&gt;ref&lt;/sub&gt; in mm is used instead; those instants are counted apart. LEP/UEP: largest difference along the edge (mm). Mismatched: instants where only one method finds engagement. End edge: the largest |end&lt;sub&gt;ABM&lt;/sub&gt; − end&lt;sub&gt;ref&lt;/sub&gt;| of the end cutting edge's engaged length (tip to the corner, in the tip plane) over the instants where both give it, and the instants where only one finds it in the stock.</source>
        <translation>Fehler der Schnittlänge, wie der Artikel ihn definiert: relativ, (l&lt;sub&gt;ABM&lt;/sub&gt; − l&lt;sub&gt;ref&lt;/sub&gt;)/l&lt;sub&gt;ref&lt;/sub&gt;, mit l&lt;sub&gt;ref&lt;/sub&gt; aus der booleschen Operation von OpenCASCADE der Schneiden mit dem Rohteilkörper. Wo l&lt;sub&gt;ref&lt;/sub&gt; &amp;lt; {tiny} mm ist (die Schneide streift das Rohteil), wird stattdessen die absolute Differenz l&lt;sub&gt;ABM&lt;/sub&gt; − l&lt;sub&gt;ref&lt;/sub&gt; in mm verwendet; diese Zeitpunkte werden gesondert gezählt. LEP/UEP: größte Differenz entlang der Schneide (mm). Abweichend: Zeitpunkte, an denen nur ein Verfahren Eingriff findet. Stirnschneide: das größte |end&lt;sub&gt;ABM&lt;/sub&gt; − end&lt;sub&gt;ref&lt;/sub&gt;| der Eingriffslänge der Stirnschneide (von der Spitze bis zur Ecke, in der Spitzenebene) über die Zeitpunkte, an denen beide sie liefern, und die Zeitpunkte, an denen nur eines sie im Rohteil findet.</translation>
    </message>
    <message>
        <source>segment</source>
        <translation>Segment</translation>
    </message>
    <message>
        <source>UEP on</source>
        <translation>UEP auf</translation>
    </message>
    <message>
        <source>section</source>
        <translation>Abschnitt</translation>
    </message>
    <message>
        <source>wall</source>
        <translation>Wand</translation>
    </message>
    <message>
        <source>Every CL point: &lt;code&gt;segments.csv&lt;/code&gt;.</source>
        <translation>Jeder CL-Punkt: &lt;code&gt;segments.csv&lt;/code&gt;.</translation>
    </message>
    <message>
        <source>model test {number} {low}–{high} mm</source>
        <translation>Modelltest {number} {low}–{high} mm</translation>
    </message>
    <message>
        <source>This job is model test {number}.</source>
        <translation>Dieser Auftrag ist Modelltest {number}.</translation>
    </message>
    <message>
        <source>Depth of cut over the pass (highest UEP z − lowest LEP z per CL point): {ours}. The paper's passes: {papers}.</source>
        <translation>Schnitttiefe über den Durchgang (höchstes UEP-z − niedrigstes LEP-z je CL-Punkt): {ours}. Die Durchgänge des Artikels: {papers}.</translation>
    </message>
    <message>
        <source>ABM engine, whole pass</source>
        <translation>ABM-Rechenkern, ganzer Durchgang</translation>
    </message>
    <message>
        <source>{time} µs per instant</source>
        <translation>{time} µs je Zeitpunkt</translation>
    </message>
    <message>
        <source>boolean reference (OpenCASCADE)</source>
        <translation>boolesche Referenz (OpenCASCADE)</translation>
    </message>
    <message>
        <source>{time} s per CL point</source>
        <translation>{time} s je CL-Punkt</translation>
    </message>
    <message>
        <source>boolean / ABM</source>
        <translation>boolesch / ABM</translation>
    </message>
    <message>
        <source>stock solid and staircase (read, build or recognise)</source>
        <translation>Rohteilkörper und Treppenstufen-Modell (lesen, aufbauen oder erkennen)</translation>
    </message>
    <message>
        <source>paper, {name}, 53 CC points (MATLAB, i7 2.7 GHz)</source>
        <translation>Artikel, {name}, 53 CC-Punkte (MATLAB, i7 2.7 GHz)</translation>
    </message>
    <message>
        <source>angle step not stated</source>
        <translation>Winkelschritt nicht angegeben</translation>
    </message>
    <message>
        <source>time</source>
        <translation>Zeit</translation>
    </message>
    <message>
        <source>one row per instant the boolean checked: cl, phi_deg, l_abm, l_ref, difference, error, error_kind, LEP and UEP of both, pieces of both, segment, uep_surface, end_abm, end_ref, end_difference (the end edge's engaged length; against the in-process stock also l_initial: ABM in the stock as given)</source>
        <translation>eine Zeile je Zeitpunkt, den die boolesche Referenz geprüft hat: cl, phi_deg, l_abm, l_ref, difference, error, error_kind, LEP und UEP beider, pieces beider, segment, uep_surface, end_abm, end_ref, end_difference (die Eingriffslänge der Stirnschneide; gegen das Zwischenrohteil auch l_initial: ABM im Rohteil wie gegeben)</translation>
    </message>
    <message>
        <source>error per CL point and engagement segment</source>
        <translation>Fehler je CL-Punkt und Eingriffssegment</translation>
    </message>
    <message>
        <source>error per kind of UEP surface</source>
        <translation>Fehler je Art der UEP-Fläche</translation>
    </message>
    <message>
        <source>depth of cut per CL point, both methods, and checked (1 where the boolean checked it; against the in-process stock also changed: whether earlier moves changed the CL point, and swept: the swept pieces the boolean sectioned)</source>
        <translation>Schnitttiefe je CL-Punkt, beide Verfahren, und checked (1, wo die boolesche Referenz ihn geprüft hat; gegen das Zwischenrohteil auch changed: ob frühere Bewegungen den CL-Punkt verändert haben, und swept: die überstrichenen Stücke, die die boolesche Referenz geschnitten hat)</translation>
    </message>
    <message>
        <source>depth of cut (ABM); paper {low}–{high} mm</source>
        <translation>Schnitttiefe (ABM); Artikel {low}–{high} mm</translation>
    </message>
    <message>
        <source>depth of cut (ABM); paper: not a model test</source>
        <translation>Schnitttiefe (ABM); Artikel: kein Modelltest</translation>
    </message>
    <message>
        <source>{stock} ({walls}; y window {low}..{high} mm)</source>
        <translation>{stock} ({walls}; y-Fenster {low}..{high} mm)</translation>
    </message>
    <message>
        <source>{tool}, {flutes} flutes, flute length {length} mm, helix {helix}°</source>
        <translation>{tool}, {flutes} Schneiden, Schneidenlänge {length} mm, Drallwinkel {helix}°</translation>
    </message>
    <message>
        <source>{tool}, {flutes} flutes, flute length {length} mm</source>
        <translation>{tool}, {flutes} Schneiden, Schneidenlänge {length} mm</translation>
    </message>
    <message>
        <source>feed {feed} mm/tooth, inclination {inclination}°, {speed} rpm</source>
        <translation>Vorschub {feed} mm/Zahn, Anstellwinkel {inclination}°, {speed} 1/min</translation>
    </message>
    <message>
        <source>feed {feed} mm/tooth, inclination {inclination}°</source>
        <translation>Vorschub {feed} mm/Zahn, Anstellwinkel {inclination}°</translation>
    </message>
    <message>
        <source>{count} of the swept pieces that meet the tool's edges (summed over the checked CL points) are moves OpenCASCADE has no reliable solids for (a bull-nose mill's moves within 5.74° of the plane across its axis, whose solids have nearly degenerate faces its booleans misjudge; oblique moves of a tool shorter than its corner radius): the reference decides where the edges lie in those with an exact inside test of its own (the tool's distance function minimised along the move, every crossing isolated to 10⁻¹⁰ mm), independent of the engine (column &lt;code&gt;gauged&lt;/code&gt; of &lt;code&gt;depth.csv&lt;/code&gt;).</source>
        <translation>{count} der überstrichenen Stücke, die die Schneiden des Werkzeugs treffen (summiert über die geprüften CL-Punkte), sind Bewegungen, für die OpenCASCADE keine verlässlichen Volumenkörper hat (Bewegungen eines Torusfräsers innerhalb von 5.74° der Ebene quer zu seiner Achse, deren Volumenkörper fast entartete Flächen haben, die seine booleschen Operationen falsch beurteilen; schräge Bewegungen eines Werkzeugs, das kürzer als sein Eckenradius ist): die Referenz entscheidet in diesen mit einem eigenen exakten Innen-Test, wo die Schneiden liegen (die Abstandsfunktion des Werkzeugs entlang der Bewegung minimiert, jeder Übergang auf 10⁻¹⁰ mm eingegrenzt), unabhängig vom Rechenkern (Spalte &lt;code&gt;gauged&lt;/code&gt; von &lt;code&gt;depth.csv&lt;/code&gt;).</translation>
    </message>
    <message>
        <source>In-process stock</source>
        <translation>Zwischenrohteil</translation>
    </message>
    <message>
        <source>For this ball mill the cutting edge is the corner arc (radius {radius} mm, sectioned by the boolean as a true circular arc) followed by the straight side: l is the arc length along both, LEP and UEP are heights along the tool axis above the tip (mm).</source>
        <translation>Bei diesem Kugelfräser ist die Schneide der Eckenbogen (Radius {radius} mm, von der booleschen Referenz als echter Kreisbogen geschnitten), gefolgt von der geraden Seite: l ist die Bogenlänge entlang beider, LEP und UEP sind Höhen entlang der Werkzeugachse über der Spitze (mm).</translation>
    </message>
    <message>
        <source>For this bull-nose mill the cutting edge is the corner arc (radius {radius} mm, sectioned by the boolean as a true circular arc) followed by the straight side: l is the arc length along both, LEP and UEP are heights along the tool axis above the tip (mm).</source>
        <translation>Bei diesem Torusfräser ist die Schneide der Eckenbogen (Radius {radius} mm, von der booleschen Referenz als echter Kreisbogen geschnitten), gefolgt von der geraden Seite: l ist die Bogenlänge entlang beider, LEP und UEP sind Höhen entlang der Werkzeugachse über der Spitze (mm).</translation>
    </message>
    <message>
        <source>peak resultant force over the pass</source>
        <translation>größte resultierende Kraft über den Durchgang</translation>
    </message>
    <message>
        <source>{force} N at CL {cl}</source>
        <translation>{force} N an CL {cl}</translation>
    </message>
    <message>
        <source>mean resultant force, pass average</source>
        <translation>mittlere resultierende Kraft, Mittel über den Durchgang</translation>
    </message>
    <message>
        <source>peak torque</source>
        <translation>größtes Drehmoment</translation>
    </message>
    <message>
        <source>Fig.</source>
        <translation>Abb.</translation>
    </message>
    <message>
        <source>yes</source>
        <translation>ja</translation>
    </message>
    <message>
        <source>no</source>
        <translation>nein</translation>
    </message>
    <message>
        <source>Both the engine and the boolean reference work on the &lt;b&gt;in-process stock&lt;/b&gt;: at each CL point, the stock minus the volumes swept by the cutting moves that end before it. The boolean reference sections each cutting-edge line with the stock solid and with exact solids of the volumes swept by the earlier moves that can reach the tool, and keeps what lies in the stock and in none of them. The pictures show the top of that in-process stock around the tool, found the same way along vertical lines. Earlier moves changed {changed} of {count} CL points ({instants} instants by more than {tiny} mm; {engaged} of the changed CL points still engage). Per instant, &lt;code&gt;comparison.csv&lt;/code&gt; has the length in the stock as given (&lt;code&gt;l_initial&lt;/code&gt;) beside both in-process lengths; &lt;code&gt;depth.csv&lt;/code&gt; says which CL points changed.</source>
        <translation>Sowohl der Rechenkern als auch die boolesche Referenz arbeiten mit dem &lt;b&gt;Zwischenrohteil&lt;/b&gt;: an jedem CL-Punkt das Rohteil ohne die Volumen, die die vor ihm endenden Schnittbewegungen überstrichen haben. Die boolesche Referenz schneidet jede Schneidenlinie mit dem Rohteilkörper und mit exakten Volumenkörpern der Volumen, die die früheren, das Werkzeug erreichenden Bewegungen überstrichen haben, und behält, was im Rohteil und in keinem von ihnen liegt. Die Bilder zeigen die Oberseite dieses Zwischenrohteils um das Werkzeug, ebenso entlang senkrechter Linien ermittelt. Frühere Bewegungen haben {changed} von {count} CL-Punkten verändert ({instants} Zeitpunkte um mehr als {tiny} mm; {engaged} der veränderten CL-Punkte sind noch im Eingriff). Je Zeitpunkt enthält &lt;code&gt;comparison.csv&lt;/code&gt; die Länge im Rohteil wie gegeben (&lt;code&gt;l_initial&lt;/code&gt;) neben beiden Längen am Zwischenrohteil; &lt;code&gt;depth.csv&lt;/code&gt; gibt an, welche CL-Punkte sich verändert haben.</translation>
    </message>
    <message>
        <source>peak spindle power</source>
        <translation>größte Spindelleistung</translation>
    </message>
    <message>
        <source>Linear edge-force model (docs/FORCES.md) on the ABM engagement, global frame, summed over the flutes cutting at each angle of flute 1; over φ at CL {shown} (dotted in the first plot). Also &lt;a href='forces.png'&gt;&lt;code&gt;forces.png&lt;/code&gt;&lt;/a&gt;.</source>
        <translation>Lineares Schneidkantenkraftmodell (docs/FORCES.md) auf dem ABM-Eingriff, globales Koordinatensystem, summiert über die Schneiden, die bei jedem Winkel von Schneide 1 schneiden; über φ an CL {shown} (im ersten Diagramm gepunktet). Außerdem &lt;a href='forces.png'&gt;&lt;code&gt;forces.png&lt;/code&gt;&lt;/a&gt;.</translation>
    </message>
    <message>
        <source>whole pass</source>
        <translation>ganzer Durchgang</translation>
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
<context>
    <name>ABM_messages</name>
    <message>
        <source>phi_deg must be finite angles of shape (p,), got shape {shape}</source>
        <translation>phi_deg muss aus endlichen Winkeln der Form (p,) bestehen, erhalten: Form {shape}</translation>
    </message>
    <message>
        <source>a boolean result edge lies on no cutting edge (nearest {distance_k} mm away)</source>
        <translation>eine Kante des Ergebnisses der booleschen Operation liegt auf keiner Schneidkante (nächste {distance_k} mm entfernt)</translation>
    </message>
    <message>
        <source>corner_lengths_in_process is for tools with a corner radius; flat-end mills have profile_boolean.flat_lengths_in_process</source>
        <translation>corner_lengths_in_process ist für Werkzeuge mit Eckenradius; für Schaftfräser gibt es profile_boolean.flat_lengths_in_process</translation>
    </message>
    <message>
        <source>the move from {point_c0} to {point_c1} mm has no exact solids here</source>
        <translation>die Bewegung von {point_c0} nach {point_c1} mm hat hier keine exakten Volumenkörper</translation>
    </message>
    <message>
        <source>OpenCASCADE did not split the corner's torus along its silhouette for the move {point_m} mm (axis {point_w})</source>
        <translation>OpenCASCADE hat den Torus der Ecke für die Bewegung {point_m} mm nicht entlang seiner Silhouette geteilt (Achse {point_w})</translation>
    </message>
    <message>
        <source>a 2.5D stock has horizontal tops and vertical walls</source>
        <translation>ein 2,5D-Rohteil hat waagerechte Deckflächen und senkrechte Wände</translation>
    </message>
    <message>
        <source>the edge {ends_edge} has no 3D curve, so its extent cannot be found</source>
        <translation>die Kante {ends_edge} hat keine 3D-Kurve, daher lässt sich ihre Ausdehnung nicht bestimmen</translation>
    </message>
    <message>
        <source>the edge {ends_edge} lies on {value}, which has no exact B-spline form, so its extent cannot be found exactly</source>
        <translation>die Kante {ends_edge} liegt auf {value}, ohne exakte B-Spline-Form, daher lässt sich ihre Ausdehnung nicht exakt bestimmen</translation>
    </message>
    <message>
        <source>{where}{name}: a vertical wall on {error}</source>
        <translation>{where}{name}: eine senkrechte Wand auf {error}</translation>
    </message>
    <message>
        <source>an OffsetSurface ({OffsetValue} mm) of {described_basis}: its offset has no exact form the walls take (offsets of planes, cylinders and extrusions of lines and circles are taken)</source>
        <translation>eine OffsetSurface ({OffsetValue} mm) von {described_basis}: ihr Versatz hat keine exakte Form, die für die Wände verwendbar ist (verwendbar sind Versätze von Ebenen, Zylindern sowie Extrusionen von Linien und Kreisen)</translation>
    </message>
    <message>
        <source>an OffsetSurface that shrinks a cylinder to its axis</source>
        <translation>eine OffsetSurface, die einen Zylinder auf seine Achse schrumpfen lässt</translation>
    </message>
    <message>
        <source>slanted top: a plane tilted {tilt}° from horizontal</source>
        <translation>schräge Oberseite: eine um {tilt}° gegen die Waagerechte geneigte Ebene</translation>
    </message>
    <message>
        <source>overhang: a plane facing down, tilted {tilt}° from horizontal</source>
        <translation>Überhang: eine nach unten weisende Ebene, um {tilt}° gegen die Waagerechte geneigt</translation>
    </message>
    <message>
        <source>wall not vertical: leans {value}°</source>
        <translation>Wand nicht senkrecht: neigt sich um {value}°</translation>
    </message>
    <message>
        <source>curved top: not a horizontal plane</source>
        <translation>gekrümmte Oberseite: keine waagerechte Ebene</translation>
    </message>
    <message>
        <source>overhang: faces down</source>
        <translation>Überhang: weist nach unten</translation>
    </message>
    <message>
        <source>wall not vertical</source>
        <translation>Wand nicht senkrecht</translation>
    </message>
    <message>
        <source>{value}, which has no exact B-spline form for the walls</source>
        <translation>{value}, ohne exakte B-Spline-Form für die Wände</translation>
    </message>
    <message>
        <source>{where}{name}: curved top: not a horizontal plane: a {type} whose control points span z {z_min} to {z_max}, near x = {pole_0}, y = {pole_1}; {RULE}</source>
        <translation>{where}{name}: gekrümmte Deckfläche: keine waagerechte Ebene: eine {type}, deren Kontrollpunkte z {z_min} bis {z_max} überspannen, nahe x = {pole_0}, y = {pole_1}; {RULE}</translation>
    </message>
    <message>
        <source>{where}{name}: wall not vertical: leans up to {value}° near x = {row_0}, y = {row_1} (a {type} whose control points drift {drift_k} mm sideways over {rise_k} mm of height); {RULE}</source>
        <translation>{where}{name}: Wand nicht senkrecht: neigt sich um bis zu {value}° nahe x = {row_0}, y = {row_1} (eine {type}, deren Kontrollpunkte auf {rise_k} mm Höhe um {drift_k} mm seitlich wandern); {RULE}</translation>
    </message>
    <message>
        <source>FreeCAD is not importable from {executable} ({error}). Install the Debian package freecad-python3 (apt-get install freecad-python3) and run the system interpreter /usr/bin/python3.</source>
        <translation>FreeCAD lässt sich aus {executable} nicht importieren ({error}). Installieren Sie das Debian-Paket freecad-python3 (apt-get install freecad-python3) und verwenden Sie den Systeminterpreter /usr/bin/python3.</translation>
    </message>
    <message>
        <source>flutes must be indices in 0..{z_1}, got {flutes}</source>
        <translation>flutes muss aus Indizes in 0..{z_1} bestehen, erhalten: {flutes}</translation>
    </message>
    <message>
        <source>a boolean result edge lies on no flute helix (nearest {distance} mm away)</source>
        <translation>eine Kante des Ergebnisses der booleschen Operation liegt auf keiner Schneidenhelix (nächste {distance} mm entfernt)</translation>
    </message>
    <message>
        <source>the {n} CL points are found {size} times in the pass of {count}; the in-process reference needs them once</source>
        <translation>die {n} CL-Punkte kommen {size}-mal im Durchgang von {count} vor; die Zwischenrohteil-Referenz benötigt sie genau einmal</translation>
    </message>
    <message>
        <source>a boolean result edge lies on no cutting edge (nearest {distance} mm away)</source>
        <translation>eine Kante des Ergebnisses der booleschen Operation liegt auf keiner Schneidkante (nächste {distance} mm entfernt)</translation>
    </message>
    <message>
        <source>flat_lengths_by_boolean is for flat-end mills; use profile_lengths_by_boolean</source>
        <translation>flat_lengths_by_boolean ist für Schaftfräser; verwenden Sie profile_lengths_by_boolean</translation>
    </message>
    <message>
        <source>flat_lengths_in_process is for flat-end mills; use corner_inprocess.corner_lengths_in_process</source>
        <translation>flat_lengths_in_process ist für Schaftfräser; verwenden Sie corner_inprocess.corner_lengths_in_process</translation>
    </message>
    <message>
        <source>a boolean result edge lies on no end edge (nearest {distance_j} mm away)</source>
        <translation>eine Kante des Ergebnisses der booleschen Operation liegt auf keiner Stirnschneide (nächste {distance_j} mm entfernt)</translation>
    </message>
    <message>
        <source>{path}: unknown file type; expected .step, .stp, .brep, .brp or .FCStd</source>
        <translation>{path}: unbekannter Dateityp; erwartet: .step, .stp, .brep, .brp oder .FCStd</translation>
    </message>
    <message>
        <source>{path}: no such file</source>
        <translation>{path}: Datei nicht vorhanden</translation>
    </message>
    <message>
        <source>{path}: the {kind} file holds no shape</source>
        <translation>{path}: die {kind}-Datei enthält keine Form</translation>
    </message>
    <message>
        <source>{path}: several solids ({join_names}); choose one with --solid NAME</source>
        <translation>{path}: mehrere Volumenkörper ({join_names}); wählen Sie einen mit --solid NAME</translation>
    </message>
    <message>
        <source>{path}: no solid named {name} in the {kind} file (its solids: none)</source>
        <translation>{path}: kein Volumenkörper namens {name} in der {kind}-Datei (sie enthält keine Volumenkörper)</translation>
    </message>
    <message>
        <source>{path}: no solid named {name} in the {kind} file (its solids: {listed})</source>
        <translation>{path}: kein Volumenkörper namens {name} in der {kind}-Datei (ihre Volumenkörper: {listed})</translation>
    </message>
    <message>
        <source>{path}: damaged {kind}: {value} of the shape's {count} vertices are not finite numbers (NaN or infinite coordinates)</source>
        <translation>{path}: beschädigte {kind}-Datei: {value} der {count} Eckpunkte der Form sind keine endlichen Zahlen (NaN oder unendliche Koordinaten)</translation>
    </message>
    <message>
        <source>{path}: damaged or unreadable {kind} (no shape after {timeout} s)</source>
        <translation>{path}: beschädigte oder unlesbare {kind}-Datei (keine Form nach {timeout} s)</translation>
    </message>
    <message>
        <source>cannot read as {kind}: {value}</source>
        <translation>nicht als {kind} lesbar: {value}</translation>
    </message>
    <message>
        <source>the reader ended with exit status {returncode} and no shape</source>
        <translation>der Leser endete mit dem Exit-Status {returncode} und ohne Form</translation>
    </message>
    <message>
        <source>{path}: damaged or unreadable {kind} ({detail})</source>
        <translation>{path}: beschädigte oder unlesbare {kind}-Datei ({detail})</translation>
    </message>
    <message>
        <source>{where}the cutting edges sweep y {s0} to {s1} mm, beyond the y window {w0} to {w1} mm that the stock was recognised over: widen the window</source>
        <translation>{where}die Schneidkanten überstreichen y {s0} bis {s1} mm, über das y-Fenster {w0} bis {w1} mm hinaus, in dem das Rohteil erkannt wurde: vergrößern Sie das Fenster</translation>
    </message>
    <message>
        <source>{path}: cannot open as a FreeCAD document: {error}</source>
        <translation>{path}: lässt sich nicht als FreeCAD-Dokument öffnen: {error}</translation>
    </message>
    <message>
        <source>{path}: {found} object with a solid named {name} (objects with solids: {names})</source>
        <translation>{path}: {found} Objekt(e) mit einem Volumenkörper namens {name} (Objekte mit Volumenkörpern: {names})</translation>
    </message>
    <message>
        <source>no object holds a solid</source>
        <translation>kein Objekt enthält einen Volumenkörper</translation>
    </message>
    <message>
        <source>several solids ({names}); choose one with --solid NAME</source>
        <translation>mehrere Volumenkörper ({names}); wählen Sie einen mit --solid NAME</translation>
    </message>
    <message>
        <source>walls must be 'exact' or 'quintic', got {walls}</source>
        <translation>walls muss 'exact' oder 'quintic' sein, erhalten: {walls}</translation>
    </message>
    <message>
        <source>wall_points must be 'chebyshev' or 'even', got {wall_points}</source>
        <translation>wall_points muss 'chebyshev' oder 'even' sein, erhalten: {wall_points}</translation>
    </message>
    <message>
        <source>{where}the solid has no top face facing +z</source>
        <translation>{where}der Volumenkörper hat keine nach +z weisende Deckfläche</translation>
    </message>
    <message>
        <source>{where}not a closed solid: an open shell, {free_edges_shape}</source>
        <translation>{where}kein geschlossener Volumenkörper: eine offene Schale, {free_edges_shape}</translation>
    </message>
    <message>
        <source>{where}holds no solid (a {ShapeType} of {count} faces)</source>
        <translation>{where}enthält keinen Volumenkörper (ein {ShapeType} aus {count} Flächen)</translation>
    </message>
    <message>
        <source>{where}holds {count} solids; a stock is one solid</source>
        <translation>{where}enthält {count} Volumenkörper; ein Rohteil ist ein einziger Volumenkörper</translation>
    </message>
    <message>
        <source>{where}holds {value} faces outside its solid</source>
        <translation>{where}enthält {value} Flächen außerhalb seines Volumenkörpers</translation>
    </message>
    <message>
        <source>{where}not a closed solid: {free_edges_shape}</source>
        <translation>{where}kein geschlossener Volumenkörper: {free_edges_shape}</translation>
    </message>
    <message>
        <source>{where}the solid is not valid (shape.check() says why)</source>
        <translation>{where}der Volumenkörper ist ungültig (shape.check() nennt den Grund)</translation>
    </message>
    <message>
        <source>{listed} has an edge bordering no other face</source>
        <translation>{listed} hat eine Kante, die an keine andere Fläche grenzt</translation>
    </message>
    <message>
        <source>{listed} have edges bordering no other face</source>
        <translation>{listed} haben Kanten, die an keine andere Fläche grenzen</translation>
    </message>
    <message>
        <source>{where}y_window ({y0}, {y1}) must be increasing and inside the stock's y range [{y_min}, {y_max}]</source>
        <translation>{where}y_window ({y0}, {y1}) muss aufsteigend sein und innerhalb des y-Bereichs [{y_min}, {y_max}] des Rohteils liegen</translation>
    </message>
    <message>
        <source>{where}{name}: overhang: faces downwards at z = {z}, above the base (z = {limits_4}); a staircase stands on its base</source>
        <translation>{where}{name}: Überhang: zeigt bei z = {z} nach unten, oberhalb der Basis (z = {limits_4}); ein Treppenstufen-Rohteil steht auf seiner Basis</translation>
    </message>
    <message>
        <source>{where}{label}: wall has no top edge along a top face</source>
        <translation>{where}{label}: Wand hat keine obere Kante entlang einer Deckfläche</translation>
    </message>
    <message>
        <source>{where}{label}: wall has more than one x for y = {points_0_1} (its top edge runs along x there, from x = {x_values_min} to {x_values_max}); {_ALONG_X}</source>
        <translation>{where}{label}: Wand hat mehr als ein x für y = {points_0_1} (ihre obere Kante verläuft dort entlang x, von x = {x_values_min} bis {x_values_max}); {_ALONG_X}</translation>
    </message>
    <message>
        <source>{where}{label}: wall has more than one x for y = {at_1} (its top edge turns back by {back} mm in y near x = {at_0}); {_ALONG_X}</source>
        <translation>{where}{label}: Wand hat mehr als ein x für y = {at_1} (ihre obere Kante läuft nahe x = {at_0} um {back} mm in y zurück); {_ALONG_X}</translation>
    </message>
    <message>
        <source>{where}{label}: wall has more than one x for y = {value} (two of its top edges overlap in y from {low} to {high}); {_ALONG_X}</source>
        <translation>{where}{label}: Wand hat mehr als ein x für y = {value} (zwei ihrer oberen Kanten überlappen sich in y von {low} bis {high}); {_ALONG_X}</translation>
    </message>
    <message>
        <source>{where}{label}: wall does not run across the y window [{y0}, {y1}]: no x at y = {value} (its top edges leave a gap from {high} to {low})</source>
        <translation>{where}{label}: Wand verläuft nicht über das ganze y-Fenster [{y0}, {y1}]: kein x bei y = {value} (ihre oberen Kanten lassen eine Lücke von {high} bis {low})</translation>
    </message>
    <message>
        <source>{where}{label}: wall does not run across the y window [{y0}, {y1}]: no x at y = {y} (its top edge spans y {y_low} to {y_high}); {_ALONG_X}</source>
        <translation>{where}{label}: Wand verläuft nicht über das ganze y-Fenster [{y0}, {y1}]: kein x bei y = {y} (ihre obere Kante überspannt y {y_low} bis {y_high}); {_ALONG_X}</translation>
    </message>
    <message>
        <source>a staircase's walls run across y with one x for each y</source>
        <translation>die Wände eines Treppenstufen-Rohteils verlaufen quer zu y, mit einem x für jedes y</translation>
    </message>
    <message>
        <source>{where}{value}: top face at z = {z} does not reach y = {y_probe}: a section must have one top across the y window</source>
        <translation>{where}{value}: Deckfläche bei z = {z} reicht nicht bis y = {y_probe}: ein Abschnitt muss über das ganze y-Fenster eine einzige Oberseite haben</translation>
    </message>
    <message>
        <source>more than one top face: {listed}</source>
        <translation>mehr als eine Deckfläche: {listed}</translation>
    </message>
    <message>
        <source>no top face</source>
        <translation>keine Deckfläche</translation>
    </message>
    <message>
        <source>{where}section {j} (x {x_probe_j} to {x_probe_j_1} at y = {y_probe}) has {what}</source>
        <translation>{where}Abschnitt {j} (x {x_probe_j} bis {x_probe_j_1} bei y = {y_probe}) hat {what}</translation>
    </message>
    <message>
        <source>{where}{join_wall_faces}: wall between sections {j_1} and {j} spans z {wall_z_range_0} to {wall_z_range_1}, but the tops beside it are at {low} and {high}</source>
        <translation>{where}{join_wall_faces}: Wand zwischen den Abschnitten {j_1} und {j} überspannt z {wall_z_range_0} bis {wall_z_range_1}, aber die Oberseiten daneben liegen bei {low} und {high}</translation>
    </message>
    <message>
        <source>the B-spline wall spans y {start} to {end}, not all of [{y_lo}, {y_hi}]</source>
        <translation>die B-Spline-Wand überspannt y {start} bis {end}, nicht ganz [{y_lo}, {y_hi}]</translation>
    </message>
    <message>
        <source>fusing the {count} sections gave {count_2} solids, expected 1</source>
        <translation>das Vereinigen der {count} Abschnitte ergab {count_2} Volumenkörper, erwartet: 1</translation>
    </message>
    <message>
        <source>the fused staircase solid is not valid</source>
        <translation>der vereinigte Volumenkörper des Treppenstufen-Rohteils ist ungültig</translation>
    </message>
    <message>
        <source>{error} (the paper's quintic walls need a staircase stock)</source>
        <translation>{error} (die quintischen Wände des Artikels erfordern ein Treppenstufen-Rohteil)</translation>
    </message>
    <message>
        <source>no wall face</source>
        <translation>keiner Wandfläche</translation>
    </message>
    <message>
        <source>{where}slab {k}: the section at z = {z} near x = {x}, y = {y} lies on {found}; expected one vertical wall</source>
        <translation>{where}Schicht {k}: der Schnitt bei z = {z} nahe x = {x}, y = {y} liegt auf {found}; erwartet: eine senkrechte Wand</translation>
    </message>
    <message>
        <source>{where}slab {k}: the section's curve ending at x = {end_0}, y = {end_1} ({face}) does not continue: the walls do not close</source>
        <translation>{where}Schicht {k}: die bei x = {end_0}, y = {end_1} endende Kurve des Schnitts ({face}) setzt sich nicht fort: die Wände schließen sich nicht</translation>
    </message>
    <message>
        <source>{where}slab {k}: the curve recognised on {face} passes {distance} mm from it near x = {x}, y = {y}: not recognised</source>
        <translation>{where}Schicht {k}: die auf {face} erkannte Kurve verläuft nahe x = {x}, y = {y} in {distance} mm Abstand davon: nicht erkannt</translation>
    </message>
    <message>
        <source>{where}slab {k} (z {z_bottom} to {z_top}): the region recognised has area {found} mm² but the solid's section {expected} mm²: not recognised</source>
        <translation>{where}Schicht {k} (z {z_bottom} bis {z_top}): der erkannte Bereich hat einen Flächeninhalt von {found} mm², der Schnitt des Volumenkörpers aber {expected} mm²: nicht erkannt</translation>
    </message>
    <message>
        <source>the terraced stock gave no solid</source>
        <translation>das terrassierte Rohteil ergab keinen Volumenkörper</translation>
    </message>
    <message>
        <source>the terraced solid is not valid</source>
        <translation>der terrassierte Volumenkörper ist ungültig</translation>
    </message>
    <message>
        <source>{name}: no such file</source>
        <translation>{name}: Datei nicht vorhanden</translation>
    </message>
    <message>
        <source>{name}: cannot open as a FreeCAD document: {error}</source>
        <translation>{name}: lässt sich nicht als FreeCAD-Dokument öffnen: {error}</translation>
    </message>
    <message>
        <source>{path}: no FreeCAD CAM Job in the document</source>
        <translation>{path}: kein FreeCAD-CAM-Job im Dokument</translation>
    </message>
    <message>
        <source>{path}: several CAM Jobs ({listed}): choose one with --cam-job NAME</source>
        <translation>{path}: mehrere CAM-Jobs ({listed}): wählen Sie einen mit --cam-job NAME</translation>
    </message>
    <message>
        <source>{path}: {value} CAM Job named {name} (its Jobs: {listed_or_none})</source>
        <translation>{path}: {value} CAM-Job(s) namens {name} (Jobs des Dokuments: {listed_or_none})</translation>
    </message>
    <message>
        <source>{os_fspath_path}: the CAM Job {Label} has no Stock: give the stock (--stock)</source>
        <translation>{os_fspath_path}: der CAM-Job {Label} hat kein Rohteil: geben Sie das Rohteil an (--stock)</translation>
    </message>
    <message>
        <source>{name}: T{number}: the tool controllers {owners_number} and {Label} give tool {number_2} different tools ({value}, {tool_describe})</source>
        <translation>{name}: T{number}: die Werkzeugcontroller {owners_number} und {Label} weisen der Werkzeugnummer {number_2} verschiedene Werkzeuge zu ({value}, {tool_describe})</translation>
    </message>
    <message>
        <source>feed has {size} values, {operation_label} {size_2} CL points</source>
        <translation>feed hat {size} Werte, {operation_label} hat {size_2} CL-Punkte</translation>
    </message>
    <message>
        <source>{Label}: {Label_2} has {count} commands now, the schedule {count_2}: the operation changed since its feeds were scheduled; schedule again</source>
        <translation>{Label}: {Label_2} hat jetzt {count} Befehle, der Plan {count_2}: die Operation wurde geändert, seit ihre Vorschübe geplant wurden; planen Sie erneut</translation>
    </message>
    <message>
        <source>{source}: the document is open in FreeCAD: add the dressup there, or close it first</source>
        <translation>{source}: das Dokument ist in FreeCAD geöffnet: fügen Sie das Dressup dort hinzu oder schließen Sie es zuerst</translation>
    </message>
    <message>
        <source>{source}: FreeCAD's CAM workbench cannot be imported here, and the document saved without it would lose its CAM objects' behaviour</source>
        <translation>{source}: der CAM-Arbeitsbereich von FreeCAD lässt sich hier nicht importieren, und ein ohne ihn gespeichertes Dokument verlöre das Verhalten seiner CAM-Objekte</translation>
    </message>
    <message>
        <source>{where_line}: {name}: not a G-code command</source>
        <translation>{where_line}: {name}: kein G-Code-Befehl</translation>
    </message>
    <message>
        <source>{source}: toolbit {Label} of shape {shape}: a shape the reader does not know; its kind is unknown</source>
        <translation>{source}: Werkzeug {Label} der Form {shape}: eine Form, die der Leser nicht kennt; seine Art ist unbekannt</translation>
    </message>
    <message>
        <source>{name} must be a {expected}, got {type}</source>
        <translation>{name} muss vom Typ {expected} sein, erhalten: {type}</translation>
    </message>
    <message>
        <source>side must be 'left' or 'right', not {side}</source>
        <translation>side muss 'left' oder 'right' sein, nicht {side}</translation>
    </message>
    <message>
        <source>centre, d and w must all be (N, 3), got {shape}, {shape_2} and {shape_3}</source>
        <translation>centre, d und w müssen alle (N, 3) sein, erhalten: {shape}, {shape_2} und {shape_3}</translation>
    </message>
    <message>
        <source>engage is for straight edges; the tool has a helix angle of {helix} deg: use flute_engagement</source>
        <translation>engage ist für gerade Schneidkanten; das Werkzeug hat einen Drallwinkel von {helix} deg: verwenden Sie flute_engagement</translation>
    </message>
    <message>
        <source>origins {shape} and directions {shape_2} must have the same shape (N, 3)</source>
        <translation>origins {shape} und directions {shape_2} müssen dieselbe Form (N, 3) haben</translation>
    </message>
    <message>
        <source>tool axes must have shape (m, 3), got {shape}</source>
        <translation>die Werkzeugachsen müssen die Form (m, 3) haben, erhalten: {shape}</translation>
    </message>
    <message>
        <source>tool axis {axes_i_tolist} is zero or not finite</source>
        <translation>die Werkzeugachse {axes_i_tolist} ist null oder nicht endlich</translation>
    </message>
    <message>
        <source>flute must be in 0..{self_flutes_1}, got {flute}</source>
        <translation>flute muss in 0..{self_flutes_1} liegen, erhalten: {flute}</translation>
    </message>
    <message>
        <source>immersion must be (start, end) in degrees, got {immersion}</source>
        <translation>immersion muss (start, end) in Grad sein, erhalten: {immersion}</translation>
    </message>
    <message>
        <source>immersion {start}:{end} must be finite and not decreasing</source>
        <translation>immersion {start}:{end} muss endlich und nicht fallend sein</translation>
    </message>
    <message>
        <source>B-spline wall: dy/du vanishes on span {j}; a helical edge needs a wall with bounded curvature</source>
        <translation>B-Spline-Wand: dy/du verschwindet im Knotenintervall {j}; eine helixförmige Kante braucht eine Wand mit beschränkter Krümmung</translation>
    </message>
    <message>
        <source>{name} must have shape {shape}, got {shape_2}</source>
        <translation>{name} muss die Form {shape} haben, erhalten: {shape_2}</translation>
    </message>
    <message>
        <source>{name}{value} is not a finite number</source>
        <translation>{name}{value} ist keine endliche Zahl</translation>
    </message>
    <message>
        <source>line must have shape ({n},), got {shape}</source>
        <translation>line muss die Form ({n},) haben, erhalten: {shape}</translation>
    </message>
    <message>
        <source>row {j} (line {line_j}): tool axis {axis_j_tolist} is not a unit vector</source>
        <translation>Zeile {j} (Dateizeile {line_j}): die Werkzeugachse {axis_j_tolist} ist kein Einheitsvektor</translation>
    </message>
    <message>
        <source>cutting must have shape ({n},), got {shape}</source>
        <translation>cutting muss die Form ({n},) haben, erhalten: {shape}</translation>
    </message>
    <message>
        <source>row {j} (line {line_j}): {name} must be positive, got {values_j}</source>
        <translation>Zeile {j} (Dateizeile {line_j}): {name} muss positiv sein, erhalten: {values_j}</translation>
    </message>
    <message>
        <source>row {j} (line {line_j}): corner_radius must be within [0, radius {self_radius_j}], got {corner_j}</source>
        <translation>Zeile {j} (Dateizeile {line_j}): corner_radius muss in [0, Radius {self_radius_j}] liegen, erhalten: {corner_j}</translation>
    </message>
    <message>
        <source>row {j} (line {line_j}): the tool axis turns by 180° in one cutting move</source>
        <translation>Zeile {j} (Dateizeile {line_j}): die Werkzeugachse dreht sich in einer Schnittbewegung um 180°</translation>
    </message>
    <message>
        <source>rotation must be an orthonormal 3×3 matrix</source>
        <translation>rotation muss eine orthonormale 3×3-Matrix sein</translation>
    </message>
    <message>
        <source>tolerance must be positive, got {tolerance}</source>
        <translation>tolerance muss positiv sein, erhalten: {tolerance}</translation>
    </message>
    <message>
        <source>{n} edge lines are not a whole number of CL points of {p} angles</source>
        <translation>{n} Kantenlinien ergeben keine ganze Zahl von CL-Punkten mit je {p} Winkeln</translation>
    </message>
    <message>
        <source>program_index must have shape ({m},), got {shape}</source>
        <translation>program_index muss die Form ({m},) haben, erhalten: {shape}</translation>
    </message>
    <message>
        <source>spacing must be positive, got {spacing}</source>
        <translation>spacing muss positiv sein, erhalten: {spacing}</translation>
    </message>
    <message>
        <source>centre, bound, move and floor must have one row per ball</source>
        <translation>centre, bound, move und floor müssen eine Zeile pro Kugel haben</translation>
    </message>
    <message>
        <source>the balls must come in program order (move non-decreasing)</source>
        <translation>die Kugeln müssen in Programmreihenfolge vorliegen (move nicht fallend)</translation>
    </message>
    <message>
        <source>{m} CL points × {p} angles need {n} lines; got {n_rows} rows of intervals, {origins_shape_0} origins and {value} directions</source>
        <translation>{m} CL-Punkte × {p} Winkel erfordern {n} Linien; erhalten: {n_rows} Zeilen mit Intervallen, {origins_shape_0} Ursprünge und {value} Richtungen</translation>
    </message>
    <message>
        <source>an interval ends at l = {value} mm, beyond the flute length {flute_length} mm</source>
        <translation>ein Intervall endet bei l = {value} mm, jenseits der Schneidenlänge {flute_length} mm</translation>
    </message>
    <message>
        <source>{name} must have shape (K,) like rows, got {shape}</source>
        <translation>{name} muss wie rows die Form (K,) haben, erhalten: {shape}</translation>
    </message>
    <message>
        <source>rows must be non-decreasing within 0..{self_n_rows_1}</source>
        <translation>rows muss innerhalb von 0..{self_n_rows_1} nicht fallend sein</translation>
    </message>
    <message>
        <source>{name} must be a number, got {type} {value}</source>
        <translation>{name} muss eine Zahl sein, erhalten: {type} {value}</translation>
    </message>
    <message>
        <source>{name} must be a finite number, got {value}</source>
        <translation>{name} muss eine endliche Zahl sein, erhalten: {value}</translation>
    </message>
    <message>
        <source>{name} must be positive, got {value}</source>
        <translation>{name} muss positiv sein, erhalten: {value}</translation>
    </message>
    <message>
        <source>{name} must be at most {largest} in size, got {number}</source>
        <translation>{name} darf höchstens {largest} groß sein, erhalten: {number}</translation>
    </message>
    <message>
        <source>{name} must be an array of numbers, got {type}</source>
        <translation>{name} muss ein Array von Zahlen sein, erhalten: {type}</translation>
    </message>
    <message>
        <source>{name} must be an array of numbers</source>
        <translation>{name} muss ein Array von Zahlen sein</translation>
    </message>
    <message>
        <source>{name} must have shape {expected}, got {shape}</source>
        <translation>{name} muss die Form {expected} haben, erhalten: {shape}</translation>
    </message>
    <message>
        <source>{name}{list_index} is not a finite number</source>
        <translation>{name}{list_index} ist keine endliche Zahl</translation>
    </message>
    <message>
        <source>flutes must be a whole number, got {flutes}</source>
        <translation>flutes muss eine ganze Zahl sein, erhalten: {flutes}</translation>
    </message>
    <message>
        <source>helix must be within [-{MAX_HELIX}, {MAX_HELIX_2}] degrees (flat-end mills have helix angles up to about {MAX_HELIX_3}°), got {helix}</source>
        <translation>helix muss in [-{MAX_HELIX}, {MAX_HELIX_2}] Grad liegen (Schaftfräser haben Drallwinkel bis etwa {MAX_HELIX_3}°), erhalten: {helix}</translation>
    </message>
    <message>
        <source>corner_radius must be within [0, {value}] mm (half the diameter: a ball), got {corner}</source>
        <translation>corner_radius muss in [0, {value}] mm liegen (halber Durchmesser: ein Kugelfräser), erhalten: {corner}</translation>
    </message>
    <message>
        <source>helical flutes on a corner are not computed: a tool with a corner radius needs straight flutes (helix 0)</source>
        <translation>gedrallte Schneiden an einer Ecke werden nicht berechnet: ein Werkzeug mit Eckenradius braucht gerade Schneiden (helix 0)</translation>
    </message>
    <message>
        <source>x_min ({x_min}) must be below x_max ({x_max})</source>
        <translation>x_min ({x_min}) muss kleiner als x_max ({x_max}) sein</translation>
    </message>
    <message>
        <source>y_min ({y_min}) must be below y_max ({y_max})</source>
        <translation>y_min ({y_min}) muss kleiner als y_max ({y_max}) sein</translation>
    </message>
    <message>
        <source>a staircase needs at least one section</source>
        <translation>ein Treppenstufen-Rohteil braucht mindestens einen Abschnitt</translation>
    </message>
    <message>
        <source>sections[{j}]: z_top {z_top_j} must be above base_z {base_z}</source>
        <translation>sections[{j}]: z_top {z_top_j} muss über base_z {base_z} liegen</translation>
    </message>
    <message>
        <source>{size} sections need {z_top_size_1} walls, got {points_shape_0}</source>
        <translation>{size} Abschnitte brauchen {z_top_size_1} Wände, erhalten: {points_shape_0}</translation>
    </message>
    <message>
        <source>wall_curves must be {count} Wall or SplineWall objects</source>
        <translation>wall_curves muss aus {count} Wall- oder SplineWall-Objekten bestehen</translation>
    </message>
    <message>
        <source>sections[{j}].wall: x = {x_k} at y = {y_k} is not beyond {previous_name} ({previous_k}); walls must be ordered along +x inside [y_min, y_max]</source>
        <translation>sections[{j}].wall: x = {x_k} bei y = {y_k} liegt nicht hinter {previous_name} ({previous_k}); Wände müssen innerhalb [y_min, y_max] entlang +x geordnet sein</translation>
    </message>
    <message>
        <source>sections[{count}].wall: x = {previous_k} at y = {y_k} is not below x_max ({x_max})</source>
        <translation>sections[{count}].wall: x = {previous_k} bei y = {y_k} liegt nicht unter x_max ({x_max})</translation>
    </message>
    <message>
        <source>a toolpath needs at least one CL point</source>
        <translation>eine Werkzeugbahn braucht mindestens einen CL-Punkt</translation>
    </message>
    <message>
        <source>{name} = {angles_i} must be within [-{limit}, {limit_2}] degrees</source>
        <translation>{name} = {angles_i} muss innerhalb [-{limit}, {limit_2}] Grad liegen</translation>
    </message>
    <message>
        <source>inclination = {inclination_i} must be within [-90, 90] degrees</source>
        <translation>inclination = {inclination_i} muss innerhalb [-90, 90] Grad liegen</translation>
    </message>
    <message>
        <source>inclination must be within (-90, 90) degrees, got {inclination}</source>
        <translation>inclination muss innerhalb (-90, 90) Grad liegen, erhalten: {inclination}</translation>
    </message>
    <message>
        <source>phi range {phi_start}:{phi_end} must not be decreasing</source>
        <translation>der phi-Bereich {phi_start}:{phi_end} darf nicht fallend sein</translation>
    </message>
    <message>
        <source>phi range / phi step gives more than 10^6 angles</source>
        <translation>phi-Bereich / phi-Schrittweite ergibt mehr als 10^6 Winkel</translation>
    </message>
    <message>
        <source>stock must be a Staircase or a TerracedStock, got {type}</source>
        <translation>das Rohteil muss ein Staircase oder ein TerracedStock sein, erhalten: {type}</translation>
    </message>
    <message>
        <source>in_process_runs is for tools with a corner radius; a flat-end tool's edges are lines (in_process_lengths)</source>
        <translation>in_process_runs ist für Werkzeuge mit Eckenradius gedacht; die Schneidkanten eines Schaftfräsers sind Geraden (in_process_lengths)</translation>
    </message>
    <message>
        <source>origins and directions must both be (N, 3), got {shape} and {shape_2}</source>
        <translation>origins und directions müssen beide die Form (N, 3) haben, erhalten: {shape} und {shape_2}</translation>
    </message>
    <message>
        <source>slab {k}: an odd number of boundary crossings on a line</source>
        <translation>Schicht {k}: ungerade Anzahl von Schnittpunkten mit dem Rand auf einer Geraden</translation>
    </message>
    <message>
        <source>engage_terraced is for straight edges; the tool has a helix angle of {helix} deg</source>
        <translation>engage_terraced ist für gerade Schneidkanten gedacht; das Werkzeug hat einen Drallwinkel von {helix} deg</translation>
    </message>
    <message>
        <source>{name} must be a finite [x, y] point, got {value}</source>
        <translation>{name} muss ein endlicher [x, y]-Punkt sein, erhalten: {value}</translation>
    </message>
    <message>
        <source>line from {value} to {self_end_tolist} has no length</source>
        <translation>die Strecke von {value} nach {self_end_tolist} hat keine Länge</translation>
    </message>
    <message>
        <source>sweep must be non-zero and at most 2π in size, got {sweep}</source>
        <translation>sweep muss ungleich null und betragsmäßig höchstens 2π sein, erhalten: {sweep}</translation>
    </message>
    <message>
        <source>degree must be a whole number, got {degree}</source>
        <translation>degree muss eine ganze Zahl sein, erhalten: {degree}</translation>
    </message>
    <message>
        <source>control must be (n, 2) with n ≥ degree + 1 = {degree_1}, got {shape}</source>
        <translation>control muss die Form (n, 2) mit n ≥ degree + 1 = {degree_1} haben, erhalten: {shape}</translation>
    </message>
    <message>
        <source>knots must have n + degree + 1 = {n_degree_1} values, got {shape}</source>
        <translation>knots muss n + degree + 1 = {n_degree_1} Werte haben, erhalten: {shape}</translation>
    </message>
    <message>
        <source>knots and control points must be finite</source>
        <translation>die Knoten und Kontrollpunkte müssen endlich sein</translation>
    </message>
    <message>
        <source>knots must be non-decreasing with knots[n] &gt; knots[degree]</source>
        <translation>knots muss nicht fallend sein, mit knots[n] &gt; knots[degree]</translation>
    </message>
    <message>
        <source>weights must be {n} positive numbers</source>
        <translation>weights muss aus {n} positiven Zahlen bestehen</translation>
    </message>
    <message>
        <source>a loop needs at least one curve</source>
        <translation>eine Kontur (Loop) braucht mindestens eine Kurve</translation>
    </message>
    <message>
        <source>curves[{c}] must be a PlanLine, PlanArc or PlanSpline, got {type}</source>
        <translation>curves[{c}] muss eine PlanLine, PlanArc oder PlanSpline sein, erhalten: {type}</translation>
    </message>
    <message>
        <source>curves[{c}] ends at {value} but the next curve starts {gap} mm away: a loop must be closed</source>
        <translation>curves[{c}] endet bei {value}, aber die nächste Kurve beginnt {gap} mm entfernt: eine Kontur muss geschlossen sein</translation>
    </message>
    <message>
        <source>z_top {z_top} must be above z_bottom {z_bottom}</source>
        <translation>z_top {z_top} muss über z_bottom {z_bottom} liegen</translation>
    </message>
    <message>
        <source>a slab needs one or more Loop objects</source>
        <translation>eine Schicht braucht ein oder mehrere Loop-Objekte</translation>
    </message>
    <message>
        <source>a terraced stock needs at least one slab</source>
        <translation>ein terrassiertes Rohteil braucht mindestens eine Schicht</translation>
    </message>
    <message>
        <source>slabs[{k}] must be a Slab, got {type}</source>
        <translation>slabs[{k}] muss ein Slab sein, erhalten: {type}</translation>
    </message>
    <message>
        <source>slabs[{k}] starts at z {z_bottom} but slabs[{k_1}] ends at {z_top}: slabs must be stacked without gaps</source>
        <translation>slabs[{k}] beginnt bei z {z_bottom}, aber slabs[{k_1}] endet bei {z_top}: Schichten müssen lückenlos übereinanderliegen</translation>
    </message>
    <message>
        <source>not a plan curve: {type}</source>
        <translation>keine Grundrisskurve: {type}</translation>
    </message>
    <message>
        <source>{face}: the B-spline runs over y {wall_span_y_0} to {wall_span_y_1}, not across the window {y_min} to {y_max}</source>
        <translation>{face}: der B-Spline reicht in y von {wall_span_y_0} bis {wall_span_y_1}, nicht über das ganze Fenster von {y_min} bis {y_max}</translation>
    </message>
    <message>
        <source>a wall needs six [x, y] points, shape (6, 2); got {shape}</source>
        <translation>eine Wand braucht sechs [x, y]-Punkte, Form (6, 2); erhalten: {shape}</translation>
    </message>
    <message>
        <source>wall points must be finite numbers</source>
        <translation>die Wandpunkte müssen endliche Zahlen sein</translation>
    </message>
    <message>
        <source>wall points need six distinct y values, got {y_tolist}</source>
        <translation>die Wandpunkte brauchen sechs verschiedene y-Werte, erhalten: {y_tolist}</translation>
    </message>
    <message>
        <source>B-spline wall: {poles_shape_0} poles of degree {p} need {value} knots</source>
        <translation>B-Spline-Wand: {poles_shape_0} Pole vom Grad {p} brauchen {value} Knoten</translation>
    </message>
    <message>
        <source>B-spline wall: weights must be positive, one per pole</source>
        <translation>B-Spline-Wand: die Gewichte müssen positiv sein, eines je Pol</translation>
    </message>
    <message>
        <source>B-spline wall: y must be strictly monotone along the curve</source>
        <translation>B-Spline-Wand: y muss entlang der Kurve streng monoton sein</translation>
    </message>
    <message>
        <source>grid {grid} mm gives {nx} x {ny} cells, more than {MAX_CELLS}</source>
        <translation>ein Raster von {grid} mm ergibt {nx} x {ny} Zellen, mehr als {MAX_CELLS}</translation>
    </message>
    <message>
        <source>the Z-map samples a straight edge; the tool has a helix angle of {helix} deg</source>
        <translation>die Z-Map tastet eine gerade Schneidkante ab; das Werkzeug hat einen Drallwinkel von {helix} deg</translation>
    </message>
    <message>
        <source>the Z-map samples a flat-end mill's edge; the tool has a corner radius of {corner_radius} mm</source>
        <translation>die Z-Map tastet die Schneidkante eines Schaftfräsers ab; das Werkzeug hat einen Eckenradius von {corner_radius} mm</translation>
    </message>
    <message>
        <source>edge_step {step} mm gives {p_n_1} samples per CL point, more than {MAX_SAMPLES}</source>
        <translation>edge_step {step} mm ergibt {p_n_1} Abtastpunkte je CL-Punkt, mehr als {MAX_SAMPLES}</translation>
    </message>
    <message>
        <source>{name} must be a number, got {value}</source>
        <translation>{name} muss eine Zahl sein, erhalten: {value}</translation>
    </message>
    <message>
        <source>{name} must be a positive number of mm, got {value}</source>
        <translation>{name} muss eine positive Zahl in mm sein, erhalten: {value}</translation>
    </message>
    <message>
        <source>{prop} {path} is missing; using {moved}</source>
        <translation>{prop} {path} fehlt; {moved} wird verwendet</translation>
    </message>
    <message>
        <source>no document: open or create a FreeCAD document first (FreeCAD.newDocument())</source>
        <translation>kein Dokument: öffnen oder erstellen Sie zuerst ein FreeCAD-Dokument (FreeCAD.newDocument())</translation>
    </message>
    <message>
        <source> (property {prop})</source>
        <translation> (Eigenschaft {prop})</translation>
    </message>
    <message>
        <source>WallModel {walls} applies to a solid stock (.step, .stp, .brep, .brp, .FCStd), not to {value}</source>
        <translation>WallModel {walls} gilt für ein Volumenkörper-Rohteil (.step, .stp, .brep, .brp, .FCStd), nicht für {value}</translation>
    </message>
    <message>
        <source>{source}: earlier moves of the program already removed all the material this operation's tool would meet (StockModel initial computes it against the stock as given)</source>
        <translation>{source}: frühere Bewegungen des Programms haben bereits das gesamte Material entfernt, auf das das Werkzeug dieser Operation treffen würde (StockModel initial rechnet gegen das Rohteil in seiner angegebenen Form)</translation>
    </message>
    <message>
        <source>{source}: the tool never touches the stock: no CL point of the pass engages it (are the toolpath and {value} in the same frame?)</source>
        <translation>{source}: das Werkzeug berührt das Rohteil nie: an keinem CL-Punkt des Durchgangs ist es im Eingriff (liegen die Werkzeugbahn und {value} im selben Koordinatensystem?)</translation>
    </message>
    <message>
        <source>{Label}: {value} (property {prop}).</source>
        <translation>{Label}: {value} (Eigenschaft {prop}).</translation>
    </message>
    <message>
        <source>results in the document not read ({error})</source>
        <translation>Ergebnisse im Dokument nicht gelesen ({error})</translation>
    </message>
    <message>
        <source>{path}: not the results saved with the document (recomputed since?)</source>
        <translation>{path}: nicht die mit dem Dokument gespeicherten Ergebnisse (inzwischen neu berechnet?)</translation>
    </message>
    <message>
        <source>{path}: {size} instants, the object says {Instants}</source>
        <translation>{path}: {size} Zeitpunkte, das Objekt gibt {Instants} an</translation>
    </message>
    <message>
        <source>{path}: no force columns, but Forces is on</source>
        <translation>{path}: keine Kraftspalten, aber Forces ist eingeschaltet</translation>
    </message>
    <message>
        <source>{path}: not computed against the stock model {StockModelUsed}</source>
        <translation>{path}: nicht gegen das Rohteilmodell {StockModelUsed} berechnet</translation>
    </message>
    <message>
        <source>results not restored ({error}); recompute to compute them</source>
        <translation>Ergebnisse nicht wiederhergestellt ({error}); berechnen Sie neu, um sie zu erhalten</translation>
    </message>
    <message>
        <source>{Label}: {role} must link an ABM {role_2} object</source>
        <translation>{Label}: {role} muss auf ein ABM-{role_2}-Objekt verweisen</translation>
    </message>
    <message>
        <source>YWindow {YWindow} applies to a solid stock (.step, .stp, .brep, .brp, .FCStd), not to {value}</source>
        <translation>YWindow {YWindow} gilt für ein Volumenkörper-Rohteil (.step, .stp, .brep, .brp, .FCStd), nicht für {value}</translation>
    </message>
    <message>
        <source>{Label}: YWindowMin ({low} mm) must be below YWindowMax ({high} mm)</source>
        <translation>{Label}: YWindowMin ({low} mm) muss kleiner als YWindowMax ({high} mm) sein</translation>
    </message>
    <message>
        <source>{value}: y window {low}..{high} mm misses the stock's y range {YMin}..{YMax} mm</source>
        <translation>{value}: das y-Fenster {low}..{high} mm verfehlt den y-Bereich des Rohteils {YMin}..{YMax} mm</translation>
    </message>
    <message>
        <source>cannot write results: {error}</source>
        <translation>Ergebnisse können nicht geschrieben werden: {error}</translation>
    </message>
    <message>
        <source>create_engagement: unknown setting {unknown_0} (known: {join_SETTINGS})</source>
        <translation>create_engagement: unbekannte Einstellung {unknown_0} (bekannt: {join_SETTINGS})</translation>
    </message>
    <message>
        <source>walls must be one of {WALL_CHOICES}, got {walls}</source>
        <translation>walls muss einer der Werte {WALL_CHOICES} sein, erhalten: {walls}</translation>
    </message>
    <message>
        <source>y_window must be auto, whole, swept or (y0, y1), got {y_window}</source>
        <translation>y_window muss auto, whole, swept oder (y0, y1) sein, erhalten: {y_window}</translation>
    </message>
    <message>
        <source>{Label}: Engagement must link an ABM Engagement object</source>
        <translation>{Label}: Engagement muss auf ein ABM-Engagement-Objekt verweisen</translation>
    </message>
    <message>
        <source>{Label}: CLPoint {CLPoint} is not a CL point of {Label_2} (0..{len_rows_1})</source>
        <translation>{Label}: CLPoint {CLPoint} ist kein CL-Punkt von {Label_2} (0..{len_rows_1})</translation>
    </message>
    <message>
        <source>{outlined} of the {count} earlier pieces near CL point {CLPoint} are moves of a tool with a corner: they are cut as the hull of the flat-end cylinder of their radius, which holds their volume, so the view shows less stock beside the corner than is left (the engine and validate take their exact volumes)</source>
        <translation>{outlined} der {count} früheren Stücke nahe CL-Punkt {CLPoint} sind Bewegungen eines Werkzeugs mit Eckenradius: sie werden als Hülle des Schaftfräser-Zylinders ihres Radius abgezogen, die ihr Volumen enthält, daher zeigt die Ansicht neben der Ecke weniger Rohteil, als übrig ist (der Rechenkern und die Validierung nehmen ihre genauen Volumen)</translation>
    </message>
    <message>
        <source>{Label}: the linked object has no shape</source>
        <translation>{Label}: das verknüpfte Objekt hat keine Geometrie (Shape)</translation>
    </message>
    <message>
        <source>{Label}: no stock source: set SourceObject or SourceFile</source>
        <translation>{Label}: keine Rohteilquelle: setzen Sie SourceObject oder SourceFile</translation>
    </message>
    <message>
        <source>walls must be one of {WALL_MODELS}, got {walls}</source>
        <translation>walls muss einer der Werte {WALL_MODELS} sein, erhalten: {walls}</translation>
    </message>
    <message>
        <source>wall_points must be one of {WALL_POINTS}, got {wall_points}</source>
        <translation>wall_points muss einer der Werte {WALL_POINTS} sein, erhalten: {wall_points}</translation>
    </message>
    <message>
        <source>{name}: {size} rows are not the same number of angles for each of {m} CL points</source>
        <translation>{name}: {size} Zeilen ergeben nicht für jeden der {m} CL-Punkte dieselbe Anzahl von Winkeln</translation>
    </message>
    <message>
        <source>{name}: rows are not in CL point order with {p} angles each</source>
        <translation>{name}: die Zeilen sind nicht in CL-Punkt-Reihenfolge mit je {p} Winkeln</translation>
    </message>
    <message>
        <source>{name}: not a results file: missing column {missing_0}</source>
        <translation>{name}: keine Ergebnisdatei: Spalte {missing_0} fehlt</translation>
    </message>
    <message>
        <source>{name}: column {column}: unknown value {unknown_0}</source>
        <translation>{name}: Spalte {column}: unbekannter Wert {unknown_0}</translation>
    </message>
    <message>
        <source>{name}: force columns without {missing_0}</source>
        <translation>{name}: Kraftspalten ohne {missing_0}</translation>
    </message>
    <message>
        <source>{name}: a force column has an empty or non-finite field</source>
        <translation>{name}: eine Kraftspalte hat ein leeres oder nicht endliches Feld</translation>
    </message>
    <message>
        <source>{summary}: no column 'changed', but {name} has length_initial</source>
        <translation>{summary}: keine Spalte 'changed', aber {name} hat length_initial</translation>
    </message>
    <message>
        <source>{name}: not a results archive ({error})</source>
        <translation>{name}: kein Ergebnisarchiv ({error})</translation>
    </message>
    <message>
        <source>{name}: not a results archive: no {value}</source>
        <translation>{name}: kein Ergebnisarchiv: {value} fehlt</translation>
    </message>
    <message>
        <source>{Label}: no toolpath file: set File</source>
        <translation>{Label}: keine Werkzeugbahndatei: setzen Sie File</translation>
    </message>
    <message>
        <source>{Label}: the CAM operation {operation} is not in the program of {Label_2} (inactive, or no moves)</source>
        <translation>{Label}: die CAM-Operation {operation} ist nicht im Programm von {Label_2} (inaktiv oder ohne Bewegungen)</translation>
    </message>
    <message>
        <source>{Label}: {path} holds several operations ({listing}): set the toolpath's Operation property to the number of the one to compute</source>
        <translation>{Label}: {path} enthält mehrere Operationen ({listing}): setzen Sie die Eigenschaft Operation der Werkzeugbahn auf die Nummer der zu berechnenden Operation</translation>
    </message>
    <message>
        <source>ktc must be positive, got {ktc}</source>
        <translation>ktc muss positiv sein, erhalten: {ktc}</translation>
    </message>
    <message>
        <source>unknown material {name} (known: {value})</source>
        <translation>unbekannter Werkstoff {name} (bekannt: {value})</translation>
    </message>
    <message>
        <source>immersion {start}:{end} must satisfy 0 &lt;= start &lt; end &lt;= 180 degrees</source>
        <translation>der Eingriffsbereich {start}:{end} muss 0 &lt;= start &lt; end &lt;= 180 Grad erfüllen</translation>
    </message>
    <message>
        <source>flute {k_1}: {size} angles instead of {size_2}</source>
        <translation>Schneide {k_1}: {size} Winkel statt {size_2}</translation>
    </message>
    <message>
        <source>feed per tooth must be a number or have shape ({m},), got {np_shape_feed}</source>
        <translation>der Vorschub pro Zahn muss eine Zahl sein oder die Form ({m},) haben, erhalten: {np_shape_feed}</translation>
    </message>
    <message>
        <source>feed per tooth must be finite and not negative at every CL point</source>
        <translation>der Vorschub pro Zahn muss an jedem CL-Punkt endlich und nicht negativ sein</translation>
    </message>
    <message>
        <source>lengths must have shape (Z, m, {size}), got {shape}</source>
        <translation>lengths muss die Form (Z, m, {size}) haben, erhalten: {shape}</translation>
    </message>
    <message>
        <source>rotation must have shape ({lengths_shape_1}, 3, 3), got {shape}</source>
        <translation>rotation muss die Form ({lengths_shape_1}, 3, 3) haben, erhalten: {shape}</translation>
    </message>
    <message>
        <source>lengths must be finite and not negative</source>
        <translation>lengths muss endlich und nicht negativ sein</translation>
    </message>
    <message>
        <source>rotation must have shape ({m}, 3, 3), got {shape}</source>
        <translation>rotation muss die Form ({m}, 3, 3) haben, erhalten: {shape}</translation>
    </message>
    <message>
        <source>{name} must be EdgeIntervals (engine.intervals), got {type}</source>
        <translation>{name} muss vom Typ EdgeIntervals (engine.intervals) sein, erhalten: {type}</translation>
    </message>
    <message>
        <source>{name} must have {n_rows} rows (CL points × angles), got {n_rows_2}</source>
        <translation>{name} muss {n_rows} Zeilen (CL-Punkte × Winkel) haben, erhalten: {n_rows_2}</translation>
    </message>
    <message>
        <source>rotation must have shape (m, 3, 3), got {shape}</source>
        <translation>rotation muss die Form (m, 3, 3) haben, erhalten: {shape}</translation>
    </message>
    <message>
        <source>runs must hold one EdgeIntervals per flute ({flutes}), got {count}</source>
        <translation>runs muss ein EdgeIntervals je Schneide ({flutes}) enthalten, erhalten: {count}</translation>
    </message>
    <message>
        <source>runs must be finite</source>
        <translation>runs muss endlich sein</translation>
    </message>
    <message>
        <source>coefficients must be Coefficients (forces.material(name), or your own), got {type}</source>
        <translation>coefficients muss ein Coefficients-Objekt sein (forces.material(name) oder ein eigenes), erhalten: {type}</translation>
    </message>
    <message>
        <source>lengths_at and runs_at are for straight flutes only</source>
        <translation>lengths_at und runs_at gibt es nur für gerade Schneiden</translation>
    </message>
    <message>
        <source>give lengths_at or runs_at, not both</source>
        <translation>geben Sie lengths_at oder runs_at an, nicht beides</translation>
    </message>
    <message>
        <source>the forces of a ball mill need each flute's engaged runs along its corner, not only its lengths of cut: lengths_at (such as the in-process stock's) cannot give them; pass runs_at instead</source>
        <translation>die Kräfte eines Kugelfräsers erfordern die Eingriffsabschnitte jeder Schneide entlang ihres Eckenradius, nicht nur ihre Schnittlängen: lengths_at (etwa die des Zwischenrohteils) kann sie nicht liefern; übergeben Sie stattdessen runs_at</translation>
    </message>
    <message>
        <source>the forces of a bull-nose mill need each flute's engaged runs along its corner, not only its lengths of cut: lengths_at (such as the in-process stock's) cannot give them; pass runs_at instead</source>
        <translation>die Kräfte eines Torusfräsers erfordern die Eingriffsabschnitte jeder Schneide entlang ihres Eckenradius, nicht nur ihre Schnittlängen: lengths_at (etwa die des Zwischenrohteils) kann sie nicht liefern; übergeben Sie stattdessen runs_at</translation>
    </message>
    <message>
        <source>{where}: {stripped} is not a finite number (digits 0-9, optional sign, '.' and exponent)</source>
        <translation>{where}: {stripped} ist keine endliche Zahl (Ziffern 0-9, optionales Vorzeichen, '.' und Exponent)</translation>
    </message>
    <message>
        <source>{where}: {stripped} is not a number (digits 0-9, optional sign, '.' and exponent)</source>
        <translation>{where}: {stripped} ist keine Zahl (Ziffern 0-9, optionales Vorzeichen, '.' und Exponent)</translation>
    </message>
    <message>
        <source>{where}: {number} is too large (at most {MAX_MAGNITUDE} in magnitude)</source>
        <translation>{where}: {number} ist zu groß (Betrag höchstens {MAX_MAGNITUDE})</translation>
    </message>
    <message>
        <source>an output path is empty; give a file name</source>
        <translation>ein Ausgabepfad ist leer; geben Sie einen Dateinamen an</translation>
    </message>
    <message>
        <source>{text}: is a folder; give a file name for the output</source>
        <translation>{text}: ist ein Ordner; geben Sie einen Dateinamen für die Ausgabe an</translation>
    </message>
    <message>
        <source>{text}: is a symbolic link (to {os_readlink_text}); it would be replaced by the output: give the file's own path</source>
        <translation>{text}: ist ein symbolischer Link (auf {os_readlink_text}); er würde durch die Ausgabe ersetzt: geben Sie den eigentlichen Pfad der Datei an</translation>
    </message>
    <message>
        <source>{text}: is {value}, not a file; it would be replaced by the output: give a file name</source>
        <translation>{text}: ist {value}, keine Datei; es würde durch die Ausgabe ersetzt: geben Sie einen Dateinamen an</translation>
    </message>
    <message>
        <source>{text}: the file name is {count} bytes long; at most {longest} are allowed here</source>
        <translation>{text}: der Dateiname ist {count} Bytes lang; hier sind höchstens {longest} erlaubt</translation>
    </message>
    <message>
        <source>give the input file itself</source>
        <translation>geben Sie die Eingabedatei selbst an</translation>
    </message>
    <message>
        <source>give the stock file itself</source>
        <translation>geben Sie die Rohteildatei selbst an</translation>
    </message>
    <message>
        <source>give the toolpath file itself</source>
        <translation>geben Sie die Werkzeugbahndatei selbst an</translation>
    </message>
    <message>
        <source>give the job file itself</source>
        <translation>geben Sie die Auftragsdatei selbst an</translation>
    </message>
    <message>
        <source>give the tool table file itself</source>
        <translation>geben Sie die Werkzeugtabellendatei selbst an</translation>
    </message>
    <message>
        <source>give the machine file itself</source>
        <translation>geben Sie die Maschinendatei selbst an</translation>
    </message>
    <message>
        <source>give the work offsets file itself</source>
        <translation>geben Sie die Datei der Nullpunktverschiebungen selbst an</translation>
    </message>
    <message>
        <source>give the results archive file itself</source>
        <translation>geben Sie die Datei des Ergebnisarchivs selbst an</translation>
    </message>
    <message>
        <source>{name}: cannot read: {value}</source>
        <translation>{name}: kann nicht gelesen werden: {value}</translation>
    </message>
    <message>
        <source>{name}: is {kind_mode}, not a file; {give}</source>
        <translation>{name}: ist {kind_mode}, keine Datei; {give}</translation>
    </message>
    <message>
        <source>a folder</source>
        <translation>ein Ordner</translation>
    </message>
    <message>
        <source>a FIFO (named pipe)</source>
        <translation>ein FIFO (benannte Pipe)</translation>
    </message>
    <message>
        <source>a socket</source>
        <translation>ein Socket</translation>
    </message>
    <message>
        <source>a character device</source>
        <translation>ein zeichenorientiertes Gerät</translation>
    </message>
    <message>
        <source>a block device</source>
        <translation>ein blockorientiertes Gerät</translation>
    </message>
    <message>
        <source>a special file</source>
        <translation>eine Spezialdatei</translation>
    </message>
    <message>
        <source>{name}: is {value}, not a file; give the input file itself</source>
        <translation>{name}: ist {value}, keine Datei; geben Sie die Eingabedatei selbst an</translation>
    </message>
    <message>
        <source>reading its {st_size} bytes</source>
        <translation>das Lesen ihrer {st_size} Bytes</translation>
    </message>
    <message>
        <source>{os_fspath_path}: not UTF-8 text ({reason} at byte {start})</source>
        <translation>{os_fspath_path}: kein UTF-8-Text ({reason} bei Byte {start})</translation>
    </message>
    <message>
        <source>{name}: JSON nested {depth} deep; at most {MAX_JSON_DEPTH} levels are read</source>
        <translation>{name}: JSON ist {depth} Ebenen tief verschachtelt; höchstens {MAX_JSON_DEPTH} Ebenen werden gelesen</translation>
    </message>
    <message>
        <source>{name}:{lineno}:{colno}: invalid JSON: {msg}</source>
        <translation>{name}:{lineno}:{colno}: ungültiges JSON: {msg}</translation>
    </message>
    <message>
        <source>{name}:{value}: duplicate key {key} in one object</source>
        <translation>{name}:{value}: doppelter Schlüssel {key} in einem Objekt</translation>
    </message>
    <message>
        <source>{name}: expected a JSON object {...}, got {type}</source>
        <translation>{name}: erwartet: ein JSON-Objekt {...}, erhalten: {type}</translation>
    </message>
    <message>
        <source>{where}: must be a number, got {json_dumps_value}</source>
        <translation>{where}: muss eine Zahl sein, erhalten: {json_dumps_value}</translation>
    </message>
    <message>
        <source>{where}: an integer of {length} characters is too large (at most {MAX_MAGNITUDE} in magnitude)</source>
        <translation>{where}: eine Ganzzahl mit {length} Zeichen ist zu groß (Betrag höchstens {MAX_MAGNITUDE})</translation>
    </message>
    <message>
        <source>{where}: must be a finite number, got {value}</source>
        <translation>{where}: muss eine endliche Zahl sein, erhalten: {value}</translation>
    </message>
    <message>
        <source>{where}: unknown keys {names} (allowed: {allowed})</source>
        <translation>{where}: unbekannte Schlüssel {names} (erlaubt: {allowed})</translation>
    </message>
    <message>
        <source>{where}: unknown key {names} (allowed: {allowed})</source>
        <translation>{where}: unbekannter Schlüssel {names} (erlaubt: {allowed})</translation>
    </message>
    <message>
        <source>{where}: missing key {missing_0}</source>
        <translation>{where}: fehlender Schlüssel {missing_0}</translation>
    </message>
    <message>
        <source>every GOTO is a rapid move or a canned-cycle hole</source>
        <translation>jedes GOTO ist eine Eilgangbewegung oder eine Bohrung eines Bohrzyklus</translation>
    </message>
    <message>
        <source>no GOTO record</source>
        <translation>kein GOTO-Datensatz</translation>
    </message>
    <message>
        <source>{name}:{last_line}: end of file and no cutting move ({reason})</source>
        <translation>{name}:{last_line}: Dateiende und keine Schnittbewegung ({reason})</translation>
    </message>
    <message>
        <source>{name}:{value}: GOTO: {detail}</source>
        <translation>{name}:{value}: GOTO: {detail}</translation>
    </message>
    <message>
        <source>every feed per tooth written to an APT file must be positive</source>
        <translation>jeder in eine APT-Datei geschriebene Vorschub pro Zahn muss positiv sein</translation>
    </message>
    <message>
        <source>{name}: the chordal tolerance must be at least {MIN_TOLERANCE} mm, got {tolerance} mm</source>
        <translation>{name}: die Sehnentoleranz muss mindestens {MIN_TOLERANCE} mm betragen, erhalten: {tolerance} mm</translation>
    </message>
    <message>
        <source>{name}: the step along arcs and curves must be at least {MIN_TOLERANCE} mm, got {step} mm</source>
        <translation>{name}: die Schrittweite entlang Bögen und Kurven muss mindestens {MIN_TOLERANCE} mm betragen, erhalten: {step} mm</translation>
    </message>
    <message>
        <source>module {__name__} has no attribute {name}</source>
        <translation>das Modul {__name__} hat kein Attribut {name}</translation>
    </message>
    <message>
        <source>give a coarser --tolerance or --step</source>
        <translation>geben Sie eine gröbere --tolerance oder --step an</translation>
    </message>
    <message>
        <source>at least {more} CL points (the program's arcs and curves so far: {so_far})</source>
        <translation>mindestens {more} CL-Punkte (die Kreisbögen und Kurven des Programms bisher: {so_far})</translation>
    </message>
    <message>
        <source>{more} CL points (the program's arcs and curves so far: {so_far})</source>
        <translation>{more} CL-Punkte (die Kreisbögen und Kurven des Programms bisher: {so_far})</translation>
    </message>
    <message>
        <source>interpolating it</source>
        <translation>beim Interpolieren</translation>
    </message>
    <message>
        <source>{so_far} CL points</source>
        <translation>{so_far} CL-Punkte</translation>
    </message>
    <message>
        <source>the circle's axis is zero</source>
        <translation>die Achse des Kreises ist null</translation>
    </message>
    <message>
        <source>the arc's start or end point lies on the circle's axis</source>
        <translation>der Start- oder Endpunkt des Bogens liegt auf der Achse des Kreises</translation>
    </message>
    <message>
        <source>{name}:{value}: tool axis (0, 0, 0) is zero</source>
        <translation>{name}:{value}: die Werkzeugachse (0, 0, 0) ist null</translation>
    </message>
    <message>
        <source>{source}:{value}: tool {kind} is none of {join_KINDS}</source>
        <translation>{source}:{value}: die Werkzeugart {kind} ist keine von {join_KINDS}</translation>
    </message>
    <message>
        <source>its axes are not unit vectors square to each other</source>
        <translation>seine Achsen sind keine zueinander senkrechten Einheitsvektoren</translation>
    </message>
    <message>
        <source>it is a reflection, not a rotation</source>
        <translation>es ist eine Spiegelung, keine Drehung</translation>
    </message>
    <message>
        <source>{name}:{start}: the record ends with the continuation mark '$' but the file ends before it is continued</source>
        <translation>{name}:{start}: der Datensatz endet mit dem Fortsetzungszeichen '$', aber die Datei endet, bevor er fortgesetzt wird</translation>
    </message>
    <message>
        <source>{name}:{line}: record {statement} has no major word before '/'</source>
        <translation>{name}:{line}: der Datensatz {statement} hat kein Hauptwort vor '/'</translation>
    </message>
    <message>
        <source>the knots decrease</source>
        <translation>die Knoten fallen</translation>
    </message>
    <message>
        <source>the knots leave the curve no parameter range</source>
        <translation>die Knoten lassen der Kurve keinen Parameterbereich</translation>
    </message>
    <message>
        <source>knot {knot} is repeated more often than the degree {degree}: the curve breaks there</source>
        <translation>der Knoten {knot} wiederholt sich öfter als der Grad {degree}: die Kurve bricht dort ab</translation>
    </message>
    <message>
        <source>{count} knots and {count_2} control points fit no B-spline of degree 1 to {MAX_DEGREE} (knots = control points + degree + 1, or the end knots written once: control points - degree + 1)</source>
        <translation>{count} Knoten und {count_2} Kontrollpunkte ergeben keinen B-Spline vom Grad 1 bis {MAX_DEGREE} (Knoten = Kontrollpunkte + Grad + 1, oder bei nur einmal geschriebenen Endknoten: Kontrollpunkte - Grad + 1)</translation>
    </message>
    <message>
        <source>{words}, degree {degree}: {reason}</source>
        <translation>{words}, Grad {degree}: {reason}</translation>
    </message>
    <message>
        <source>its knots give no curve ({listed})</source>
        <translation>seine Knoten ergeben keine Kurve ({listed})</translation>
    </message>
    <message>
        <source>the curve bends too sharply to be interpolated (its second derivative is not finite)</source>
        <translation>die Kurve ist zu stark gekrümmt, um interpoliert zu werden (ihre zweite Ableitung ist nicht endlich)</translation>
    </message>
    <message>
        <source>{source}:{first_line}: {self_label}: no cutting moves</source>
        <translation>{source}:{first_line}: {self_label}: keine Schnittbewegungen</translation>
    </message>
    <message>
        <source>a milling tool the ABM engine does not compute yet (it computes flat-end, bull-nose and ball-end mills)</source>
        <translation>ein Fräswerkzeug, das der ABM-Rechenkern noch nicht berechnet (er berechnet Schaft-, Torus- und Kugelfräser)</translation>
    </message>
    <message>
        <source>a turning program, not milling</source>
        <translation>ein Drehprogramm, kein Fräsen</translation>
    </message>
    <message>
        <source>not a milling tool (the ABM engine computes flat-end, bull-nose and ball-end mills)</source>
        <translation>kein Fräswerkzeug (der ABM-Rechenkern berechnet Schaft-, Torus- und Kugelfräser)</translation>
    </message>
    <message>
        <source>operation {number}: {what}: {reason}</source>
        <translation>Operation {number}: {what}: {reason}</translation>
    </message>
    <message>
        <source>operation {number}: no cutting moves ({holes} canned-cycle hole positions)</source>
        <translation>Operation {number}: keine Schnittbewegungen ({holes} Bohrpositionen aus Bohrzyklen)</translation>
    </message>
    <message>
        <source>operation {number}: no cutting moves</source>
        <translation>Operation {number}: keine Schnittbewegungen</translation>
    </message>
    <message>
        <source>{source}: operation {n}: the program has operations 1 to {count}</source>
        <translation>{source}: Operation {n}: das Programm hat die Operationen 1 bis {count}</translation>
    </message>
    <message>
        <source>{source}: no operation: the file has no moves</source>
        <translation>{source}: keine Operation: die Datei enthält keine Bewegungen</translation>
    </message>
    <message>
        <source>{count} milling operations; choose one with --operation N</source>
        <translation>{count} Fräsoperationen; wählen Sie eine mit --operation N</translation>
    </message>
    <message>
        <source>no operation the engine can run: {refusals}</source>
        <translation>keine Operation, die der Rechenkern ausführen kann: {refusals}</translation>
    </message>
    <message>
        <source>{source}: {reason}; operations: {listing}</source>
        <translation>{source}: {reason}; Operationen: {listing}</translation>
    </message>
    <message>
        <source>{value}; the record is skipped (the engine does not need it)</source>
        <translation>{value}; der Datensatz wird übersprungen (der Rechenkern braucht ihn nicht)</translation>
    </message>
    <message>
        <source>argument {position} {arg} is not a number</source>
        <translation>Argument {position} {arg} ist keine Zahl</translation>
    </message>
    <message>
        <source>argument {position} is empty</source>
        <translation>Argument {position} ist leer</translation>
    </message>
    <message>
        <source>argument {position} {arg} is not a number of at most {MAX_MAGNITUDE} in magnitude</source>
        <translation>Argument {position} {arg} ist keine Zahl mit einem Betrag von höchstens {MAX_MAGNITUDE}</translation>
    </message>
    <message>
        <source>argument {position} {arg} is neither a number nor a word</source>
        <translation>Argument {position} {arg} ist weder eine Zahl noch ein Wort</translation>
    </message>
    <message>
        <source>tool axis (0, 0, 0) is zero</source>
        <translation>die Werkzeugachse (0, 0, 0) ist null</translation>
    </message>
    <message>
        <source>takes x,y,z or x,y,z,i,j,k, got {count} number(s)</source>
        <translation>erwartet x,y,z oder x,y,z,i,j,k, erhalten: {count} Zahl(en)</translation>
    </message>
    <message>
        <source>the arc of the CIRCLE on line {circle_line} has no start point (no move before it)</source>
        <translation>der Bogen des CIRCLE in Zeile {circle_line} hat keinen Startpunkt (keine Bewegung davor)</translation>
    </message>
    <message>
        <source>the arc of the CIRCLE on line {circle_line}: {error}</source>
        <translation>der Bogen des CIRCLE in Zeile {circle_line}: {error}</translation>
    </message>
    <message>
        <source>the arc's {label} point is {off} mm off the circle of radius {radius} mm; the arc follows the points</source>
        <translation>der {label} Punkt des Bogens liegt {off} mm neben dem Kreis mit Radius {radius} mm; der Bogen folgt den Punkten</translation>
    </message>
    <message>
        <source>needs xc,yc,zc,i,j,k[,r], got {count} number(s)</source>
        <translation>erfordert xc,yc,zc,i,j,k[,r], erhalten: {count} Zahl(en)</translation>
    </message>
    <message>
        <source>expected numbers and one direction (CLOCKWISE or COUNTERCLOCKWISE), got {value}</source>
        <translation>erwartet wurden Zahlen und eine Richtung (CLOCKWISE oder COUNTERCLOCKWISE), erhalten: {value}</translation>
    </message>
    <message>
        <source>the circle's axis (0, 0, 0) is zero</source>
        <translation>die Achse des Kreises (0, 0, 0) ist null</translation>
    </message>
    <message>
        <source>a relative move needs a position before it</source>
        <translation>eine relative Bewegung braucht eine vorangehende Position</translation>
    </message>
    <message>
        <source>takes d or dx,dy,dz, got {count} number(s)</source>
        <translation>erwartet d oder dx,dy,dz, erhalten: {count} Zahl(en)</translation>
    </message>
    <message>
        <source>{word_upper}: a number above {MAX_MAGNITUDE} in magnitude</source>
        <translation>{word_upper}: eine Zahl, betragsmäßig größer als {MAX_MAGNITUDE}</translation>
    </message>
    <message>
        <source>a control point needs x,y,z[,w], got {count} number(s)</source>
        <translation>ein Kontrollpunkt erfordert x,y,z[,w], erhalten: {count} Zahl(en)</translation>
    </message>
    <message>
        <source>the NURBS block has no CNTRL records</source>
        <translation>der NURBS-Block hat keine CNTRL-Datensätze</translation>
    </message>
    <message>
        <source>a rational NURBS (control points of different weights) is not read</source>
        <translation>ein rationaler NURBS (Kontrollpunkte mit unterschiedlichen Gewichten) wird nicht gelesen</translation>
    </message>
    <message>
        <source>the control points mix x,y,z and x,y,z,w</source>
        <translation>die Kontrollpunkte mischen x,y,z und x,y,z,w</translation>
    </message>
    <message>
        <source>the curve ({words}, degree {degree}) starts {gap} mm from the tool's position; the tool moves there in a straight line</source>
        <translation>die Kurve ({words}, Grad {degree}) beginnt {gap} mm von der Position des Werkzeugs entfernt; das Werkzeug fährt geradlinig dorthin</translation>
    </message>
    <message>
        <source>{join_record_args} gives no axis i,j,k; the axis is kept</source>
        <translation>{join_record_args} gibt keine Achse i,j,k an; die Achse bleibt</translation>
    </message>
    <message>
        <source>{join_record_args} gives no feed rate; the feed is kept</source>
        <translation>{join_record_args} gibt keinen Vorschub an; der Vorschub bleibt</translation>
    </message>
    <message>
        <source>feed rate must be positive, got {numbers_0}</source>
        <translation>die Vorschubgeschwindigkeit muss positiv sein, erhalten: {numbers_0}</translation>
    </message>
    <message>
        <source>surface speed {speed} {surface} for {value} gives no spindle speed in rpm</source>
        <translation>Schnittgeschwindigkeit {speed} {surface} für {value} ergibt keine Drehzahl in U/min</translation>
    </message>
    <message>
        <source>expected MM or INCHES, got {join_record_args}</source>
        <translation>erwartet: MM oder INCHES, erhalten: {join_record_args}</translation>
    </message>
    <message>
        <source>{join_record_args}: cutter compensation in the control; the CL points are taken as the tool tip's centre as written (an offset the control adds, such as wear, is left out)</source>
        <translation>{join_record_args}: Fräserradiuskorrektur in der Steuerung; die CL-Punkte werden wie geschrieben als Mittelpunkt der Werkzeugspitze genommen (ein Versatz, den die Steuerung hinzufügt, etwa für Verschleiß, bleibt unberücksichtigt)</translation>
    </message>
    <message>
        <source>{join_record_args} gives no diameter; not read</source>
        <translation>{join_record_args} gibt keinen Durchmesser an; nicht gelesen</translation>
    </message>
    <message>
        <source>diameter must be positive, got {numbers_0}</source>
        <translation>der Durchmesser muss positiv sein, erhalten: {numbers_0}</translation>
    </message>
    <message>
        <source>{join_record_args} is no flute length; not read</source>
        <translation>{join_record_args} ist keine Schneidenlänge; nicht gelesen</translation>
    </message>
    <message>
        <source>needs 9 numbers (origin, X axis, Y axis), got {count}</source>
        <translation>erfordert 9 Zahlen (Ursprung, X-Achse, Y-Achse), erhalten: {count}</translation>
    </message>
    <message>
        <source>needs 12 numbers (a 3 x 4 matrix, row by row), got {count}</source>
        <translation>erfordert 12 Zahlen (eine 3 x 4-Matrix, zeilenweise), erhalten: {count}</translation>
    </message>
    <message>
        <source>not a frame: {frame}</source>
        <translation>kein Koordinatensystem: {frame}</translation>
    </message>
    <message>
        <source>{join_record_args} gives no angle; the table is kept</source>
        <translation>{join_record_args} gibt keinen Winkel an; der Tisch bleibt</translation>
    </message>
    <message>
        <source>angles read in radians, as CAMWorks writes them ({numbers_0} rad = {angle} deg)</source>
        <translation>Winkel im Bogenmaß gelesen, wie CAMWorks sie schreibt ({numbers_0} rad = {angle} Grad)</translation>
    </message>
    <message>
        <source>the table's angle {angle}° is beyond ±{MAX_ANGLE}°</source>
        <translation>der Tischwinkel {angle}° liegt außerhalb von ±{MAX_ANGLE}°</translation>
    </message>
    <message>
        <source>no GOTO follows: the circle is not a move</source>
        <translation>kein GOTO folgt: der Kreis ist keine Bewegung</translation>
    </message>
    <message>
        <source>operation {number} mixes feeds per minute and per revolution; its feeds are reported as written, each in its own kind</source>
        <translation>Operation {number} mischt Vorschübe pro Minute und pro Umdrehung; ihre Vorschübe werden wie geschrieben ausgegeben, jeder in seiner eigenen Art</translation>
    </message>
    <message>
        <source>{source}: only a CL (APT) program can be written back with new feeds</source>
        <translation>{source}: nur ein CL-Programm (APT) kann mit neuen Vorschüben zurückgeschrieben werden</translation>
    </message>
    <message>
        <source>feed has {size} values, operation {number} {size_2} cutting CL points</source>
        <translation>der Vorschub hat {size} Werte, Operation {number} {size_2} schneidende CL-Punkte</translation>
    </message>
    <message>
        <source>every feed written back must be positive</source>
        <translation>jeder zurückgeschriebene Vorschub muss positiv sein</translation>
    </message>
    <message>
        <source>{source}:{line}: {op_label}: the feed {exact} {unit} rounds down to 0 at the {decimals} decimals this file writes its feeds with</source>
        <translation>{source}:{line}: {op_label}: der Vorschub {exact} {unit} wird bei den {decimals} Nachkommastellen, mit denen diese Datei ihre Vorschübe schreibt, auf 0 abgerundet</translation>
    </message>
    <message>
        <source>{name}: not a FreeCAD document (an FCStd is a zip file)</source>
        <translation>{name}: kein FreeCAD-Dokument (eine FCStd-Datei ist eine ZIP-Datei)</translation>
    </message>
    <message>
        <source>{name}: binary content, not a CL file (APT / CLSF text) or toolpath CSV</source>
        <translation>{name}: binärer Inhalt, keine CL-Datei (APT-/CLSF-Text) und keine Werkzeugbahn-CSV</translation>
    </message>
    <message>
        <source>{name}: empty file: no CL records and no toolpath CSV header</source>
        <translation>{name}: leere Datei: keine CL-Datensätze und keine Werkzeugbahn-CSV-Kopfzeile</translation>
    </message>
    <message>
        <source>{name}: unknown content: neither G-code, APT / CL records (WORD/...) nor a toolpath CSV header (x,y,z,...)</source>
        <translation>{name}: unbekannter Inhalt: weder G-Code noch APT-/CL-Datensätze (WORD/...) noch eine Werkzeugbahn-CSV-Kopfzeile (x,y,z,...)</translation>
    </message>
    <message>
        <source>frame must be one of {FRAMES}, got {frame}</source>
        <translation>frame muss einer von {FRAMES} sein, erhalten: {frame}</translation>
    </message>
    <message>
        <source>strings[{index}] = {value} holds a NUL character</source>
        <translation>strings[{index}] = {value} enthält ein NUL-Zeichen</translation>
    </message>
    <message>
        <source>{name} must be a 1-D array (n,), got shape {shape}</source>
        <translation>{name} muss ein 1-D-Array (n,) sein, erhalten: Form {shape}</translation>
    </message>
    <message>
        <source>{name} must be integers within int64, got dtype {dtype}</source>
        <translation>{name} muss aus Ganzzahlen im Bereich von int64 bestehen, erhalten: dtype {dtype}</translation>
    </message>
    <message>
        <source>{name}:{number}: {value}: a comment '(' is not closed on its line</source>
        <translation>{name}:{number}: {value}: ein Kommentar '(' wird in seiner Zeile nicht geschlossen</translation>
    </message>
    <message>
        <source>{name}:{number}: ): a ')' closes no comment</source>
        <translation>{name}:{number}: ): ein ')' schließt keinen Kommentar</translation>
    </message>
    <message>
        <source>{name}:{number}: {match_group}: the number is above {MAX_MAGNITUDE} in magnitude</source>
        <translation>{name}:{number}: {match_group}: die Zahl ist betragsmäßig größer als {MAX_MAGNITUDE}</translation>
    </message>
    <message>
        <source>{name}:{number}: {match_group}: O-words (subroutines, loops, conditions) are not read; only a program number alone on its line</source>
        <translation>{name}:{number}: {match_group}: O-Wörter (Unterprogramme, Schleifen, Bedingungen) werden nicht gelesen; nur eine Programmnummer allein in ihrer Zeile</translation>
    </message>
    <message>
        <source>parameters and expressions (#, [ ]) are not read</source>
        <translation>Parameter und Ausdrücke (#, [ ]) werden nicht gelesen</translation>
    </message>
    <message>
        <source>assignments (X=…) are not read: write a letter and a number</source>
        <translation>Zuweisungen (X=…) werden nicht gelesen: schreiben Sie einen Buchstaben und eine Zahl</translation>
    </message>
    <message>
        <source>not a G-code word (a letter and a number)</source>
        <translation>kein G-Code-Wort (ein Buchstabe und eine Zahl)</translation>
    </message>
    <message>
        <source>a letter without a number</source>
        <translation>ein Buchstabe ohne Zahl</translation>
    </message>
    <message>
        <source>{letter} is needed: with G90.1 the centre is written whole</source>
        <translation>{letter} wird benötigt: mit G90.1 wird der Mittelpunkt vollständig (absolut) angegeben</translation>
    </message>
    <message>
        <source>an R arc needs an end other than its start (a full circle is written with I J K)</source>
        <translation>ein R-Bogen braucht einen Endpunkt, der vom Startpunkt verschieden ist (ein Vollkreis wird mit I J K geschrieben)</translation>
    </message>
    <message>
        <source>radius {abs_radius} mm does not fit: the ends are {length} mm apart, more than its diameter</source>
        <translation>der Radius {abs_radius} mm passt nicht: die Endpunkte liegen {length} mm auseinander, mehr als sein Durchmesser</translation>
    </message>
    <message>
        <source>the centre is the start point</source>
        <translation>der Mittelpunkt ist der Startpunkt</translation>
    </message>
    <message>
        <source>the end is {last} mm from the centre, the start {first} mm: the arc does not fit (at most {RADIUS_TOLERANCE} mm apart)</source>
        <translation>der Endpunkt ist {last} mm vom Mittelpunkt entfernt, der Startpunkt {first} mm: der Bogen passt nicht (höchstens {RADIUS_TOLERANCE} mm Unterschied)</translation>
    </message>
    <message>
        <source>coordinate offsets set by the program (G92) are not read: use G54-G59 and an offsets table</source>
        <translation>vom Programm gesetzte Koordinatenverschiebungen (G92) werden nicht gelesen: verwenden Sie G54-G59 und eine Nullpunkttabelle</translation>
    </message>
    <message>
        <source>subprogram calls are not read</source>
        <translation>Unterprogrammaufrufe werden nicht gelesen</translation>
    </message>
    <message>
        <source>subprogram returns are not read</source>
        <translation>Unterprogrammrücksprünge werden nicht gelesen</translation>
    </message>
    <message>
        <source>not a G code this reader knows (docs/GCODE.md)</source>
        <translation>kein G-Code, den dieser Einleser kennt (docs/GCODE.md)</translation>
    </message>
    <message>
        <source>{groups_group} and {text} in one block: both set the {group}</source>
        <translation>{groups_group} und {text} in einem Satz: beide setzen {group}</translation>
    </message>
    <message>
        <source>not an M code this reader knows (docs/GCODE.md)</source>
        <translation>kein M-Code, den dieser Einleser kennt (docs/GCODE.md)</translation>
    </message>
    <message>
        <source>the letter {letter} is not read (axes X Y Z and A B C; no U V W, E)</source>
        <translation>der Buchstabe {letter} wird nicht gelesen (Achsen X Y Z und A B C; kein U V W, E)</translation>
    </message>
    <message>
        <source>{letter} is given twice in one block</source>
        <translation>{letter} ist in einem Satz doppelt angegeben</translation>
    </message>
    <message>
        <source>{source}:{first_line}: operation {number} mixes feeds per minute and per revolution; its feeds are reported as written, each in its own kind</source>
        <translation>{source}:{first_line}: Operation {number} mischt Vorschübe pro Minute und pro Umdrehung; ihre Vorschübe werden wie geschrieben ausgegeben, jeder in seiner eigenen Art</translation>
    </message>
    <message>
        <source>an incremental R (G91) from a height not known yet</source>
        <translation>ein inkrementelles R (G91) ab einer noch nicht bekannten Höhe</translation>
    </message>
    <message>
        <source>an incremental Z (G91) needs R first</source>
        <translation>ein inkrementelles Z (G91) braucht zuerst R</translation>
    </message>
    <message>
        <source>a hole whose X Y is not known yet</source>
        <translation>eine Bohrung, deren X Y noch nicht bekannt ist</translation>
    </message>
    <message>
        <source>L: the repeats must be a whole number</source>
        <translation>L: die Anzahl der Wiederholungen muss eine ganze Zahl sein</translation>
    </message>
    <message>
        <source>an arc needs its end: the axis words of its plane (the start's, for a full circle)</source>
        <translation>ein Bogen braucht seinen Endpunkt: die Achsen-Wörter seiner Ebene (die des Startpunkts, für einen Vollkreis)</translation>
    </message>
    <message>
        <source>an axis word with no motion in force (G0, G1, G2, G3 or a hole cycle)</source>
        <translation>ein Achsen-Wort ohne aktive Bewegungsart (G0, G1, G2, G3 oder ein Bohrzyklus)</translation>
    </message>
    <message>
        <source>needs a {letter} word</source>
        <translation>erfordert ein {letter}-Wort</translation>
    </message>
    <message>
        <source>a feed cannot be negative</source>
        <translation>ein Vorschub kann nicht negativ sein</translation>
    </message>
    <message>
        <source>a surface speed with a tool of unknown diameter gives no spindle speed in rpm</source>
        <translation>eine Schnittgeschwindigkeit mit einem Werkzeug unbekannten Durchmessers ergibt keine Drehzahl in U/min</translation>
    </message>
    <message>
        <source>no T word has selected a tool to load</source>
        <translation>kein T-Wort hat ein zu ladendes Werkzeug ausgewählt</translation>
    </message>
    <message>
        <source>{code} loads tool {number}, and no tool table names it: give the tool table (--tool-table FILE: a LinuxCNC tool table, or the FreeCAD document that posted the program)</source>
        <translation>{code} lädt Werkzeug {number}, und keine Werkzeugtabelle nennt es: geben Sie die Werkzeugtabelle an (--tool-table FILE: eine LinuxCNC-Werkzeugtabelle oder das FreeCAD-Dokument, aus dem das Programm postprozessiert wurde)</translation>
    </message>
    <message>
        <source>{code} loads tool {number}, which {tools_source} does not name (its tools: {known})</source>
        <translation>{code} lädt Werkzeug {number}, das {tools_source} nicht nennt (dort genannte Werkzeuge: {known})</translation>
    </message>
    <message>
        <source>cutter compensation in the control; the moves are taken as the tool tip's path as written</source>
        <translation>Fräserradiuskorrektur in der Steuerung; die Bewegungen werden wie geschrieben als Bahn der Werkzeugspitze genommen</translation>
    </message>
    <message>
        <source>L{kind} is not read (only L2: a work offset written whole)</source>
        <translation>L{kind} wird nicht gelesen (nur L2: eine vollständig angegebene Nullpunktverschiebung)</translation>
    </message>
    <message>
        <source>P{number}: the work coordinate systems are P1 (G54) to P9 (G59.3)</source>
        <translation>P{number}: die Werkstückkoordinatensysteme sind P1 (G54) bis P9 (G59.3)</translation>
    </message>
    <message>
        <source>an incremental move (G91) from a {letter} position not known yet</source>
        <translation>eine inkrementelle Bewegung (G91) ab einer noch nicht bekannten {letter}-Position</translation>
    </message>
    <message>
        <source>a rotary axis word, and no machine file names the kinematics: give --machine FILE (docs/GCODE.md)</source>
        <translation>ein Drehachsen-Wort, und keine Maschinendatei nennt die Kinematik: geben Sie --machine FILE an (docs/GCODE.md)</translation>
    </message>
    <message>
        <source>the machine {kinematics} has no {letter} axis (its rotary axes: {value})</source>
        <translation>die Maschine {kinematics} hat keine {letter}-Achse (ihre Drehachsen: {value})</translation>
    </message>
    <message>
        <source>the {letter} axis at {angles_letter}° is beyond ±{MAX_ANGLE}°</source>
        <translation>die {letter}-Achse bei {angles_letter}° liegt außerhalb von ±{MAX_ANGLE}°</translation>
    </message>
    <message>
        <source>TCP off</source>
        <translation>TCP aus</translation>
    </message>
    <message>
        <source>the {kinematics} machine turns the tool about its pivot: the tool's length is needed (Z in the tool table, or tool_length in {source})</source>
        <translation>die Maschine {kinematics} dreht das Werkzeug um ihren Drehpunkt: die Werkzeuglänge wird benötigt (Z in der Werkzeugtabelle oder tool_length in {source})</translation>
    </message>
    <message>
        <source>a feed move to a point whose {join_unknown} is not known yet (no {unknown_0} word since the start or the last G28 / G30)</source>
        <translation>eine Vorschubbewegung zu einem Punkt, dessen {join_unknown} noch nicht bekannt ist (kein {unknown_0}-Wort seit dem Anfang oder dem letzten G28 / G30)</translation>
    </message>
    <message>
        <source>an arc that also turns a rotary axis is not read</source>
        <translation>ein Bogen, der zugleich eine Drehachse bewegt, wird nicht gelesen</translation>
    </message>
    <message>
        <source>an arc from a position not known yet</source>
        <translation>ein Bogen ab einer noch nicht bekannten Position</translation>
    </message>
    <message>
        <source>{normal} is along the normal of the plane G{plane}: it gives no centre</source>
        <translation>{normal} liegt entlang der Normalen der Ebene G{plane}: daraus ergibt sich kein Mittelpunkt</translation>
    </message>
    <message>
        <source>needs its centre (I J K) or its radius (R)</source>
        <translation>braucht seinen Mittelpunkt (I J K) oder seinen Radius (R)</translation>
    </message>
    <message>
        <source>P{value}: the turns must be a whole number from 1</source>
        <translation>P{value}: die Anzahl der Windungen muss eine ganze Zahl ab 1 sein</translation>
    </message>
    <message>
        <source>inverse time feed (G93) needs an F word on every feed move</source>
        <translation>Vorschub in inverser Zeit (G93) erfordert ein F-Wort in jeder Vorschubbewegung</translation>
    </message>
    <message>
        <source>hole cycles are read in the XY plane (G17) only</source>
        <translation>Bohrzyklen werden nur in der XY-Ebene (G17) gelesen</translation>
    </message>
    <message>
        <source>{name}: missing key 'kinematics' (one of {join_KINEMATICS})</source>
        <translation>{name}: fehlender Schlüssel 'kinematics' (einer von {join_KINEMATICS})</translation>
    </message>
    <message>
        <source>{name}: kinematics: expected one of {join_KINEMATICS}, got {kind}</source>
        <translation>{name}: kinematics: erwartet: einer von {join_KINEMATICS}, erhalten: {kind}</translation>
    </message>
    <message>
        <source>{name}: tool_length: must not be negative, got {tool_length}</source>
        <translation>{name}: tool_length: darf nicht negativ sein, erhalten: {tool_length}</translation>
    </message>
    <message>
        <source>{name}: {key}: must be a list of {size} numbers (mm)</source>
        <translation>{name}: {key}: muss eine Liste von {size} Zahlen sein (mm)</translation>
    </message>
    <message>
        <source>{name}:{number}: expected 'parameter value' (LinuxCNC parameter file), got {raw_strip}</source>
        <translation>{name}:{number}: erwartet: 'parameter value' (LinuxCNC-Parameterdatei), erhalten: {raw_strip}</translation>
    </message>
    <message>
        <source>{name}:{number}: {fields_1}: not a number of at most {MAX_MAGNITUDE} in magnitude</source>
        <translation>{name}:{number}: {fields_1}: keine Zahl mit einem Betrag von höchstens {MAX_MAGNITUDE}</translation>
    </message>
    <message>
        <source>{name}: {key} is not a work coordinate system ({join_SYSTEMS})</source>
        <translation>{name}: {key} ist kein Werkstückkoordinatensystem ({join_SYSTEMS})</translation>
    </message>
    <message>
        <source>{name}: {key}: must be [x, y, z] or [x, y, z, a, b, c] (mm, degrees)</source>
        <translation>{name}: {key}: muss [x, y, z] oder [x, y, z, a, b, c] sein (mm, Grad)</translation>
    </message>
    <message>
        <source>{name}: --{option_replace} applies to {words_kinds_0}, and this file is {value}</source>
        <translation>{name}: --{option_replace} gilt für {words_kinds_0}, und diese Datei ist {value}</translation>
    </message>
    <message>
        <source>a CL file or toolpath CSV</source>
        <translation>eine CL-Datei oder Werkzeugbahn-CSV</translation>
    </message>
    <message>
        <source>the program works in inches, and {files} {value} lengths in the machine's units, which LinuxCNC does not write in the file: say them (--machine-units mm or inch)</source>
        <translation>das Programm arbeitet in Zoll, und {files} {value} Längen in den Einheiten der Maschine, die LinuxCNC nicht in die Datei schreibt: geben Sie diese an (--machine-units mm or inch)</translation>
    </message>
    <message>
        <source>{name}:{number}: {shown}: not a tool table word (T P X Y Z A B C U V W D I J Q and a number)</source>
        <translation>{name}:{number}: {shown}: kein Wort einer Werkzeugtabelle (T P X Y Z A B C U V W D I J Q und eine Zahl)</translation>
    </message>
    <message>
        <source>{name}:{number}: {letter}: given twice on the line</source>
        <translation>{name}:{number}: {letter}: in der Zeile doppelt angegeben</translation>
    </message>
    <message>
        <source>{name}:{number}: {match_group}: the number is above {MAX_MAGNITUDE}</source>
        <translation>{name}:{number}: {match_group}: die Zahl ist größer als {MAX_MAGNITUDE}</translation>
    </message>
    <message>
        <source>{name}:{number}: no T word: each line of a tool table describes tool T&lt;n&gt;</source>
        <translation>{name}:{number}: kein T-Wort: jede Zeile einer Werkzeugtabelle beschreibt ein Werkzeug T&lt;n&gt;</translation>
    </message>
    <message>
        <source>{name}:{number}: T{tool}: the table describes tool {tool_2} twice</source>
        <translation>{name}:{number}: T{tool}: die Tabelle beschreibt das Werkzeug {tool_2} doppelt</translation>
    </message>
    <message>
        <source>toolpath has {count} CL points, the engagement {value}</source>
        <translation>die Werkzeugbahn hat {count} CL-Punkte, der Eingriff {value}</translation>
    </message>
    <message>
        <source>{name}: empty file; expected a results header {value},...</source>
        <translation>{name}: leere Datei; erwartet: eine Ergebnis-Kopfzeile {value},...</translation>
    </message>
    <message>
        <source>{name}:1: a column named twice in the header</source>
        <translation>{name}:1: eine Spalte ist in der Kopfzeile doppelt benannt</translation>
    </message>
    <message>
        <source>{name}:{number}: expected {count} fields, got {count_2}</source>
        <translation>{name}:{number}: erwartet: {count} Felder, erhalten: {count_2}</translation>
    </message>
    <message>
        <source>{name}:{number}: a line of {count} characters; at most {MAX_LINE} are read</source>
        <translation>{name}:{number}: eine Zeile mit {count} Zeichen; höchstens {MAX_LINE} werden gelesen</translation>
    </message>
    <message>
        <source>{name}:{number}: a field of {longest} characters; at most {MAX_FIELD} are read</source>
        <translation>{name}:{number}: ein Feld mit {longest} Zeichen; höchstens {MAX_FIELD} werden gelesen</translation>
    </message>
    <message>
        <source>{name}:{row}: column {column}: {field} is not a valid int</source>
        <translation>{name}:{row}: Spalte {column}: {field} ist kein gültiger int</translation>
    </message>
    <message>
        <source>chunk columns {list_columns} differ from the first chunk's {value}</source>
        <translation>die Spalten {list_columns} des Blocks weichen von {value} des ersten Blocks ab</translation>
    </message>
    <message>
        <source>column {key}: {dtype} {shape}, expected {dtype_2} (rows,)</source>
        <translation>Spalte {key}: {dtype} {shape}, erwartet: {dtype_2} (rows,)</translation>
    </message>
    <message>
        <source>chunk columns {list_columns} differ from the first chunk's {list_self_dtypes}</source>
        <translation>die Spalten {list_columns} des Blocks weichen von {list_self_dtypes} des ersten Blocks ab</translation>
    </message>
    <message>
        <source>{name}: not an ABM results archive (no 'format' member saying {FORMAT})</source>
        <translation>{name}: kein ABM-Ergebnisarchiv (kein Eintrag 'format' mit dem Inhalt {FORMAT})</translation>
    </message>
    <message>
        <source>{name}: not a results archive: no array {prefix_missing_0}</source>
        <translation>{name}: kein Ergebnisarchiv: kein Array {prefix_missing_0}</translation>
    </message>
    <message>
        <source>{name}: unknown array {prefix_unknown_0} in a results archive</source>
        <translation>{name}: unbekanntes Array {prefix_unknown_0} in einem Ergebnisarchiv</translation>
    </message>
    <message>
        <source>{name}: not a results archive (an .npz file is a zip file, and this is not one)</source>
        <translation>{name}: kein Ergebnisarchiv (eine .npz-Datei ist eine ZIP-Datei, und dies ist keine)</translation>
    </message>
    <message>
        <source>{name}: not a results archive: {count} members (at most {MAX_MEMBERS})</source>
        <translation>{name}: kein Ergebnisarchiv: {count} Einträge (höchstens {MAX_MEMBERS})</translation>
    </message>
    <message>
        <source>{name}: not a results archive: damaged ({error})</source>
        <translation>{name}: kein Ergebnisarchiv: beschädigt ({error})</translation>
    </message>
    <message>
        <source>{name}: not a results archive: member {filename} is not an .npy array</source>
        <translation>{name}: kein Ergebnisarchiv: der Eintrag {filename} ist kein .npy-Array</translation>
    </message>
    <message>
        <source>{name}: not a results archive: member {filename}</source>
        <translation>{name}: kein Ergebnisarchiv: Eintrag {filename}</translation>
    </message>
    <message>
        <source>{where} is compressed; the archives written here store their arrays uncompressed</source>
        <translation>{where} ist komprimiert; die hier geschriebenen Archive speichern ihre Arrays unkomprimiert</translation>
    </message>
    <message>
        <source>{where} claims {file_size} bytes in a file of {size}</source>
        <translation>{where} gibt {file_size} Bytes an, in einer Datei von {size}</translation>
    </message>
    <message>
        <source>npy version {version}</source>
        <translation>npy-Version {version}</translation>
    </message>
    <message>
        <source>{where}: not an .npy header ({type}: {error})</source>
        <translation>{where}: kein .npy-Header ({type}: {error})</translation>
    </message>
    <message>
        <source>{where}: holds {dtype} values, which are not read (no pickled objects)</source>
        <translation>{where}: enthält Werte vom Typ {dtype}, die nicht gelesen werden (keine gepickelten Objekte)</translation>
    </message>
    <message>
        <source>{name}: not a results archive: array {value}: shape {shape}; a results array is 1-D or a scalar</source>
        <translation>{name}: kein Ergebnisarchiv: Array {value}: Form {shape}; ein Ergebnis-Array ist 1-D oder ein Skalar</translation>
    </message>
    <message>
        <source>{where}: shape {shape} of {dtype} needs {value} bytes; the member holds {body}</source>
        <translation>{where}: Form {shape} von {dtype} braucht {value} Bytes; der Eintrag enthält {body}</translation>
    </message>
    <message>
        <source>{where}: cut short</source>
        <translation>{where}: vorzeitig abgeschnitten</translation>
    </message>
    <message>
        <source>{name}: array {key}: {dtype} of shape {shape}, expected {dtype_2} of shape {rows}</source>
        <translation>{name}: Array {key}: {dtype} der Form {shape}, erwartet: {dtype_2} der Form {rows}</translation>
    </message>
    <message>
        <source>{name}: array {key}: no labels ({LABELS_column}: a 1-D str array)</source>
        <translation>{name}: Array {key}: keine Bezeichnungen ({LABELS_column}: ein 1-D-str-Array)</translation>
    </message>
    <message>
        <source>{name}: array {key}: row {bad_0}: code {values_bad_0} has no label (labels 0..{names_size_1})</source>
        <translation>{name}: Array {key}: Zeile {bad_0}: Code {values_bad_0} hat keine Bezeichnung (Bezeichnungen 0..{names_size_1})</translation>
    </message>
    <message>
        <source>{name}: array {key}: row {bad_0}: {values_bad_0} is too large (at most {MAX_MAGNITUDE} in magnitude)</source>
        <translation>{name}: Array {key}: Zeile {bad_0}: {values_bad_0} ist zu groß (Betrag höchstens {MAX_MAGNITUDE})</translation>
    </message>
    <message>
        <source>{name}: missing key 'format' (a staircase file starts with "format": "{FORMAT}")</source>
        <translation>{name}: fehlender Schlüssel 'format' (eine Treppenstufen-Rohteil-Datei beginnt mit "format": "{FORMAT}")</translation>
    </message>
    <message>
        <source>{name}: format must be {FORMAT}, got {value}</source>
        <translation>{name}: format muss {FORMAT} sein, erhalten: {value}</translation>
    </message>
    <message>
        <source>{name}: units must be 'mm', got {value}</source>
        <translation>{name}: units muss 'mm' sein, erhalten: {value}</translation>
    </message>
    <message>
        <source>{name}: sections must be a non-empty list of sections, got {value}</source>
        <translation>{name}: sections muss eine nicht leere Liste von Abschnitten sein, erhalten: {value}</translation>
    </message>
    <message>
        <source>{name}: sections[{j}]</source>
        <translation>{name}: sections[{j}]</translation>
    </message>
    <message>
        <source>{where}: expected an object {"z_top": ...}, got {value}</source>
        <translation>{where}: erwartet: ein Objekt {"z_top": ...}, erhalten: {value}</translation>
    </message>
    <message>
        <source>{where}: the first section starts at x_min and must not have a wall</source>
        <translation>{where}: der erste Abschnitt beginnt bei x_min und darf keine Wand haben</translation>
    </message>
    <message>
        <source>{where}: a wall needs six [x, y] points, got {got}</source>
        <translation>{where}: eine Wand braucht sechs [x, y]-Punkte, erhalten: {got}</translation>
    </message>
    <message>
        <source>{where}[{k}]: expected an [x, y] pair, got {json_dumps_point}</source>
        <translation>{where}[{k}]: erwartet wurde ein [x, y]-Paar, erhalten: {json_dumps_point}</translation>
    </message>
    <message>
        <source>zip member {name} reserved twice</source>
        <translation>ZIP-Element {name} zweimal reserviert</translation>
    </message>
    <message>
        <source>zip member {name}: size {size} &lt; 0</source>
        <translation>ZIP-Element {name}: Größe {size} &lt; 0</translation>
    </message>
    <message>
        <source>zip member {value}: {value_2} bytes given, {size} reserved</source>
        <translation>ZIP-Element {value}: {value_2} Bytes übergeben, {size} reserviert</translation>
    </message>
    <message>
        <source>zip member {value}: {written} of {size} bytes written</source>
        <translation>ZIP-Element {value}: {written} von {size} Bytes geschrieben</translation>
    </message>
    <message>
        <source>{where}: must be {what}, got {json_dumps_value}</source>
        <translation>{where}: muss {what} sein, erhalten: {json_dumps_value}</translation>
    </message>
    <message>
        <source>{where}: expected an [x, y] pair, got {json_dumps_value}</source>
        <translation>{where}: erwartet wurde ein [x, y]-Paar, erhalten: {json_dumps_value}</translation>
    </message>
    <message>
        <source>{where}: expected a curve object {"type": ...}, got {json_dumps_data}</source>
        <translation>{where}: erwartet wurde ein Kurvenobjekt {"type": ...}, erhalten: {json_dumps_data}</translation>
    </message>
    <message>
        <source>{where}.type: must be "line", "arc" or "spline", got {json_dumps_kind}</source>
        <translation>{where}.type: muss "line", "arc" oder "spline" sein, erhalten: {json_dumps_kind}</translation>
    </message>
    <message>
        <source>{where}.face: must be a string, got {json_dumps_face}</source>
        <translation>{where}.face: muss eine Zeichenkette sein, erhalten: {json_dumps_face}</translation>
    </message>
    <message>
        <source>a list of numbers</source>
        <translation>eine Liste von Zahlen</translation>
    </message>
    <message>
        <source>a list of [x, y] points</source>
        <translation>eine Liste von [x, y]-Punkten</translation>
    </message>
    <message>
        <source>{where}.degree: must be a whole number, got {value}</source>
        <translation>{where}.degree: muss eine ganze Zahl sein, erhalten: {value}</translation>
    </message>
    <message>
        <source>a non-empty list of slabs</source>
        <translation>eine nicht leere Liste von Schichten</translation>
    </message>
    <message>
        <source>{name}: slabs[{k}]</source>
        <translation>{name}: slabs[{k}]</translation>
    </message>
    <message>
        <source>{where}: expected an object {"z_top": ..., "loops": [...]}, got {json_dumps_slab}</source>
        <translation>{where}: erwartet wurde ein Objekt {"z_top": ..., "loops": [...]}, erhalten: {json_dumps_slab}</translation>
    </message>
    <message>
        <source>a non-empty list of loops</source>
        <translation>eine nicht leere Liste von Schleifen</translation>
    </message>
    <message>
        <source>a non-empty list of curves</source>
        <translation>eine nicht leere Liste von Kurven</translation>
    </message>
    <message>
        <source>{where}: encloses no area ({area} mm²): a loop must bound a region</source>
        <translation>{where}: umschließt keine Fläche ({area} mm²): eine Schleife muss einen Bereich begrenzen</translation>
    </message>
    <message>
        <source>{where}.loops[{i}]: the same contour as loops[{seen_key}]; by the even-odd rule the two cancel and bound no region</source>
        <translation>{where}.loops[{i}]: dieselbe Kontur wie loops[{seen_key}]; nach der Gerade-Ungerade-Regel heben sich beide auf und begrenzen keinen Bereich</translation>
    </message>
    <message>
        <source>{name}: empty file; expected a header such as {_EXAMPLE}</source>
        <translation>{name}: leere Datei; erwartet wurde eine Kopfzeile wie {_EXAMPLE}</translation>
    </message>
    <message>
        <source>{name}: no CL points: the file has a header but no rows</source>
        <translation>{name}: keine CL-Punkte: die Datei hat eine Kopfzeile, aber keine Datenzeilen</translation>
    </message>
    <message>
        <source>{name}:{numbers_bad_0}: column {column}: {values_bad_0} is not a whole number of at least {low}</source>
        <translation>{name}:{numbers_bad_0}: Spalte {column}: {values_bad_0} ist keine ganze Zahl von mindestens {low}</translation>
    </message>
    <message>
        <source>{source}: operation {operation}: the file has one pass (no operation column)</source>
        <translation>{source}: Operation {operation}: die Datei hat nur einen Durchgang (keine Spalte operation)</translation>
    </message>
    <message>
        <source>{source}: {count} operations; choose one with --operation N; operations: {listing}</source>
        <translation>{source}: {count} Operationen; wählen Sie eine mit --operation N; Operationen: {listing}</translation>
    </message>
    <message>
        <source>{source}: no operation {operation}; the file has operations {value}</source>
        <translation>{source}: keine Operation {operation}; die Datei enthält die Operationen {value}</translation>
    </message>
    <message>
        <source>{where}: a line of {count} characters; at most {MAX_LINE} are read</source>
        <translation>{where}: eine Zeile mit {count} Zeichen; höchstens {MAX_LINE} werden gelesen</translation>
    </message>
    <message>
        <source>{where}: not a CSV line: {error}</source>
        <translation>{where}: keine CSV-Zeile: {error}</translation>
    </message>
    <message>
        <source>{where}: a field of {longest} characters; at most {MAX_FIELD} are read</source>
        <translation>{where}: ein Feld mit {longest} Zeichen; höchstens {MAX_FIELD} werden gelesen</translation>
    </message>
    <message>
        <source>{where}: duplicate column {duplicate_0}</source>
        <translation>{where}: doppelte Spalte {duplicate_0}</translation>
    </message>
    <message>
        <source>{where}: unknown columns {names}; known columns: {listed}</source>
        <translation>{where}: unbekannte Spalten {names}; bekannte Spalten: {listed}</translation>
    </message>
    <message>
        <source>{where}: unknown column {names}; known columns: {listed}</source>
        <translation>{where}: unbekannte Spalte {names}; bekannte Spalten: {listed}</translation>
    </message>
    <message>
        <source>{where}: give the tool orientation as theta_a, theta_b or as i, j, k, not both</source>
        <translation>{where}: geben Sie die Werkzeugorientierung als theta_a, theta_b oder als i, j, k an, nicht beides</translation>
    </message>
    <message>
        <source>{where}: missing column {missing_0} of the {label} ({join_group})</source>
        <translation>{where}: fehlende Spalte {missing_0} von {label} ({join_group})</translation>
    </message>
    <message>
        <source>{where}: expected {count} fields ({join_header}), got {count_2}</source>
        <translation>{where}: erwartet wurden {count} Felder ({join_header}), erhalten: {count_2}</translation>
    </message>
    <message>
        <source>is empty: give CL indices such as 0,27,80-100</source>
        <translation>ist leer: geben Sie CL-Indizes an, etwa 0,27,80-100</translation>
    </message>
    <message>
        <source>item {position} {item} is not a CL index or a range A-B (such as 0,27,80-100)</source>
        <translation>Eintrag {position} {item} ist weder ein CL-Index noch ein Bereich A-B (etwa 0,27,80-100)</translation>
    </message>
    <message>
        <source>item {position} {item} runs backwards (write {high}-{low})</source>
        <translation>Eintrag {position} {item} läuft rückwärts (schreiben Sie {high}-{low})</translation>
    </message>
    <message>
        <source>item {position}: CL point {index} is not in the pass (0..{m_1})</source>
        <translation>Eintrag {position}: CL-Punkt {index} liegt nicht im Durchgang (0..{m_1})</translation>
    </message>
    <message>
        <source>must be a positive whole number of CL points, got {every}</source>
        <translation>muss eine positive ganze Anzahl von CL-Punkten sein, erhalten: {every}</translation>
    </message>
    <message>
        <source>{source}:{line}: {word}: record not understood, ignored ({count} times)</source>
        <translation>{source}:{line}: {word}: Datensatz nicht verstanden, ignoriert ({count}-mal)</translation>
    </message>
    <message>
        <source>{source}:{line}: {word}: record not understood, ignored</source>
        <translation>{source}:{line}: {word}: Datensatz nicht verstanden, ignoriert</translation>
    </message>
    <message>
        <source>{source}: records that carry nothing the engine needs, ignored: {records}</source>
        <translation>{source}: Datensätze ohne etwas, das der Rechenkern braucht, ignoriert: {records}</translation>
    </message>
    <message>
        <source>{name}: unknown stock file type; expected .json, .step, .stp, .brep, .brp or .FCStd</source>
        <translation>{name}: unbekannter Rohteil-Dateityp; erwartet: .json, .step, .stp, .brep, .brp oder .FCStd</translation>
    </message>
    <message>
        <source>{name}: y window {y_window_0}..{y_window_1} mm misses the stock's y range {YMin}..{YMax} mm</source>
        <translation>{name}: das y-Fenster {y_window_0}..{y_window_1} mm liegt außerhalb des y-Bereichs des Rohteils {YMin}..{YMax} mm</translation>
    </message>
    <message>
        <source>{name}: the stock is 2.5D along ({value}) in the part, {angle}° from the z of the operation's frame: the operation must be computed in its frame turned to the stock (abm engage, validate and schedule do)</source>
        <translation>{name}: das Rohteil ist im Bauteil 2.5D entlang ({value}), {angle}° gegen die z-Achse des Koordinatensystems der Operation: die Operation muss in ihrem zum Rohteil gedrehten Koordinatensystem berechnet werden (abm engage, validate und schedule tun das)</translation>
    </message>
    <message>
        <source>{name}: the operation's frame is turned against the part's, and a stock JSON can only be moved, not turned: give the stock as a solid (STEP, BREP, FCStd)</source>
        <translation>{name}: das Koordinatensystem der Operation ist gegenüber dem des Bauteils gedreht, und ein Rohteil-JSON kann nur verschoben, nicht gedreht werden: geben Sie das Rohteil als Volumenkörper an (STEP, BREP, FCStd)</translation>
    </message>
    <message>
        <source>{name}: {key}: must be a string</source>
        <translation>{name}: {key}: muss eine Zeichenkette sein</translation>
    </message>
    <message>
        <source>{name}: {key}: must be [start, end] in degrees, e.g. [0, 180]</source>
        <translation>{name}: {key}: muss [start, end] in Grad sein, z. B. [0, 180]</translation>
    </message>
    <message>
        <source>{what}: its {holes} canned-cycle holes are not in the in-process stock (holes are not swept)</source>
        <translation>{what}: ihre {holes} Bohrungen aus Bohrzyklen sind nicht im Zwischenrohteil (Bohrungen werden nicht überstrichen)</translation>
    </message>
    <message>
        <source>{what}: the file gives no diameter, so its {count} cutting moves are not in the in-process stock</source>
        <translation>{what}: die Datei gibt keinen Durchmesser an, daher sind ihre {count} Schnittbewegungen nicht im Zwischenrohteil</translation>
    </message>
    <message>
        <source>the tool's length in the file</source>
        <translation>die Länge des Werkzeugs in der Datei</translation>
    </message>
    <message>
        <source>the program's extent</source>
        <translation>die Ausdehnung des Programms</translation>
    </message>
    <message>
        <source>{what}: the file gives no flute length: in the in-process stock it removes material with its whole length, {length} mm ({whence})</source>
        <translation>{what}: die Datei gibt keine Schneidenlänge an: im Zwischenrohteil entfernt es Material mit seiner ganzen Länge, {length} mm ({whence})</translation>
    </message>
    <message>
        <source>{what}: swept as a flat-end cylinder of its diameter in the in-process stock</source>
        <translation>{what}: im Zwischenrohteil als Schaftfräser-Zylinder seines Durchmessers überstrichen</translation>
    </message>
    <message>
        <source>{source}: the in-process stock cannot sweep the program: {error}; the stock model initial (the stock as given) can</source>
        <translation>{source}: das Zwischenrohteil kann das Programm nicht durchlaufen: {error}; das Rohteilmodell initial (das Rohteil wie angegeben) kann es</translation>
    </message>
    <message>
        <source>{toolpath}: give the stock (--stock): only a FreeCAD CAM Job's document (FCStd) holds its own</source>
        <translation>{toolpath}: geben Sie das Rohteil an (--stock): nur das Dokument (FCStd) eines FreeCAD-CAM-Jobs enthält sein eigenes</translation>
    </message>
    <message>
        <source>is required for the forces: give a material or the coefficients ktc, krc and kac</source>
        <translation>wird für die Schnittkräfte benötigt: geben Sie einen Werkstoff oder die Koeffizienten ktc, krc und kac an</translation>
    </message>
    <message>
        <source>applies to a solid stock (.step, .stp, .brep, .brp, .FCStd), not to {stock}</source>
        <translation>gilt für ein Volumenkörper-Rohteil (.step, .stp, .brep, .brp, .FCStd), nicht für {stock}</translation>
    </message>
    <message>
        <source>y window must be whole, swept or (y0, y1), got {window}</source>
        <translation>das y-Fenster muss whole, swept oder (y0, y1) sein, erhalten: {window}</translation>
    </message>
    <message>
        <source>expected CL indices such as 0,22,40, got {text}</source>
        <translation>erwartet wurden CL-Indizes wie 0,22,40, erhalten: {text}</translation>
    </message>
    <message>
        <source>CL point {index} is not in the pass (0..{m_1})</source>
        <translation>CL-Punkt {index} liegt nicht im Durchgang (0..{m_1})</translation>
    </message>
    <message>
        <source>must be a number, got {json_dumps_value}</source>
        <translation>muss eine Zahl sein, erhalten: {json_dumps_value}</translation>
    </message>
    <message>
        <source>must be a number, got {value}</source>
        <translation>muss eine Zahl sein, erhalten: {value}</translation>
    </message>
    <message>
        <source>must be a finite number, got {number}</source>
        <translation>muss eine endliche Zahl sein, erhalten: {number}</translation>
    </message>
    <message>
        <source>must be at most {MAX_MAGNITUDE} in size, got {number}</source>
        <translation>muss dem Betrag nach höchstens {MAX_MAGNITUDE} sein, erhalten: {number}</translation>
    </message>
    <message>
        <source>must be a whole number, got {number}</source>
        <translation>muss eine ganze Zahl sein, erhalten: {number}</translation>
    </message>
    <message>
        <source>must be {self_range_text}, got {number}{shown}</source>
        <translation>muss {self_range_text} sein, erhalten: {number}{shown}</translation>
    </message>
    <message>
        <source>must not be below the first rotation angle {start}°, got {end}°</source>
        <translation>darf nicht unter dem ersten Drehwinkel {start}° liegen, erhalten: {end}°</translation>
    </message>
    <message>
        <source>gives more than {MAX_ANGLES} angles from {start}° to {end}°; take a larger step</source>
        <translation>ergibt mehr als {MAX_ANGLES} Winkel von {start}° bis {end}°; wählen Sie eine größere Schrittweite</translation>
    </message>
    <message>
        <source>must be at most half the tool diameter ({value} mm: a ball-end mill), got {corner} mm</source>
        <translation>muss höchstens der halbe Werkzeugdurchmesser sein ({value} mm: ein Kugelfräser), erhalten: {corner} mm</translation>
    </message>
    <message>
        <source>must be above the start of immersion {low}°, got {high}°</source>
        <translation>muss größer als der Eingriffsbeginn {low}° sein, erhalten: {high}°</translation>
    </message>
    <message>
        <source>{source} gives {name} {file_value}, {where} {other}: using {file_value_2}, the value the toolpath was made for</source>
        <translation>{source} gibt {name} {file_value} an, {where} {other}: {file_value_2} wird verwendet, der Wert, für den die Werkzeugbahn erstellt wurde</translation>
    </message>
    <message>
        <source>is {helix}°, but helical flutes on a corner are not computed: a tool with a corner radius ({corner} mm) needs straight flutes (helix 0)</source>
        <translation>ist {helix}°, aber Schneiden mit Drall am Eckenradius werden nicht berechnet: ein Werkzeug mit Eckenradius ({corner} mm) braucht gerade Schneiden (helix 0)</translation>
    </message>
    <message>
        <source>needs a staircase stock: the helix solver does not take a general 2.5D stock yet (use straight flutes, helix 0)</source>
        <translation>erfordert ein Treppenstufen-Rohteil: der Drall-Löser nimmt noch kein allgemeines 2,5D-Rohteil (verwenden Sie gerade Schneiden, Drallwinkel 0)</translation>
    </message>
    <message>
        <source>must be one of {value}, got {stock_model}</source>
        <translation>muss einer der Werte {value} sein, erhalten: {stock_model}</translation>
    </message>
    <message>
        <source>a helical tool</source>
        <translation>einem Werkzeug mit Drallwinkel</translation>
    </message>
    <message>
        <source>the Z-map method</source>
        <translation>der Z-Map-Methode</translation>
    </message>
    <message>
        <source>in-process is not available with {missing} yet: use initial</source>
        <translation>in-process ist mit {missing} noch nicht verfügbar: verwenden Sie initial</translation>
    </message>
    <message>
        <source>the in-process stock is not available with {missing} yet</source>
        <translation>das Zwischenrohteil ist mit {missing} noch nicht verfügbar</translation>
    </message>
    <message>
        <source>must be a positive number of mm, got {sweep_tolerance}</source>
        <translation>muss eine positive Zahl in mm sein, erhalten: {sweep_tolerance}</translation>
    </message>
    <message>
        <source>the in-process stock sweeps the program's {curved} arcs and curves as the chords between their CL points, each within {tolerance} mm of the arc (at most {step} mm long)</source>
        <translation>das Zwischenrohteil überstreicht die {curved} Bögen und Kurven des Programms als Sehnen zwischen ihren CL-Punkten, jede innerhalb von {tolerance} mm vom Bogen (höchstens {step} mm lang)</translation>
    </message>
    <message>
        <source>give a larger --sweep-tolerance or --stock-model initial (the stock as given)</source>
        <translation>geben Sie eine größere --sweep-tolerance oder --stock-model initial (das Rohteil wie gegeben) an</translation>
    </message>
    <message>
        <source>give --stock-model initial (the stock as given)</source>
        <translation>geben Sie --stock-model initial (das Rohteil wie gegeben) an</translation>
    </message>
    <message>
        <source>the in-process stock</source>
        <translation>das Zwischenrohteil</translation>
    </message>
    <message>
        <source>the in-process stock would sweep the program's cutting moves into {value} pieces and bounding balls</source>
        <translation>das Zwischenrohteil würde die Schnittbewegungen des Programms in {value} Stücke und Hüllkugeln überstreichen</translation>
    </message>
    <message>
        <source>its sweep ({value} pieces, {count_text_balls} bounding balls)</source>
        <translation>sein Überstreichen ({value} Stücke, {count_text_balls} Hüllkugeln)</translation>
    </message>
    <message>
        <source>give a larger --phi-step or a shorter --phi-range</source>
        <translation>geben Sie einen größeren --phi-step oder einen kürzeren --phi-range an</translation>
    </message>
    <message>
        <source>{count_text_m} CL points x {count_text_p} angles = {value} instants</source>
        <translation>{count_text_m} CL-Punkte x {count_text_p} Winkel = {value} Zeitpunkte</translation>
    </message>
    <message>
        <source>the {command} run</source>
        <translation>der Lauf von {command}</translation>
    </message>
    <message>
        <source>would check {many} CL points x {angles} angles x {flutes} flutes = {total} instants</source>
        <translation>würde {many} CL-Punkte x {angles} Winkel x {flutes} Schneiden = {total} Zeitpunkte prüfen</translation>
    </message>
    <message>
        <source>would check {many} CL points x {angles} angles = {total} instants</source>
        <translation>würde {many} CL-Punkte x {angles} Winkel = {total} Zeitpunkte prüfen</translation>
    </message>
    <message>
        <source>the boolean reference</source>
        <translation>die boolesche Referenz</translation>
    </message>
    <message>
        <source>check fewer CL points (--check, --check-every) or give a larger --phi-step</source>
        <translation>prüfen Sie weniger CL-Punkte (--check, --check-every) oder geben Sie einen größeren --phi-step an</translation>
    </message>
    <message>
        <source>{grid} mm gives the stock {cells} Z-map cells, more than the Z-map holds ({MAX_CELLS}): give a larger --grid</source>
        <translation>{grid} mm ergibt für das Rohteil {cells} Z-Map-Zellen, mehr als die Z-Map fasst ({MAX_CELLS}): geben Sie ein größeres --grid an</translation>
    </message>
    <message>
        <source>the Z-map's {cells} cells</source>
        <translation>die {cells} Zellen der Z-Map</translation>
    </message>
    <message>
        <source>give a larger --grid</source>
        <translation>geben Sie ein größeres --grid an</translation>
    </message>
    <message>
        <source>an edge step of {edge_step} mm samples the {length} mm flute at {along} points, {p} angles x {along_2} = {each} per CL point, more than the Z-map takes ({MAX_SAMPLES}): give a larger {option} or --phi-step</source>
        <translation>ein Kantenschritt von {edge_step} mm tastet die {length} mm lange Schneide an {along} Punkten ab, {p} Winkel x {along_2} = {each} je CL-Punkt, mehr als die Z-Map aufnimmt ({MAX_SAMPLES}): geben Sie einen größeren Wert für {option} oder --phi-step an</translation>
    </message>
    <message>
        <source>an edge step of {edge_step} mm samples the {length} mm flute at {along} points (the edge step is the grid's unless --edge-step is given), {p} angles x {along_2} = {each} per CL point, more than the Z-map takes ({MAX_SAMPLES}): give a larger {option} or --phi-step</source>
        <translation>ein Kantenschritt von {edge_step} mm tastet die {length} mm lange Schneide an {along} Punkten ab (der Kantenschritt ist der des Rasters, sofern --edge-step nicht angegeben ist), {p} Winkel x {along_2} = {each} je CL-Punkt, mehr als die Z-Map aufnimmt ({MAX_SAMPLES}): geben Sie einen größeren Wert für {option} oder --phi-step an</translation>
    </message>
    <message>
        <source>the Z-map would sample {samples} edge points ({m} CL points x {p} angles x {along} along the edge)</source>
        <translation>die Z-Map würde {samples} Kantenpunkte abtasten ({m} CL-Punkte x {p} Winkel x {along} entlang der Schneide)</translation>
    </message>
    <message>
        <source>the Z-map would sample {samples} edge points ({m} CL points x {p} angles x {along} along the edge) (the edge step is the grid's unless --edge-step is given)</source>
        <translation>die Z-Map würde {samples} Kantenpunkte abtasten ({m} CL-Punkte x {p} Winkel x {along} entlang der Schneide) (der Kantenschritt ist der des Rasters, sofern --edge-step nicht angegeben ist)</translation>
    </message>
    <message>
        <source>give a larger {option} or --phi-step</source>
        <translation>geben Sie einen größeren Wert für {option} oder --phi-step an</translation>
    </message>
    <message>
        <source>the Z-map baseline needs a staircase stock; {source} is a general 2.5D stock</source>
        <translation>das Z-Map-Basisverfahren benötigt ein Treppenstufen-Rohteil; {source} ist ein allgemeines 2.5D-Rohteil</translation>
    </message>
    <message>
        <source>{toolpath}: the tool never touches the stock: no CL point of the pass engages it (are the toolpath and {stock} in the same frame?)</source>
        <translation>{toolpath}: das Werkzeug berührt das Rohteil nie: kein CL-Punkt des Durchgangs ist mit ihm im Eingriff (liegen die Werkzeugbahn und {stock} im selben Koordinatensystem?)</translation>
    </message>
    <message>
        <source>{path}: cannot write: {folder} is not a folder</source>
        <translation>{path}: kann nicht geschrieben werden: {folder} ist kein Ordner</translation>
    </message>
    <message>
        <source>{path}: written twice (as {seen_key} too); choose another name</source>
        <translation>{path}: doppelt geschrieben (auch als {seen_key}); wählen Sie einen anderen Namen</translation>
    </message>
    <message>
        <source>{path}: is an input and would be overwritten by an output</source>
        <translation>{path}: ist eine Eingabe und würde von einer Ausgabe überschrieben</translation>
    </message>
    <message>
        <source>must be a folder, and {report} is a file</source>
        <translation>muss ein Ordner sein, aber {report} ist eine Datei</translation>
    </message>
    <message>
        <source>{report}: folder holds files but no report (index.html); it would be replaced as a whole: choose a new or empty folder</source>
        <translation>{report}: der Ordner enthält Dateien, aber keinen Bericht (index.html); er würde als Ganzes ersetzt: wählen Sie einen neuen oder leeren Ordner</translation>
    </message>
    <message>
        <source> and {len_foreign_1} more</source>
        <translation> und {len_foreign_1} weitere</translation>
    </message>
    <message>
        <source>{report}: folder holds {foreign_0}{more}, which no report writes; an older report there is replaced as a whole, which would delete it: choose a new or empty folder, or move it away</source>
        <translation>{report}: der Ordner enthält {foreign_0}{more}, was von keinem Bericht geschrieben wird; ein älterer Bericht dort wird als Ganzes ersetzt, wodurch dies gelöscht würde: wählen Sie einen neuen oder leeren Ordner, oder verschieben Sie es an einen anderen Ort</translation>
    </message>
    <message>
        <source>{inside_0}: lies inside the report folder {report}, which is replaced as a whole</source>
        <translation>{inside_0}: liegt im Berichtsordner {report}, der als Ganzes ersetzt wird</translation>
    </message>
    <message>
        <source>must end in .FCStd, got {fcstd}</source>
        <translation>muss auf .FCStd enden, erhalten: {fcstd}</translation>
    </message>
    <message>
        <source>applies to the Z-map method (zmap), not to abm</source>
        <translation>gilt für das Z-Map-Verfahren (zmap), nicht für abm</translation>
    </message>
    <message>
        <source>must be 0 (all cores) or a positive number of processes, got {workers}</source>
        <translation>muss 0 (alle Kerne) oder eine positive Anzahl von Prozessen sein, erhalten: {workers}</translation>
    </message>
    <message>
        <source>expected a Dask scheduler address such as tcp://127.0.0.1:8786, got {scheduler}</source>
        <translation>erwartet wurde eine Dask-Scheduler-Adresse wie tcp://127.0.0.1:8786, erhalten: {scheduler}</translation>
    </message>
    <message>
        <source>applies to the abm method: the Z-map updates its stock CL point by CL point</source>
        <translation>gilt für das abm-Verfahren: die Z-Map aktualisiert ihr Rohteil CL-Punkt für CL-Punkt</translation>
    </message>
    <message>
        <source>must be a positive number of mm, got {value}</source>
        <translation>muss eine positive Zahl in mm sein, erhalten: {value}</translation>
    </message>
    <message>
        <source>needs the abm method</source>
        <translation>erfordert das abm-Verfahren</translation>
    </message>
    <message>
        <source>the Z-map baseline samples a flat-end mill's edge; this ball mill (corner radius {corner} mm) is computed by the ABM engine only</source>
        <translation>das Z-Map-Basisverfahren tastet die Kante eines Schaftfräsers ab; dieser Kugelfräser (Eckenradius {corner} mm) wird nur vom ABM-Rechenkern berechnet</translation>
    </message>
    <message>
        <source>the Z-map baseline samples a flat-end mill's edge; this bull-nose mill (corner radius {corner} mm) is computed by the ABM engine only</source>
        <translation>das Z-Map-Basisverfahren tastet die Kante eines Schaftfräsers ab; dieser Torusfräser (Eckenradius {corner} mm) wird nur vom ABM-Rechenkern berechnet</translation>
    </message>
    <message>
        <source>the Z-map method: {error}</source>
        <translation>das Z-Map-Verfahren: {error}</translation>
    </message>
    <message>
        <source>{toolpath}: earlier moves of the program already removed all the material this operation's tool would meet (--stock-model initial computes it against the stock as given)</source>
        <translation>{toolpath}: frühere Bewegungen des Programms haben bereits das gesamte Material entfernt, auf das das Werkzeug dieser Operation treffen würde (--stock-model initial berechnet sie gegen das Rohteil wie angegeben)</translation>
    </message>
    <message>
        <source>must be 1..{flutes} (the tool has {flutes_2} flutes), got {flute}</source>
        <translation>muss 1..{flutes} sein (das Werkzeug hat {flutes_2} Schneiden), erhalten: {flute}</translation>
    </message>
    <message>
        <source>is not available with helical edges (--helix, --flute) yet</source>
        <translation>ist mit Schneidkanten mit Drall (--helix, --flute) noch nicht verfügbar</translation>
    </message>
    <message>
        <source>{toolpath}: {model_note}; validating against the stock as given</source>
        <translation>{toolpath}: {model_note}; es wird gegen das Rohteil wie gegeben validiert</translation>
    </message>
    <message>
        <source>{stock}: the boolean reference cannot build the stock's solid ({type}: {error})</source>
        <translation>{stock}: die boolesche Referenz kann den Volumenkörper des Rohteils nicht erzeugen ({type}: {error})</translation>
    </message>
    <message>
        <source>in-process is not available for validate with --flute (the helix boolean) yet: use initial</source>
        <translation>in-process ist für validate mit --flute (die boolesche Operation mit Helix) noch nicht verfügbar: verwenden Sie initial</translation>
    </message>
    <message>
        <source>must be a positive number, got {limit}</source>
        <translation>muss eine positive Zahl sein, erhalten: {limit}</translation>
    </message>
    <message>
        <source>must be a positive feed per tooth (mm), got {min_feed}</source>
        <translation>muss ein positiver Vorschub pro Zahn (mm) sein, erhalten: {min_feed}</translation>
    </message>
    <message>
        <source>must end in .apt, .cls, .csv or (for a FreeCAD CAM Job) .FCStd, got {out}</source>
        <translation>muss auf .apt, .cls, .csv oder (für einen FreeCAD-CAM-Job) .FCStd enden, erhalten: {out}</translation>
    </message>
    <message>
        <source>a FreeCAD document (.FCStd) is written for a FreeCAD CAM Job's program only, not for {toolpath}</source>
        <translation>ein FreeCAD-Dokument (.FCStd) wird nur für das Programm eines FreeCAD-CAM-Jobs geschrieben, nicht für {toolpath}</translation>
    </message>
    <message>
        <source>{model_note}: the feeds are scheduled against the stock as given</source>
        <translation>{model_note}: die Vorschübe werden gegen das Rohteil wie gegeben geplant</translation>
    </message>
    <message>
        <source> and {value} more</source>
        <translation> und {value} weitere</translation>
    </message>
    <message>
        <source>{count} CL points cannot keep the force at or under {limit} N at any feed from the minimum feed up; they get the minimum feed: {shown}{more}</source>
        <translation>{count} CL-Punkte können die Schnittkraft bei keinem Vorschub ab dem Mindestvorschub auf höchstens {limit} N halten; sie erhalten den Mindestvorschub: {shown}{more}</translation>
    </message>
    <message>
        <source>{count} CL points cannot keep the area at or under {limit} mm² at any feed from the minimum feed up; they get the minimum feed: {shown}{more}</source>
        <translation>{count} CL-Punkte können den Spanungsquerschnitt bei keinem Vorschub ab dem Mindestvorschub auf höchstens {limit} mm² halten; sie erhalten den Mindestvorschub: {shown}{more}</translation>
    </message>
    <message>
        <source>{toolpath}: {operation_label}: the dressup's feeds are per minute and need a spindle speed (its tool controller's, or give the spindle speed)</source>
        <translation>{toolpath}: {operation_label}: die Vorschübe des Dressups sind pro Minute angegeben und benötigen eine Drehzahl (die seines Werkzeugcontrollers, oder geben Sie die Drehzahl an)</translation>
    </message>
    <message>
        <source>{source}: {operation_label}: feeds per minute need a spindle speed (SPINDL, or give the spindle speed)</source>
        <translation>{source}: {operation_label}: Vorschübe pro Minute benötigen eine Drehzahl (SPINDL, oder geben Sie die Drehzahl an)</translation>
    </message>
    <message>
        <source>{why}: {shown} (more than the {most} a run takes without confirmation): {remedy}, or give --allow-large to run it anyway</source>
        <translation>{why}: {shown} (mehr als die {most}, die ein Lauf ohne Bestätigung verarbeitet): {remedy}, oder geben Sie --allow-large an, um ihn trotzdem auszuführen</translation>
    </message>
    <message>
        <source>{why}: {shown} (more than the {most} a run takes without confirmation): give --allow-large to run it anyway</source>
        <translation>{why}: {shown} (mehr als die {most}, die ein Lauf ohne Bestätigung verarbeitet): geben Sie --allow-large an, um ihn trotzdem auszuführen</translation>
    </message>
    <message>
        <source>{why}: {what} would need about {size} of memory, and this process may use {free}: {remedy}</source>
        <translation>{why}: {what} würde etwa {size} Arbeitsspeicher benötigen, und der für diesen Prozess nutzbare Arbeitsspeicher beträgt {free}: {remedy}</translation>
    </message>
    <message>
        <source>{why}: {what} would need about {size} of memory, and this process may use {free}</source>
        <translation>{why}: {what} würde etwa {size} Arbeitsspeicher benötigen, und der für diesen Prozess nutzbare Arbeitsspeicher beträgt {free}</translation>
    </message>
    <message>
        <source>{why}: {os_fspath_path} would take about {size_text_needed}, and {folder} has {size_text_space} free; give --allow-large to try anyway</source>
        <translation>{why}: {os_fspath_path} würde etwa {size_text_needed} belegen, und in {folder} sind {size_text_space} frei; geben Sie --allow-large an, um es trotzdem zu versuchen</translation>
    </message>
    <message>
        <source>job {job}, CL points {start}..{last}: {name}: {cause}</source>
        <translation>Auftrag {job}, CL-Punkte {start}..{last}: {name}: {cause}</translation>
    </message>
    <message>
        <source>CL points {start}..{last}: {name}: {cause}</source>
        <translation>CL-Punkte {start}..{last}: {name}: {cause}</translation>
    </message>
    <message>
        <source>workers must be a whole number &gt;= 0 (0 = all cores), got {workers}</source>
        <translation>workers muss eine ganze Zahl &gt;= 0 sein (0 = alle Kerne), erhalten: {workers}</translation>
    </message>
    <message>
        <source>chunk of CL points {start}..{start_n_1}: {name} differs from the first chunk's</source>
        <translation>Block der CL-Punkte {start}..{start_n_1}: {name} weicht von dem des ersten Blocks ab</translation>
    </message>
    <message>
        <source>{filled} of {m} CL points added</source>
        <translation>{filled} von {m} CL-Punkten hinzugefügt</translation>
    </message>
    <message>
        <source>could not start {workers} worker processes ({value}; a limit on processes?)</source>
        <translation>konnte {workers} Arbeitsprozesse nicht starten ({value}; eine Begrenzung der Prozessanzahl?)</translation>
    </message>
    <message>
        <source>Dask scheduler address must look like tcp://host:port, got {address}</source>
        <translation>Die Dask-Scheduler-Adresse muss die Form tcp://host:port haben, erhalten: {address}</translation>
    </message>
    <message>
        <source>Dask scheduler {address}: no answer within {SCHEDULER_TIMEOUT} s ({type}: {error})</source>
        <translation>Dask-Scheduler {address}: keine Antwort innerhalb von {SCHEDULER_TIMEOUT} s ({type}: {error})</translation>
    </message>
    <message>
        <source>kind must be one of {LIMITS}, got {kind}</source>
        <translation>kind muss einer der Werte {LIMITS} sein, erhalten: {kind}</translation>
    </message>
    <message>
        <source>the force limit must be a positive number, got {limit}</source>
        <translation>der Grenzwert der Schnittkraft muss eine positive Zahl sein, erhalten: {limit}</translation>
    </message>
    <message>
        <source>the area limit must be a positive number, got {limit}</source>
        <translation>der Grenzwert des Spanungsquerschnitts muss eine positive Zahl sein, erhalten: {limit}</translation>
    </message>
    <message>
        <source>the minimum feed must be finite and not negative</source>
        <translation>der Mindestvorschub muss endlich und nicht negativ sein</translation>
    </message>
    <message>
        <source>feeds in {unit} need the spindle speed to give a feed per tooth</source>
        <translation>Vorschübe in {unit} benötigen die Drehzahl, um einen Vorschub pro Zahn zu ergeben</translation>
    </message>
    <message>
        <source>a reference for a tool with a corner must give lep_xyz and uep_xyz</source>
        <translation>eine Referenz für ein Werkzeug mit Eckenradius muss lep_xyz und uep_xyz angeben</translation>
    </message>
    <message>
        <source>reference[{name}] must have shape {m_p}, got {shape}</source>
        <translation>reference[{name}] muss die Form {m_p} haben, erhalten: {shape}</translation>
    </message>
    <message>
        <source>no CL point of the pass engages the stock</source>
        <translation>kein CL-Punkt des Durchgangs ist im Eingriff mit dem Rohteil</translation>
    </message>
    <message>
        <source>cls must be distinct CL indices in 0..{m_1}, at least one; got {list_cls}</source>
        <translation>cls müssen verschiedene CL-Indizes in 0..{m_1} sein, mindestens einer; erhalten: {list_cls}</translation>
    </message>
    <message>
        <source>flute {flute} was not checked; checked: {list_self_flutes}</source>
        <translation>Schneide {flute} wurde nicht geprüft; geprüft: {list_self_flutes}</translation>
    </message>
    <message>
        <source>flutes must be indices in 0..{tool_flutes_1}, got {flutes}</source>
        <translation>flutes müssen Indizes in 0..{tool_flutes_1} sein, erhalten: {flutes}</translation>
    </message>
    <message>
        <source>no CL point of the pass engages the stock with the checked flutes</source>
        <translation>kein CL-Punkt des Durchgangs ist mit den geprüften Schneiden im Eingriff mit dem Rohteil</translation>
    </message>
    <message>
        <source>stopped with {value} of {count} tasks unanswered</source>
        <translation>angehalten mit {value} von {count} unbeantworteten Aufgaben</translation>
    </message>
    <message>
        <source>a worker process ended without answering task {index} (exit code {exitcode})</source>
        <translation>ein Arbeitsprozess endete, ohne auf Aufgabe {index} zu antworten (Exit-Code {exitcode})</translation>
    </message>
    <message>
        <source>the worker process ended without answering (exit code {exitcode})</source>
        <translation>der Arbeitsprozess endete ohne Antwort (Exit-Code {exitcode})</translation>
    </message>
    <message>
        <source>positive</source>
        <translation>positiv</translation>
    </message>
    <message>
        <source>above {low}</source>
        <translation>größer als {low}</translation>
    </message>
    <message>
        <source>at least {low}</source>
        <translation>mindestens {low}</translation>
    </message>
    <message>
        <source>below {high}</source>
        <translation>kleiner als {high}</translation>
    </message>
    <message>
        <source>at most {high}</source>
        <translation>höchstens {high}</translation>
    </message>
    <message>
        <source>within {interval}</source>
        <translation>im Bereich {interval}</translation>
    </message>
    <message>
        <source>is required: the toolpath file does not give it</source>
        <translation>ist erforderlich: die Werkzeugbahndatei enthält diesen Wert nicht</translation>
    </message>
</context>
<context>
    <name>ABM_parameters</name>
    <message>
        <source>tool diameter</source>
        <translation>Werkzeugdurchmesser</translation>
    </message>
    <message>
        <source>number of flutes</source>
        <translation>Schneidenzahl</translation>
    </message>
    <message>
        <source>flute length</source>
        <translation>Schneidenlänge</translation>
    </message>
    <message>
        <source>corner radius</source>
        <translation>Eckenradius</translation>
    </message>
    <message>
        <source>helix angle</source>
        <translation>Drallwinkel</translation>
    </message>
    <message>
        <source>feed per tooth</source>
        <translation>Vorschub pro Zahn</translation>
    </message>
    <message>
        <source>spindle speed</source>
        <translation>Drehzahl</translation>
    </message>
    <message>
        <source>inclination angle</source>
        <translation>Anstellwinkel</translation>
    </message>
    <message>
        <source>first rotation angle φ</source>
        <translation>erster Drehwinkel φ</translation>
    </message>
    <message>
        <source>last rotation angle φ</source>
        <translation>letzter Drehwinkel φ</translation>
    </message>
    <message>
        <source>step of φ</source>
        <translation>Schrittweite von φ</translation>
    </message>
    <message>
        <source>Ktc (tangential cutting coefficient)</source>
        <translation>Ktc (tangentialer Schnittkraftkoeffizient)</translation>
    </message>
    <message>
        <source>Krc (radial cutting coefficient)</source>
        <translation>Krc (radialer Schnittkraftkoeffizient)</translation>
    </message>
    <message>
        <source>Kac (axial cutting coefficient)</source>
        <translation>Kac (axialer Schnittkraftkoeffizient)</translation>
    </message>
    <message>
        <source>Kte (tangential edge coefficient)</source>
        <translation>Kte (tangentialer Schneidkantenkoeffizient)</translation>
    </message>
    <message>
        <source>Kre (radial edge coefficient)</source>
        <translation>Kre (radialer Schneidkantenkoeffizient)</translation>
    </message>
    <message>
        <source>Kae (axial edge coefficient)</source>
        <translation>Kae (axialer Schneidkantenkoeffizient)</translation>
    </message>
    <message>
        <source>start of immersion</source>
        <translation>Eingriffsbeginn</translation>
    </message>
    <message>
        <source>end of immersion</source>
        <translation>Eingriffsende</translation>
    </message>
</context>
</TS>
