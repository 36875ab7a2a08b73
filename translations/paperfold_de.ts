<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de">
<context>
    <name>Legend</name>
    <message>
        <source>simulation mesh (edges)</source>
        <translation>Simulationsnetz (Kanten)</translation>
    </message>
    <message>
        <source>Break probability P (Eq. 10, per %1 % more contraction)</source>
        <translation>Bruchwahrscheinlichkeit P (Gl. 10, je %1 % mehr Stauchung)</translation>
    </message>
    <message>
        <source>breakable spring</source>
        <translation>brechbare Feder</translation>
    </message>
    <message>
        <source>unbreakable spring</source>
        <translation>unzerbrechliche Feder</translation>
    </message>
    <message>
        <source>crease (broken)</source>
        <translation>Knick (gebrochen)</translation>
    </message>
    <message>
        <source>hinge</source>
        <translation>Scharnier</translation>
    </message>
    <message>
        <source>broken in the last second</source>
        <translation>in der letzten Sekunde gebrochen</translation>
    </message>
    <message>
        <source>Strain |l/l0 - 1|, stretched or compressed</source>
        <translation>Dehnung |l/l0 - 1|, gestreckt oder gestaucht</translation>
    </message>
</context>
<context>
    <name>UndoCommands</name>
    <message numerus="yes">
        <source>Push (%n break(s) or hinge(s))</source>
        <translation>
            <numerusform>Drücken (%n Bruch oder Scharnier)</numerusform>
            <numerusform>Drücken (%n Brüche oder Scharniere)</numerusform>
        </translation>
    </message>
    <message>
        <source>Change %1</source>
        <translation>%1 ändern</translation>
    </message>
    <message>
        <source>stretch stiffness</source>
        <translation>Dehnsteifigkeit</translation>
    </message>
    <message>
        <source>bending stiffness</source>
        <translation>Biegesteifigkeit</translation>
    </message>
    <message>
        <source>integrator</source>
        <translation>Integrator</translation>
    </message>
    <message>
        <source>paper</source>
        <translation>Papier</translation>
    </message>
    <message>
        <source>Jacobi sweeps</source>
        <translation>Jacobi-Durchläufe</translation>
    </message>
    <message>
        <source>steps per second</source>
        <translation>Schritte pro Sekunde</translation>
    </message>
    <message>
        <source>gravity outside the filter</source>
        <translation>Schwerkraft außerhalb des Filters</translation>
    </message>
    <message>
        <source>Fold</source>
        <translation>Falten</translation>
    </message>
    <message>
        <source>Settle</source>
        <translation>Beruhigen</translation>
    </message>
    <message numerus="yes">
        <source>Grab (%n break(s) or hinge(s))</source>
        <translation>
            <numerusform>Greifen (%n Bruch oder Scharnier)</numerusform>
            <numerusform>Greifen (%n Brüche oder Scharniere)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Pin %n vertex(es)</source>
        <translation>
            <numerusform>Anheften (%n Knoten)</numerusform>
            <numerusform>Anheften (%n Knoten)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Unpin %n vertex(es)</source>
        <translation>
            <numerusform>Lösen (%n Knoten)</numerusform>
            <numerusform>Lösen (%n Knoten)</numerusform>
        </translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>Zurücksetzen</translation>
    </message>
    <message numerus="yes">
        <source>Fold (%n break(s) or hinge(s))</source>
        <translation>
            <numerusform>Falten (%n Bruch oder Scharnier)</numerusform>
            <numerusform>Falten (%n Brüche oder Scharniere)</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>pf::ActionTexts</name>
    <message>
        <source>&amp;Press (sphere on a sheet)</source>
        <translation>&amp;Drücken (Kugel auf einem Blatt)</translation>
    </message>
    <message>
        <source>&amp;Drape (hanging sheet)</source>
        <translation>&amp;Hängen (hängendes Blatt)</translation>
    </message>
    <message>
        <source>&amp;Compress (edges pushed together)</source>
        <translation>&amp;Stauchen (Kanten zusammengeschoben)</translation>
    </message>
    <message>
        <source>D&amp;rop (tilted sheet falls)</source>
        <translation>&amp;Fallen (schräges Blatt fällt)</translation>
    </message>
    <message>
        <source>&amp;Open…</source>
        <translation>Ö&amp;ffnen…</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>&amp;Speichern</translation>
    </message>
    <message>
        <source>Save &amp;As…</source>
        <translation>Speichern &amp;unter…</translation>
    </message>
    <message>
        <source>Save &amp;Recording…</source>
        <translation>&amp;Aufzeichnung speichern…</translation>
    </message>
    <message>
        <source>Save everything done since New or Open; paperfold replay does it again</source>
        <translation>Alles seit Neu oder Öffnen Getane speichern; paperfold replay wiederholt es</translation>
    </message>
    <message>
        <source>Export &amp;Image…</source>
        <translation>&amp;Bild exportieren…</translation>
    </message>
    <message>
        <source>Export &amp;Mesh…</source>
        <translation>&amp;Netz exportieren…</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <source>&amp;Play</source>
        <translation>&amp;Abspielen</translation>
    </message>
    <message>
        <source>Play or pause the simulation (Space)</source>
        <translation>Simulation abspielen oder anhalten (Leertaste)</translation>
    </message>
    <message>
        <source>S&amp;tep</source>
        <translation>Einzel&amp;schritt</translation>
    </message>
    <message>
        <source>Advance one step</source>
        <translation>Einen Schritt weiter</translation>
    </message>
    <message>
        <source>&amp;Reset</source>
        <translation>&amp;Zurücksetzen</translation>
    </message>
    <message>
        <source>&amp;Spring kinds</source>
        <translation>&amp;Federarten</translation>
    </message>
    <message>
        <source>&amp;Break probability</source>
        <translation>&amp;Bruchwahrscheinlichkeit</translation>
    </message>
    <message>
        <source>S&amp;train</source>
        <translation>&amp;Dehnung</translation>
    </message>
    <message>
        <source>&amp;Recent breaks</source>
        <translation>&amp;Letzte Brüche</translation>
    </message>
    <message>
        <source>Simulation &amp;wireframe</source>
        <translation>Simulations-&amp;Drahtgitter</translation>
    </message>
    <message>
        <source>&amp;Top</source>
        <translation>Von &amp;oben</translation>
    </message>
    <message>
        <source>&amp;Front</source>
        <translation>Von &amp;vorn</translation>
    </message>
    <message>
        <source>&amp;Isometric</source>
        <translation>&amp;Isometrisch</translation>
    </message>
    <message>
        <source>Fit to &amp;sheet</source>
        <translation>Auf das &amp;Blatt einpassen</translation>
    </message>
    <message>
        <source>&amp;Mouse and Keys</source>
        <translation>&amp;Maus und Tasten</translation>
    </message>
    <message>
        <source>&amp;About PaperFold</source>
        <translation>Ü&amp;ber PaperFold</translation>
    </message>
    <message>
        <source>System language</source>
        <translation>Systemsprache</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Rückgängig</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Wiederholen</translation>
    </message>
    <message>
        <source>&amp;Pause</source>
        <translation>&amp;Pause</translation>
    </message>
    <message>
        <source>Sett&amp;le</source>
        <translation>Zur R&amp;uhe kommen lassen</translation>
    </message>
    <message>
        <source>Let the sheet come to rest without new breaks and keep it so until the next edit (Ctrl+K)</source>
        <translation>Das Blatt ohne neue Brüche zur Ruhe kommen lassen und bis zur nächsten Bearbeitung so halten (Strg+K)</translation>
    </message>
    <message>
        <source>&amp;Push</source>
        <translation>&amp;Drücken</translation>
    </message>
    <message>
        <source>Push: the left button presses the sphere into the sheet and ploughs it (P)</source>
        <translation>Drücken: Die linke Maustaste drückt die Kugel ins Blatt und pflügt es (P)</translation>
    </message>
    <message>
        <source>&amp;Grab</source>
        <translation>&amp;Greifen</translation>
    </message>
    <message>
        <source>Grab: pick up a point of the sheet and drag it; the wheel lifts or lowers it while held; release lets it fall (G)</source>
        <translation>Greifen: einen Punkt des Blatts aufnehmen und ziehen; das Mausrad hebt oder senkt ihn, solange er gehalten wird; Loslassen lässt ihn fallen (G)</translation>
    </message>
    <message>
        <source>P&amp;in</source>
        <translation>&amp;Anheften</translation>
    </message>
    <message>
        <source>Pin: a click pins the paper around the point, or frees it if it is pinned; Ctrl + wheel sizes the region (I)</source>
        <translation>Anheften: Ein Klick heftet das Papier um den Punkt an oder löst es, wenn es angeheftet ist; Strg + Mausrad ändert die Größe des Bereichs (I)</translation>
    </message>
    <message>
        <source>Start the current scene again (Edit ▸ Undo gives it back)</source>
        <translation>Die aktuelle Szene neu beginnen (Bearbeiten ▸ Rückgängig holt sie zurück)</translation>
    </message>
    <message>
        <source>&amp;Fold (one edge turned over onto the other)</source>
        <translation>Fal&amp;ten (eine Kante auf die andere umgeschlagen)</translation>
    </message>
    <message>
        <source>&amp;Fold</source>
        <translation>&amp;Falten</translation>
    </message>
    <message>
        <source>Fold: draw a line across the paper; the lighter side (or the side without pins) is carried round it, pressed flat, opened to the angle set in the Parameters panel and let go (L)</source>
        <translation>Falten: eine Linie über das Papier ziehen; die leichtere Seite (oder die ohne angeheftete Stellen) wird um sie herumgeführt, flach gepresst, auf den im Bereich Parameter eingestellten Winkel geöffnet und losgelassen (L)</translation>
    </message>
    <message>
        <source>Cr&amp;umple Cycles (crumpled and pulled flat, ten times)</source>
        <translation>&amp;Knüllen (zehnmal zerknüllt und glatt gezogen)</translation>
    </message>
    <message>
        <source>&amp;Crease Lines</source>
        <translation>&amp;Knicklinien</translation>
    </message>
    <message>
        <source>The paper&apos;s creases drawn as fine lines a shade darker than the paper, as the damaged fibres of a crease show, also once the paper is pulled flat</source>
        <translation>Die Knicke des Papiers als feine Linien, etwas dunkler als das Papier, wie die verletzten Fasern eines Knicks sie zeigen, auch wenn das Papier wieder glattgezogen ist</translation>
    </message>
</context>
<context>
    <name>pf::ChartBrowser</name>
    <message>
        <source>No bench_*.png in %1. Run: paperfold bench --output-dir %1</source>
        <translation>Kein bench_*.png in %1. Ausführen: paperfold bench --output-dir %1</translation>
    </message>
    <message>
        <source>No chart in %1 yet: choose the folder &apos;paperfold bench --output-dir&apos; wrote</source>
        <translation>Noch kein Diagramm in %1: Ordner wählen, den &apos;paperfold bench --output-dir&apos; geschrieben hat</translation>
    </message>
</context>
<context>
    <name>pf::EditorDialogs</name>
    <message>
        <source>PaperFold sheets (*.paper)</source>
        <translation>PaperFold-Blätter (*.paper)</translation>
    </message>
    <message>
        <source>Open Sheet</source>
        <translation>Blatt öffnen</translation>
    </message>
    <message>
        <source>Save Sheet</source>
        <translation>Blatt speichern</translation>
    </message>
    <message>
        <source>Export Image</source>
        <translation>Bild exportieren</translation>
    </message>
    <message>
        <source>PNG images (*.png)</source>
        <translation>PNG-Bilder (*.png)</translation>
    </message>
    <message>
        <source>Export Mesh</source>
        <translation>Netz exportieren</translation>
    </message>
    <message>
        <source>Meshes (*.obj *.ply *.glb)</source>
        <translation>Netze (*.obj *.ply *.glb)</translation>
    </message>
    <message>
        <source>Save Recording</source>
        <translation>Aufzeichnung speichern</translation>
    </message>
    <message>
        <source>PaperFold recordings (*.paperrec)</source>
        <translation>PaperFold-Aufzeichnungen (*.paperrec)</translation>
    </message>
    <message>
        <source>PaperFold</source>
        <translation>PaperFold</translation>
    </message>
    <message>
        <source>The sheet has unsaved changes. Save them?</source>
        <translation>Das Blatt hat ungespeicherte Änderungen. Speichern?</translation>
    </message>
    <message>
        <source>Size in pixels (width x height):</source>
        <translation>Größe in Pixeln (Breite x Höhe):</translation>
    </message>
    <message>
        <source>Picture for the Paper</source>
        <translation>Bild für das Papier</translation>
    </message>
    <message>
        <source>Images (*.png *.jpg *.jpeg *.bmp *.webp)</source>
        <translation>Bilder (*.png *.jpg *.jpeg *.bmp *.webp)</translation>
    </message>
    <message>
        <source>Paper Colour</source>
        <translation>Papierfarbe</translation>
    </message>
    <message>
        <source>Subdivision level, 0 to %1: 0 writes the simulation mesh; each level splits every triangle in four along the paper&apos;s curved surface.</source>
        <translation>Unterteilungsstufe, 0 bis %1: 0 schreibt das Simulationsnetz; jede Stufe teilt jedes Dreieck entlang der gekrümmten Papierfläche in vier.</translation>
    </message>
</context>
<context>
    <name>pf::HelpText</name>
    <message>
        <source>Mouse and Keys</source>
        <translation>Maus und Tasten</translation>
    </message>
    <message>
        <source>About PaperFold</source>
        <translation>Über PaperFold</translation>
    </message>
    <message>
        <source>&lt;p&gt;&lt;b&gt;PaperFold %1&lt;/b&gt;&lt;/p&gt;&lt;p&gt;Crumple and fold virtual paper in real time, after Kang &amp;amp; Cho, &lt;i&gt;A Simple and Effective Model for Interactive Paper Folding&lt;/i&gt;.&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;PaperFold %1&lt;/b&gt;&lt;/p&gt;&lt;p&gt;Virtuelles Papier in Echtzeit zerknittern und falten, nach Kang &amp;amp; Cho, &lt;i&gt;A Simple and Effective Model for Interactive Paper Folding&lt;/i&gt;.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;table cellspacing=&quot;2&quot; cellpadding=&quot;3&quot;&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;P&lt;/b&gt;, &lt;b&gt;G&lt;/b&gt;, &lt;b&gt;I&lt;/b&gt;, &lt;b&gt;L&lt;/b&gt;&lt;/td&gt;&lt;td&gt;tools: push, grab, pin, fold&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Left drag&lt;/b&gt; (push)&lt;/td&gt;&lt;td&gt;press the sphere into the paper and plough it (one undo step per stroke)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Left drag&lt;/b&gt; (grab)&lt;/td&gt;&lt;td&gt;pick up the point under the cursor and drag it; the wheel lifts or lowers it while held; release lets it fall&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Click&lt;/b&gt; (pin)&lt;/td&gt;&lt;td&gt;pin the paper around the point, or free it if it is pinned&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Left drag&lt;/b&gt; (fold)&lt;/td&gt;&lt;td&gt;draw the fold line across the paper; the lighter side (or the side without pins) is carried round it (valley or mountain, and the angle, in the Parameters panel)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Ctrl + wheel&lt;/b&gt;&lt;/td&gt;&lt;td&gt;sphere radius (and the pin region)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Right drag&lt;/b&gt;, arrow keys&lt;/td&gt;&lt;td&gt;orbit the camera&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Middle drag&lt;/b&gt;, Shift + right drag&lt;/td&gt;&lt;td&gt;pan&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Wheel&lt;/b&gt;, + and −&lt;/td&gt;&lt;td&gt;zoom&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;1&lt;/b&gt;, &lt;b&gt;2&lt;/b&gt;, &lt;b&gt;3&lt;/b&gt;, &lt;b&gt;F&lt;/b&gt;&lt;/td&gt;&lt;td&gt;top, front, isometric view; fit to sheet&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Space&lt;/b&gt;, &lt;b&gt;Ctrl+.&lt;/b&gt;, &lt;b&gt;Ctrl+K&lt;/b&gt;, &lt;b&gt;Ctrl+R&lt;/b&gt;&lt;/td&gt;&lt;td&gt;play/pause, single step, settle, reset&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Alt+1…5&lt;/b&gt;&lt;/td&gt;&lt;td&gt;overlays: spring kinds, break probability, strain, recent breaks, wireframe&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Ctrl+Z&lt;/b&gt;, &lt;b&gt;Ctrl+Shift+Z&lt;/b&gt;&lt;/td&gt;&lt;td&gt;undo, redo&lt;/td&gt;&lt;/tr&gt;&lt;/table&gt;</source>
        <translation>&lt;table cellspacing=&quot;2&quot; cellpadding=&quot;3&quot;&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;P&lt;/b&gt;, &lt;b&gt;G&lt;/b&gt;, &lt;b&gt;I&lt;/b&gt;, &lt;b&gt;L&lt;/b&gt;&lt;/td&gt;&lt;td&gt;Werkzeuge: drücken, greifen, anheften, falten&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Linke Maustaste ziehen&lt;/b&gt; (Drücken)&lt;/td&gt;&lt;td&gt;die Kugel ins Papier drücken und es pflügen (ein Rückgängig-Schritt pro Strich)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Linke Maustaste ziehen&lt;/b&gt; (Greifen)&lt;/td&gt;&lt;td&gt;den Punkt unter dem Zeiger aufnehmen und ziehen; das Mausrad hebt oder senkt ihn, solange er gehalten wird; Loslassen lässt ihn fallen&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Klick&lt;/b&gt; (Anheften)&lt;/td&gt;&lt;td&gt;das Papier um den Punkt anheften oder lösen, wenn es angeheftet ist&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Linke Maustaste ziehen&lt;/b&gt; (Falten)&lt;/td&gt;&lt;td&gt;die Faltlinie über das Papier ziehen; die leichtere Seite (oder die ohne angeheftete Stellen) wird um sie herumgeführt (Tal oder Berg und der Winkel im Bereich Parameter)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Strg + Mausrad&lt;/b&gt;&lt;/td&gt;&lt;td&gt;Kugelradius (und der Anheftbereich)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Rechte Maustaste ziehen&lt;/b&gt;, Pfeiltasten&lt;/td&gt;&lt;td&gt;Kamera umkreisen&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Mittlere Maustaste ziehen&lt;/b&gt;, Umschalt + rechte Maustaste&lt;/td&gt;&lt;td&gt;verschieben&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Mausrad&lt;/b&gt;, + und −&lt;/td&gt;&lt;td&gt;zoomen&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;1&lt;/b&gt;, &lt;b&gt;2&lt;/b&gt;, &lt;b&gt;3&lt;/b&gt;, &lt;b&gt;F&lt;/b&gt;&lt;/td&gt;&lt;td&gt;Ansicht von oben, von vorn, isometrisch; auf das Blatt einpassen&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Leertaste&lt;/b&gt;, &lt;b&gt;Strg+.&lt;/b&gt;, &lt;b&gt;Strg+K&lt;/b&gt;, &lt;b&gt;Strg+R&lt;/b&gt;&lt;/td&gt;&lt;td&gt;Abspielen/Anhalten, Einzelschritt, zur Ruhe kommen lassen, Zurücksetzen&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Alt+1…5&lt;/b&gt;&lt;/td&gt;&lt;td&gt;Überlagerungen: Federarten, Bruchwahrscheinlichkeit, Dehnung, letzte Brüche, Drahtgitter&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Strg+Z&lt;/b&gt;, &lt;b&gt;Strg+Umschalt+Z&lt;/b&gt;&lt;/td&gt;&lt;td&gt;rückgängig, wiederholen&lt;/td&gt;&lt;/tr&gt;&lt;/table&gt;</translation>
    </message>
</context>
<context>
    <name>pf::MainWindow</name>
    <message>
        <source>The simulation blew up at step %1 and was paused; the last good state is kept. Try more steps per second or the jacobi integrator.</source>
        <translation>Die Simulation ist in Schritt %1 instabil geworden und wurde angehalten; der letzte gültige Zustand bleibt erhalten. Versuchen Sie mehr Schritte pro Sekunde oder den Integrator „jacobi“.</translation>
    </message>
    <message>
        <source>Ctrl+E</source>
        <translation>Ctrl+E</translation>
    </message>
    <message>
        <source>Ctrl+Shift+S</source>
        <translation>Ctrl+Shift+S</translation>
    </message>
    <message>
        <source>Ctrl+Shift+E</source>
        <translation>Ctrl+Shift+E</translation>
    </message>
    <message>
        <source>Ctrl+Y</source>
        <translation>Ctrl+Y</translation>
    </message>
    <message>
        <source>Ctrl+.</source>
        <translation>Ctrl+.</translation>
    </message>
    <message>
        <source>Ctrl+R</source>
        <translation>Ctrl+R</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <source>&amp;New</source>
        <translation>&amp;Neu</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>&amp;Zuletzt geöffnet</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>&amp;Bearbeiten</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <source>&amp;Overlays</source>
        <translation>&amp;Überlagerungen</translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>&amp;Sprache</translation>
    </message>
    <message>
        <source>&amp;Simulation</source>
        <translation>&amp;Simulation</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <source>Main toolbar</source>
        <translation>Hauptwerkzeugleiste</translation>
    </message>
    <message>
        <source>Parameters</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <source>History</source>
        <translation>Verlauf</translation>
    </message>
    <message>
        <source>&lt;new sheet&gt;</source>
        <translation>&lt;neues Blatt&gt;</translation>
    </message>
    <message>
        <source>Untitled</source>
        <translation>Unbenannt</translation>
    </message>
    <message>
        <source>%1[*] — PaperFold</source>
        <translation>%1[*] — PaperFold</translation>
    </message>
    <message>
        <source>Could not open the sheet: %1</source>
        <translation>Das Blatt konnte nicht geöffnet werden: %1</translation>
    </message>
    <message>
        <source>Could not save the sheet: %1</source>
        <translation>Das Blatt konnte nicht gespeichert werden: %1</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>%1 gespeichert</translation>
    </message>
    <message>
        <source>Could not export the image: %1</source>
        <translation>Das Bild konnte nicht exportiert werden: %1</translation>
    </message>
    <message>
        <source>Choose a file ending in .obj, .ply or .glb</source>
        <translation>Wählen Sie eine Datei mit der Endung .obj, .ply oder .glb</translation>
    </message>
    <message>
        <source>Could not export the mesh: %1</source>
        <translation>Das Netz konnte nicht exportiert werden: %1</translation>
    </message>
    <message>
        <source>Solver</source>
        <translation>Löser</translation>
    </message>
    <message>
        <source>Could not save the recording: %1</source>
        <translation>Die Aufzeichnung konnte nicht gespeichert werden: %1</translation>
    </message>
    <message>
        <source>Paused: the push moves the paper only while the simulation runs (Space plays, Ctrl+. steps).</source>
        <translation>Angehalten: Das Drücken bewegt das Papier nur, während die Simulation läuft (Leertaste spielt ab, Strg+. macht einen Schritt).</translation>
    </message>
    <message>
        <source>The image size is width x height, each from 16 to %1 pixels, such as 1920x1080.</source>
        <translation>Die Bildgröße ist Breite x Höhe, jeweils 16 bis %1 Pixel, etwa 1920x1080.</translation>
    </message>
    <message>
        <source>Settled: the sheet stays as it is until the next edit.</source>
        <translation>Beruhigt: Das Blatt bleibt bis zur nächsten Bearbeitung, wie es ist.</translation>
    </message>
    <message>
        <source>Ctrl+K</source>
        <translation>Ctrl+K</translation>
    </message>
    <message>
        <source>Settling: the sheet comes to rest…</source>
        <translation>Beruhigen: Das Blatt kommt zur Ruhe…</translation>
    </message>
    <message>
        <source>Settling once the simulation plays (Space).</source>
        <translation>Beruhigt wird, sobald die Simulation läuft (Leertaste).</translation>
    </message>
    <message>
        <source>&amp;Tools</source>
        <translation>&amp;Werkzeuge</translation>
    </message>
    <message>
        <source>Paused: the grab moves the paper only while the simulation runs (Space plays, Ctrl+. steps).</source>
        <translation>Angehalten: Das Greifen bewegt das Papier nur, während die Simulation läuft (Leertaste spielt ab, Strg+. macht einen Schritt).</translation>
    </message>
    <message>
        <source>Rendering the image (%1 x %2)…</source>
        <translation>Das Bild wird gerendert (%1 x %2)…</translation>
    </message>
    <message>
        <source>Export Image</source>
        <translation>Bild exportieren</translation>
    </message>
    <message>
        <source>Exported %1</source>
        <translation>%1 exportiert</translation>
    </message>
    <message>
        <source>An image is being exported; close once it is written.</source>
        <translation>Ein Bild wird exportiert; schließen Sie, sobald es geschrieben ist.</translation>
    </message>
    <message>
        <source>Paused: the fold is carried round once the simulation runs (Space plays, Ctrl+. steps).</source>
        <translation>Angehalten: Die Faltung wird ausgeführt, sobald die Simulation läuft (Leertaste spielt ab, Strg+. macht einen Schritt).</translation>
    </message>
    <message>
        <source>Left drag pushes the paper · L folds, G grabs and I pins (Tools menu) · right drag orbits · the wheel zooms · F1 lists every key</source>
        <translation>Linke Maustaste ziehen drückt das Papier · L faltet, G greift, I heftet an (Menü Werkzeuge) · rechte Maustaste ziehen dreht die Ansicht · Mausrad zoomt · F1 zeigt alle Tasten</translation>
    </message>
    <message>
        <source>Folding: the paper is carried round the line, pressed and let go…</source>
        <translation>Falten: Das Papier wird um die Linie geführt, gepresst und losgelassen…</translation>
    </message>
    <message>
        <source>Not folded: draw a longer line across the paper.</source>
        <translation>Nicht gefaltet: Ziehen Sie eine längere Linie über das Papier.</translation>
    </message>
    <message>
        <source>Not folded: the line must cross the paper.</source>
        <translation>Nicht gefaltet: Die Linie muss über das Papier gehen.</translation>
    </message>
    <message>
        <source>Not folded: there is paper on one side of the line only.</source>
        <translation>Nicht gefaltet: Papier liegt nur auf einer Seite der Linie.</translation>
    </message>
    <message>
        <source>Not folded: the angle must lie between 1° and 180°.</source>
        <translation>Nicht gefaltet: Der Winkel muss zwischen 1° und 180° liegen.</translation>
    </message>
    <message>
        <source>Not folded: another edit is under way.</source>
        <translation>Nicht gefaltet: Eine andere Bearbeitung läuft noch.</translation>
    </message>
    <message>
        <source>Not folded: this way the flap would go through the desk, and pins hold the paper down. Fold the other way (Valley or Mountain), or unpin the paper.</source>
        <translation>Nicht gefaltet: So ginge die Lasche durch den Tisch, und angeheftete Stellen halten das Papier fest. Falten Sie andersherum (Tal oder Berg) oder lösen Sie die Anheftung.</translation>
    </message>
    <message>
        <source>Not folded: pins hold the paper on both sides of the line. Unpin one side: the pinned side stays, the other is folded over.</source>
        <translation>Nicht gefaltet: Angeheftete Stellen halten das Papier auf beiden Seiten der Linie fest. Lösen Sie eine Seite: Die angeheftete Seite bleibt liegen, die andere wird umgefaltet.</translation>
    </message>
    <message>
        <source>Not now: a fold is under way.</source>
        <translation>Nicht jetzt: Eine Faltung läuft noch.</translation>
    </message>
    <message>
        <source>Folded. Edit ▸ Undo unfolds the paper.</source>
        <translation>Gefaltet. Bearbeiten ▸ Rückgängig entfaltet das Papier.</translation>
    </message>
    <message>
        <source>The fold opened %1° again after it was let go: its crease did not hold the flap. Edit ▸ Undo unfolds the paper.</source>
        <translation>Die Faltung hat sich nach dem Loslassen wieder um %1° geöffnet: Ihr Knick hat die Lasche nicht gehalten. Bearbeiten ▸ Rückgängig entfaltet das Papier.</translation>
    </message>
    <message>
        <source>Only part of the fold held: %1 % of the paper on the flap&apos;s side lies unfolded. The fold holds the paper that lies flat along the line, not layers above or below it. Edit ▸ Undo unfolds the paper.</source>
        <translation>Die Faltung hat nur zum Teil gehalten: %1 % des Papiers auf der Seite der Lasche liegt ungefaltet. Die Faltung hält das Papier, das entlang der Linie flach liegt, nicht die Lagen darüber oder darunter. Bearbeiten ▸ Rückgängig entfaltet das Papier.</translation>
    </message>
    <message>
        <source>Already settled: the sheet stays as it is until the next edit.</source>
        <translation>Bereits beruhigt: Das Blatt bleibt bis zur nächsten Bearbeitung, wie es ist.</translation>
    </message>
    <message>
        <source>Not settled: an edit is under way. Settle once it is over.</source>
        <translation>Nicht beruhigt: Eine Bearbeitung läuft noch. Beruhigen Sie das Blatt, wenn sie vorbei ist.</translation>
    </message>
    <message>
        <source>The fold is opening again: its crease does not hold the flap. Edit ▸ Undo unfolds the paper.</source>
        <translation>Die Faltung öffnet sich wieder: Ihr Knick hält die Lasche nicht. Bearbeiten ▸ Rückgängig entfaltet das Papier.</translation>
    </message>
    <message>
        <source>The fold fell shut after it was let go: its crease cannot hold the flap up at %1°. Edit ▸ Undo unfolds the paper.</source>
        <translation>Die Faltung ist nach dem Loslassen zugefallen: Ihr Knick kann die Lasche bei %1° nicht aufrecht halten. Bearbeiten ▸ Rückgängig entfaltet das Papier.</translation>
    </message>
    <message>
        <source>The fold closed %1° further than asked after it was let go: its crease cannot hold the flap at that angle. Edit ▸ Undo unfolds the paper.</source>
        <translation>Die Faltung hat sich nach dem Loslassen %1° weiter geschlossen als verlangt: Ihr Knick kann die Lasche in diesem Winkel nicht halten. Bearbeiten ▸ Rückgängig entfaltet das Papier.</translation>
    </message>
    <message>
        <source>Undo waits until the fold is let go.</source>
        <translation>Rückgängig wartet, bis die Faltung losgelassen ist.</translation>
    </message>
    <message>
        <source>Undo waits until the sheet has settled.</source>
        <translation>Rückgängig wartet, bis das Blatt zur Ruhe gekommen ist.</translation>
    </message>
    <message>
        <source>Undo waits until the mouse lets go of the paper.</source>
        <translation>Rückgängig wartet, bis die Maus das Papier loslässt.</translation>
    </message>
    <message>
        <source>Paused: the fold waits. Space plays and carries the paper round the line; Ctrl+. steps.</source>
        <translation>Angehalten: Die Faltung wartet. Die Leertaste spielt ab und führt das Papier um die Linie; Strg+. macht einen Schritt.</translation>
    </message>
    <message>
        <source>Undo waits until the fold is let go, and the simulation is paused: Space plays.</source>
        <translation>Rückgängig wartet, bis die Faltung losgelassen ist, und die Simulation ist angehalten: Die Leertaste spielt ab.</translation>
    </message>
    <message>
        <source>The pins hold this paper taut: the hand pulls it with at most %1 N, as a pinch does before paper slips from it, and paper does not stretch to follow.</source>
        <translation>Die Anheftungen halten dieses Papier straff: Die Hand zieht mit höchstens %1 N, wie ein Fingergriff, bevor Papier aus ihm rutscht, und Papier dehnt sich nicht, um ihr zu folgen.</translation>
    </message>
    <message>
        <source>This push moved nothing: the tool touched no paper, or slid over paper it cannot move (paper held by pins, say). Push where the paper is free, or unpin it.</source>
        <translation>Dieses Drücken hat nichts bewegt: Das Werkzeug hat kein Papier berührt oder ist über Papier geglitten, das es nicht bewegen kann (etwa Papier, das Anheftungen festhalten). Drücken Sie dort, wo das Papier frei ist, oder lösen Sie die Anheftungen.</translation>
    </message>
    <message>
        <source>Not now: the mouse holds the paper. Let go first.</source>
        <translation>Nicht jetzt: Die Maus hält das Papier. Erst loslassen.</translation>
    </message>
    <message>
        <source>&lt;new: %1&gt;</source>
        <translation>&lt;neues Blatt: %1&gt;</translation>
    </message>
</context>
<context>
    <name>pf::PaperLookMenu</name>
    <message>
        <source>Could not use the picture as paper: %1</source>
        <translation>Das Bild kann nicht als Papier verwendet werden: %1</translation>
    </message>
    <message>
        <source>&amp;Paper</source>
        <translation>&amp;Papier</translation>
    </message>
    <message>
        <source>Paper &amp;Colour…</source>
        <translation>Papier&amp;farbe…</translation>
    </message>
    <message>
        <source>&amp;Plain</source>
        <translation>&amp;Schlicht</translation>
    </message>
    <message>
        <source>Paper &amp;Grain</source>
        <translation>Papier&amp;struktur</translation>
    </message>
    <message>
        <source>P&amp;icture: %1…</source>
        <translation>&amp;Bild: %1…</translation>
    </message>
    <message>
        <source>P&amp;icture…</source>
        <translation>&amp;Bild…</translation>
    </message>
    <message>
        <source>Print a picture over the whole sheet</source>
        <translation>Ein Bild über das ganze Blatt drucken</translation>
    </message>
</context>
<context>
    <name>pf::ParameterPanel</name>
    <message>
        <source>φ fragility</source>
        <translation>φ Brüchigkeit</translation>
    </message>
    <message>
        <source>Fragility φ scales the normal dot products of the break probability (Eq. 10). Larger φ: stiffer paper that breaks only where it is already curved; at 1 a flat region never breaks. Smaller φ: softer paper that crumples anywhere it is compressed.</source>
        <translation>Die Brüchigkeit φ gewichtet die Skalarprodukte der Normalen in der Bruchwahrscheinlichkeit (Gl. 10). Größeres φ: steiferes Papier, das nur dort bricht, wo es schon gekrümmt ist; bei 1 bricht eine ebene Stelle nie. Kleineres φ: weicheres Papier, das überall knittert, wo es gestaucht wird.</translation>
    </message>
    <message>
        <source>ψ recursive break</source>
        <translation>ψ wiederholter Bruch</translation>
    </message>
    <message>
        <source>ψ sets how far a new vertex moves out of the surface when a spring breaks (Eq. 11). At 1 the two halves keep the rest length and do not break again at once; smaller ψ leaves them compressed, so breaks repeat into finer crumples.</source>
        <translation>ψ bestimmt, wie weit ein neuer Knoten aus der Fläche tritt, wenn eine Feder bricht (Gl. 11). Bei 1 behalten die beiden Hälften die Ruhelänge und brechen nicht sofort wieder; kleineres ψ lässt sie gestaucht, sodass sich Brüche zu feineren Knittern wiederholen.</translation>
    </message>
    <message>
        <source>σ shapes the subdivided surface that is drawn (§4.3): 0 keeps flat facets and sharp creases, larger values round them off. It does not change the simulation.</source>
        <translation>σ formt die unterteilte Fläche, die gezeichnet wird (§4.3): 0 lässt ebene Facetten und scharfe Knicke, größere Werte runden sie ab. Die Simulation ändert sich dadurch nicht.</translation>
    </message>
    <message>
        <source>Tool radius</source>
        <translation>Werkzeugradius</translation>
    </message>
    <message>
        <source>Radius of the sphere you push the paper with (Ctrl+wheel in the view).</source>
        <translation>Radius der Kugel, mit der Sie das Papier drücken (Strg+Mausrad in der Ansicht).</translation>
    </message>
    <message>
        <source> cm</source>
        <translation> cm</translation>
    </message>
    <message>
        <source>Advanced</source>
        <translation>Erweitert</translation>
    </message>
    <message>
        <source>Stretch stiffness</source>
        <translation>Dehnsteifigkeit</translation>
    </message>
    <message>
        <source>Bending stiffness</source>
        <translation>Biegesteifigkeit</translation>
    </message>
    <message>
        <source>Resolution</source>
        <translation>Auflösung</translation>
    </message>
    <message>
        <source>Vertices along the sheet&apos;s short side.</source>
        <translation>Knoten entlang der kurzen Blattseite.</translation>
    </message>
    <message>
        <source>Sheet size</source>
        <translation>Blattgröße</translation>
    </message>
    <message>
        <source>Resolution and size apply to the next New or Reset.</source>
        <translation>Auflösung und Größe gelten beim nächsten Neu oder Zurücksetzen.</translation>
    </message>
    <message>
        <source>Push depth</source>
        <translation>Drucktiefe</translation>
    </message>
    <message>
        <source>How deep a push presses the sphere into the paper, as a share of its radius: deeper pushes crease harder.</source>
        <translation>Wie tief ein Druck die Kugel ins Papier drückt, als Anteil ihres Radius: tiefere Drucke falten stärker.</translation>
    </message>
    <message>
        <source>Fold</source>
        <translation>Falten</translation>
    </message>
    <message>
        <source>Valley</source>
        <translation>Tal</translation>
    </message>
    <message>
        <source>Mountain</source>
        <translation>Berg</translation>
    </message>
    <message>
        <source>The Fold tool (L): draw a line across the paper; the lighter side (or the side without pins) is carried round it, pressed flat, opened to this angle and let go. A valley fold turns the flap up toward you, a mountain fold away from you, under the paper.</source>
        <translation>Das Werkzeug Falten (L): eine Linie über das Papier ziehen; die leichtere Seite (oder die ohne angeheftete Stellen) wird um sie herumgeführt, flach gepresst, auf diesen Winkel geöffnet und losgelassen. Eine Talfalte klappt die Lasche zu Ihnen hin nach oben, eine Bergfalte von Ihnen weg unter das Papier.</translation>
    </message>
    <message>
        <source>σ crumple smoothing</source>
        <translation>σ Knitterglättung</translation>
    </message>
</context>
<context>
    <name>pf::SolverPanel</name>
    <message>
        <source>tissue</source>
        <translation>Seidenpapier</translation>
    </message>
    <message>
        <source>office</source>
        <translation>Büropapier</translation>
    </message>
    <message>
        <source>card</source>
        <translation>Karton</translation>
    </message>
    <message>
        <source>%1 µs</source>
        <translation>%1 µs</translation>
    </message>
    <message>
        <source>max %1 %, RMS %2 %</source>
        <translation>max. %1 %, RMS %2 %</translation>
    </message>
    <message>
        <source>Integrator</source>
        <translation>Integrator</translation>
    </message>
    <message>
        <source>Jacobi sweeps</source>
        <translation>Jacobi-Durchläufe</translation>
    </message>
    <message>
        <source>Steps per second</source>
        <translation>Schritte pro Sekunde</translation>
    </message>
    <message>
        <source>Cores used</source>
        <translation>Genutzte Kerne</translation>
    </message>
    <message numerus="yes">
        <source>How many of this computer&apos;s %n cores step the sheet. The sheet moves the same, to the last bit, on any number; by default one core is left to draw the view.</source>
        <translation>
            <numerusform>Wie viele der %n Kerne dieses Computers das Blatt rechnen. Das Blatt bewegt sich bei jeder Zahl gleich, bis aufs letzte Bit; standardmäßig bleibt ein Kern frei, der die Ansicht zeichnet.</numerusform>
            <numerusform>Wie viele der %n Kerne dieses Computers das Blatt rechnen. Das Blatt bewegt sich bei jeder Zahl gleich, bis aufs letzte Bit; standardmäßig bleibt ein Kern frei, der die Ansicht zeichnet.</numerusform>
        </translation>
    </message>
    <message>
        <source>Gravity outside the implicit filter</source>
        <translation>Schwerkraft außerhalb des impliziten Filters</translation>
    </message>
    <message>
        <source>Start the Jacobi iteration at Δv = h·g. The paper&apos;s step divides gravity by W, so a hanging sheet falls at a fraction of g; this keeps free fall exact at the same stability.</source>
        <translation>Startet die Jacobi-Iteration bei Δv = h·g. Der Schritt des Artikels teilt die Schwerkraft durch W, sodass ein hängendes Blatt nur mit einem Bruchteil von g fällt; so bleibt der freie Fall bei gleicher Stabilität exakt.</translation>
    </message>
    <message>
        <source>Step time</source>
        <translation>Schrittzeit</translation>
    </message>
    <message>
        <source>Stretch</source>
        <translation>Dehnung</translation>
    </message>
    <message>
        <source>max(l/l0 - 1, 0) over the uncreased structural springs, live: how far the paper is pulled longer (edges that paper bending between two vertices shortens do not count)</source>
        <translation>max(l/l0 - 1, 0) über die ungefalteten Strukturfedern, live: wie weit das Papier in die Länge gezogen ist (Kanten, die das Biegen des Papiers zwischen zwei Knoten verkürzt, zählen nicht)</translation>
    </message>
    <message>
        <source>Open Latest Chart…</source>
        <translation>Neuestes Diagramm öffnen…</translation>
    </message>
    <message>
        <source>Show the newest speed–accuracy chart written by &apos;paperfold bench&apos;.</source>
        <translation>Das neueste Geschwindigkeits-Genauigkeits-Diagramm von „paperfold bench“ anzeigen.</translation>
    </message>
    <message>
        <source>jacobi: the paper&apos;s approximate implicit step (Eq. 6); jacobi-scalar: the same with k·I blocks; symplectic: explicit; backward-euler: the exact implicit step (slow, the reference); xpbd: paper from its physical constants (docs/material.md).</source>
        <translation>jacobi: der näherungsweise implizite Schritt des Artikels (Gl. 6); jacobi-scalar: derselbe mit k·I-Blöcken; symplectic: explizit; backward-euler: der exakte implizite Schritt (langsam, die Referenz); xpbd: Papier aus seinen physikalischen Konstanten (docs/material.md).</translation>
    </message>
    <message>
        <source>Paper</source>
        <translation>Papier</translation>
    </message>
    <message>
        <source>The paper&apos;s weight, stretch and bending stiffness and friction, used by the xpbd integrator: tissue 20 g/m², office 80 g/m², card 250 g/m².</source>
        <translation>Gewicht, Dehn- und Biegesteifigkeit und Reibung des Papiers, vom xpbd-Integrator verwendet: Seidenpapier 20 g/m², Büropapier 80 g/m², Karton 250 g/m².</translation>
    </message>
    <message numerus="yes">
        <source>%n per second</source>
        <translation>
            <numerusform>%n pro Sekunde</numerusform>
            <numerusform>%n pro Sekunde</numerusform>
        </translation>
    </message>
    <message>
        <source>Breaks</source>
        <translation>Brüche</translation>
    </message>
    <message>
        <source>Breaks in the last second of simulated time: paper breaks while it is loaded further, and stops when the load stops</source>
        <translation>Brüche in der letzten simulierten Sekunde: Papier bricht, solange die Last weiter wächst, und hört auf, wenn sie aufhört</translation>
    </message>
    <message>
        <source>How many steps one simulated second takes (the step h = 1/N s). More steps are more accurate and cost more: the sheet moves in real time while the computer can take them that fast. The paper&apos;s behaviour is checked at 240 (&apos;paperfold fidelity&apos;).</source>
        <translation>Wie viele Schritte eine simulierte Sekunde braucht (Schrittweite h = 1/N s). Mehr Schritte sind genauer und kosten mehr: Das Blatt bewegt sich in Echtzeit, solange der Rechner sie so schnell schafft. Das Verhalten des Papiers ist bei 240 geprüft (&apos;paperfold fidelity&apos;).</translation>
    </message>
</context>
<context>
    <name>pf::StatusReadout</name>
    <message>
        <source>%1 · paused</source>
        <translation>%1 · angehalten</translation>
    </message>
    <message>
        <source>In brackets: the breaks in the last second of simulated time, which lasts longer than a second on the clock while the sheet runs behind real time</source>
        <translation>In Klammern: die Brüche in der letzten Sekunde simulierter Zeit, die auf der Uhr länger als eine Sekunde dauert, solange das Blatt langsamer als in Echtzeit läuft</translation>
    </message>
    <message>
        <source>%1 · %2× real time</source>
        <translation>%1 · %2× Echtzeit</translation>
    </message>
    <message>
        <source>The computer cannot take the steps as fast as they happen: the sheet moves slower than in real time. Fewer steps per second (Solver dock), a smaller sheet or another integrator are faster.</source>
        <translation>Der Computer schafft die Schritte nicht so schnell, wie sie geschehen: Das Blatt bewegt sich langsamer als in Echtzeit. Weniger Schritte pro Sekunde (Löser-Dock), ein kleineres Blatt oder ein anderer Integrator sind schneller.</translation>
    </message>
    <message>
        <source>%1 fps</source>
        <translation>%1 fps</translation>
    </message>
    <message>
        <source>step %1 µs</source>
        <translation>Schritt %1 µs</translation>
    </message>
    <message>
        <source>%1 · at rest</source>
        <translation>%1 · in Ruhe</translation>
    </message>
    <message>
        <source>%1 vertices · %2 springs · %3 (%4/s) · %5</source>
        <translation>%1 Knoten · %2 Federn · %3 (%4/s) · %5</translation>
    </message>
    <message numerus="yes">
        <source>%n break(s)</source>
        <translation>
            <numerusform>%n Bruch</numerusform>
            <numerusform>%n Brüche</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n hinge(s)</source>
        <translation>
            <numerusform>%n Scharnier</numerusform>
            <numerusform>%n Scharniere</numerusform>
        </translation>
    </message>
    <message>
        <source>no step yet</source>
        <translation>noch kein Schritt</translation>
    </message>
    <message>
        <source>at rest</source>
        <translation>in Ruhe</translation>
    </message>
    <message>
        <source>settled</source>
        <translation>beruhigt</translation>
    </message>
    <message>
        <source>%1 · settled</source>
        <translation>%1 · beruhigt</translation>
    </message>
    <message>
        <source>– fps</source>
        <translation>– fps</translation>
    </message>
    <message>
        <source>Nothing moves, so the view is not drawn again until something changes.</source>
        <translation>Nichts bewegt sich, daher wird die Ansicht erst neu gezeichnet, wenn sich etwas ändert.</translation>
    </message>
</context>
<context>
    <name>pf::StrokeHistory</name>
    <message>
        <source>Could not undo “%1”: the paper is no longer as this step left it.</source>
        <translation>„%1“ konnte nicht rückgängig gemacht werden: Das Papier ist nicht mehr so, wie dieser Schritt es hinterlassen hat.</translation>
    </message>
    <message>
        <source>Could not redo “%1”: the paper is no longer as this step found it.</source>
        <translation>„%1“ konnte nicht wiederholt werden: Das Papier ist nicht mehr so, wie dieser Schritt es vorgefunden hat.</translation>
    </message>
</context>
<context>
    <name>pf::Viewport</name>
    <message>
        <source>OpenGL 3.3 is not available (missing %1)</source>
        <translation>OpenGL 3.3 ist nicht verfügbar (%1 fehlt)</translation>
    </message>
</context>
</TS>
