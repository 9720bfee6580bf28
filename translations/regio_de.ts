<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>SolverPresets</name>
    <message>
        <source>Draft</source>
        <translation>Entwurf</translation>
    </message>
    <message>
        <source>Normal</source>
        <translation>Normal</translation>
    </message>
    <message>
        <source>Final</source>
        <translation>Endgültig</translation>
    </message>
    <message>
        <source>Hemicube: %1 x %1 (sides %1 x %2)</source>
        <translation>Hemicube: %1 × %1 (Seiten %1 × %2)</translation>
    </message>
    <message>
        <source>Patch size: %1 m, %2 elements per patch</source>
        <translation>Patch-Größe: %1 m, %2 Elemente pro Patch</translation>
    </message>
    <message>
        <source>Stops after %1 iterations or below %2 % unshot</source>
        <translation>Stoppt nach %1 Iterationen oder unter %2 % noch nicht abgestrahlter Leistung</translation>
    </message>
    <message>
        <source>Visibility: %1; regions: %2</source>
        <translation>Sichtbarkeit: %1; Regionen: %2</translation>
    </message>
    <message>
        <source>Regions: %1; BSP fragments: %2 (%3 splits, depth %4)</source>
        <translation>Regionen: %1; BSP-Fragmente: %2 (%3 Teilungen, Tiefe %4)</translation>
    </message>
    <message>
        <source>Patches: %1; elements: %2 (before adaptive subdivision)</source>
        <translation>Patches: %1; Elemente: %2 (vor der adaptiven Unterteilung)</translation>
    </message>
    <message>
        <source>Prepared in %1 s</source>
        <translation>Vorbereitet in %1 s</translation>
    </message>
    <message>
        <source>The scene cannot be prepared:</source>
        <translation>Die Szene kann nicht vorbereitet werden:</translation>
    </message>
    <message>
        <source>error: %1</source>
        <translation>Fehler: %1</translation>
    </message>
    <message>
        <source>warning: %1</source>
        <translation>Warnung: %1</translation>
    </message>
    <message>
        <source>Adaptive subdivision: threshold %1, shortest edge %2 m, anchoring %3</source>
        <translation>Adaptive Unterteilung: Schwellenwert %1, kürzeste Kante %2 m, Verankerung %3</translation>
    </message>
    <message>
        <source>on</source>
        <translation>ein</translation>
    </message>
    <message>
        <source>off</source>
        <translation>aus</translation>
    </message>
    <message>
        <source>Adaptive subdivision: off</source>
        <translation>Adaptive Unterteilung: aus</translation>
    </message>
</context>
<context>
    <name>TransformGizmo</name>
    <message>
        <source>Move by (%1, %2, %3) m</source>
        <translation>Verschiebung um (%1, %2, %3) m</translation>
    </message>
    <message>
        <source>Rotate by %1° about %2</source>
        <translation>Drehung um %1° um die %2-Achse</translation>
    </message>
    <message>
        <source>Scale by %1</source>
        <translation>Skalierung mit Faktor %1</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <source>cannot open %1:</source>
        <translation>%1 kann nicht geöffnet werden:</translation>
    </message>
    <message>
        <source>there is no display to open the editor&apos;s window on (DISPLAY is not set). Run it on a desktop, or with ssh -X.</source>
        <translation>es gibt keinen Bildschirm, auf dem das Editorfenster geöffnet werden kann (DISPLAY ist nicht gesetzt). Starten Sie den Editor auf einem Desktop oder mit ssh -X.</translation>
    </message>
    <message>
        <source>--screenshot draws the editor&apos;s window and needs a display, real or virtual: run it on a desktop or under Xvfb (xvfb-run -a regio --screenshot ...).</source>
        <translation>--screenshot zeichnet das Editorfenster und benötigt einen echten oder virtuellen Bildschirm: Starten Sie den Editor auf einem Desktop oder unter Xvfb (xvfb-run -a regio --screenshot ...).</translation>
    </message>
    <message>
        <source>there is no panel %1</source>
        <translation>es gibt kein Bedienfeld %1</translation>
    </message>
</context>
<context>
    <name>regio::editor::Authoring</name>
    <message>
        <source>&amp;Material</source>
        <translation>&amp;Material</translation>
    </message>
    <message>
        <source>Add a new grey material</source>
        <translation>Ein neues graues Material hinzufügen</translation>
    </message>
    <message>
        <source>&amp;Group</source>
        <translation>&amp;Gruppieren</translation>
    </message>
    <message>
        <source>Put the selected parts (or objects) into one new object</source>
        <translation>Die ausgewählten Teile (oder Objekte) in einem neuen Objekt zusammenfassen</translation>
    </message>
    <message>
        <source>&amp;Ungroup</source>
        <translation>Gruppierung a&amp;ufheben</translation>
    </message>
    <message>
        <source>Make every part of the selected objects an object of its own</source>
        <translation>Jedes Teil der ausgewählten Objekte zu einem eigenen Objekt machen</translation>
    </message>
    <message>
        <source>Split Across &amp;X</source>
        <translation>Quer zu &amp;X aufteilen</translation>
    </message>
    <message>
        <source>Split Across &amp;Y</source>
        <translation>Quer zu &amp;Y aufteilen</translation>
    </message>
    <message>
        <source>Split Across &amp;Z</source>
        <translation>Quer zu &amp;Z aufteilen</translation>
    </message>
    <message>
        <source>Cut the selected parts in two with a plane through the selection&apos;s centre</source>
        <translation>Die ausgewählten Teile mit einer Ebene durch den Mittelpunkt der Auswahl in zwei Stücke schneiden</translation>
    </message>
    <message>
        <source>&amp;Clip Tool (Three Points)</source>
        <translation>Schnitt&amp;werkzeug (drei Punkte)</translation>
    </message>
    <message>
        <source>Click three points; the plane through them cuts the selected parts</source>
        <translation>Klicken Sie auf drei Punkte; die Ebene durch diese Punkte schneidet die ausgewählten Teile</translation>
    </message>
    <message>
        <source>Store View as Scene &amp;Camera</source>
        <translation>Ansicht als Szenen&amp;kamera speichern</translation>
    </message>
    <message>
        <source>Save the current view in the scene file</source>
        <translation>Die aktuelle Ansicht in der Szenendatei speichern</translation>
    </message>
    <message>
        <source>&amp;Navigation and Shortcuts</source>
        <translation>&amp;Navigation und Tastenkürzel</translation>
    </message>
    <message>
        <source>Navigation</source>
        <translation>Navigation</translation>
    </message>
    <message>
        <source>&lt;table&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Middle drag&lt;/b&gt; or &lt;b&gt;Alt+left drag&lt;/b&gt;&lt;/td&gt;&lt;td&gt;orbit&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Shift+middle&lt;/b&gt; or &lt;b&gt;Alt+Shift+left&lt;/b&gt;&lt;/td&gt;&lt;td&gt;pan&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Wheel&lt;/b&gt;, &lt;b&gt;Ctrl+middle&lt;/b&gt;, pinch&lt;/td&gt;&lt;td&gt;zoom&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Two-finger scroll&lt;/b&gt;&lt;/td&gt;&lt;td&gt;orbit (Shift: pan)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Right drag + W A S D Q E&lt;/b&gt;&lt;/td&gt;&lt;td&gt;fly (Shift: faster)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;F&lt;/b&gt; / &lt;b&gt;Home&lt;/b&gt;&lt;/td&gt;&lt;td&gt;frame selection / everything&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Keypad 1 3 7&lt;/b&gt; (Ctrl: opposite), &lt;b&gt;0&lt;/b&gt;, &lt;b&gt;5&lt;/b&gt;&lt;/td&gt;&lt;td&gt;front, right, top, isometric, orthographic&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;1 2 3&lt;/b&gt;&lt;/td&gt;&lt;td&gt;select objects, parts, faces&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;W E R&lt;/b&gt;&lt;/td&gt;&lt;td&gt;move, rotate, scale gizmo&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;C&lt;/b&gt;&lt;/td&gt;&lt;td&gt;clip tool: click three points&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Click&lt;/b&gt;, &lt;b&gt;Ctrl+click&lt;/b&gt;&lt;/td&gt;&lt;td&gt;select, add or remove&lt;/td&gt;&lt;/tr&gt;&lt;/table&gt;</source>
        <translation>&lt;table&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Mittlere Taste ziehen&lt;/b&gt; oder &lt;b&gt;Alt+linke Taste ziehen&lt;/b&gt;&lt;/td&gt;&lt;td&gt;umkreisen&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Shift+mittlere Taste&lt;/b&gt; oder &lt;b&gt;Alt+Shift+linke Taste&lt;/b&gt;&lt;/td&gt;&lt;td&gt;verschieben&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Mausrad&lt;/b&gt;, &lt;b&gt;Ctrl+mittlere Taste&lt;/b&gt;, Zwei-Finger-Zoom&lt;/td&gt;&lt;td&gt;zoomen&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Mit zwei Fingern scrollen&lt;/b&gt;&lt;/td&gt;&lt;td&gt;umkreisen (Shift: verschieben)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Rechte Taste ziehen + W A S D Q E&lt;/b&gt;&lt;/td&gt;&lt;td&gt;fliegen (Shift: schneller)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;F&lt;/b&gt; / &lt;b&gt;Home&lt;/b&gt;&lt;/td&gt;&lt;td&gt;Auswahl / alles einpassen&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Ziffernblock 1 3 7&lt;/b&gt; (Ctrl: Gegenseite), &lt;b&gt;0&lt;/b&gt;, &lt;b&gt;5&lt;/b&gt;&lt;/td&gt;&lt;td&gt;vorne, rechts, oben, isometrisch, orthografisch&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;1 2 3&lt;/b&gt;&lt;/td&gt;&lt;td&gt;Objekte, Teile, Flächen auswählen&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;W E R&lt;/b&gt;&lt;/td&gt;&lt;td&gt;Gizmo zum Verschieben, Drehen, Skalieren&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;C&lt;/b&gt;&lt;/td&gt;&lt;td&gt;Schnittwerkzeug: drei Punkte anklicken&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Klicken&lt;/b&gt;, &lt;b&gt;Ctrl+Klicken&lt;/b&gt;&lt;/td&gt;&lt;td&gt;auswählen, hinzufügen oder entfernen&lt;/td&gt;&lt;/tr&gt;&lt;/table&gt;</translation>
    </message>
    <message>
        <source>Assign &amp;Material</source>
        <translation>&amp;Material zuweisen</translation>
    </message>
    <message>
        <source>No materials</source>
        <translation>Keine Materialien</translation>
    </message>
    <message>
        <source>Select the parts or objects to cut first</source>
        <translation>Wählen Sie zuerst die zu schneidenden Teile oder Objekte aus</translation>
    </message>
    <message>
        <source>Rename</source>
        <translation>Umbenennen</translation>
    </message>
    <message>
        <source>&amp;Id:</source>
        <translation>&amp;ID:</translation>
    </message>
    <message>
        <source>&amp;Name:</source>
        <translation>&amp;Name:</translation>
    </message>
    <message>
        <source>Ids are what files and BSP orders refer to; names are for people.</source>
        <translation>Auf IDs verweisen Dateien und BSP-Reihenfolgen; Namen sind für Menschen.</translation>
    </message>
    <message>
        <source>Duplicate</source>
        <translation>Duplizieren</translation>
    </message>
    <message numerus="yes">
        <source>Delete %n object(s)</source>
        <translation>
            <numerusform>%n Objekt löschen</numerusform>
            <numerusform>%n Objekte löschen</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Delete %n part(s)</source>
        <translation>
            <numerusform>%n Teil löschen</numerusform>
            <numerusform>%n Teile löschen</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Delete %n material(s)</source>
        <translation>
            <numerusform>%n Material löschen</numerusform>
            <numerusform>%n Materialien löschen</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Delete %n region(s)</source>
        <translation>
            <numerusform>%n Region löschen</numerusform>
            <numerusform>%n Regionen löschen</numerusform>
        </translation>
    </message>
    <message>
        <source>faces cannot be deleted on their own; split or delete the part</source>
        <translation>Flächen können nicht einzeln gelöscht werden; teilen oder löschen Sie das Teil</translation>
    </message>
    <message>
        <source>Rename %1</source>
        <translation>%1 umbenennen</translation>
    </message>
    <message>
        <source>Ungroup</source>
        <translation>Gruppierung aufheben</translation>
    </message>
    <message>
        <source>the plane does not cross any selected part</source>
        <translation>die Ebene schneidet keines der ausgewählten Teile</translation>
    </message>
    <message numerus="yes">
        <source>Split %n part(s)</source>
        <translation>
            <numerusform>%n Teil aufteilen</numerusform>
            <numerusform>%n Teile aufteilen</numerusform>
        </translation>
    </message>
    <message>
        <source>Assign %1</source>
        <translation>%1 zuweisen</translation>
    </message>
    <message numerus="yes">
        <source>Transform %n part(s)</source>
        <translation>
            <numerusform>%n Teil transformieren</numerusform>
            <numerusform>%n Teile transformieren</numerusform>
        </translation>
    </message>
    <message>
        <source>New object: %1</source>
        <translation>Neues Objekt: %1</translation>
    </message>
</context>
<context>
    <name>regio::editor::Autosave</name>
    <message>
        <source>Autosave to %1 failed: %2</source>
        <translation>Automatisches Speichern in %1 fehlgeschlagen: %2</translation>
    </message>
</context>
<context>
    <name>regio::editor::BspAuthoring</name>
    <message>
        <source>&amp;Suggest Order</source>
        <translation>Reihenfolge &amp;vorschlagen</translation>
    </message>
    <message>
        <source>Compute a low-split root order for the region and compare it with the current one</source>
        <translation>Eine Wurzelreihenfolge mit wenigen Teilungen für die Region berechnen und mit der aktuellen vergleichen</translation>
    </message>
    <message>
        <source>&amp;Apply Suggested Order</source>
        <translation>Vorgeschlagene Reihenfolge &amp;anwenden</translation>
    </message>
    <message>
        <source>&amp;Discard Suggested Order</source>
        <translation>Vorgeschlagene Reihenfolge ver&amp;werfen</translation>
    </message>
    <message>
        <source>Show &amp;Fragments</source>
        <translation>F&amp;ragmente anzeigen</translation>
    </message>
    <message>
        <source>Draw the region&apos;s BSP fragments: splits orange, region cuts cyan</source>
        <translation>Die BSP-Fragmente der Region zeichnen: Teilungen orange, Regionsschnitte cyan</translation>
    </message>
    <message>
        <source>&amp;Pick Face to Insert</source>
        <translation>Fläche zum &amp;Einfügen wählen</translation>
    </message>
    <message>
        <source>Click faces in the viewport to add them to the region&apos;s BSP order</source>
        <translation>Klicken Sie Flächen in der Ansicht an, um sie zur BSP-Reihenfolge der Region hinzuzufügen</translation>
    </message>
    <message>
        <source>Insert &amp;Selected Faces</source>
        <translation>Ausgewählte Flächen ein&amp;fügen</translation>
    </message>
    <message>
        <source>Painter Order from &amp;Point…</source>
        <translation>Zeichenreihenfolge ab &amp;Punkt…</translation>
    </message>
    <message>
        <source>Click a surface: the elements are painted in the solver&apos;s back-to-front order from there</source>
        <translation>Klicken Sie auf eine Oberfläche: Die Elemente werden von dort aus in der Reihenfolge des Lösers von hinten nach vorne gezeichnet</translation>
    </message>
    <message>
        <source>Painter Order from Pa&amp;tch…</source>
        <translation>Zeichenreihenfolge ab Pa&amp;tch…</translation>
    </message>
    <message>
        <source>Click a surface: the patch there shoots, as in the solver</source>
        <translation>Klicken Sie auf eine Oberfläche: Der Patch dort strahlt ab, wie im Löser</translation>
    </message>
    <message>
        <source>S&amp;top Painter Order</source>
        <translation>Zeichenreihenfolge &amp;stoppen</translation>
    </message>
    <message>
        <source>%1 is already in the BSP order of %2</source>
        <translation>%1 ist bereits in der BSP-Reihenfolge von %2</translation>
    </message>
    <message>
        <source>%1 is not inside region %2</source>
        <translation>%1 liegt nicht in Region %2</translation>
    </message>
    <message>
        <source>Added %1 to the BSP order of %2</source>
        <translation>%1 zur BSP-Reihenfolge von %2 hinzugefügt</translation>
    </message>
    <message>
        <source>No selected face can be added to the BSP order of %1</source>
        <translation>Keine ausgewählte Fläche kann zur BSP-Reihenfolge von %1 hinzugefügt werden</translation>
    </message>
    <message numerus="yes">
        <source>Add %n face(s) to the BSP order of %1</source>
        <translation>
            <numerusform>%n Fläche zur BSP-Reihenfolge von %1 hinzufügen</numerusform>
            <numerusform>%n Flächen zur BSP-Reihenfolge von %1 hinzufügen</numerusform>
        </translation>
    </message>
    <message>
        <source>No suggestion: %1</source>
        <translation>Kein Vorschlag: %1</translation>
    </message>
    <message>
        <source>Click faces to add them to the BSP order of %1; Esc ends</source>
        <translation>Klicken Sie Flächen an, um sie zur BSP-Reihenfolge von %1 hinzuzufügen; Esc beendet</translation>
    </message>
    <message>
        <source>Click a surface: its patch shoots</source>
        <translation>Klicken Sie auf eine Oberfläche: Der Patch dort strahlt ab</translation>
    </message>
    <message>
        <source>Click a surface to paint from there</source>
        <translation>Klicken Sie auf eine Oberfläche, um von dort aus zu zeichnen</translation>
    </message>
    <message>
        <source>The scene cannot be prepared; see the diagnostics</source>
        <translation>Die Szene kann nicht vorbereitet werden; siehe Diagnose</translation>
    </message>
    <message numerus="yes">
        <source>Painter order: %n element(s), back to front</source>
        <translation>
            <numerusform>Zeichenreihenfolge: %n Element, von hinten nach vorne</numerusform>
            <numerusform>Zeichenreihenfolge: %n Elemente, von hinten nach vorne</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>regio::editor::BspOrderDock</name>
    <message>
        <source>BSP Order</source>
        <translation>BSP-Reihenfolge</translation>
    </message>
    <message>
        <source>Region:</source>
        <translation>Region:</translation>
    </message>
    <message>
        <source>The region whose BSP root order is edited (also chosen by selecting a region)</source>
        <translation>Die Region, deren BSP-Reihenfolge bearbeitet wird (auch durch Auswählen einer Region wählbar)</translation>
    </message>
    <message>
        <source>Faces used as BSP roots, first = root of the region&apos;s tree; drag to reorder</source>
        <translation>Als BSP-Wurzeln verwendete Flächen, erste = Wurzel des Baums der Region; zum Umsortieren ziehen</translation>
    </message>
    <message>
        <source>Move to Top</source>
        <translation>Ganz nach oben</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Entfernen</translation>
    </message>
    <message>
        <source>Pick in Viewport</source>
        <translation>In der Ansicht wählen</translation>
    </message>
    <message>
        <source>Click faces in the viewport to add them at the end of the order; Esc ends</source>
        <translation>Klicken Sie Flächen in der Ansicht an, um sie am Ende der Reihenfolge hinzuzufügen; Esc beendet</translation>
    </message>
    <message>
        <source>Insert Selected</source>
        <translation>Ausgewählte einfügen</translation>
    </message>
    <message>
        <source>Region</source>
        <translation>Region</translation>
    </message>
    <message>
        <source>Scene</source>
        <translation>Szene</translation>
    </message>
    <message>
        <source>Single BSP</source>
        <translation>Einzelner BSP-Baum</translation>
    </message>
    <message>
        <source>Suggested region</source>
        <translation>Region (Vorschlag)</translation>
    </message>
    <message>
        <source>Suggested scene</source>
        <translation>Szene (Vorschlag)</translation>
    </message>
    <message>
        <source>Fragments</source>
        <translation>Fragmente</translation>
    </message>
    <message>
        <source>Splits</source>
        <translation>Teilungen</translation>
    </message>
    <message>
        <source>Depth</source>
        <translation>Tiefe</translation>
    </message>
    <message>
        <source>Fragments after region clipping and BSP splits, polygons split, longest root-to-leaf path; Single BSP is the whole scene as one tree without regions</source>
        <translation>Fragmente nach dem Zuschneiden an Regionen und den BSP-Teilungen, geteilte Polygone, längster Pfad von der Wurzel zu einem Blatt; „Einzelner BSP-Baum“ ist die ganze Szene als ein Baum ohne Regionen</translation>
    </message>
    <message>
        <source>Suggest Order</source>
        <translation>Reihenfolge vorschlagen</translation>
    </message>
    <message>
        <source>Greedy low-split, balanced root order (Thibault and Naylor), shown before it is applied</source>
        <translation>Gierig bestimmte, ausgewogene Wurzelreihenfolge mit wenigen Teilungen (Thibault und Naylor), wird vor dem Anwenden angezeigt</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>Anwenden</translation>
    </message>
    <message>
        <source>Discard</source>
        <translation>Verwerfen</translation>
    </message>
    <message>
        <source>Order</source>
        <translation>Reihenfolge</translation>
    </message>
    <message>
        <source>Show fragments and split lines in the viewport</source>
        <translation>Fragmente und Teilungslinien in der Ansicht anzeigen</translation>
    </message>
    <message>
        <source>Root face</source>
        <translation>Wurzelfläche</translation>
    </message>
    <message>
        <source>The region&apos;s BSP tree: each node&apos;s plane is its root face&apos;s; select a node to see its plane</source>
        <translation>Der BSP-Baum der Region: Die Ebene jedes Knotens ist die seiner Wurzelfläche; wählen Sie einen Knoten aus, um seine Ebene zu sehen</translation>
    </message>
    <message>
        <source>Tree</source>
        <translation>Baum</translation>
    </message>
    <message>
        <source>Pick a point or a patch: the elements are painted in the order the solver&apos;s hemicube paints them from there, back to front (blue first, red last; grey: seen from behind, painted as blockers).</source>
        <translation>Wählen Sie einen Punkt oder einen Patch: Die Elemente werden in der Reihenfolge gezeichnet, in der der Hemicube des Lösers sie von dort aus zeichnet, von hinten nach vorne (blau zuerst, rot zuletzt; grau: von hinten gesehen, als Verdecker gezeichnet).</translation>
    </message>
    <message>
        <source>From Point…</source>
        <translation>Ab Punkt…</translation>
    </message>
    <message>
        <source>From Patch…</source>
        <translation>Ab Patch…</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Stoppen</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>Abspielen</translation>
    </message>
    <message>
        <source>Elements painted so far</source>
        <translation>Bisher gezeichnete Elemente</translation>
    </message>
    <message>
        <source>Painter Order</source>
        <translation>Zeichenreihenfolge</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>Updating…</source>
        <translation>Wird aktualisiert…</translation>
    </message>
    <message>
        <source>The scene cannot be prepared: %1</source>
        <translation>Die Szene kann nicht vorbereitet werden: %1</translation>
    </message>
    <message>
        <source>Computed by the solver&apos;s preparation in %1 ms</source>
        <translation>Von der Vorbereitung des Lösers in %1 ms berechnet</translation>
    </message>
    <message numerus="yes">
        <source>Suggested order: %n root face(s). Apply replaces the region&apos;s order (one undo step).</source>
        <translation>
            <numerusform>Vorgeschlagene Reihenfolge: %n Wurzelfläche. „Anwenden“ ersetzt die Reihenfolge der Region (ein Rückgängig-Schritt).</numerusform>
            <numerusform>Vorgeschlagene Reihenfolge: %n Wurzelflächen. „Anwenden“ ersetzt die Reihenfolge der Region (ein Rückgängig-Schritt).</numerusform>
        </translation>
    </message>
    <message>
        <source>No tree for this region</source>
        <translation>Kein Baum für diese Region</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>back</source>
        <translation>hinten</translation>
    </message>
    <message>
        <source>front</source>
        <translation>vorne</translation>
    </message>
    <message>
        <source>%1 nodes, depth %2, %3 fragments from %4 polygons</source>
        <translation>%1 Knoten, Tiefe %2, %3 Fragmente aus %4 Polygonen</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pausieren</translation>
    </message>
    <message>
        <source>No playback</source>
        <translation>Keine Wiedergabe</translation>
    </message>
    <message>
        <source>From patch %1</source>
        <translation>Ab Patch %1</translation>
    </message>
    <message>
        <source>From point (%1, %2, %3)</source>
        <translation>Ab Punkt (%1, %2, %3)</translation>
    </message>
    <message>
        <source>%1 regions walked, %2 culled, %3 nodes, %4 elements</source>
        <translation>%1 Regionen durchlaufen, %2 verworfen, %3 Knoten, %4 Elemente</translation>
    </message>
    <message>
        <source>Step %1: element %2 of node %3, receiving</source>
        <translation>Schritt %1: Element %2 von Knoten %3, empfangend</translation>
    </message>
    <message>
        <source>Step %1: element %2 of node %3, blocking (seen from behind)</source>
        <translation>Schritt %1: Element %2 von Knoten %3, verdeckend (von hinten gesehen)</translation>
    </message>
</context>
<context>
    <name>regio::editor::ColourButton</name>
    <message>
        <source>Pick a colour</source>
        <translation>Farbe wählen</translation>
    </message>
</context>
<context>
    <name>regio::editor::CommandLine</name>
    <message>
        <source>Regio: an editor for radiosity scenes with regions and BSP orders.</source>
        <translation>Regio: ein Editor für Radiosity-Szenen mit Regionen und BSP-Reihenfolgen.</translation>
    </message>
    <message>
        <source>Show the scene, save a picture of the window to &lt;file&gt; and exit.</source>
        <translation>Die Szene anzeigen, ein Bild des Fensters in &lt;file&gt; speichern und beenden.</translation>
    </message>
    <message>
        <source>Window size, for example 1280x800.</source>
        <translation>Fenstergröße, zum Beispiel 1280x800.</translation>
    </message>
    <message>
        <source>The scene file to open (.json).</source>
        <translation>Die zu öffnende Szenendatei (.json).</translation>
    </message>
    <message>
        <source>only one scene file can be opened, got %1</source>
        <translation>es kann nur eine Szenendatei geöffnet werden, angegeben wurden %1</translation>
    </message>
    <message>
        <source>--screenshot needs a file name</source>
        <translation>--screenshot benötigt einen Dateinamen</translation>
    </message>
    <message>
        <source>--size wants WIDTHxHEIGHT in pixels (64 to 16384), got &quot;%1&quot;</source>
        <translation>--size erwartet BREITExHÖHE in Pixeln (64 bis 16384), angegeben wurde &quot;%1&quot;</translation>
    </message>
    <message>
        <source>With --screenshot: solve the radiosity preview with exactly &lt;n&gt; shooting steps first and show it.</source>
        <translation>Mit --screenshot: die Radiosity-Vorschau zuerst mit genau &lt;n&gt; Abstrahlschritten lösen und anzeigen.</translation>
    </message>
    <message>
        <source>--preview-iterations wants a number of shooting steps (0 or more), got &quot;%1&quot;</source>
        <translation>--preview-iterations erwartet eine Anzahl von Abstrahlschritten (0 oder mehr), angegeben wurde &quot;%1&quot;</translation>
    </message>
    <message>
        <source>--preview-iterations needs --screenshot</source>
        <translation>--preview-iterations benötigt --screenshot</translation>
    </message>
    <message>
        <source>User interface language for this run (en, cs, de).</source>
        <translation>Sprache der Benutzeroberfläche für diesen Aufruf (en, cs, de).</translation>
    </message>
    <message>
        <source>With --screenshot: bring the panel &lt;name&gt; to the front first (Materials, Regions, BspOrder, Solver, Properties).</source>
        <translation>Mit --screenshot: zuerst das Bedienfeld &lt;name&gt; nach vorn holen (Materials, Regions, BspOrder, Solver, Properties).</translation>
    </message>
</context>
<context>
    <name>regio::editor::Commands</name>
    <message>
        <source>Set BSP order of %1</source>
        <translation>BSP-Reihenfolge von %1 festlegen</translation>
    </message>
    <message>
        <source>Add %1 to the BSP order of %2</source>
        <translation>%1 zur BSP-Reihenfolge von %2 hinzufügen</translation>
    </message>
    <message>
        <source>Remove entry %1 from the BSP order of %2</source>
        <translation>Eintrag %1 aus der BSP-Reihenfolge von %2 entfernen</translation>
    </message>
    <message>
        <source>Move BSP entry %1 of %2 to %3</source>
        <translation>BSP-Eintrag %1 von %2 nach %3 verschieben</translation>
    </message>
    <message>
        <source>Add material %1</source>
        <translation>Material %1 hinzufügen</translation>
    </message>
    <message>
        <source>Delete material %1</source>
        <translation>Material %1 löschen</translation>
    </message>
    <message>
        <source>Rename %1 to %2</source>
        <translation>%1 in %2 umbenennen</translation>
    </message>
    <message>
        <source>Name %1 &quot;%2&quot;</source>
        <translation>Name von %1: &quot;%2&quot;</translation>
    </message>
    <message>
        <source>Reflectance of %1</source>
        <translation>Reflexionsgrad von %1</translation>
    </message>
    <message>
        <source>Emission of %1</source>
        <translation>Emission von %1</translation>
    </message>
    <message>
        <source>Add %1</source>
        <translation>%1 hinzufügen</translation>
    </message>
    <message>
        <source>Delete %1</source>
        <translation>%1 löschen</translation>
    </message>
    <message>
        <source>Duplicate %1</source>
        <translation>%1 duplizieren</translation>
    </message>
    <message numerus="yes">
        <source>Group %n part(s)</source>
        <translation>
            <numerusform>%n Teil gruppieren</numerusform>
            <numerusform>%n Teile gruppieren</numerusform>
        </translation>
    </message>
    <message>
        <source>Group objects into %1</source>
        <translation>Objekte in %1 gruppieren</translation>
    </message>
    <message>
        <source>Ungroup %1</source>
        <translation>Gruppierung von %1 aufheben</translation>
    </message>
    <message>
        <source>Make parts separate objects</source>
        <translation>Teile zu eigenen Objekten machen</translation>
    </message>
    <message>
        <source>Move parts to %1</source>
        <translation>Teile nach %1 verschieben</translation>
    </message>
    <message>
        <source>Material of %1: %2</source>
        <translation>Material von %1: %2</translation>
    </message>
    <message>
        <source>Material of %1: the part&apos;s</source>
        <translation>Material von %1: das des Teils</translation>
    </message>
    <message>
        <source>Move %1 to %2</source>
        <translation>%1 nach %2 verschieben</translation>
    </message>
    <message numerus="yes">
        <source>Transform %n part(s)</source>
        <translation>
            <numerusform>%n Teil transformieren</numerusform>
            <numerusform>%n Teile transformieren</numerusform>
        </translation>
    </message>
    <message>
        <source>Split %1</source>
        <translation>%1 aufteilen</translation>
    </message>
    <message>
        <source>Add region %1</source>
        <translation>Region %1 hinzufügen</translation>
    </message>
    <message>
        <source>Delete region %1</source>
        <translation>Region %1 löschen</translation>
    </message>
    <message>
        <source>Resize region %1</source>
        <translation>Größe von Region %1 ändern</translation>
    </message>
    <message>
        <source>Change solver settings</source>
        <translation>Einstellungen des Lösers ändern</translation>
    </message>
    <message>
        <source>Store the view as the scene camera</source>
        <translation>Ansicht als Szenenkamera speichern</translation>
    </message>
    <message>
        <source>Clear the scene camera</source>
        <translation>Szenenkamera entfernen</translation>
    </message>
    <message>
        <source>Clip %1 to regions</source>
        <translation>%1 an Regionen zuschneiden</translation>
    </message>
</context>
<context>
    <name>regio::editor::ConvergenceDock</name>
    <message>
        <source>Convergence</source>
        <translation>Konvergenz</translation>
    </message>
    <message>
        <source>unshot</source>
        <translation>noch nicht abgestrahlt</translation>
    </message>
    <message>
        <source>absorbed</source>
        <translation>absorbiert</translation>
    </message>
    <message>
        <source>escaped</source>
        <translation>entwichen</translation>
    </message>
    <message>
        <source>balance error</source>
        <translation>Bilanzfehler</translation>
    </message>
    <message>
        <source>iteration</source>
        <translation>Iteration</translation>
    </message>
    <message>
        <source>fraction of emitted power</source>
        <translation>Anteil der emittierten Leistung</translation>
    </message>
</context>
<context>
    <name>regio::editor::DiagnosticsDock</name>
    <message>
        <source>Diagnostics</source>
        <translation>Diagnose</translation>
    </message>
    <message>
        <source>The scene is valid.</source>
        <translation>Die Szene ist gültig.</translation>
    </message>
    <message numerus="yes">
        <source>%n error(s)</source>
        <translation>
            <numerusform>%n Fehler</numerusform>
            <numerusform>%n Fehler</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n warning(s)</source>
        <translation>
            <numerusform>%n Warnung</numerusform>
            <numerusform>%n Warnungen</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>regio::editor::DiagnosticsModel</name>
    <message>
        <source>line %1, column %2</source>
        <translation>Zeile %1, Spalte %2</translation>
    </message>
    <message>
        <source>(whole scene)</source>
        <translation>(ganze Szene)</translation>
    </message>
    <message>
        <source>Error</source>
        <translation>Fehler</translation>
    </message>
    <message>
        <source>Warning</source>
        <translation>Warnung</translation>
    </message>
    <message>
        <source>Severity</source>
        <translation>Schweregrad</translation>
    </message>
    <message>
        <source>Where</source>
        <translation>Ort</translation>
    </message>
    <message>
        <source>Problem</source>
        <translation>Problem</translation>
    </message>
    <message>
        <source>material %1</source>
        <translation>Material %1</translation>
    </message>
    <message>
        <source>object %1</source>
        <translation>Objekt %1</translation>
    </message>
    <message>
        <source>part %1</source>
        <translation>Teil %1</translation>
    </message>
    <message>
        <source>face %1</source>
        <translation>Fläche %1</translation>
    </message>
    <message>
        <source>region %1</source>
        <translation>Region %1</translation>
    </message>
</context>
<context>
    <name>regio::editor::HemicubeDialog</name>
    <message>
        <source>Hemicube</source>
        <translation>Hemicube</translation>
    </message>
    <message>
        <source>Face %1</source>
        <translation>Fläche %1</translation>
    </message>
    <message>
        <source>Patch %1 of face %2, %3 x %3 pixels: %4 elements seen; %5 % of the form factor escapes, %6 % falls on back faces (black: nothing, grey: back faces).</source>
        <translation>Patch %1 von Fläche %2, %3 × %3 Pixel: %4 Elemente sichtbar; %5 % des Formfaktors entweichen, %6 % fallen auf Rückseiten (schwarz: nichts, grau: Rückseiten).</translation>
    </message>
</context>
<context>
    <name>regio::editor::ImageFile</name>
    <message>
        <source>cannot write %1: %2</source>
        <translation>%1 kann nicht geschrieben werden: %2</translation>
    </message>
</context>
<context>
    <name>regio::editor::ImportDialog</name>
    <message>
        <source>error: </source>
        <translation>Fehler: </translation>
    </message>
    <message>
        <source>warning: </source>
        <translation>Warnung: </translation>
    </message>
    <message>
        <source>Import %1</source>
        <translation>%1 importieren</translation>
    </message>
    <message>
        <source>Metres per model unit: 0.001 for a model in millimetres</source>
        <translation>Meter pro Modelleinheit: 0,001 für ein Modell in Millimetern</translation>
    </message>
    <message>
        <source>Y is up</source>
        <translation>Y zeigt nach oben</translation>
    </message>
    <message>
        <source>Z is up</source>
        <translation>Z zeigt nach oben</translation>
    </message>
    <message>
        <source> °</source>
        <translation> °</translation>
    </message>
    <message>
        <source>Triangles whose normals differ by at most this angle merge into one face</source>
        <translation>Dreiecke, deren Normalen sich um höchstens diesen Winkel unterscheiden, werden zu einer Fläche zusammengeführt</translation>
    </message>
    <message>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <source>Corners this close are welded; corners this close to a plane lie in it</source>
        <translation>Ecken in diesem Abstand werden verschmolzen; Ecken in diesem Abstand zu einer Ebene werden in die Ebene gelegt</translation>
    </message>
    <message>
        <source>Propose regions and BSP orders</source>
        <translation>Regionen und BSP-Reihenfolgen vorschlagen</translation>
    </message>
    <message>
        <source>As a new scene</source>
        <translation>Als neue Szene</translation>
    </message>
    <message>
        <source>Into the open scene (one undo step)</source>
        <translation>In die geöffnete Szene (ein Rückgängig-Schritt)</translation>
    </message>
    <message>
        <source>Scale:</source>
        <translation>Maßstab:</translation>
    </message>
    <message>
        <source>Up axis:</source>
        <translation>Hochachse:</translation>
    </message>
    <message>
        <source>Merge angle:</source>
        <translation>Zusammenführungswinkel:</translation>
    </message>
    <message>
        <source>Merge distance:</source>
        <translation>Zusammenführungsabstand:</translation>
    </message>
    <message>
        <source>Import:</source>
        <translation>Importieren:</translation>
    </message>
    <message>
        <source>Import</source>
        <translation>Importieren</translation>
    </message>
    <message>
        <source>Importing %1…</source>
        <translation>%1 wird importiert…</translation>
    </message>
    <message>
        <source>The model cannot be imported (the reasons are below).</source>
        <translation>Das Modell kann nicht importiert werden (die Gründe stehen unten).</translation>
    </message>
    <message>
        <source>%1 triangles into %2 faces; %3 objects, %4 parts (%5 closed), %6 materials, %7 emitting faces.</source>
        <translation>%1 Dreiecke zu %2 Flächen; %3 Objekte, %4 Teile (%5 geschlossen), %6 Materialien, %7 emittierende Flächen.</translation>
    </message>
    <message>
        <source>Left out: %1 triangles of no area, %2 repeated, %3 points or lines.</source>
        <translation>Ausgelassen: %1 Dreiecke ohne Flächeninhalt, %2 doppelte, %3 Punkte oder Linien.</translation>
    </message>
    <message>
        <source>Regions: %1; BSP fragments: %2 (one BSP tree: %3).</source>
        <translation>Regionen: %1; BSP-Fragmente: %2 (ein BSP-Baum: %3).</translation>
    </message>
</context>
<context>
    <name>regio::editor::LegendWidget</name>
    <message>
        <source>False colour: luminance of the displayed radiosity, W/m²</source>
        <translation>Falschfarben: Luminanz der angezeigten Radiosity, W/m²</translation>
    </message>
</context>
<context>
    <name>regio::editor::MainWindow</name>
    <message>
        <source>Refused: %1</source>
        <translation>Abgelehnt: %1</translation>
    </message>
    <message>
        <source>Viewport</source>
        <translation>Ansicht</translation>
    </message>
    <message>
        <source>No problems</source>
        <translation>Keine Probleme</translation>
    </message>
    <message numerus="yes">
        <source>%n error(s)</source>
        <translation>
            <numerusform>%n Fehler</numerusform>
            <numerusform>%n Fehler</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n warning(s)</source>
        <translation>
            <numerusform>%n Warnung</numerusform>
            <numerusform>%n Warnungen</numerusform>
        </translation>
    </message>
    <message>
        <source>History</source>
        <translation>Verlauf</translation>
    </message>
    <message>
        <source>&lt;opened scene&gt;</source>
        <translation>&lt;geöffnete Szene&gt;</translation>
    </message>
    <message>
        <source>Preferences</source>
        <translation>Einstellungen</translation>
    </message>
    <message>
        <source>The new language takes effect when Regio is started again.</source>
        <translation>Die neue Sprache wird nach einem Neustart von Regio wirksam.</translation>
    </message>
    <message>
        <source>%1[*] — Regio</source>
        <translation>%1[*] — Regio</translation>
    </message>
    <message>
        <source>%1 objects, %2 parts, %3 faces, %4 materials, %5 regions</source>
        <translation>%1 Objekte, %2 Teile, %3 Flächen, %4 Materialien, %5 Regionen</translation>
    </message>
    <message>
        <source>Unsaved changes</source>
        <translation>Ungespeicherte Änderungen</translation>
    </message>
    <message>
        <source>The scene &quot;%1&quot; has unsaved changes. Save them?</source>
        <translation>Die Szene &quot;%1&quot; enthält ungespeicherte Änderungen. Möchten Sie sie speichern?</translation>
    </message>
    <message>
        <source>New scene</source>
        <translation>Neue Szene</translation>
    </message>
    <message>
        <source>Open Scene</source>
        <translation>Szene öffnen</translation>
    </message>
    <message>
        <source>Regio scenes (*.json);;All files (*)</source>
        <translation>Regio-Szenen (*.json);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Opened %1</source>
        <translation>%1 geöffnet</translation>
    </message>
    <message>
        <source>Could not open %1</source>
        <translation>%1 konnte nicht geöffnet werden</translation>
    </message>
    <message>
        <source>Cannot open scene</source>
        <translation>Szene kann nicht geöffnet werden</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt; could not be opened. The scene you are editing is unchanged.</source>
        <translation>&lt;b&gt;%1&lt;/b&gt; konnte nicht geöffnet werden. Die Szene, die Sie bearbeiten, bleibt unverändert.</translation>
    </message>
    <message>
        <source>Save failed</source>
        <translation>Speichern fehlgeschlagen</translation>
    </message>
    <message>
        <source>The scene could not be saved to %1:
%2
The file on disk is unchanged.</source>
        <translation>Die Szene konnte nicht in %1 gespeichert werden:
%2
Die Datei auf dem Datenträger ist unverändert.</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>%1 gespeichert</translation>
    </message>
    <message>
        <source>Save Scene As</source>
        <translation>Szene speichern unter</translation>
    </message>
    <message>
        <source>untitled.json</source>
        <translation>unbenannt.json</translation>
    </message>
    <message>
        <source>Regio scenes (*.json)</source>
        <translation>Regio-Szenen (*.json)</translation>
    </message>
    <message>
        <source>Revert</source>
        <translation>Gespeicherte Version laden</translation>
    </message>
    <message>
        <source>Drop every change since &quot;%1&quot; was last saved?</source>
        <translation>Alle Änderungen seit dem letzten Speichern von &quot;%1&quot; verwerfen?</translation>
    </message>
    <message>
        <source>Open Recent</source>
        <translation>Zuletzt geöffnet</translation>
    </message>
    <message>
        <source>%1 no longer exists.</source>
        <translation>%1 existiert nicht mehr.</translation>
    </message>
    <message>
        <source>&amp;%1 %2</source>
        <translation>&amp;%1 %2</translation>
    </message>
    <message>
        <source>No recent files</source>
        <translation>Keine zuletzt geöffneten Dateien</translation>
    </message>
    <message>
        <source>Clear List</source>
        <translation>Liste leeren</translation>
    </message>
    <message>
        <source>an unsaved scene</source>
        <translation>einer ungespeicherten Szene</translation>
    </message>
    <message>
        <source>Recover Scene</source>
        <translation>Szene wiederherstellen</translation>
    </message>
    <message>
        <source>Regio did not shut down cleanly. Changes to %1 were autosaved on %2.</source>
        <translation>Regio wurde nicht ordnungsgemäß beendet. Änderungen an %1 wurden am %2 automatisch gespeichert.</translation>
    </message>
    <message>
        <source>Restore them? Discarding deletes the autosaved copy.</source>
        <translation>Möchten Sie sie wiederherstellen? Beim Verwerfen wird die automatisch gespeicherte Kopie gelöscht.</translation>
    </message>
    <message>
        <source>Restore</source>
        <translation>Wiederherstellen</translation>
    </message>
    <message>
        <source>Later</source>
        <translation>Später</translation>
    </message>
    <message>
        <source>The autosaved scene cannot be read: %1</source>
        <translation>Die automatisch gespeicherte Szene kann nicht gelesen werden: %1</translation>
    </message>
    <message>
        <source>Recovered autosaved changes; save to keep them.</source>
        <translation>Automatisch gespeicherte Änderungen wiederhergestellt; speichern Sie, um sie zu behalten.</translation>
    </message>
    <message>
        <source>About Regio</source>
        <translation>Über Regio</translation>
    </message>
    <message>
        <source>&lt;h3&gt;Regio %1&lt;/h3&gt;&lt;p&gt;An editor for radiosity scenes: whole-part B-rep objects, axis-aligned regions and their BSP root-patch orders.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Regio %1&lt;/h3&gt;&lt;p&gt;Ein Editor für Radiosity-Szenen: B-Rep-Objekte aus ganzen Teilen, achsenparallele Regionen und ihre BSP-Reihenfolgen der Wurzel-Patches.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&amp;New</source>
        <translation>&amp;Neu</translation>
    </message>
    <message>
        <source>Start a new, empty scene</source>
        <translation>Eine neue, leere Szene beginnen</translation>
    </message>
    <message>
        <source>&amp;Open…</source>
        <translation>Ö&amp;ffnen…</translation>
    </message>
    <message>
        <source>Open a scene file</source>
        <translation>Eine Szenendatei öffnen</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>&amp;Speichern</translation>
    </message>
    <message>
        <source>Save the scene</source>
        <translation>Die Szene speichern</translation>
    </message>
    <message>
        <source>Save &amp;As…</source>
        <translation>Speichern &amp;unter…</translation>
    </message>
    <message>
        <source>Save the scene under a new name</source>
        <translation>Die Szene unter einem neuen Namen speichern</translation>
    </message>
    <message>
        <source>Re&amp;vert</source>
        <translation>Gespeicherte &amp;Version laden</translation>
    </message>
    <message>
        <source>Drop unsaved changes and reload the file</source>
        <translation>Ungespeicherte Änderungen verwerfen und die Datei neu laden</translation>
    </message>
    <message>
        <source>&amp;Preferences…</source>
        <translation>&amp;Einstellungen…</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Rückgängig</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Wiederherstellen</translation>
    </message>
    <message>
        <source>Select &amp;All</source>
        <translation>&amp;Alles auswählen</translation>
    </message>
    <message>
        <source>&amp;Deselect</source>
        <translation>Auswahl auf&amp;heben</translation>
    </message>
    <message>
        <source>D&amp;uplicate</source>
        <translation>Dupli&amp;zieren</translation>
    </message>
    <message>
        <source>Copy the selected objects or parts</source>
        <translation>Die ausgewählten Objekte oder Teile kopieren</translation>
    </message>
    <message>
        <source>De&amp;lete</source>
        <translation>&amp;Löschen</translation>
    </message>
    <message>
        <source>Delete the selection</source>
        <translation>Die Auswahl löschen</translation>
    </message>
    <message>
        <source>Re&amp;name…</source>
        <translation>&amp;Umbenennen…</translation>
    </message>
    <message>
        <source>Rename the selected element</source>
        <translation>Den ausgewählten Eintrag umbenennen</translation>
    </message>
    <message>
        <source>&amp;Frame Selection</source>
        <translation>Auswahl &amp;einpassen</translation>
    </message>
    <message>
        <source>Fit the selection in the view (everything when nothing is selected)</source>
        <translation>Die Auswahl in die Ansicht einpassen (alles, wenn nichts ausgewählt ist)</translation>
    </message>
    <message>
        <source>Frame &amp;All</source>
        <translation>&amp;Alles einpassen</translation>
    </message>
    <message>
        <source>&amp;Orthographic</source>
        <translation>&amp;Orthografisch</translation>
    </message>
    <message>
        <source>Hide &amp;Back Faces</source>
        <translation>&amp;Rückseiten ausblenden</translation>
    </message>
    <message>
        <source>Faces seen from behind are not drawn: look into rooms from outside</source>
        <translation>Von hinten gesehene Flächen werden nicht gezeichnet: So blicken Sie von außen in Räume hinein</translation>
    </message>
    <message>
        <source>Show &amp;Grid</source>
        <translation>Raster an&amp;zeigen</translation>
    </message>
    <message>
        <source>Show &amp;Regions</source>
        <translation>Re&amp;gionen anzeigen</translation>
    </message>
    <message>
        <source>&amp;Solid</source>
        <translation>&amp;Schattiert</translation>
    </message>
    <message>
        <source>&amp;Wireframe</source>
        <translation>&amp;Drahtgitter</translation>
    </message>
    <message>
        <source>Face &amp;Normals</source>
        <translation>Flächen&amp;normalen</translation>
    </message>
    <message>
        <source>Colour faces by their normal and show which way they face</source>
        <translation>Flächen nach ihrer Normalen einfärben und ihre Ausrichtung anzeigen</translation>
    </message>
    <message>
        <source>Select &amp;Objects</source>
        <translation>&amp;Objekte auswählen</translation>
    </message>
    <message>
        <source>Select &amp;Parts</source>
        <translation>&amp;Teile auswählen</translation>
    </message>
    <message>
        <source>Select F&amp;aces</source>
        <translation>&amp;Flächen auswählen</translation>
    </message>
    <message>
        <source>&amp;Move</source>
        <translation>&amp;Verschieben</translation>
    </message>
    <message>
        <source>&amp;Rotate</source>
        <translation>&amp;Drehen</translation>
    </message>
    <message>
        <source>&amp;Scale</source>
        <translation>&amp;Skalieren</translation>
    </message>
    <message>
        <source>Snap to &amp;Grid</source>
        <translation>Am &amp;Raster einrasten</translation>
    </message>
    <message>
        <source>&amp;Front</source>
        <translation>&amp;Vorne</translation>
    </message>
    <message>
        <source>&amp;Back</source>
        <translation>&amp;Hinten</translation>
    </message>
    <message>
        <source>&amp;Right</source>
        <translation>&amp;Rechts</translation>
    </message>
    <message>
        <source>&amp;Left</source>
        <translation>&amp;Links</translation>
    </message>
    <message>
        <source>&amp;Top</source>
        <translation>&amp;Oben</translation>
    </message>
    <message>
        <source>Botto&amp;m</source>
        <translation>&amp;Unten</translation>
    </message>
    <message>
        <source>&amp;Isometric</source>
        <translation>&amp;Isometrisch</translation>
    </message>
    <message>
        <source>&amp;About Regio</source>
        <translation>Ü&amp;ber Regio</translation>
    </message>
    <message>
        <source>About &amp;Qt</source>
        <translation>Über &amp;Qt</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>&amp;Zuletzt geöffnet</translation>
    </message>
    <message>
        <source>Open E&amp;xample</source>
        <translation>Beispie&amp;l öffnen</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>&amp;Bearbeiten</translation>
    </message>
    <message>
        <source>&amp;Create</source>
        <translation>&amp;Erstellen</translation>
    </message>
    <message>
        <source>&amp;Modify</source>
        <translation>Ä&amp;ndern</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <source>Standard &amp;Views</source>
        <translation>S&amp;tandardansichten</translation>
    </message>
    <message>
        <source>&amp;Panels</source>
        <translation>&amp;Bedienfelder</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <source>File</source>
        <translation>Datei</translation>
    </message>
    <message>
        <source>Tools</source>
        <translation>Werkzeuge</translation>
    </message>
    <message>
        <source>Create</source>
        <translation>Erstellen</translation>
    </message>
    <message>
        <source>&amp;Regions</source>
        <translation>&amp;Regionen</translation>
    </message>
    <message>
        <source>&amp;BSP</source>
        <translation>B&amp;SP</translation>
    </message>
    <message>
        <source>&amp;Solve</source>
        <translation>&amp;Lösen</translation>
    </message>
    <message>
        <source>Solve</source>
        <translation>Lösen</translation>
    </message>
    <message>
        <source>Import Model</source>
        <translation>Modell importieren</translation>
    </message>
    <message>
        <source>Models (*.obj *.gltf *.glb *.fbx *.dae *.ply *.stl *.3ds *.blend *.off *.x *.lwo *.ase *.ac);;All files (*)</source>
        <translation>Modelle (*.obj *.gltf *.glb *.fbx *.dae *.ply *.stl *.3ds *.blend *.off *.x *.lwo *.ase *.ac);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Imported %1 as a new scene</source>
        <translation>%1 als neue Szene importiert</translation>
    </message>
    <message>
        <source>Import %1</source>
        <translation>%1 importieren</translation>
    </message>
    <message>
        <source>Imported %1 (objects: %2)</source>
        <translation>%1 importiert (Objekte: %2)</translation>
    </message>
    <message>
        <source>&amp;Import Model…</source>
        <translation>Modell &amp;importieren…</translation>
    </message>
    <message>
        <source>Ctrl+I</source>
        <translation>Ctrl+I</translation>
    </message>
    <message>
        <source>Import a model file (OBJ, glTF, FBX, Collada, PLY, STL, 3DS, ...)</source>
        <translation>Eine Modelldatei importieren (OBJ, glTF, FBX, Collada, PLY, STL, 3DS, ...)</translation>
    </message>
    <message>
        <source>&amp;Reset Layout</source>
        <translation>&amp;Layout zurücksetzen</translation>
    </message>
    <message>
        <source>Put every panel back where it was at first start, sized to the window</source>
        <translation>Alle Bedienfelder wieder wie beim ersten Start anordnen, an die Fenstergröße angepasst</translation>
    </message>
    <message>
        <source>User &amp;Guide</source>
        <translation>&amp;Benutzerhandbuch</translation>
    </message>
    <message>
        <source>Open the user guide</source>
        <translation>Das Benutzerhandbuch öffnen</translation>
    </message>
    <message>
        <source>No program opens %1 on this system</source>
        <translation>Kein Programm auf diesem System öffnet %1</translation>
    </message>
    <message>
        <source>E&amp;xamples</source>
        <translation>Bei&amp;spiele</translation>
    </message>
</context>
<context>
    <name>regio::editor::MaterialsDock</name>
    <message>
        <source>Materials</source>
        <translation>Materialien</translation>
    </message>
    <message>
        <source>Add</source>
        <translation>Hinzufügen</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Löschen</translation>
    </message>
    <message>
        <source>Only a material nothing uses can be deleted</source>
        <translation>Nur ein Material, das nirgends verwendet wird, kann gelöscht werden</translation>
    </message>
    <message>
        <source>Assign to Selection</source>
        <translation>Der Auswahl zuweisen</translation>
    </message>
    <message>
        <source>Id:</source>
        <translation>ID:</translation>
    </message>
    <message>
        <source>(no name)</source>
        <translation>(kein Name)</translation>
    </message>
    <message>
        <source>Name:</source>
        <translation>Name:</translation>
    </message>
    <message>
        <source>Diffuse reflectance per channel (red, green, blue), below 1</source>
        <translation>Diffuser Reflexionsgrad pro Kanal (Rot, Grün, Blau), kleiner als 1</translation>
    </message>
    <message>
        <source>Reflectance:</source>
        <translation>Reflexionsgrad:</translation>
    </message>
    <message>
        <source>Emitted power per unit area per channel (W/m²)</source>
        <translation>Emittierte Leistung pro Flächeneinheit und Kanal (W/m²)</translation>
    </message>
    <message>
        <source>Emission:</source>
        <translation>Emission:</translation>
    </message>
    <message>
        <source>The strongest channel of the emission; the others keep their ratio</source>
        <translation>Der stärkste Kanal der Emission; die anderen behalten ihr Verhältnis bei</translation>
    </message>
    <message>
        <source>Strength:</source>
        <translation>Stärke:</translation>
    </message>
</context>
<context>
    <name>regio::editor::PreferencesDialog</name>
    <message>
        <source>Preferences</source>
        <translation>Einstellungen</translation>
    </message>
    <message>
        <source>System default</source>
        <translation>Systemstandard</translation>
    </message>
    <message>
        <source>&amp;Language:</source>
        <translation>&amp;Sprache:</translation>
    </message>
    <message>
        <source> min</source>
        <translation> min</translation>
    </message>
    <message>
        <source>Off</source>
        <translation>Aus</translation>
    </message>
    <message>
        <source>How often unsaved changes are written to a recovery file</source>
        <translation>Wie oft ungespeicherte Änderungen in eine Wiederherstellungsdatei geschrieben werden</translation>
    </message>
    <message>
        <source>&amp;Autosave every:</source>
        <translation>&amp;Automatisch speichern alle:</translation>
    </message>
    <message>
        <source> m</source>
        <translation> m</translation>
    </message>
    <message>
        <source>&amp;Grid step:</source>
        <translation>&amp;Rasterweite:</translation>
    </message>
    <message>
        <source>Snap moves, rotations and scaling</source>
        <translation>Verschiebungen, Drehungen und Skalierungen einrasten</translation>
    </message>
    <message>
        <source>&amp;Snapping:</source>
        <translation>&amp;Einrasten:</translation>
    </message>
    <message>
        <source>A&amp;ngle step:</source>
        <translation>&amp;Winkelschritt:</translation>
    </message>
</context>
<context>
    <name>regio::editor::PreviewController</name>
    <message>
        <source>Nothing of the solution under the cursor.</source>
        <translation>Unter dem Mauszeiger liegt nichts von der Lösung.</translation>
    </message>
    <message>
        <source>The preview cannot solve this scene: %1</source>
        <translation>Die Vorschau kann diese Szene nicht lösen: %1</translation>
    </message>
    <message>
        <source>&amp;Run</source>
        <translation>&amp;Starten</translation>
    </message>
    <message>
        <source>Solve the scene as it is now (the preview shows it progressively)</source>
        <translation>Die Szene in ihrem aktuellen Zustand lösen (die Vorschau zeigt sie schrittweise)</translation>
    </message>
    <message>
        <source>&amp;Pause</source>
        <translation>&amp;Pausieren</translation>
    </message>
    <message>
        <source>Pause the solve, or resume it</source>
        <translation>Die Lösung pausieren oder weiterlaufen lassen</translation>
    </message>
    <message>
        <source>&amp;Stop</source>
        <translation>S&amp;toppen</translation>
    </message>
    <message>
        <source>End the solve; the solution stays</source>
        <translation>Den Lösungsvorgang beenden; die Lösung bleibt erhalten</translation>
    </message>
    <message>
        <source>Rese&amp;t</source>
        <translation>&amp;Zurücksetzen</translation>
    </message>
    <message>
        <source>Drop the solution and show the materials again</source>
        <translation>Die Lösung verwerfen und wieder die Materialien anzeigen</translation>
    </message>
    <message>
        <source>&amp;Live</source>
        <translation>&amp;Live</translation>
    </message>
    <message>
        <source>Solve again automatically after a pause in editing</source>
        <translation>Nach einer Bearbeitungspause automatisch erneut lösen</translation>
    </message>
    <message>
        <source>&amp;Dry Run…</source>
        <translation>Prob&amp;elauf…</translation>
    </message>
    <message>
        <source>List the effective settings and the patch and element counts</source>
        <translation>Die wirksamen Einstellungen sowie die Anzahl der Patches und Elemente auflisten</translation>
    </message>
    <message>
        <source>&amp;Inspect</source>
        <translation>&amp;Untersuchen</translation>
    </message>
    <message>
        <source>Click a surface of the solution to see its element</source>
        <translation>Klicken Sie auf eine Oberfläche der Lösung, um ihr Element zu sehen</translation>
    </message>
    <message>
        <source>&amp;Hemicube…</source>
        <translation>&amp;Hemicube…</translation>
    </message>
    <message>
        <source>Show the item buffer of the inspected patch</source>
        <translation>Den Item-Buffer des untersuchten Patches anzeigen</translation>
    </message>
    <message>
        <source>Draft</source>
        <translation>Entwurf</translation>
    </message>
    <message>
        <source>Coarse and fast: for previews while editing</source>
        <translation>Grob und schnell: für Vorschauen während der Bearbeitung</translation>
    </message>
    <message>
        <source>Normal</source>
        <translation>Normal</translation>
    </message>
    <message>
        <source>The default settings</source>
        <translation>Die Standardeinstellungen</translation>
    </message>
    <message>
        <source>Final</source>
        <translation>Endgültig</translation>
    </message>
    <message>
        <source>Fine meshes and a large hemicube: for batch solving</source>
        <translation>Feine Netze und ein großer Hemicube: für die Lösung in der Stapelverarbeitung</translation>
    </message>
    <message>
        <source>Export Lit &amp;Model…</source>
        <translation>Beleuchtetes &amp;Modell exportieren…</translation>
    </message>
    <message>
        <source>Write the shown solution as glTF, PLY or OBJ</source>
        <translation>Die angezeigte Lösung als glTF, PLY oder OBJ schreiben</translation>
    </message>
    <message>
        <source>Export Viewport &amp;Image…</source>
        <translation>Ansicht als &amp;Bild exportieren…</translation>
    </message>
    <message>
        <source>Save the viewport as a picture</source>
        <translation>Die Ansicht als Bild speichern</translation>
    </message>
    <message>
        <source>Export for &amp;Batch…</source>
        <translation>Für Stapel&amp;verarbeitung exportieren…</translation>
    </message>
    <message>
        <source>Write a self-contained scene with final settings and the regio-solve command</source>
        <translation>Eine eigenständige Szene mit den Einstellungen „Endgültig“ und den regio-solve-Befehl schreiben</translation>
    </message>
    <message>
        <source>&amp;Presets</source>
        <translation>V&amp;oreinstellungen</translation>
    </message>
    <message>
        <source>iteration %1, unshot %2 %, %3 elements, %4 s</source>
        <translation>Iteration %1, noch nicht abgestrahlt %2 %, %3 Elemente, %4 s</translation>
    </message>
    <message>
        <source>Preview: not solved</source>
        <translation>Vorschau: nicht gelöst</translation>
    </message>
    <message>
        <source>Preview: preparing the scene…</source>
        <translation>Vorschau: Szene wird vorbereitet…</translation>
    </message>
    <message>
        <source>Solving: %1</source>
        <translation>Wird gelöst: %1</translation>
    </message>
    <message>
        <source>Solving…</source>
        <translation>Wird gelöst…</translation>
    </message>
    <message>
        <source>Paused: %1</source>
        <translation>Pausiert: %1</translation>
    </message>
    <message>
        <source>Paused</source>
        <translation>Pausiert</translation>
    </message>
    <message>
        <source>Solved</source>
        <translation>Gelöst</translation>
    </message>
    <message>
        <source>Preview: the scene cannot be solved</source>
        <translation>Vorschau: Die Szene kann nicht gelöst werden</translation>
    </message>
    <message>
        <source> (stale: the scene changed)</source>
        <translation> (veraltet: die Szene wurde geändert)</translation>
    </message>
    <message>
        <source>Res&amp;ume</source>
        <translation>&amp;Weiter</translation>
    </message>
    <message>
        <source>Dry Run</source>
        <translation>Probelauf</translation>
    </message>
    <message>
        <source>Hemicube</source>
        <translation>Hemicube</translation>
    </message>
    <message>
        <source>Patch (or inspect a surface first):</source>
        <translation>Patch (oder zuerst eine Oberfläche untersuchen):</translation>
    </message>
    <message>
        <source>there is no solution to export</source>
        <translation>es gibt keine Lösung zum Exportieren</translation>
    </message>
    <message>
        <source>the viewport could not be read</source>
        <translation>die Ansicht konnte nicht gelesen werden</translation>
    </message>
    <message>
        <source>Export Lit Model</source>
        <translation>Beleuchtetes Modell exportieren</translation>
    </message>
    <message>
        <source>glTF binary (*.glb);;glTF (*.gltf);;PLY (*.ply);;OBJ (*.obj)</source>
        <translation>glTF binär (*.glb);;glTF (*.gltf);;PLY (*.ply);;OBJ (*.obj)</translation>
    </message>
    <message>
        <source>Exported %1</source>
        <translation>%1 exportiert</translation>
    </message>
    <message>
        <source>Export Viewport Image</source>
        <translation>Ansicht als Bild exportieren</translation>
    </message>
    <message>
        <source>PNG image (*.png);;JPEG image (*.jpg)</source>
        <translation>PNG-Bild (*.png);;JPEG-Bild (*.jpg)</translation>
    </message>
    <message>
        <source>Export for Batch</source>
        <translation>Für Stapelverarbeitung exportieren</translation>
    </message>
    <message>
        <source>Regio scene (*.json)</source>
        <translation>Regio-Szene (*.json)</translation>
    </message>
    <message>
        <source>Wrote %1 with the final preset&apos;s settings. This command, now on the clipboard, solves it and writes the report, the lit model and a picture:

%2</source>
        <translation>%1 wurde mit den Einstellungen der Voreinstellung „Endgültig“ geschrieben. Dieser Befehl, der sich jetzt in der Zwischenablage befindet, löst die Szene und schreibt den Bericht, das beleuchtete Modell und ein Bild:

%2</translation>
    </message>
    <message>
        <source>&amp;Continue</source>
        <translation>&amp;Fortsetzen</translation>
    </message>
    <message>
        <source>Go on from where the solve stopped: its iteration limit or your Stop</source>
        <translation>Dort weitermachen, wo die Lösung angehalten hat: an ihrer Iterationsgrenze oder durch Ihr Stoppen</translation>
    </message>
    <message>
        <source>Stopped at the iteration limit, not converged: %1 (Continue goes on)</source>
        <translation>An der Iterationsgrenze angehalten, nicht konvergiert: %1 („Fortsetzen“ macht weiter)</translation>
    </message>
    <message>
        <source>Stopped by you, not converged: %1 (Continue goes on)</source>
        <translation>Von Ihnen gestoppt, nicht konvergiert: %1 („Fortsetzen“ macht weiter)</translation>
    </message>
    <message>
        <source>Converged: %1</source>
        <translation>Konvergiert: %1</translation>
    </message>
    <message>
        <source> (refining the mesh…)</source>
        <translation> (das Netz wird verfeinert…)</translation>
    </message>
</context>
<context>
    <name>regio::editor::PreviewExport</name>
    <message>
        <source>there is no solution to export</source>
        <translation>es gibt keine Lösung zum Exportieren</translation>
    </message>
    <message>
        <source>%1: unknown model format (use .gltf, .glb, .ply or .obj)</source>
        <translation>%1: unbekanntes Modellformat (verwenden Sie .gltf, .glb, .ply oder .obj)</translation>
    </message>
</context>
<context>
    <name>regio::editor::PreviewInspector</name>
    <message>
        <source>Element %1 of face %2</source>
        <translation>Element %1 von Fläche %2</translation>
    </message>
    <message>
        <source>Patch: %1; region: %2</source>
        <translation>Patch: %1; Region: %2</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>unbekannt</translation>
    </message>
    <message>
        <source>Radiosity: %1 W/m²</source>
        <translation>Radiosity: %1 W/m²</translation>
    </message>
    <message>
        <source>Unshot: %1 W/m²</source>
        <translation>Noch nicht abgestrahlt: %1 W/m²</translation>
    </message>
    <message>
        <source>Shown (with ambient): %1 W/m²</source>
        <translation>Angezeigt (mit Umgebungsterm): %1 W/m²</translation>
    </message>
    <message>
        <source>Area: %1 m²</source>
        <translation>Flächeninhalt: %1 m²</translation>
    </message>
</context>
<context>
    <name>regio::editor::PreviewRunner</name>
    <message>
        <source>the scene could not be prepared</source>
        <translation>die Szene konnte nicht vorbereitet werden</translation>
    </message>
</context>
<context>
    <name>regio::editor::PreviewScreenshot</name>
    <message>
        <source>the preview did not finish within %1 s</source>
        <translation>die Vorschau wurde nicht innerhalb von %1 s fertig</translation>
    </message>
    <message>
        <source>the preview failed: %1</source>
        <translation>die Vorschau ist fehlgeschlagen: %1</translation>
    </message>
</context>
<context>
    <name>regio::editor::PreviewSession</name>
    <message>
        <source>the solver ran out of memory (try a larger patch size or a lower hemicube resolution)</source>
        <translation>dem Löser ist der Speicher ausgegangen (versuchen Sie eine größere Patch-Größe oder eine niedrigere Hemicube-Auflösung)</translation>
    </message>
    <message>
        <source>the solver failed: %1</source>
        <translation>der Löser ist fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>the solver failed</source>
        <translation>der Löser ist fehlgeschlagen</translation>
    </message>
</context>
<context>
    <name>regio::editor::PrimitiveDialog</name>
    <message>
        <source>Box</source>
        <translation>Quader</translation>
    </message>
    <message>
        <source>Room</source>
        <translation>Raum</translation>
    </message>
    <message>
        <source>Prism / Cylinder</source>
        <translation>Prisma / Zylinder</translation>
    </message>
    <message>
        <source>Wedge</source>
        <translation>Keil</translation>
    </message>
    <message>
        <source>Stairs</source>
        <translation>Treppe</translation>
    </message>
    <message>
        <source>&amp;Id:</source>
        <translation>&amp;ID:</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>(keines)</translation>
    </message>
    <message>
        <source>&amp;Material:</source>
        <translation>&amp;Material:</translation>
    </message>
    <message>
        <source>&amp;Base centre (m):</source>
        <translation>&amp;Basismittelpunkt (m):</translation>
    </message>
    <message>
        <source>&amp;Size (m):</source>
        <translation>&amp;Größe (m):</translation>
    </message>
    <message>
        <source>Si&amp;des:</source>
        <translation>&amp;Seiten:</translation>
    </message>
    <message>
        <source>S&amp;teps:</source>
        <translation>S&amp;tufen:</translation>
    </message>
    <message>
        <source>New object: %1</source>
        <translation>Neues Objekt: %1</translation>
    </message>
</context>
<context>
    <name>regio::editor::PropertiesDock</name>
    <message>
        <source>Properties</source>
        <translation>Eigenschaften</translation>
    </message>
    <message>
        <source>Solver</source>
        <translation>Löser</translation>
    </message>
    <message>
        <source> m</source>
        <translation> m</translation>
    </message>
    <message>
        <source>Scene camera</source>
        <translation>Szenenkamera</translation>
    </message>
    <message>
        <source>Store Current View</source>
        <translation>Aktuelle Ansicht speichern</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>Entfernen</translation>
    </message>
    <message>
        <source>(no name)</source>
        <translation>(kein Name)</translation>
    </message>
    <message>
        <source>Name:</source>
        <translation>Name:</translation>
    </message>
    <message>
        <source>Material:</source>
        <translation>Material:</translation>
    </message>
    <message>
        <source>Transform</source>
        <translation>Transformation</translation>
    </message>
    <message>
        <source>Centre of the selection&apos;s bounding box; editing it moves the selection</source>
        <translation>Mittelpunkt des Begrenzungsquaders der Auswahl; eine Änderung verschiebt die Auswahl</translation>
    </message>
    <message>
        <source>Move</source>
        <translation>Verschieben</translation>
    </message>
    <message>
        <source>Centre:</source>
        <translation>Mittelpunkt:</translation>
    </message>
    <message>
        <source>Rotate</source>
        <translation>Drehen</translation>
    </message>
    <message>
        <source>Rotate by:</source>
        <translation>Drehen um:</translation>
    </message>
    <message>
        <source>Scale</source>
        <translation>Skalieren</translation>
    </message>
    <message>
        <source>Scale by:</source>
        <translation>Skalieren um:</translation>
    </message>
    <message>
        <source>Minimum:</source>
        <translation>Minimum:</translation>
    </message>
    <message>
        <source>Maximum:</source>
        <translation>Maximum:</translation>
    </message>
    <message>
        <source>Eye %1, looking at %2, field of view %3°</source>
        <translation>Augpunkt %1, Blick auf %2, Sichtfeld %3°</translation>
    </message>
    <message>
        <source>None: the view frames the whole scene when it opens.</source>
        <translation>Keine: Die Ansicht zeigt beim Öffnen die ganze Szene.</translation>
    </message>
    <message>
        <source>&lt;b&gt;Object&lt;/b&gt; %1</source>
        <translation>&lt;b&gt;Objekt&lt;/b&gt; %1</translation>
    </message>
    <message>
        <source>&lt;b&gt;Part&lt;/b&gt; %1</source>
        <translation>&lt;b&gt;Teil&lt;/b&gt; %1</translation>
    </message>
    <message numerus="yes">
        <source>&lt;b&gt;%n objects&lt;/b&gt;</source>
        <translation>
            <numerusform>&lt;b&gt;%n Objekt&lt;/b&gt;</numerusform>
            <numerusform>&lt;b&gt;%n Objekte&lt;/b&gt;</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>&lt;b&gt;%n parts&lt;/b&gt;</source>
        <translation>
            <numerusform>&lt;b&gt;%n Teil&lt;/b&gt;</numerusform>
            <numerusform>&lt;b&gt;%n Teile&lt;/b&gt;</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n part(s)</source>
        <translation>
            <numerusform>%n Teil</numerusform>
            <numerusform>%n Teile</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n face(s)</source>
        <translation>
            <numerusform>%n Fläche</numerusform>
            <numerusform>%n Flächen</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n vertices</source>
        <translation>
            <numerusform>%n Eckpunkt</numerusform>
            <numerusform>%n Eckpunkte</numerusform>
        </translation>
    </message>
    <message>
        <source>Size %1 m</source>
        <translation>Größe %1 m</translation>
    </message>
    <message numerus="yes">
        <source>&lt;b&gt;%n faces&lt;/b&gt;</source>
        <translation>
            <numerusform>&lt;b&gt;%n Fläche&lt;/b&gt;</numerusform>
            <numerusform>&lt;b&gt;%n Flächen&lt;/b&gt;</numerusform>
        </translation>
    </message>
    <message>
        <source>(the part&apos;s material)</source>
        <translation>(Material des Teils)</translation>
    </message>
    <message>
        <source>&lt;b&gt;Face&lt;/b&gt; %1</source>
        <translation>&lt;b&gt;Fläche&lt;/b&gt; %1</translation>
    </message>
    <message>
        <source>(the part&apos;s: %1)</source>
        <translation>(das des Teils: %1)</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keines</translation>
    </message>
    <message>
        <source>The face&apos;s vertex loop is broken.</source>
        <translation>Die Eckpunktschleife der Fläche ist fehlerhaft.</translation>
    </message>
    <message numerus="yes">
        <source>Part %1
%n vertices</source>
        <translation>
            <numerusform>Teil %1
%n Eckpunkt</numerusform>
            <numerusform>Teil %1
%n Eckpunkte</numerusform>
        </translation>
    </message>
    <message>
        <source>Area %1 m²</source>
        <translation>Flächeninhalt %1 m²</translation>
    </message>
    <message>
        <source>Normal %1</source>
        <translation>Normale %1</translation>
    </message>
    <message>
        <source>Centroid %1</source>
        <translation>Schwerpunkt %1</translation>
    </message>
    <message>
        <source>Off its plane by at most %1 m</source>
        <translation>Höchstens %1 m von ihrer Ebene entfernt</translation>
    </message>
    <message>
        <source>&lt;b&gt;Material&lt;/b&gt; %1&lt;br&gt;Used as the default of %2 part(s) and by %3 face(s) of their own.&lt;br&gt;Edit its colours in the Materials panel.</source>
        <translation>&lt;b&gt;Material&lt;/b&gt; %1&lt;br&gt;Als Standardmaterial von %2 Teil(en) und von %3 Fläche(n) mit eigenem Material verwendet.&lt;br&gt;Bearbeiten Sie seine Farben im Bedienfeld „Materialien“.</translation>
    </message>
    <message numerus="yes">
        <source>&lt;b&gt;%n regions&lt;/b&gt;</source>
        <translation>
            <numerusform>&lt;b&gt;%n Region&lt;/b&gt;</numerusform>
            <numerusform>&lt;b&gt;%n Regionen&lt;/b&gt;</numerusform>
        </translation>
    </message>
    <message>
        <source>&lt;b&gt;Region&lt;/b&gt; %1</source>
        <translation>&lt;b&gt;Region&lt;/b&gt; %1</translation>
    </message>
    <message numerus="yes">
        <source>BSP order: %n face(s)</source>
        <translation>
            <numerusform>BSP-Reihenfolge: %n Fläche</numerusform>
            <numerusform>BSP-Reihenfolge: %n Flächen</numerusform>
        </translation>
    </message>
    <message>
        <source>The hemicube, the mesh and when to stop are set in the Solver panel, beside the preview.</source>
        <translation>Hemicube, Netz und Abbruchbedingungen werden im Bedienfeld „Löser“ neben der Vorschau eingestellt.</translation>
    </message>
    <message>
        <source>Show Solver Panel</source>
        <translation>Bedienfeld „Löser“ anzeigen</translation>
    </message>
</context>
<context>
    <name>regio::editor::RegionAuthoring</name>
    <message>
        <source>&amp;Region Tool</source>
        <translation>&amp;Regionswerkzeug</translation>
    </message>
    <message>
        <source>Draw a region box in the viewport and resize the selected one by its face handles</source>
        <translation>Einen Regionsquader in der Ansicht zeichnen und die Größe des ausgewählten über seine Flächengriffe ändern</translation>
    </message>
    <message>
        <source>Region Around &amp;Selection</source>
        <translation>Region um &amp;Auswahl</translation>
    </message>
    <message>
        <source>Add a region box around the selected parts (the whole scene when nothing is selected)</source>
        <translation>Einen Regionsquader um die ausgewählten Teile hinzufügen (um die ganze Szene, wenn nichts ausgewählt ist)</translation>
    </message>
    <message>
        <source>Re&amp;name Region…</source>
        <translation>Region &amp;umbenennen…</translation>
    </message>
    <message>
        <source>&amp;Delete Region</source>
        <translation>Region &amp;löschen</translation>
    </message>
    <message>
        <source>&amp;Clip Selected Parts to Regions</source>
        <translation>Ausgewählte Teile an Regionen &amp;zuschneiden</translation>
    </message>
    <message>
        <source>Cut each selected part that straddles region boundaries into one piece per region</source>
        <translation>Jedes ausgewählte Teil, das über Regionsgrenzen hinweg reicht, in ein Stück pro Region zerschneiden</translation>
    </message>
    <message>
        <source>&amp;Propose Automatic Regions</source>
        <translation>Automatische Regionen &amp;vorschlagen</translation>
    </message>
    <message>
        <source>Suggest region boxes whose planes pass between the parts, with their BSP figures</source>
        <translation>Regionsquader vorschlagen, deren Ebenen zwischen den Teilen verlaufen, mit ihren BSP-Kennzahlen</translation>
    </message>
    <message>
        <source>&amp;Accept Proposed Regions</source>
        <translation>Vorgeschlagene Regionen ü&amp;bernehmen</translation>
    </message>
    <message>
        <source>Replace the scene&apos;s regions by the proposed ones</source>
        <translation>Die Regionen der Szene durch die vorgeschlagenen ersetzen</translation>
    </message>
    <message>
        <source>D&amp;iscard Proposed Regions</source>
        <translation>Vorgeschlagene Regionen verw&amp;erfen</translation>
    </message>
    <message>
        <source>Show Region &amp;Boxes</source>
        <translation>Regions&amp;quader anzeigen</translation>
    </message>
    <message>
        <source>&amp;Colour Parts by Region</source>
        <translation>Teile nach Region &amp;färben</translation>
    </message>
    <message>
        <source>Each face in its region&apos;s colour; grey outside every region</source>
        <translation>Jede Fläche in der Farbe ihrer Region; grau außerhalb aller Regionen</translation>
    </message>
    <message>
        <source>Show &amp;Separating Planes</source>
        <translation>&amp;Trennebenen anzeigen</translation>
    </message>
    <message>
        <source>The planes of the solver&apos;s regional tree between the region boxes</source>
        <translation>Die Ebenen des Regionenbaums des Lösers zwischen den Regionsquadern</translation>
    </message>
    <message>
        <source>The scene changed: the proposed regions were discarded</source>
        <translation>Die Szene wurde geändert: Die vorgeschlagenen Regionen wurden verworfen</translation>
    </message>
    <message>
        <source>Clip Part to Regions</source>
        <translation>Teil an Regionen zuschneiden</translation>
    </message>
    <message>
        <source>Cut the straddling part into one piece per region</source>
        <translation>Das über Regionsgrenzen reichende Teil in ein Stück pro Region zerschneiden</translation>
    </message>
    <message>
        <source>The scene is empty: draw a region with the region tool</source>
        <translation>Die Szene ist leer: Zeichnen Sie eine Region mit dem Regionswerkzeug</translation>
    </message>
    <message>
        <source>No selected part straddles a region boundary</source>
        <translation>Kein ausgewähltes Teil reicht über eine Regionsgrenze hinweg</translation>
    </message>
    <message numerus="yes">
        <source>Clip %n part(s) to regions</source>
        <translation>
            <numerusform>%n Teil an Regionen zuschneiden</numerusform>
            <numerusform>%n Teile an Regionen zuschneiden</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Clipped to regions: %n piece(s)</source>
        <translation>
            <numerusform>An Regionen zugeschnitten: %n Stück</numerusform>
            <numerusform>An Regionen zugeschnitten: %n Stücke</numerusform>
        </translation>
    </message>
    <message>
        <source>no regions could be proposed</source>
        <translation>es konnten keine Regionen vorgeschlagen werden</translation>
    </message>
    <message>
        <source>No proposal: %1</source>
        <translation>Kein Vorschlag: %1</translation>
    </message>
    <message numerus="yes">
        <source>&lt;b&gt;Proposed: %n region(s)&lt;/b&gt;</source>
        <translation>
            <numerusform>&lt;b&gt;Vorgeschlagen: %n Region&lt;/b&gt;</numerusform>
            <numerusform>&lt;b&gt;Vorgeschlagen: %n Regionen&lt;/b&gt;</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 fragments, %2 splits, depth %3</source>
        <translation>%1 Fragmente, %2 Teilungen, Tiefe %3</translation>
    </message>
    <message>
        <source>Current regions: %1 fragments, %2 splits</source>
        <translation>Aktuelle Regionen: %1 Fragmente, %2 Teilungen</translation>
    </message>
    <message>
        <source>Single BSP: %1 fragments, %2 splits</source>
        <translation>Einzelner BSP-Baum: %1 Fragmente, %2 Teilungen</translation>
    </message>
    <message numerus="yes">
        <source>%n part(s) cross the proposed planes; after accepting, clip them from the Diagnostics panel or the Regions menu.</source>
        <translation>
            <numerusform>%n Teil schneidet die vorgeschlagenen Ebenen; schneiden Sie es nach dem Übernehmen über das Bedienfeld „Diagnose“ oder das Menü „Regionen“ zu.</numerusform>
            <numerusform>%n Teile schneiden die vorgeschlagenen Ebenen; schneiden Sie sie nach dem Übernehmen über das Bedienfeld „Diagnose“ oder das Menü „Regionen“ zu.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Proposed %n region(s): accept or discard them in the Regions panel</source>
        <translation>
            <numerusform>%n Region vorgeschlagen: Übernehmen oder verwerfen Sie sie im Bedienfeld „Regionen“</numerusform>
            <numerusform>%n Regionen vorgeschlagen: Übernehmen oder verwerfen Sie sie im Bedienfeld „Regionen“</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Accept %n proposed region(s)</source>
        <translation>
            <numerusform>%n vorgeschlagene Region übernehmen</numerusform>
            <numerusform>%n vorgeschlagene Regionen übernehmen</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Accepted %n region(s)</source>
        <translation>
            <numerusform>%n Region übernommen</numerusform>
            <numerusform>%n Regionen übernommen</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>regio::editor::RegionBoxTool</name>
    <message>
        <source>Region tool: drag on the ground or a horizontal face to draw a box; drag a handle of the selected region to resize it; Esc leaves the tool</source>
        <translation>Regionswerkzeug: Ziehen Sie auf dem Boden oder einer horizontalen Fläche, um einen Quader zu zeichnen; ziehen Sie an einem Griff der ausgewählten Region, um ihre Größe zu ändern; Esc verlässt das Werkzeug</translation>
    </message>
    <message>
        <source>Aim at the ground grid or a horizontal face to start a region</source>
        <translation>Zielen Sie auf das Bodenraster oder eine horizontale Fläche, um eine Region zu beginnen</translation>
    </message>
    <message>
        <source>Region %1 × %2 × %3 m</source>
        <translation>Region %1 × %2 × %3 m</translation>
    </message>
    <message>
        <source>Region %1: %2 %3 = %4 m</source>
        <translation>Region %1: %2 %3 = %4 m</translation>
    </message>
    <message>
        <source>max</source>
        <translation>max</translation>
    </message>
    <message>
        <source>min</source>
        <translation>min</translation>
    </message>
    <message>
        <source>Region drawing cancelled</source>
        <translation>Zeichnen der Region abgebrochen</translation>
    </message>
    <message>
        <source>The box is too thin; drag a larger rectangle</source>
        <translation>Der Quader ist zu dünn; ziehen Sie ein größeres Rechteck auf</translation>
    </message>
    <message>
        <source>Added region %1</source>
        <translation>Region %1 hinzugefügt</translation>
    </message>
</context>
<context>
    <name>regio::editor::RegionsDock</name>
    <message>
        <source>Regions</source>
        <translation>Regionen</translation>
    </message>
    <message>
        <source>Region</source>
        <translation>Region</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Parts</source>
        <translation>Teile</translation>
    </message>
    <message>
        <source>Faces</source>
        <translation>Flächen</translation>
    </message>
    <message>
        <source>Fragments</source>
        <translation>Fragmente</translation>
    </message>
    <message>
        <source>Polygons in the region&apos;s BSP tree after clipping and splitting, as the solver builds it (fewer is better)</source>
        <translation>Polygone im BSP-Baum der Region nach Zuschneiden und Teilen, wie der Löser ihn aufbaut (weniger ist besser)</translation>
    </message>
    <message>
        <source>Node</source>
        <translation>Knoten</translation>
    </message>
    <message>
        <source>Side</source>
        <translation>Seite</translation>
    </message>
    <message>
        <source>Regional Tree</source>
        <translation>Regionenbaum</translation>
    </message>
    <message>
        <source>Accept</source>
        <translation>Übernehmen</translation>
    </message>
    <message>
        <source>Discard</source>
        <translation>Verwerfen</translation>
    </message>
    <message>
        <source>min %1, max %2</source>
        <translation>min %1, max %2</translation>
    </message>
    <message>
        <source>Overlaps %1: regions must not share volume</source>
        <translation>Überlappt %1: Regionen dürfen kein gemeinsames Volumen haben</translation>
    </message>
    <message>
        <source>Computing BSP figures…</source>
        <translation>BSP-Kennzahlen werden berechnet…</translation>
    </message>
    <message>
        <source>No BSP figures: the solver cannot prepare this scene (see Diagnostics).</source>
        <translation>Keine BSP-Kennzahlen: Der Löser kann diese Szene nicht vorbereiten (siehe Diagnose).</translation>
    </message>
    <message>
        <source>No regions: one BSP tree, %1 fragments, %2 splits, depth %3.</source>
        <translation>Keine Regionen: ein BSP-Baum, %1 Fragmente, %2 Teilungen, Tiefe %3.</translation>
    </message>
    <message>
        <source>%1 regions: %2 fragments, %3 splits, depth %4.</source>
        <translation>%1 Regionen: %2 Fragmente, %3 Teilungen, Tiefe %4.</translation>
    </message>
    <message>
        <source>Single BSP: %1 fragments, %2 splits, depth %3.</source>
        <translation>Einzelner BSP-Baum: %1 Fragmente, %2 Teilungen, Tiefe %3.</translation>
    </message>
    <message>
        <source>(updating…)</source>
        <translation>(wird aktualisiert…)</translation>
    </message>
    <message>
        <source>No regions: the whole scene is one BSP tree</source>
        <translation>Keine Regionen: Die ganze Szene ist ein BSP-Baum</translation>
    </message>
    <message>
        <source>No regional tree: the region boxes overlap or cannot be separated</source>
        <translation>Kein Regionenbaum: Die Regionsquader überlappen sich oder lassen sich nicht trennen</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>%1 = %2</source>
        <translation>%1 = %2</translation>
    </message>
    <message>
        <source>front (%1 ≥ %2)</source>
        <translation>vorne (%1 ≥ %2)</translation>
    </message>
    <message>
        <source>back (%1 ≤ %2)</source>
        <translation>hinten (%1 ≤ %2)</translation>
    </message>
</context>
<context>
    <name>regio::editor::SceneDocument</name>
    <message>
        <source>Untitled</source>
        <translation>Unbenannt</translation>
    </message>
    <message>
        <source>the scene has never been saved</source>
        <translation>die Szene wurde noch nie gespeichert</translation>
    </message>
</context>
<context>
    <name>regio::editor::SceneTreeDock</name>
    <message>
        <source>Scene</source>
        <translation>Szene</translation>
    </message>
    <message>
        <source>Filter by id or name</source>
        <translation>Nach ID oder Name filtern</translation>
    </message>
</context>
<context>
    <name>regio::editor::SceneTreeModel</name>
    <message numerus="yes">
        <source>%n vertices</source>
        <translation>
            <numerusform>%n Eckpunkt</numerusform>
            <numerusform>%n Eckpunkte</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 (part)</source>
        <translation>%1 (Teil)</translation>
    </message>
    <message>
        <source>Unknown material &quot;%1&quot;</source>
        <translation>Unbekanntes Material &quot;%1&quot;</translation>
    </message>
    <message>
        <source>Id</source>
        <translation>ID</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Material</source>
        <translation>Material</translation>
    </message>
</context>
<context>
    <name>regio::editor::ScreenshotRunner</name>
    <message>
        <source>no frame was rendered within %1 s</source>
        <translation>innerhalb von %1 s wurde kein Bild gerendert</translation>
    </message>
    <message>
        <source>the viewport cannot render: %1</source>
        <translation>die Ansicht kann nicht rendern: %1</translation>
    </message>
    <message>
        <source>the viewport&apos;s framebuffer could not be read</source>
        <translation>der Framebuffer der Ansicht konnte nicht gelesen werden</translation>
    </message>
</context>
<context>
    <name>regio::editor::SolverDock</name>
    <message>
        <source>Solver</source>
        <translation>Löser</translation>
    </message>
    <message>
        <source>Settings</source>
        <translation>Einstellungen</translation>
    </message>
    <message>
        <source>Custom</source>
        <translation>Benutzerdefiniert</translation>
    </message>
    <message>
        <source>Preset:</source>
        <translation>Voreinstellung:</translation>
    </message>
    <message>
        <source>Resolution of the hemicube&apos;s top face (the sides are half as high)</source>
        <translation>Auflösung der Oberseite des Hemicubes (die Seiten sind halb so hoch)</translation>
    </message>
    <message>
        <source>Hemicube:</source>
        <translation>Hemicube:</translation>
    </message>
    <message>
        <source> m</source>
        <translation> m</translation>
    </message>
    <message>
        <source>Patch size:</source>
        <translation>Patch-Größe:</translation>
    </message>
    <message>
        <source>Elements per patch:</source>
        <translation>Elemente pro Patch:</translation>
    </message>
    <message>
        <source>Adaptive subdivision</source>
        <translation>Adaptive Unterteilung</translation>
    </message>
    <message>
        <source>Relative radiosity difference to a neighbour that splits an element</source>
        <translation>Relativer Radiosity-Unterschied zu einem Nachbarn, ab dem ein Element geteilt wird</translation>
    </message>
    <message>
        <source>Threshold:</source>
        <translation>Schwellenwert:</translation>
    </message>
    <message>
        <source>Minimum edge:</source>
        <translation>Kürzeste Kante:</translation>
    </message>
    <message>
        <source>Anchor T-vertices</source>
        <translation>T-Eckpunkte verankern</translation>
    </message>
    <message>
        <source>Maximum iterations:</source>
        <translation>Maximale Iterationen:</translation>
    </message>
    <message>
        <source>Stop when the unshot power falls below this fraction of the emitted power</source>
        <translation>Anhalten, wenn die noch nicht abgestrahlte Leistung unter diesen Anteil der emittierten Leistung fällt</translation>
    </message>
    <message>
        <source>Convergence:</source>
        <translation>Konvergenz:</translation>
    </message>
    <message>
        <source>Painter (no z-buffer)</source>
        <translation>Maleralgorithmus (kein Z-Puffer)</translation>
    </message>
    <message>
        <source>Z-buffer</source>
        <translation>Z-Puffer</translation>
    </message>
    <message>
        <source>Visibility:</source>
        <translation>Sichtbarkeit:</translation>
    </message>
    <message>
        <source>Authored</source>
        <translation>Manuell erstellt</translation>
    </message>
    <message>
        <source>None (one BSP tree)</source>
        <translation>Keine (ein BSP-Baum)</translation>
    </message>
    <message>
        <source>Automatic</source>
        <translation>Automatisch</translation>
    </message>
    <message>
        <source>Regions:</source>
        <translation>Regionen:</translation>
    </message>
    <message>
        <source>Display</source>
        <translation>Darstellung</translation>
    </message>
    <message>
        <source> EV</source>
        <translation> EV</translation>
    </message>
    <message>
        <source>Exposure:</source>
        <translation>Belichtung:</translation>
    </message>
    <message>
        <source>Gamma:</source>
        <translation>Gamma:</translation>
    </message>
    <message>
        <source>Ambient term</source>
        <translation>Umgebungsterm</translation>
    </message>
    <message>
        <source>Show the not yet shot energy as a uniform ambient light (Cohen et al. 1988)</source>
        <translation>Die noch nicht abgestrahlte Energie als gleichmäßiges Umgebungslicht anzeigen (Cohen et al. 1988)</translation>
    </message>
    <message>
        <source>False colour</source>
        <translation>Falschfarben</translation>
    </message>
    <message>
        <source>Logarithmic</source>
        <translation>Logarithmisch</translation>
    </message>
    <message>
        <source>Linear</source>
        <translation>Linear</translation>
    </message>
    <message>
        <source>Element mesh</source>
        <translation>Elementnetz</translation>
    </message>
    <message>
        <source>Inspector</source>
        <translation>Inspektor</translation>
    </message>
    <message>
        <source>Turn on Inspect and click a surface of the solution.</source>
        <translation>Schalten Sie „Untersuchen“ ein und klicken Sie auf eine Oberfläche der Lösung.</translation>
    </message>
    <message>
        <source>White at exposure 0: %1 W/m²</source>
        <translation>Weiß bei Belichtung 0: %1 W/m²</translation>
    </message>
    <message>
        <source>Draw the element edges (where adaptive subdivision split elements) and, in orange (magenta on false colour), the edges anchoring adds to close T-vertices</source>
        <translation>Die Elementkanten zeichnen (wo die adaptive Unterteilung Elemente geteilt hat) und in Orange (Magenta bei Falschfarben) die Kanten, die die Verankerung zum Schließen von T-Eckpunkten hinzufügt</translation>
    </message>
</context>
<context>
    <name>regio::editor::Viewport</name>
    <message>
        <source>Clip: click three points on surfaces to define the cutting plane (Esc cancels)</source>
        <translation>Schneiden: Klicken Sie auf drei Punkte auf Oberflächen, um die Schnittebene festzulegen (Esc bricht ab)</translation>
    </message>
    <message>
        <source>OpenGL 3.3 is needed, this system offers %1.%2</source>
        <translation>OpenGL 3.3 wird benötigt, dieses System bietet %1.%2</translation>
    </message>
    <message>
        <source>The viewport shaders do not compile: %1</source>
        <translation>Die Shader der Ansicht lassen sich nicht kompilieren: %1</translation>
    </message>
    <message>
        <source>%1 › %2 › %3</source>
        <translation>%1 › %2 › %3</translation>
    </message>
    <message>
        <source>Cancelled</source>
        <translation>Abgebrochen</translation>
    </message>
</context>
</TS>
