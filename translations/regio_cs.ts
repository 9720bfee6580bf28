<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="cs_CZ">
<context>
    <name>SolverPresets</name>
    <message>
        <source>Draft</source>
        <translation>Náčrt</translation>
    </message>
    <message>
        <source>Normal</source>
        <translation>Běžné</translation>
    </message>
    <message>
        <source>Final</source>
        <translation>Finální</translation>
    </message>
    <message>
        <source>Hemicube: %1 x %1 (sides %1 x %2)</source>
        <translation>Polokrychle: %1 × %1 (boky %1 × %2)</translation>
    </message>
    <message>
        <source>Patch size: %1 m, %2 elements per patch</source>
        <translation>Velikost plošky: %1 m, %2 prvků na plošku</translation>
    </message>
    <message>
        <source>Stops after %1 iterations or below %2 % unshot</source>
        <translation>Skončí po %1 iteracích nebo pod %2 % nevyzářeného výkonu</translation>
    </message>
    <message>
        <source>Visibility: %1; regions: %2</source>
        <translation>Viditelnost: %1; oblasti: %2</translation>
    </message>
    <message>
        <source>Regions: %1; BSP fragments: %2 (%3 splits, depth %4)</source>
        <translation>Oblasti: %1; fragmenty BSP: %2 (%3 dělení, hloubka %4)</translation>
    </message>
    <message>
        <source>Patches: %1; elements: %2 (before adaptive subdivision)</source>
        <translation>Plošky: %1; prvky: %2 (před adaptivním dělením)</translation>
    </message>
    <message>
        <source>Prepared in %1 s</source>
        <translation>Připraveno za %1 s</translation>
    </message>
    <message>
        <source>The scene cannot be prepared:</source>
        <translation>Scénu nelze připravit:</translation>
    </message>
    <message>
        <source>error: %1</source>
        <translation>chyba: %1</translation>
    </message>
    <message>
        <source>warning: %1</source>
        <translation>varování: %1</translation>
    </message>
    <message>
        <source>Adaptive subdivision: threshold %1, shortest edge %2 m, anchoring %3</source>
        <translation>Adaptivní dělení: práh %1, nejkratší hrana %2 m, kotvení %3</translation>
    </message>
    <message>
        <source>on</source>
        <translation>zapnuto</translation>
    </message>
    <message>
        <source>off</source>
        <translation>vypnuto</translation>
    </message>
    <message>
        <source>Adaptive subdivision: off</source>
        <translation>Adaptivní dělení: vypnuto</translation>
    </message>
</context>
<context>
    <name>TransformGizmo</name>
    <message>
        <source>Move by (%1, %2, %3) m</source>
        <translation>Posun o (%1, %2, %3) m</translation>
    </message>
    <message>
        <source>Rotate by %1° about %2</source>
        <translation>Otočení o %1° kolem %2</translation>
    </message>
    <message>
        <source>Scale by %1</source>
        <translation>Změna měřítka %1×</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <source>cannot open %1:</source>
        <translation>nelze otevřít %1:</translation>
    </message>
    <message>
        <source>there is no display to open the editor&apos;s window on (DISPLAY is not set). Run it on a desktop, or with ssh -X.</source>
        <translation>není displej, na kterém by se otevřelo okno editoru (DISPLAY není nastaveno). Spusťte jej na ploše nebo přes ssh -X.</translation>
    </message>
    <message>
        <source>--screenshot draws the editor&apos;s window and needs a display, real or virtual: run it on a desktop or under Xvfb (xvfb-run -a regio --screenshot ...).</source>
        <translation>--screenshot kreslí okno editoru a potřebuje displej, skutečný nebo virtuální: spusťte jej na ploše nebo pod Xvfb (xvfb-run -a regio --screenshot ...).</translation>
    </message>
    <message>
        <source>there is no panel %1</source>
        <translation>panel %1 neexistuje</translation>
    </message>
</context>
<context>
    <name>regio::editor::Authoring</name>
    <message>
        <source>&amp;Material</source>
        <translation>&amp;Materiál</translation>
    </message>
    <message>
        <source>Add a new grey material</source>
        <translation>Přidat nový šedý materiál</translation>
    </message>
    <message>
        <source>&amp;Group</source>
        <translation>&amp;Seskupit</translation>
    </message>
    <message>
        <source>Put the selected parts (or objects) into one new object</source>
        <translation>Vložit vybrané části (nebo objekty) do jednoho nového objektu</translation>
    </message>
    <message>
        <source>&amp;Ungroup</source>
        <translation>Zr&amp;ušit seskupení</translation>
    </message>
    <message>
        <source>Make every part of the selected objects an object of its own</source>
        <translation>Udělat z každé části vybraných objektů samostatný objekt</translation>
    </message>
    <message>
        <source>Split Across &amp;X</source>
        <translation>Rozdělit napříč &amp;X</translation>
    </message>
    <message>
        <source>Split Across &amp;Y</source>
        <translation>Rozdělit napříč &amp;Y</translation>
    </message>
    <message>
        <source>Split Across &amp;Z</source>
        <translation>Rozdělit napříč &amp;Z</translation>
    </message>
    <message>
        <source>Cut the selected parts in two with a plane through the selection&apos;s centre</source>
        <translation>Rozříznout vybrané části na dvě rovinou procházející středem výběru</translation>
    </message>
    <message>
        <source>&amp;Clip Tool (Three Points)</source>
        <translation>Oř&amp;ezávací nástroj (tři body)</translation>
    </message>
    <message>
        <source>Click three points; the plane through them cuts the selected parts</source>
        <translation>Klikněte na tři body; rovina jimi proložená rozřízne vybrané části</translation>
    </message>
    <message>
        <source>Store View as Scene &amp;Camera</source>
        <translation>Uložit pohled jako &amp;kameru scény</translation>
    </message>
    <message>
        <source>Save the current view in the scene file</source>
        <translation>Uložit aktuální pohled do souboru scény</translation>
    </message>
    <message>
        <source>&amp;Navigation and Shortcuts</source>
        <translation>&amp;Navigace a klávesové zkratky</translation>
    </message>
    <message>
        <source>Navigation</source>
        <translation>Navigace</translation>
    </message>
    <message>
        <source>&lt;table&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Middle drag&lt;/b&gt; or &lt;b&gt;Alt+left drag&lt;/b&gt;&lt;/td&gt;&lt;td&gt;orbit&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Shift+middle&lt;/b&gt; or &lt;b&gt;Alt+Shift+left&lt;/b&gt;&lt;/td&gt;&lt;td&gt;pan&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Wheel&lt;/b&gt;, &lt;b&gt;Ctrl+middle&lt;/b&gt;, pinch&lt;/td&gt;&lt;td&gt;zoom&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Two-finger scroll&lt;/b&gt;&lt;/td&gt;&lt;td&gt;orbit (Shift: pan)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Right drag + W A S D Q E&lt;/b&gt;&lt;/td&gt;&lt;td&gt;fly (Shift: faster)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;F&lt;/b&gt; / &lt;b&gt;Home&lt;/b&gt;&lt;/td&gt;&lt;td&gt;frame selection / everything&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Keypad 1 3 7&lt;/b&gt; (Ctrl: opposite), &lt;b&gt;0&lt;/b&gt;, &lt;b&gt;5&lt;/b&gt;&lt;/td&gt;&lt;td&gt;front, right, top, isometric, orthographic&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;1 2 3&lt;/b&gt;&lt;/td&gt;&lt;td&gt;select objects, parts, faces&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;W E R&lt;/b&gt;&lt;/td&gt;&lt;td&gt;move, rotate, scale gizmo&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;C&lt;/b&gt;&lt;/td&gt;&lt;td&gt;clip tool: click three points&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Click&lt;/b&gt;, &lt;b&gt;Ctrl+click&lt;/b&gt;&lt;/td&gt;&lt;td&gt;select, add or remove&lt;/td&gt;&lt;/tr&gt;&lt;/table&gt;</source>
        <translation>&lt;table&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Tažení prostředním tlačítkem&lt;/b&gt; nebo &lt;b&gt;Alt+levým&lt;/b&gt;&lt;/td&gt;&lt;td&gt;kroužení&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Shift+prostřední&lt;/b&gt; nebo &lt;b&gt;Alt+Shift+levé&lt;/b&gt;&lt;/td&gt;&lt;td&gt;posun pohledu&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Kolečko&lt;/b&gt;, &lt;b&gt;Ctrl+prostřední&lt;/b&gt;, sevření prstů&lt;/td&gt;&lt;td&gt;přiblížení&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Posun dvěma prsty&lt;/b&gt;&lt;/td&gt;&lt;td&gt;kroužení (Shift: posun)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Tažení pravým + W A S D Q E&lt;/b&gt;&lt;/td&gt;&lt;td&gt;let (Shift: rychleji)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;F&lt;/b&gt; / &lt;b&gt;Home&lt;/b&gt;&lt;/td&gt;&lt;td&gt;zaměřit výběr / vše&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Numerická 1 3 7&lt;/b&gt; (Ctrl: opačně), &lt;b&gt;0&lt;/b&gt;, &lt;b&gt;5&lt;/b&gt;&lt;/td&gt;&lt;td&gt;zepředu, zprava, shora, izometricky, ortograficky&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;1 2 3&lt;/b&gt;&lt;/td&gt;&lt;td&gt;vybírat objekty, části, stěny&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;W E R&lt;/b&gt;&lt;/td&gt;&lt;td&gt;manipulátor posunu, otočení, měřítka&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;C&lt;/b&gt;&lt;/td&gt;&lt;td&gt;ořezávací nástroj: klikněte na tři body&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Klik&lt;/b&gt;, &lt;b&gt;Ctrl+klik&lt;/b&gt;&lt;/td&gt;&lt;td&gt;vybrat, přidat nebo odebrat&lt;/td&gt;&lt;/tr&gt;&lt;/table&gt;</translation>
    </message>
    <message>
        <source>Assign &amp;Material</source>
        <translation>Přiřadit mate&amp;riál</translation>
    </message>
    <message>
        <source>No materials</source>
        <translation>Žádné materiály</translation>
    </message>
    <message>
        <source>Select the parts or objects to cut first</source>
        <translation>Nejprve vyberte části nebo objekty, které se mají rozříznout</translation>
    </message>
    <message>
        <source>Rename</source>
        <translation>Přejmenovat</translation>
    </message>
    <message>
        <source>&amp;Id:</source>
        <translation>&amp;Id:</translation>
    </message>
    <message>
        <source>&amp;Name:</source>
        <translation>&amp;Název:</translation>
    </message>
    <message>
        <source>Ids are what files and BSP orders refer to; names are for people.</source>
        <translation>Na id se odkazují soubory a pořadí BSP; názvy jsou pro lidi.</translation>
    </message>
    <message>
        <source>Duplicate</source>
        <translation>Zdvojit</translation>
    </message>
    <message numerus="yes">
        <source>Delete %n object(s)</source>
        <translation>
            <numerusform>Smazat %n objekt</numerusform>
            <numerusform>Smazat %n objekty</numerusform>
            <numerusform>Smazat %n objektů</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Delete %n part(s)</source>
        <translation>
            <numerusform>Smazat %n část</numerusform>
            <numerusform>Smazat %n části</numerusform>
            <numerusform>Smazat %n částí</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Delete %n material(s)</source>
        <translation>
            <numerusform>Smazat %n materiál</numerusform>
            <numerusform>Smazat %n materiály</numerusform>
            <numerusform>Smazat %n materiálů</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Delete %n region(s)</source>
        <translation>
            <numerusform>Smazat %n oblast</numerusform>
            <numerusform>Smazat %n oblasti</numerusform>
            <numerusform>Smazat %n oblastí</numerusform>
        </translation>
    </message>
    <message>
        <source>faces cannot be deleted on their own; split or delete the part</source>
        <translation>stěny nelze mazat samostatně; rozdělte nebo smažte celou část</translation>
    </message>
    <message>
        <source>Rename %1</source>
        <translation>Přejmenovat %1</translation>
    </message>
    <message>
        <source>Ungroup</source>
        <translation>Zrušit seskupení</translation>
    </message>
    <message>
        <source>the plane does not cross any selected part</source>
        <translation>rovina neprochází žádnou vybranou částí</translation>
    </message>
    <message numerus="yes">
        <source>Split %n part(s)</source>
        <translation>
            <numerusform>Rozdělit %n část</numerusform>
            <numerusform>Rozdělit %n části</numerusform>
            <numerusform>Rozdělit %n částí</numerusform>
        </translation>
    </message>
    <message>
        <source>Assign %1</source>
        <translation>Přiřadit %1</translation>
    </message>
    <message numerus="yes">
        <source>Transform %n part(s)</source>
        <translation>
            <numerusform>Transformovat %n část</numerusform>
            <numerusform>Transformovat %n části</numerusform>
            <numerusform>Transformovat %n částí</numerusform>
        </translation>
    </message>
    <message>
        <source>New object: %1</source>
        <translation>Nový objekt: %1</translation>
    </message>
</context>
<context>
    <name>regio::editor::Autosave</name>
    <message>
        <source>Autosave to %1 failed: %2</source>
        <translation>Automatické uložení do %1 selhalo: %2</translation>
    </message>
</context>
<context>
    <name>regio::editor::BspAuthoring</name>
    <message>
        <source>&amp;Suggest Order</source>
        <translation>&amp;Navrhnout pořadí</translation>
    </message>
    <message>
        <source>Compute a low-split root order for the region and compare it with the current one</source>
        <translation>Spočítat pořadí kořenů s málo děleními a porovnat je se současným</translation>
    </message>
    <message>
        <source>&amp;Apply Suggested Order</source>
        <translation>&amp;Použít navržené pořadí</translation>
    </message>
    <message>
        <source>&amp;Discard Suggested Order</source>
        <translation>&amp;Zahodit navržené pořadí</translation>
    </message>
    <message>
        <source>Show &amp;Fragments</source>
        <translation>Zobrazit &amp;fragmenty</translation>
    </message>
    <message>
        <source>Draw the region&apos;s BSP fragments: splits orange, region cuts cyan</source>
        <translation>Kreslit fragmenty BSP oblasti: dělení oranžově, řezy oblastí azurově</translation>
    </message>
    <message>
        <source>&amp;Pick Face to Insert</source>
        <translation>&amp;Vybrat stěnu k vložení</translation>
    </message>
    <message>
        <source>Click faces in the viewport to add them to the region&apos;s BSP order</source>
        <translation>Klepnutím na stěny v pohledu je přidáte do pořadí BSP oblasti</translation>
    </message>
    <message>
        <source>Insert &amp;Selected Faces</source>
        <translation>Vložit vy&amp;brané stěny</translation>
    </message>
    <message>
        <source>Painter Order from &amp;Point…</source>
        <translation>Malířovo pořadí z &amp;bodu…</translation>
    </message>
    <message>
        <source>Click a surface: the elements are painted in the solver&apos;s back-to-front order from there</source>
        <translation>Klepněte na povrch: prvky se vykreslí v pořadí řešiče odzadu dopředu z tohoto místa</translation>
    </message>
    <message>
        <source>Painter Order from Pa&amp;tch…</source>
        <translation>Malířovo pořadí z p&amp;lošky…</translation>
    </message>
    <message>
        <source>Click a surface: the patch there shoots, as in the solver</source>
        <translation>Klepněte na povrch: ploška v tom místě vyzařuje jako v řešiči</translation>
    </message>
    <message>
        <source>S&amp;top Painter Order</source>
        <translation>&amp;Ukončit malířovo pořadí</translation>
    </message>
    <message>
        <source>%1 is already in the BSP order of %2</source>
        <translation>%1 už je v pořadí BSP oblasti %2</translation>
    </message>
    <message>
        <source>%1 is not inside region %2</source>
        <translation>%1 neleží v oblasti %2</translation>
    </message>
    <message>
        <source>Added %1 to the BSP order of %2</source>
        <translation>%1 přidáno do pořadí BSP oblasti %2</translation>
    </message>
    <message>
        <source>No selected face can be added to the BSP order of %1</source>
        <translation>Žádnou vybranou stěnu nelze přidat do pořadí BSP oblasti %1</translation>
    </message>
    <message numerus="yes">
        <source>Add %n face(s) to the BSP order of %1</source>
        <translation>
            <numerusform>Přidat %n stěnu do pořadí BSP oblasti %1</numerusform>
            <numerusform>Přidat %n stěny do pořadí BSP oblasti %1</numerusform>
            <numerusform>Přidat %n stěn do pořadí BSP oblasti %1</numerusform>
        </translation>
    </message>
    <message>
        <source>No suggestion: %1</source>
        <translation>Žádný návrh: %1</translation>
    </message>
    <message>
        <source>Click faces to add them to the BSP order of %1; Esc ends</source>
        <translation>Klepnutím na stěny je přidáte do pořadí BSP oblasti %1; Esc končí</translation>
    </message>
    <message>
        <source>Click a surface: its patch shoots</source>
        <translation>Klepněte na povrch: jeho ploška vyzařuje</translation>
    </message>
    <message>
        <source>Click a surface to paint from there</source>
        <translation>Klepněte na povrch, odkud se má kreslit</translation>
    </message>
    <message>
        <source>The scene cannot be prepared; see the diagnostics</source>
        <translation>Scénu nelze připravit; viz diagnostiku</translation>
    </message>
    <message numerus="yes">
        <source>Painter order: %n element(s), back to front</source>
        <translation>
            <numerusform>Malířovo pořadí: %n prvek, odzadu dopředu</numerusform>
            <numerusform>Malířovo pořadí: %n prvky, odzadu dopředu</numerusform>
            <numerusform>Malířovo pořadí: %n prvků, odzadu dopředu</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>regio::editor::BspOrderDock</name>
    <message>
        <source>BSP Order</source>
        <translation>Pořadí BSP</translation>
    </message>
    <message>
        <source>Region:</source>
        <translation>Oblast:</translation>
    </message>
    <message>
        <source>The region whose BSP root order is edited (also chosen by selecting a region)</source>
        <translation>Oblast, jejíž pořadí kořenů BSP se upravuje (volí se i výběrem oblasti)</translation>
    </message>
    <message>
        <source>Faces used as BSP roots, first = root of the region&apos;s tree; drag to reorder</source>
        <translation>Stěny použité jako kořeny BSP, první = kořen stromu oblasti; přetažením změníte pořadí</translation>
    </message>
    <message>
        <source>Move to Top</source>
        <translation>Přesunout nahoru</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Odebrat</translation>
    </message>
    <message>
        <source>Pick in Viewport</source>
        <translation>Vybrat v pohledu</translation>
    </message>
    <message>
        <source>Click faces in the viewport to add them at the end of the order; Esc ends</source>
        <translation>Klepnutím na stěny v pohledu je přidáte na konec pořadí; Esc končí</translation>
    </message>
    <message>
        <source>Insert Selected</source>
        <translation>Vložit vybrané</translation>
    </message>
    <message>
        <source>Region</source>
        <translation>Oblast</translation>
    </message>
    <message>
        <source>Scene</source>
        <translation>Scéna</translation>
    </message>
    <message>
        <source>Single BSP</source>
        <translation>Jediný BSP</translation>
    </message>
    <message>
        <source>Suggested region</source>
        <translation>Navržená oblast</translation>
    </message>
    <message>
        <source>Suggested scene</source>
        <translation>Navržená scéna</translation>
    </message>
    <message>
        <source>Fragments</source>
        <translation>Fragmenty</translation>
    </message>
    <message>
        <source>Splits</source>
        <translation>Dělení</translation>
    </message>
    <message>
        <source>Depth</source>
        <translation>Hloubka</translation>
    </message>
    <message>
        <source>Fragments after region clipping and BSP splits, polygons split, longest root-to-leaf path; Single BSP is the whole scene as one tree without regions</source>
        <translation>Fragmenty po ořezu oblastmi a dělení BSP, rozdělené mnohoúhelníky, nejdelší cesta od kořene k listu; Jediný BSP je celá scéna jako jeden strom bez oblastí</translation>
    </message>
    <message>
        <source>Suggest Order</source>
        <translation>Navrhnout pořadí</translation>
    </message>
    <message>
        <source>Greedy low-split, balanced root order (Thibault and Naylor), shown before it is applied</source>
        <translation>Hladové vyvážené pořadí kořenů s málo děleními (Thibault a Naylor), zobrazené před použitím</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>Použít</translation>
    </message>
    <message>
        <source>Discard</source>
        <translation>Zahodit</translation>
    </message>
    <message>
        <source>Order</source>
        <translation>Pořadí</translation>
    </message>
    <message>
        <source>Show fragments and split lines in the viewport</source>
        <translation>Zobrazit fragmenty a dělicí čáry v pohledu</translation>
    </message>
    <message>
        <source>Root face</source>
        <translation>Kořenová stěna</translation>
    </message>
    <message>
        <source>The region&apos;s BSP tree: each node&apos;s plane is its root face&apos;s; select a node to see its plane</source>
        <translation>Strom BSP oblasti: rovina každého uzlu je rovinou jeho kořenové stěny; vyberte uzel a uvidíte jeho rovinu</translation>
    </message>
    <message>
        <source>Tree</source>
        <translation>Strom</translation>
    </message>
    <message>
        <source>Pick a point or a patch: the elements are painted in the order the solver&apos;s hemicube paints them from there, back to front (blue first, red last; grey: seen from behind, painted as blockers).</source>
        <translation>Vyberte bod nebo plošku: prvky se vykreslí v pořadí, v jakém je odtud kreslí polokrychle řešiče, odzadu dopředu (modré první, červené poslední; šedé: viděné zezadu, kreslené jako překážky).</translation>
    </message>
    <message>
        <source>From Point…</source>
        <translation>Z bodu…</translation>
    </message>
    <message>
        <source>From Patch…</source>
        <translation>Z plošky…</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Zastavit</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>Přehrát</translation>
    </message>
    <message>
        <source>Elements painted so far</source>
        <translation>Dosud vykreslené prvky</translation>
    </message>
    <message>
        <source>Painter Order</source>
        <translation>Malířovo pořadí</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>Updating…</source>
        <translation>Aktualizuje se…</translation>
    </message>
    <message>
        <source>The scene cannot be prepared: %1</source>
        <translation>Scénu nelze připravit: %1</translation>
    </message>
    <message>
        <source>Computed by the solver&apos;s preparation in %1 ms</source>
        <translation>Spočítáno přípravou řešiče za %1 ms</translation>
    </message>
    <message numerus="yes">
        <source>Suggested order: %n root face(s). Apply replaces the region&apos;s order (one undo step).</source>
        <translation>
            <numerusform>Navržené pořadí: %n kořenová stěna. Použít nahradí pořadí oblasti (jeden krok zpět).</numerusform>
            <numerusform>Navržené pořadí: %n kořenové stěny. Použít nahradí pořadí oblasti (jeden krok zpět).</numerusform>
            <numerusform>Navržené pořadí: %n kořenových stěn. Použít nahradí pořadí oblasti (jeden krok zpět).</numerusform>
        </translation>
    </message>
    <message>
        <source>No tree for this region</source>
        <translation>Tato oblast nemá strom</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>back</source>
        <translation>vzadu</translation>
    </message>
    <message>
        <source>front</source>
        <translation>vpředu</translation>
    </message>
    <message>
        <source>%1 nodes, depth %2, %3 fragments from %4 polygons</source>
        <translation>%1 uzlů, hloubka %2, %3 fragmentů z %4 mnohoúhelníků</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pozastavit</translation>
    </message>
    <message>
        <source>No playback</source>
        <translation>Žádné přehrávání</translation>
    </message>
    <message>
        <source>From patch %1</source>
        <translation>Z plošky %1</translation>
    </message>
    <message>
        <source>From point (%1, %2, %3)</source>
        <translation>Z bodu (%1, %2, %3)</translation>
    </message>
    <message>
        <source>%1 regions walked, %2 culled, %3 nodes, %4 elements</source>
        <translation>%1 prošlých oblastí, %2 vyřazených, %3 uzlů, %4 prvků</translation>
    </message>
    <message>
        <source>Step %1: element %2 of node %3, receiving</source>
        <translation>Krok %1: prvek %2 uzlu %3, přijímá</translation>
    </message>
    <message>
        <source>Step %1: element %2 of node %3, blocking (seen from behind)</source>
        <translation>Krok %1: prvek %2 uzlu %3, stíní (viděn zezadu)</translation>
    </message>
</context>
<context>
    <name>regio::editor::ColourButton</name>
    <message>
        <source>Pick a colour</source>
        <translation>Vybrat barvu</translation>
    </message>
</context>
<context>
    <name>regio::editor::CommandLine</name>
    <message>
        <source>Regio: an editor for radiosity scenes with regions and BSP orders.</source>
        <translation>Regio: editor scén pro radiozitu s oblastmi a pořadím BSP.</translation>
    </message>
    <message>
        <source>Show the scene, save a picture of the window to &lt;file&gt; and exit.</source>
        <translation>Zobrazit scénu, uložit obrázek okna do &lt;file&gt; a skončit.</translation>
    </message>
    <message>
        <source>Window size, for example 1280x800.</source>
        <translation>Velikost okna, například 1280x800.</translation>
    </message>
    <message>
        <source>The scene file to open (.json).</source>
        <translation>Soubor scény, který se má otevřít (.json).</translation>
    </message>
    <message>
        <source>only one scene file can be opened, got %1</source>
        <translation>lze otevřít jen jeden soubor scény, zadáno %1</translation>
    </message>
    <message>
        <source>--screenshot needs a file name</source>
        <translation>--screenshot potřebuje název souboru</translation>
    </message>
    <message>
        <source>--size wants WIDTHxHEIGHT in pixels (64 to 16384), got &quot;%1&quot;</source>
        <translation>--size očekává ŠÍŘKAxVÝŠKA v pixelech (64 až 16384), zadáno „%1“</translation>
    </message>
    <message>
        <source>With --screenshot: solve the radiosity preview with exactly &lt;n&gt; shooting steps first and show it.</source>
        <translation>S --screenshot: nejprve spočítat náhled radiozity přesně s &lt;n&gt; kroky vyzařování a zobrazit ho.</translation>
    </message>
    <message>
        <source>--preview-iterations wants a number of shooting steps (0 or more), got &quot;%1&quot;</source>
        <translation>--preview-iterations očekává počet kroků vyzařování (0 nebo více), dostal „%1“</translation>
    </message>
    <message>
        <source>--preview-iterations needs --screenshot</source>
        <translation>--preview-iterations vyžaduje --screenshot</translation>
    </message>
    <message>
        <source>User interface language for this run (en, cs, de).</source>
        <translation>Jazyk uživatelského rozhraní pro toto spuštění (en, cs, de).</translation>
    </message>
    <message>
        <source>With --screenshot: bring the panel &lt;name&gt; to the front first (Materials, Regions, BspOrder, Solver, Properties).</source>
        <translation>S --screenshot: nejprve přenést do popředí panel &lt;name&gt; (Materials, Regions, BspOrder, Solver, Properties).</translation>
    </message>
</context>
<context>
    <name>regio::editor::Commands</name>
    <message>
        <source>Set BSP order of %1</source>
        <translation>Nastavit pořadí BSP oblasti %1</translation>
    </message>
    <message>
        <source>Add %1 to the BSP order of %2</source>
        <translation>Přidat %1 do pořadí BSP oblasti %2</translation>
    </message>
    <message>
        <source>Remove entry %1 from the BSP order of %2</source>
        <translation>Odebrat položku %1 z pořadí BSP oblasti %2</translation>
    </message>
    <message>
        <source>Move BSP entry %1 of %2 to %3</source>
        <translation>Přesunout položku BSP %1 oblasti %2 na %3</translation>
    </message>
    <message>
        <source>Add material %1</source>
        <translation>Přidat materiál %1</translation>
    </message>
    <message>
        <source>Delete material %1</source>
        <translation>Smazat materiál %1</translation>
    </message>
    <message>
        <source>Rename %1 to %2</source>
        <translation>Přejmenovat %1 na %2</translation>
    </message>
    <message>
        <source>Name %1 &quot;%2&quot;</source>
        <translation>Pojmenovat %1 „%2“</translation>
    </message>
    <message>
        <source>Reflectance of %1</source>
        <translation>Odrazivost materiálu %1</translation>
    </message>
    <message>
        <source>Emission of %1</source>
        <translation>Vyzařování materiálu %1</translation>
    </message>
    <message>
        <source>Add %1</source>
        <translation>Přidat %1</translation>
    </message>
    <message>
        <source>Delete %1</source>
        <translation>Smazat %1</translation>
    </message>
    <message>
        <source>Duplicate %1</source>
        <translation>Zdvojit %1</translation>
    </message>
    <message numerus="yes">
        <source>Group %n part(s)</source>
        <translation>
            <numerusform>Seskupit %n část</numerusform>
            <numerusform>Seskupit %n části</numerusform>
            <numerusform>Seskupit %n částí</numerusform>
        </translation>
    </message>
    <message>
        <source>Group objects into %1</source>
        <translation>Seskupit objekty do %1</translation>
    </message>
    <message>
        <source>Ungroup %1</source>
        <translation>Zrušit seskupení %1</translation>
    </message>
    <message>
        <source>Make parts separate objects</source>
        <translation>Udělat z částí samostatné objekty</translation>
    </message>
    <message>
        <source>Move parts to %1</source>
        <translation>Přesunout části do %1</translation>
    </message>
    <message>
        <source>Material of %1: %2</source>
        <translation>Materiál %1: %2</translation>
    </message>
    <message>
        <source>Material of %1: the part&apos;s</source>
        <translation>Materiál %1: podle části</translation>
    </message>
    <message>
        <source>Move %1 to %2</source>
        <translation>Přesunout %1 do %2</translation>
    </message>
    <message numerus="yes">
        <source>Transform %n part(s)</source>
        <translation>
            <numerusform>Transformovat %n část</numerusform>
            <numerusform>Transformovat %n části</numerusform>
            <numerusform>Transformovat %n částí</numerusform>
        </translation>
    </message>
    <message>
        <source>Split %1</source>
        <translation>Rozdělit %1</translation>
    </message>
    <message>
        <source>Add region %1</source>
        <translation>Přidat oblast %1</translation>
    </message>
    <message>
        <source>Delete region %1</source>
        <translation>Smazat oblast %1</translation>
    </message>
    <message>
        <source>Resize region %1</source>
        <translation>Změnit velikost oblasti %1</translation>
    </message>
    <message>
        <source>Change solver settings</source>
        <translation>Změnit nastavení řešiče</translation>
    </message>
    <message>
        <source>Store the view as the scene camera</source>
        <translation>Uložit pohled jako kameru scény</translation>
    </message>
    <message>
        <source>Clear the scene camera</source>
        <translation>Odstranit kameru scény</translation>
    </message>
    <message>
        <source>Clip %1 to regions</source>
        <translation>Oříznout %1 podle oblastí</translation>
    </message>
</context>
<context>
    <name>regio::editor::ConvergenceDock</name>
    <message>
        <source>Convergence</source>
        <translation>Konvergence</translation>
    </message>
    <message>
        <source>unshot</source>
        <translation>nevyzářeno</translation>
    </message>
    <message>
        <source>absorbed</source>
        <translation>pohlceno</translation>
    </message>
    <message>
        <source>escaped</source>
        <translation>uniklo</translation>
    </message>
    <message>
        <source>balance error</source>
        <translation>chyba bilance</translation>
    </message>
    <message>
        <source>iteration</source>
        <translation>iterace</translation>
    </message>
    <message>
        <source>fraction of emitted power</source>
        <translation>podíl vyzářeného výkonu</translation>
    </message>
</context>
<context>
    <name>regio::editor::DiagnosticsDock</name>
    <message>
        <source>Diagnostics</source>
        <translation>Diagnostika</translation>
    </message>
    <message>
        <source>The scene is valid.</source>
        <translation>Scéna je v pořádku.</translation>
    </message>
    <message numerus="yes">
        <source>%n error(s)</source>
        <translation>
            <numerusform>%n chyba</numerusform>
            <numerusform>%n chyby</numerusform>
            <numerusform>%n chyb</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n warning(s)</source>
        <translation>
            <numerusform>%n varování</numerusform>
            <numerusform>%n varování</numerusform>
            <numerusform>%n varování</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>regio::editor::DiagnosticsModel</name>
    <message>
        <source>line %1, column %2</source>
        <translation>řádek %1, sloupec %2</translation>
    </message>
    <message>
        <source>(whole scene)</source>
        <translation>(celá scéna)</translation>
    </message>
    <message>
        <source>Error</source>
        <translation>Chyba</translation>
    </message>
    <message>
        <source>Warning</source>
        <translation>Varování</translation>
    </message>
    <message>
        <source>Severity</source>
        <translation>Závažnost</translation>
    </message>
    <message>
        <source>Where</source>
        <translation>Kde</translation>
    </message>
    <message>
        <source>Problem</source>
        <translation>Problém</translation>
    </message>
    <message>
        <source>material %1</source>
        <translation>materiál %1</translation>
    </message>
    <message>
        <source>object %1</source>
        <translation>objekt %1</translation>
    </message>
    <message>
        <source>part %1</source>
        <translation>část %1</translation>
    </message>
    <message>
        <source>face %1</source>
        <translation>stěna %1</translation>
    </message>
    <message>
        <source>region %1</source>
        <translation>oblast %1</translation>
    </message>
</context>
<context>
    <name>regio::editor::HemicubeDialog</name>
    <message>
        <source>Hemicube</source>
        <translation>Polokrychle</translation>
    </message>
    <message>
        <source>Face %1</source>
        <translation>Stěna %1</translation>
    </message>
    <message>
        <source>Patch %1 of face %2, %3 x %3 pixels: %4 elements seen; %5 % of the form factor escapes, %6 % falls on back faces (black: nothing, grey: back faces).</source>
        <translation>Ploška %1 stěny %2, %3 × %3 pixelů: viditelných prvků %4; %5 % konfiguračního faktoru uniká, %6 % dopadá na odvrácené stěny (černá: nic, šedá: odvrácené stěny).</translation>
    </message>
</context>
<context>
    <name>regio::editor::ImageFile</name>
    <message>
        <source>cannot write %1: %2</source>
        <translation>nelze zapsat %1: %2</translation>
    </message>
</context>
<context>
    <name>regio::editor::ImportDialog</name>
    <message>
        <source>error: </source>
        <translation>chyba: </translation>
    </message>
    <message>
        <source>warning: </source>
        <translation>varování: </translation>
    </message>
    <message>
        <source>Import %1</source>
        <translation>Import %1</translation>
    </message>
    <message>
        <source>Metres per model unit: 0.001 for a model in millimetres</source>
        <translation>Metrů na jednotku modelu: 0,001 pro model v milimetrech</translation>
    </message>
    <message>
        <source>Y is up</source>
        <translation>Y míří vzhůru</translation>
    </message>
    <message>
        <source>Z is up</source>
        <translation>Z míří vzhůru</translation>
    </message>
    <message>
        <source> °</source>
        <translation> °</translation>
    </message>
    <message>
        <source>Triangles whose normals differ by at most this angle merge into one face</source>
        <translation>Trojúhelníky, jejichž normály se liší nejvýše o tento úhel, se sloučí do jedné stěny</translation>
    </message>
    <message>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <source>Corners this close are welded; corners this close to a plane lie in it</source>
        <translation>Takto blízké rohy se svaří; takto blízké rohy k rovině v ní leží</translation>
    </message>
    <message>
        <source>Propose regions and BSP orders</source>
        <translation>Navrhnout oblasti a pořadí BSP</translation>
    </message>
    <message>
        <source>As a new scene</source>
        <translation>Jako novou scénu</translation>
    </message>
    <message>
        <source>Into the open scene (one undo step)</source>
        <translation>Do otevřené scény (jeden krok zpět)</translation>
    </message>
    <message>
        <source>Scale:</source>
        <translation>Měřítko:</translation>
    </message>
    <message>
        <source>Up axis:</source>
        <translation>Osa vzhůru:</translation>
    </message>
    <message>
        <source>Merge angle:</source>
        <translation>Úhel slučování:</translation>
    </message>
    <message>
        <source>Merge distance:</source>
        <translation>Vzdálenost slučování:</translation>
    </message>
    <message>
        <source>Import:</source>
        <translation>Importovat:</translation>
    </message>
    <message>
        <source>Import</source>
        <translation>Importovat</translation>
    </message>
    <message>
        <source>Importing %1…</source>
        <translation>Importuje se %1…</translation>
    </message>
    <message>
        <source>The model cannot be imported (the reasons are below).</source>
        <translation>Model nelze importovat (důvody jsou níže).</translation>
    </message>
    <message>
        <source>%1 triangles into %2 faces; %3 objects, %4 parts (%5 closed), %6 materials, %7 emitting faces.</source>
        <translation>Trojúhelníky: %1, z nich stěny: %2; objekty: %3, části: %4 (uzavřené: %5), materiály: %6, vyzařující stěny: %7.</translation>
    </message>
    <message>
        <source>Left out: %1 triangles of no area, %2 repeated, %3 points or lines.</source>
        <translation>Vynecháno: trojúhelníky bez plochy: %1, opakované: %2, body a čáry: %3.</translation>
    </message>
    <message>
        <source>Regions: %1; BSP fragments: %2 (one BSP tree: %3).</source>
        <translation>Oblasti: %1; fragmenty BSP: %2 (jeden strom BSP: %3).</translation>
    </message>
</context>
<context>
    <name>regio::editor::LegendWidget</name>
    <message>
        <source>False colour: luminance of the displayed radiosity, W/m²</source>
        <translation>Nepravé barvy: jas zobrazené radiozity, W/m²</translation>
    </message>
</context>
<context>
    <name>regio::editor::MainWindow</name>
    <message>
        <source>Refused: %1</source>
        <translation>Odmítnuto: %1</translation>
    </message>
    <message>
        <source>Viewport</source>
        <translation>Pohled</translation>
    </message>
    <message>
        <source>No problems</source>
        <translation>Bez problémů</translation>
    </message>
    <message numerus="yes">
        <source>%n error(s)</source>
        <translation>
            <numerusform>%n chyba</numerusform>
            <numerusform>%n chyby</numerusform>
            <numerusform>%n chyb</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n warning(s)</source>
        <translation>
            <numerusform>%n varování</numerusform>
            <numerusform>%n varování</numerusform>
            <numerusform>%n varování</numerusform>
        </translation>
    </message>
    <message>
        <source>History</source>
        <translation>Historie</translation>
    </message>
    <message>
        <source>&lt;opened scene&gt;</source>
        <translation>&lt;otevřená scéna&gt;</translation>
    </message>
    <message>
        <source>Preferences</source>
        <translation>Předvolby</translation>
    </message>
    <message>
        <source>The new language takes effect when Regio is started again.</source>
        <translation>Nový jazyk se projeví při příštím spuštění Regia.</translation>
    </message>
    <message>
        <source>%1[*] — Regio</source>
        <translation>%1[*] — Regio</translation>
    </message>
    <message>
        <source>%1 objects, %2 parts, %3 faces, %4 materials, %5 regions</source>
        <translation>objekty: %1, části: %2, stěny: %3, materiály: %4, oblasti: %5</translation>
    </message>
    <message>
        <source>Unsaved changes</source>
        <translation>Neuložené změny</translation>
    </message>
    <message>
        <source>The scene &quot;%1&quot; has unsaved changes. Save them?</source>
        <translation>Scéna „%1“ obsahuje neuložené změny. Uložit je?</translation>
    </message>
    <message>
        <source>New scene</source>
        <translation>Nová scéna</translation>
    </message>
    <message>
        <source>Open Scene</source>
        <translation>Otevřít scénu</translation>
    </message>
    <message>
        <source>Regio scenes (*.json);;All files (*)</source>
        <translation>Scény Regio (*.json);;Všechny soubory (*)</translation>
    </message>
    <message>
        <source>Opened %1</source>
        <translation>Otevřeno %1</translation>
    </message>
    <message>
        <source>Could not open %1</source>
        <translation>Nelze otevřít %1</translation>
    </message>
    <message>
        <source>Cannot open scene</source>
        <translation>Scénu nelze otevřít</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt; could not be opened. The scene you are editing is unchanged.</source>
        <translation>Soubor &lt;b&gt;%1&lt;/b&gt; nelze otevřít. Upravovaná scéna zůstala beze změny.</translation>
    </message>
    <message>
        <source>Save failed</source>
        <translation>Uložení selhalo</translation>
    </message>
    <message>
        <source>The scene could not be saved to %1:
%2
The file on disk is unchanged.</source>
        <translation>Scénu nelze uložit do %1:
%2
Soubor na disku zůstal beze změny.</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>Uloženo %1</translation>
    </message>
    <message>
        <source>Save Scene As</source>
        <translation>Uložit scénu jako</translation>
    </message>
    <message>
        <source>untitled.json</source>
        <translation>bez-nazvu.json</translation>
    </message>
    <message>
        <source>Regio scenes (*.json)</source>
        <translation>Scény Regio (*.json)</translation>
    </message>
    <message>
        <source>Revert</source>
        <translation>Vrátit</translation>
    </message>
    <message>
        <source>Drop every change since &quot;%1&quot; was last saved?</source>
        <translation>Zahodit všechny změny od posledního uložení „%1“?</translation>
    </message>
    <message>
        <source>Open Recent</source>
        <translation>Otevřít nedávné</translation>
    </message>
    <message>
        <source>%1 no longer exists.</source>
        <translation>%1 už neexistuje.</translation>
    </message>
    <message>
        <source>&amp;%1 %2</source>
        <translation>&amp;%1 %2</translation>
    </message>
    <message>
        <source>No recent files</source>
        <translation>Žádné nedávné soubory</translation>
    </message>
    <message>
        <source>Clear List</source>
        <translation>Vymazat seznam</translation>
    </message>
    <message>
        <source>an unsaved scene</source>
        <translation>neuložené scéně</translation>
    </message>
    <message>
        <source>Recover Scene</source>
        <translation>Obnovit scénu</translation>
    </message>
    <message>
        <source>Regio did not shut down cleanly. Changes to %1 were autosaved on %2.</source>
        <translation>Regio nebylo řádně ukončeno. Změny v %1 byly automaticky uloženy %2.</translation>
    </message>
    <message>
        <source>Restore them? Discarding deletes the autosaved copy.</source>
        <translation>Obnovit je? Zahozením se automaticky uložená kopie smaže.</translation>
    </message>
    <message>
        <source>Restore</source>
        <translation>Obnovit</translation>
    </message>
    <message>
        <source>Later</source>
        <translation>Později</translation>
    </message>
    <message>
        <source>The autosaved scene cannot be read: %1</source>
        <translation>Automaticky uloženou scénu nelze přečíst: %1</translation>
    </message>
    <message>
        <source>Recovered autosaved changes; save to keep them.</source>
        <translation>Automaticky uložené změny byly obnoveny; uložte je, chcete-li je zachovat.</translation>
    </message>
    <message>
        <source>About Regio</source>
        <translation>O aplikaci Regio</translation>
    </message>
    <message>
        <source>&lt;h3&gt;Regio %1&lt;/h3&gt;&lt;p&gt;An editor for radiosity scenes: whole-part B-rep objects, axis-aligned regions and their BSP root-patch orders.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Regio %1&lt;/h3&gt;&lt;p&gt;Editor scén pro radiozitu: objekty B-rep složené z celků a částí, osově zarovnané oblasti a jejich pořadí kořenových plošek BSP.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&amp;New</source>
        <translation>&amp;Nový</translation>
    </message>
    <message>
        <source>Start a new, empty scene</source>
        <translation>Začít novou, prázdnou scénu</translation>
    </message>
    <message>
        <source>&amp;Open…</source>
        <translation>&amp;Otevřít…</translation>
    </message>
    <message>
        <source>Open a scene file</source>
        <translation>Otevřít soubor scény</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>&amp;Uložit</translation>
    </message>
    <message>
        <source>Save the scene</source>
        <translation>Uložit scénu</translation>
    </message>
    <message>
        <source>Save &amp;As…</source>
        <translation>Uložit j&amp;ako…</translation>
    </message>
    <message>
        <source>Save the scene under a new name</source>
        <translation>Uložit scénu pod novým názvem</translation>
    </message>
    <message>
        <source>Re&amp;vert</source>
        <translation>&amp;Vrátit k uloženému</translation>
    </message>
    <message>
        <source>Drop unsaved changes and reload the file</source>
        <translation>Zahodit neuložené změny a znovu načíst soubor</translation>
    </message>
    <message>
        <source>&amp;Preferences…</source>
        <translation>&amp;Předvolby…</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>Ukonči&amp;t</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Zpět</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>Z&amp;novu</translation>
    </message>
    <message>
        <source>Select &amp;All</source>
        <translation>Vybrat vš&amp;e</translation>
    </message>
    <message>
        <source>&amp;Deselect</source>
        <translation>Zr&amp;ušit výběr</translation>
    </message>
    <message>
        <source>D&amp;uplicate</source>
        <translation>Zd&amp;vojit</translation>
    </message>
    <message>
        <source>Copy the selected objects or parts</source>
        <translation>Zkopírovat vybrané objekty nebo části</translation>
    </message>
    <message>
        <source>De&amp;lete</source>
        <translation>&amp;Smazat</translation>
    </message>
    <message>
        <source>Delete the selection</source>
        <translation>Smazat výběr</translation>
    </message>
    <message>
        <source>Re&amp;name…</source>
        <translation>Pře&amp;jmenovat…</translation>
    </message>
    <message>
        <source>Rename the selected element</source>
        <translation>Přejmenovat vybraný prvek</translation>
    </message>
    <message>
        <source>&amp;Frame Selection</source>
        <translation>&amp;Zaměřit výběr</translation>
    </message>
    <message>
        <source>Fit the selection in the view (everything when nothing is selected)</source>
        <translation>Přizpůsobit pohled výběru (celé scéně, když není nic vybráno)</translation>
    </message>
    <message>
        <source>Frame &amp;All</source>
        <translation>Zaměřit &amp;vše</translation>
    </message>
    <message>
        <source>&amp;Orthographic</source>
        <translation>Or&amp;tografická projekce</translation>
    </message>
    <message>
        <source>Hide &amp;Back Faces</source>
        <translation>Skrýt &amp;odvrácené stěny</translation>
    </message>
    <message>
        <source>Faces seen from behind are not drawn: look into rooms from outside</source>
        <translation>Stěny viděné zezadu se nekreslí: do místností lze nahlížet zvenku</translation>
    </message>
    <message>
        <source>Show &amp;Grid</source>
        <translation>Zobrazit &amp;mřížku</translation>
    </message>
    <message>
        <source>Show &amp;Regions</source>
        <translation>Zobrazit o&amp;blasti</translation>
    </message>
    <message>
        <source>&amp;Solid</source>
        <translation>&amp;Plné</translation>
    </message>
    <message>
        <source>&amp;Wireframe</source>
        <translation>&amp;Drátový model</translation>
    </message>
    <message>
        <source>Face &amp;Normals</source>
        <translation>&amp;Normály stěn</translation>
    </message>
    <message>
        <source>Colour faces by their normal and show which way they face</source>
        <translation>Obarvit stěny podle normály a ukázat, kam jsou natočeny</translation>
    </message>
    <message>
        <source>Select &amp;Objects</source>
        <translation>Vybírat &amp;objekty</translation>
    </message>
    <message>
        <source>Select &amp;Parts</source>
        <translation>Vybírat &amp;části</translation>
    </message>
    <message>
        <source>Select F&amp;aces</source>
        <translation>Vybírat s&amp;těny</translation>
    </message>
    <message>
        <source>&amp;Move</source>
        <translation>&amp;Posun</translation>
    </message>
    <message>
        <source>&amp;Rotate</source>
        <translation>&amp;Otočení</translation>
    </message>
    <message>
        <source>&amp;Scale</source>
        <translation>&amp;Měřítko</translation>
    </message>
    <message>
        <source>Snap to &amp;Grid</source>
        <translation>Přichytávat k mří&amp;žce</translation>
    </message>
    <message>
        <source>&amp;Front</source>
        <translation>&amp;Zepředu</translation>
    </message>
    <message>
        <source>&amp;Back</source>
        <translation>Zeza&amp;du</translation>
    </message>
    <message>
        <source>&amp;Right</source>
        <translation>Z&amp;prava</translation>
    </message>
    <message>
        <source>&amp;Left</source>
        <translation>Z&amp;leva</translation>
    </message>
    <message>
        <source>&amp;Top</source>
        <translation>&amp;Shora</translation>
    </message>
    <message>
        <source>Botto&amp;m</source>
        <translation>Zd&amp;ola</translation>
    </message>
    <message>
        <source>&amp;Isometric</source>
        <translation>&amp;Izometricky</translation>
    </message>
    <message>
        <source>&amp;About Regio</source>
        <translation>&amp;O aplikaci Regio</translation>
    </message>
    <message>
        <source>About &amp;Qt</source>
        <translation>O &amp;Qt</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Soubor</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>Otevřít ne&amp;dávné</translation>
    </message>
    <message>
        <source>Open E&amp;xample</source>
        <translation>Otevřít u&amp;kázku</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>Úp&amp;ravy</translation>
    </message>
    <message>
        <source>&amp;Create</source>
        <translation>&amp;Vytvořit</translation>
    </message>
    <message>
        <source>&amp;Modify</source>
        <translation>&amp;Změnit</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>Zo&amp;brazení</translation>
    </message>
    <message>
        <source>Standard &amp;Views</source>
        <translation>Standardní poh&amp;ledy</translation>
    </message>
    <message>
        <source>&amp;Panels</source>
        <translation>P&amp;anely</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Nápověda</translation>
    </message>
    <message>
        <source>File</source>
        <translation>Soubor</translation>
    </message>
    <message>
        <source>Tools</source>
        <translation>Nástroje</translation>
    </message>
    <message>
        <source>Create</source>
        <translation>Vytvořit</translation>
    </message>
    <message>
        <source>&amp;Regions</source>
        <translation>&amp;Oblasti</translation>
    </message>
    <message>
        <source>&amp;BSP</source>
        <translation>&amp;BSP</translation>
    </message>
    <message>
        <source>&amp;Solve</source>
        <translation>Ř&amp;ešit</translation>
    </message>
    <message>
        <source>Solve</source>
        <translation>Řešit</translation>
    </message>
    <message>
        <source>Import Model</source>
        <translation>Importovat model</translation>
    </message>
    <message>
        <source>Models (*.obj *.gltf *.glb *.fbx *.dae *.ply *.stl *.3ds *.blend *.off *.x *.lwo *.ase *.ac);;All files (*)</source>
        <translation>Modely (*.obj *.gltf *.glb *.fbx *.dae *.ply *.stl *.3ds *.blend *.off *.x *.lwo *.ase *.ac);;Všechny soubory (*)</translation>
    </message>
    <message>
        <source>Imported %1 as a new scene</source>
        <translation>%1 importován jako nová scéna</translation>
    </message>
    <message>
        <source>Import %1</source>
        <translation>Import %1</translation>
    </message>
    <message>
        <source>Imported %1 (objects: %2)</source>
        <translation>%1 importován (objekty: %2)</translation>
    </message>
    <message>
        <source>&amp;Import Model…</source>
        <translation>&amp;Importovat model…</translation>
    </message>
    <message>
        <source>Ctrl+I</source>
        <translation>Ctrl+I</translation>
    </message>
    <message>
        <source>Import a model file (OBJ, glTF, FBX, Collada, PLY, STL, 3DS, ...)</source>
        <translation>Importovat soubor modelu (OBJ, glTF, FBX, Collada, PLY, STL, 3DS, …)</translation>
    </message>
    <message>
        <source>&amp;Reset Layout</source>
        <translation>Ob&amp;novit rozvržení</translation>
    </message>
    <message>
        <source>Put every panel back where it was at first start, sized to the window</source>
        <translation>Vrátit všechny panely tam, kde byly při prvním spuštění, s velikostí podle okna</translation>
    </message>
    <message>
        <source>User &amp;Guide</source>
        <translation>Uživatelská &amp;příručka</translation>
    </message>
    <message>
        <source>Open the user guide</source>
        <translation>Otevřít uživatelskou příručku</translation>
    </message>
    <message>
        <source>No program opens %1 on this system</source>
        <translation>Žádný program v tomto systému neotevře %1</translation>
    </message>
    <message>
        <source>E&amp;xamples</source>
        <translation>&amp;Ukázky</translation>
    </message>
</context>
<context>
    <name>regio::editor::MaterialsDock</name>
    <message>
        <source>Materials</source>
        <translation>Materiály</translation>
    </message>
    <message>
        <source>Add</source>
        <translation>Přidat</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Smazat</translation>
    </message>
    <message>
        <source>Only a material nothing uses can be deleted</source>
        <translation>Smazat lze jen materiál, který nic nepoužívá</translation>
    </message>
    <message>
        <source>Assign to Selection</source>
        <translation>Přiřadit výběru</translation>
    </message>
    <message>
        <source>Id:</source>
        <translation>Id:</translation>
    </message>
    <message>
        <source>(no name)</source>
        <translation>(bez názvu)</translation>
    </message>
    <message>
        <source>Name:</source>
        <translation>Název:</translation>
    </message>
    <message>
        <source>Diffuse reflectance per channel (red, green, blue), below 1</source>
        <translation>Difuzní odrazivost pro každý kanál (červený, zelený, modrý), menší než 1</translation>
    </message>
    <message>
        <source>Reflectance:</source>
        <translation>Odrazivost:</translation>
    </message>
    <message>
        <source>Emitted power per unit area per channel (W/m²)</source>
        <translation>Vyzařovaný výkon na jednotku plochy pro každý kanál (W/m²)</translation>
    </message>
    <message>
        <source>Emission:</source>
        <translation>Vyzařování:</translation>
    </message>
    <message>
        <source>The strongest channel of the emission; the others keep their ratio</source>
        <translation>Nejsilnější kanál vyzařování; ostatní si zachovají poměr</translation>
    </message>
    <message>
        <source>Strength:</source>
        <translation>Síla:</translation>
    </message>
</context>
<context>
    <name>regio::editor::PreferencesDialog</name>
    <message>
        <source>Preferences</source>
        <translation>Předvolby</translation>
    </message>
    <message>
        <source>System default</source>
        <translation>Podle systému</translation>
    </message>
    <message>
        <source>&amp;Language:</source>
        <translation>&amp;Jazyk:</translation>
    </message>
    <message>
        <source> min</source>
        <translation> min</translation>
    </message>
    <message>
        <source>Off</source>
        <translation>Vypnuto</translation>
    </message>
    <message>
        <source>How often unsaved changes are written to a recovery file</source>
        <translation>Jak často se neuložené změny zapisují do souboru pro obnovu</translation>
    </message>
    <message>
        <source>&amp;Autosave every:</source>
        <translation>&amp;Automaticky ukládat každých:</translation>
    </message>
    <message>
        <source> m</source>
        <translation> m</translation>
    </message>
    <message>
        <source>&amp;Grid step:</source>
        <translation>&amp;Krok mřížky:</translation>
    </message>
    <message>
        <source>Snap moves, rotations and scaling</source>
        <translation>Přichytávat posuny, otočení a změny měřítka</translation>
    </message>
    <message>
        <source>&amp;Snapping:</source>
        <translation>Při&amp;chytávání:</translation>
    </message>
    <message>
        <source>A&amp;ngle step:</source>
        <translation>Krok ú&amp;hlu:</translation>
    </message>
</context>
<context>
    <name>regio::editor::PreviewController</name>
    <message>
        <source>Nothing of the solution under the cursor.</source>
        <translation>Pod kurzorem není nic z řešení.</translation>
    </message>
    <message>
        <source>The preview cannot solve this scene: %1</source>
        <translation>Náhled tuto scénu nedokáže vyřešit: %1</translation>
    </message>
    <message>
        <source>&amp;Run</source>
        <translation>&amp;Spustit</translation>
    </message>
    <message>
        <source>Solve the scene as it is now (the preview shows it progressively)</source>
        <translation>Vyřešit scénu v současném stavu (náhled ji ukazuje postupně)</translation>
    </message>
    <message>
        <source>&amp;Pause</source>
        <translation>&amp;Pozastavit</translation>
    </message>
    <message>
        <source>Pause the solve, or resume it</source>
        <translation>Pozastavit řešení nebo v něm pokračovat</translation>
    </message>
    <message>
        <source>&amp;Stop</source>
        <translation>&amp;Zastavit</translation>
    </message>
    <message>
        <source>End the solve; the solution stays</source>
        <translation>Ukončit řešení; řešení zůstane</translation>
    </message>
    <message>
        <source>Rese&amp;t</source>
        <translation>&amp;Vynulovat</translation>
    </message>
    <message>
        <source>Drop the solution and show the materials again</source>
        <translation>Zahodit řešení a znovu ukázat materiály</translation>
    </message>
    <message>
        <source>&amp;Live</source>
        <translation>Ž&amp;ivě</translation>
    </message>
    <message>
        <source>Solve again automatically after a pause in editing</source>
        <translation>Po přestávce v úpravách automaticky řešit znovu</translation>
    </message>
    <message>
        <source>&amp;Dry Run…</source>
        <translation>&amp;Zkušební příprava…</translation>
    </message>
    <message>
        <source>List the effective settings and the patch and element counts</source>
        <translation>Vypsat platná nastavení a počty plošek a prvků</translation>
    </message>
    <message>
        <source>&amp;Inspect</source>
        <translation>&amp;Prozkoumat</translation>
    </message>
    <message>
        <source>Click a surface of the solution to see its element</source>
        <translation>Klepnutím na povrch řešení zobrazíte jeho prvek</translation>
    </message>
    <message>
        <source>&amp;Hemicube…</source>
        <translation>Polo&amp;krychle…</translation>
    </message>
    <message>
        <source>Show the item buffer of the inspected patch</source>
        <translation>Zobrazit buffer položek zkoumané plošky</translation>
    </message>
    <message>
        <source>Draft</source>
        <translation>Náčrt</translation>
    </message>
    <message>
        <source>Coarse and fast: for previews while editing</source>
        <translation>Hrubé a rychlé: pro náhledy během úprav</translation>
    </message>
    <message>
        <source>Normal</source>
        <translation>Běžné</translation>
    </message>
    <message>
        <source>The default settings</source>
        <translation>Výchozí nastavení</translation>
    </message>
    <message>
        <source>Final</source>
        <translation>Finální</translation>
    </message>
    <message>
        <source>Fine meshes and a large hemicube: for batch solving</source>
        <translation>Jemné sítě a velká polokrychle: pro dávkové řešení</translation>
    </message>
    <message>
        <source>Export Lit &amp;Model…</source>
        <translation>Exportovat osvětlený &amp;model…</translation>
    </message>
    <message>
        <source>Write the shown solution as glTF, PLY or OBJ</source>
        <translation>Zapsat zobrazené řešení jako glTF, PLY nebo OBJ</translation>
    </message>
    <message>
        <source>Export Viewport &amp;Image…</source>
        <translation>Exportovat &amp;obrázek pohledu…</translation>
    </message>
    <message>
        <source>Save the viewport as a picture</source>
        <translation>Uložit pohled jako obrázek</translation>
    </message>
    <message>
        <source>Export for &amp;Batch…</source>
        <translation>Exportovat pro &amp;dávku…</translation>
    </message>
    <message>
        <source>Write a self-contained scene with final settings and the regio-solve command</source>
        <translation>Zapsat soběstačnou scénu s finálním nastavením a příkazem regio-solve</translation>
    </message>
    <message>
        <source>&amp;Presets</source>
        <translation>&amp;Předvolby</translation>
    </message>
    <message>
        <source>iteration %1, unshot %2 %, %3 elements, %4 s</source>
        <translation>iterace %1, nevyzářeno %2 %, %3 prvků, %4 s</translation>
    </message>
    <message>
        <source>Preview: not solved</source>
        <translation>Náhled: nevyřešeno</translation>
    </message>
    <message>
        <source>Preview: preparing the scene…</source>
        <translation>Náhled: příprava scény…</translation>
    </message>
    <message>
        <source>Solving: %1</source>
        <translation>Řeší se: %1</translation>
    </message>
    <message>
        <source>Solving…</source>
        <translation>Řeší se…</translation>
    </message>
    <message>
        <source>Paused: %1</source>
        <translation>Pozastaveno: %1</translation>
    </message>
    <message>
        <source>Paused</source>
        <translation>Pozastaveno</translation>
    </message>
    <message>
        <source>Solved</source>
        <translation>Vyřešeno</translation>
    </message>
    <message>
        <source>Preview: the scene cannot be solved</source>
        <translation>Náhled: scénu nelze vyřešit</translation>
    </message>
    <message>
        <source> (stale: the scene changed)</source>
        <translation> (zastaralé: scéna se změnila)</translation>
    </message>
    <message>
        <source>Res&amp;ume</source>
        <translation>Pokra&amp;čovat</translation>
    </message>
    <message>
        <source>Dry Run</source>
        <translation>Zkušební příprava</translation>
    </message>
    <message>
        <source>Hemicube</source>
        <translation>Polokrychle</translation>
    </message>
    <message>
        <source>Patch (or inspect a surface first):</source>
        <translation>Ploška (nebo nejprve prozkoumejte povrch):</translation>
    </message>
    <message>
        <source>there is no solution to export</source>
        <translation>není žádné řešení k exportu</translation>
    </message>
    <message>
        <source>the viewport could not be read</source>
        <translation>pohled nelze přečíst</translation>
    </message>
    <message>
        <source>Export Lit Model</source>
        <translation>Exportovat osvětlený model</translation>
    </message>
    <message>
        <source>glTF binary (*.glb);;glTF (*.gltf);;PLY (*.ply);;OBJ (*.obj)</source>
        <translation>glTF binární (*.glb);;glTF (*.gltf);;PLY (*.ply);;OBJ (*.obj)</translation>
    </message>
    <message>
        <source>Exported %1</source>
        <translation>Exportováno %1</translation>
    </message>
    <message>
        <source>Export Viewport Image</source>
        <translation>Exportovat obrázek pohledu</translation>
    </message>
    <message>
        <source>PNG image (*.png);;JPEG image (*.jpg)</source>
        <translation>Obrázek PNG (*.png);;Obrázek JPEG (*.jpg)</translation>
    </message>
    <message>
        <source>Export for Batch</source>
        <translation>Exportovat pro dávku</translation>
    </message>
    <message>
        <source>Regio scene (*.json)</source>
        <translation>Scéna Regio (*.json)</translation>
    </message>
    <message>
        <source>Wrote %1 with the final preset&apos;s settings. This command, now on the clipboard, solves it and writes the report, the lit model and a picture:

%2</source>
        <translation>Zapsáno %1 s nastavením finální předvolby. Tento příkaz, nyní ve schránce, ji vyřeší a zapíše zprávu, osvětlený model a obrázek:

%2</translation>
    </message>
    <message>
        <source>&amp;Continue</source>
        <translation>Po&amp;kračovat v řešení</translation>
    </message>
    <message>
        <source>Go on from where the solve stopped: its iteration limit or your Stop</source>
        <translation>Pokračovat tam, kde se řešení zastavilo: na limitu iterací nebo po vašem Zastavit</translation>
    </message>
    <message>
        <source>Stopped at the iteration limit, not converged: %1 (Continue goes on)</source>
        <translation>Zastaveno na limitu iterací, nezkonvergovalo: %1 (Pokračovat v řešení jde dál)</translation>
    </message>
    <message>
        <source>Stopped by you, not converged: %1 (Continue goes on)</source>
        <translation>Zastaveno vámi, nezkonvergovalo: %1 (Pokračovat v řešení jde dál)</translation>
    </message>
    <message>
        <source>Converged: %1</source>
        <translation>Zkonvergovalo: %1</translation>
    </message>
    <message>
        <source> (refining the mesh…)</source>
        <translation> (zjemňuje se síť…)</translation>
    </message>
</context>
<context>
    <name>regio::editor::PreviewExport</name>
    <message>
        <source>there is no solution to export</source>
        <translation>není žádné řešení k exportu</translation>
    </message>
    <message>
        <source>%1: unknown model format (use .gltf, .glb, .ply or .obj)</source>
        <translation>%1: neznámý formát modelu (použijte .gltf, .glb, .ply nebo .obj)</translation>
    </message>
</context>
<context>
    <name>regio::editor::PreviewInspector</name>
    <message>
        <source>Element %1 of face %2</source>
        <translation>Prvek %1 stěny %2</translation>
    </message>
    <message>
        <source>Patch: %1; region: %2</source>
        <translation>Ploška: %1; oblast: %2</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>neznámá</translation>
    </message>
    <message>
        <source>Radiosity: %1 W/m²</source>
        <translation>Radiozita: %1 W/m²</translation>
    </message>
    <message>
        <source>Unshot: %1 W/m²</source>
        <translation>Nevyzářeno: %1 W/m²</translation>
    </message>
    <message>
        <source>Shown (with ambient): %1 W/m²</source>
        <translation>Zobrazeno (s ambientní složkou): %1 W/m²</translation>
    </message>
    <message>
        <source>Area: %1 m²</source>
        <translation>Plocha: %1 m²</translation>
    </message>
</context>
<context>
    <name>regio::editor::PreviewRunner</name>
    <message>
        <source>the scene could not be prepared</source>
        <translation>scénu nebylo možné připravit</translation>
    </message>
</context>
<context>
    <name>regio::editor::PreviewScreenshot</name>
    <message>
        <source>the preview did not finish within %1 s</source>
        <translation>náhled neskončil do %1 s</translation>
    </message>
    <message>
        <source>the preview failed: %1</source>
        <translation>náhled selhal: %1</translation>
    </message>
</context>
<context>
    <name>regio::editor::PreviewSession</name>
    <message>
        <source>the solver ran out of memory (try a larger patch size or a lower hemicube resolution)</source>
        <translation>řešiči došla paměť (zkuste větší velikost plošky nebo nižší rozlišení polokrychle)</translation>
    </message>
    <message>
        <source>the solver failed: %1</source>
        <translation>řešič selhal: %1</translation>
    </message>
    <message>
        <source>the solver failed</source>
        <translation>řešič selhal</translation>
    </message>
</context>
<context>
    <name>regio::editor::PrimitiveDialog</name>
    <message>
        <source>Box</source>
        <translation>Kvádr</translation>
    </message>
    <message>
        <source>Room</source>
        <translation>Místnost</translation>
    </message>
    <message>
        <source>Prism / Cylinder</source>
        <translation>Hranol / válec</translation>
    </message>
    <message>
        <source>Wedge</source>
        <translation>Klín</translation>
    </message>
    <message>
        <source>Stairs</source>
        <translation>Schodiště</translation>
    </message>
    <message>
        <source>&amp;Id:</source>
        <translation>&amp;Id:</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>(žádný)</translation>
    </message>
    <message>
        <source>&amp;Material:</source>
        <translation>&amp;Materiál:</translation>
    </message>
    <message>
        <source>&amp;Base centre (m):</source>
        <translation>Střed &amp;podstavy (m):</translation>
    </message>
    <message>
        <source>&amp;Size (m):</source>
        <translation>&amp;Rozměry (m):</translation>
    </message>
    <message>
        <source>Si&amp;des:</source>
        <translation>Počet &amp;stěn:</translation>
    </message>
    <message>
        <source>S&amp;teps:</source>
        <translation>Počet s&amp;chodů:</translation>
    </message>
    <message>
        <source>New object: %1</source>
        <translation>Nový objekt: %1</translation>
    </message>
</context>
<context>
    <name>regio::editor::PropertiesDock</name>
    <message>
        <source>Properties</source>
        <translation>Vlastnosti</translation>
    </message>
    <message>
        <source>Solver</source>
        <translation>Řešič</translation>
    </message>
    <message>
        <source> m</source>
        <translation> m</translation>
    </message>
    <message>
        <source>Scene camera</source>
        <translation>Kamera scény</translation>
    </message>
    <message>
        <source>Store Current View</source>
        <translation>Uložit aktuální pohled</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>Odstranit</translation>
    </message>
    <message>
        <source>(no name)</source>
        <translation>(bez názvu)</translation>
    </message>
    <message>
        <source>Name:</source>
        <translation>Název:</translation>
    </message>
    <message>
        <source>Material:</source>
        <translation>Materiál:</translation>
    </message>
    <message>
        <source>Transform</source>
        <translation>Transformace</translation>
    </message>
    <message>
        <source>Centre of the selection&apos;s bounding box; editing it moves the selection</source>
        <translation>Střed obalového kvádru výběru; jeho změnou se výběr posune</translation>
    </message>
    <message>
        <source>Move</source>
        <translation>Posunout</translation>
    </message>
    <message>
        <source>Centre:</source>
        <translation>Střed:</translation>
    </message>
    <message>
        <source>Rotate</source>
        <translation>Otočit</translation>
    </message>
    <message>
        <source>Rotate by:</source>
        <translation>Otočit o:</translation>
    </message>
    <message>
        <source>Scale</source>
        <translation>Změnit měřítko</translation>
    </message>
    <message>
        <source>Scale by:</source>
        <translation>Měřítko:</translation>
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
        <translation>Oko %1, pohled na %2, zorné pole %3°</translation>
    </message>
    <message>
        <source>None: the view frames the whole scene when it opens.</source>
        <translation>Žádná: po otevření pohled zabere celou scénu.</translation>
    </message>
    <message>
        <source>&lt;b&gt;Object&lt;/b&gt; %1</source>
        <translation>&lt;b&gt;Objekt&lt;/b&gt; %1</translation>
    </message>
    <message>
        <source>&lt;b&gt;Part&lt;/b&gt; %1</source>
        <translation>&lt;b&gt;Část&lt;/b&gt; %1</translation>
    </message>
    <message numerus="yes">
        <source>&lt;b&gt;%n objects&lt;/b&gt;</source>
        <translation>
            <numerusform>&lt;b&gt;%n objekt&lt;/b&gt;</numerusform>
            <numerusform>&lt;b&gt;%n objekty&lt;/b&gt;</numerusform>
            <numerusform>&lt;b&gt;%n objektů&lt;/b&gt;</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>&lt;b&gt;%n parts&lt;/b&gt;</source>
        <translation>
            <numerusform>&lt;b&gt;%n část&lt;/b&gt;</numerusform>
            <numerusform>&lt;b&gt;%n části&lt;/b&gt;</numerusform>
            <numerusform>&lt;b&gt;%n částí&lt;/b&gt;</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n part(s)</source>
        <translation>
            <numerusform>%n část</numerusform>
            <numerusform>%n části</numerusform>
            <numerusform>%n částí</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n face(s)</source>
        <translation>
            <numerusform>%n stěna</numerusform>
            <numerusform>%n stěny</numerusform>
            <numerusform>%n stěn</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n vertices</source>
        <translation>
            <numerusform>%n vrchol</numerusform>
            <numerusform>%n vrcholy</numerusform>
            <numerusform>%n vrcholů</numerusform>
        </translation>
    </message>
    <message>
        <source>Size %1 m</source>
        <translation>Rozměry %1 m</translation>
    </message>
    <message numerus="yes">
        <source>&lt;b&gt;%n faces&lt;/b&gt;</source>
        <translation>
            <numerusform>&lt;b&gt;%n stěna&lt;/b&gt;</numerusform>
            <numerusform>&lt;b&gt;%n stěny&lt;/b&gt;</numerusform>
            <numerusform>&lt;b&gt;%n stěn&lt;/b&gt;</numerusform>
        </translation>
    </message>
    <message>
        <source>(the part&apos;s material)</source>
        <translation>(materiál části)</translation>
    </message>
    <message>
        <source>&lt;b&gt;Face&lt;/b&gt; %1</source>
        <translation>&lt;b&gt;Stěna&lt;/b&gt; %1</translation>
    </message>
    <message>
        <source>(the part&apos;s: %1)</source>
        <translation>(podle části: %1)</translation>
    </message>
    <message>
        <source>none</source>
        <translation>žádný</translation>
    </message>
    <message>
        <source>The face&apos;s vertex loop is broken.</source>
        <translation>Smyčka vrcholů stěny je poškozená.</translation>
    </message>
    <message numerus="yes">
        <source>Part %1
%n vertices</source>
        <translation>
            <numerusform>Část %1
%n vrchol</numerusform>
            <numerusform>Část %1
%n vrcholy</numerusform>
            <numerusform>Část %1
%n vrcholů</numerusform>
        </translation>
    </message>
    <message>
        <source>Area %1 m²</source>
        <translation>Plocha %1 m²</translation>
    </message>
    <message>
        <source>Normal %1</source>
        <translation>Normála %1</translation>
    </message>
    <message>
        <source>Centroid %1</source>
        <translation>Těžiště %1</translation>
    </message>
    <message>
        <source>Off its plane by at most %1 m</source>
        <translation>Odchylka od roviny nejvýše %1 m</translation>
    </message>
    <message>
        <source>&lt;b&gt;Material&lt;/b&gt; %1&lt;br&gt;Used as the default of %2 part(s) and by %3 face(s) of their own.&lt;br&gt;Edit its colours in the Materials panel.</source>
        <translation>&lt;b&gt;Materiál&lt;/b&gt; %1&lt;br&gt;Výchozí materiál částí: %2; vlastní materiál stěn: %3.&lt;br&gt;Jeho barvy upravíte v panelu Materiály.</translation>
    </message>
    <message numerus="yes">
        <source>&lt;b&gt;%n regions&lt;/b&gt;</source>
        <translation>
            <numerusform>&lt;b&gt;%n oblast&lt;/b&gt;</numerusform>
            <numerusform>&lt;b&gt;%n oblasti&lt;/b&gt;</numerusform>
            <numerusform>&lt;b&gt;%n oblastí&lt;/b&gt;</numerusform>
        </translation>
    </message>
    <message>
        <source>&lt;b&gt;Region&lt;/b&gt; %1</source>
        <translation>&lt;b&gt;Oblast&lt;/b&gt; %1</translation>
    </message>
    <message numerus="yes">
        <source>BSP order: %n face(s)</source>
        <translation>
            <numerusform>Pořadí BSP: %n stěna</numerusform>
            <numerusform>Pořadí BSP: %n stěny</numerusform>
            <numerusform>Pořadí BSP: %n stěn</numerusform>
        </translation>
    </message>
    <message>
        <source>The hemicube, the mesh and when to stop are set in the Solver panel, beside the preview.</source>
        <translation>Polokrychle, síť a podmínky zastavení se nastavují v panelu Řešič vedle náhledu.</translation>
    </message>
    <message>
        <source>Show Solver Panel</source>
        <translation>Zobrazit panel Řešič</translation>
    </message>
</context>
<context>
    <name>regio::editor::RegionAuthoring</name>
    <message>
        <source>&amp;Region Tool</source>
        <translation>Nástroj &amp;oblasti</translation>
    </message>
    <message>
        <source>Draw a region box in the viewport and resize the selected one by its face handles</source>
        <translation>Nakreslit kvádr oblasti v pohledu a měnit velikost vybraného tažením úchytů jeho stěn</translation>
    </message>
    <message>
        <source>Region Around &amp;Selection</source>
        <translation>Oblast kolem &amp;výběru</translation>
    </message>
    <message>
        <source>Add a region box around the selected parts (the whole scene when nothing is selected)</source>
        <translation>Přidat kvádr oblasti kolem vybraných dílů (celé scény, když není nic vybráno)</translation>
    </message>
    <message>
        <source>Re&amp;name Region…</source>
        <translation>Pře&amp;jmenovat oblast…</translation>
    </message>
    <message>
        <source>&amp;Delete Region</source>
        <translation>&amp;Smazat oblast</translation>
    </message>
    <message>
        <source>&amp;Clip Selected Parts to Regions</source>
        <translation>&amp;Oříznout vybrané díly podle oblastí</translation>
    </message>
    <message>
        <source>Cut each selected part that straddles region boundaries into one piece per region</source>
        <translation>Rozříznout každý vybraný díl přesahující hranice oblastí na jeden kus v každé oblasti</translation>
    </message>
    <message>
        <source>&amp;Propose Automatic Regions</source>
        <translation>&amp;Navrhnout automatické oblasti</translation>
    </message>
    <message>
        <source>Suggest region boxes whose planes pass between the parts, with their BSP figures</source>
        <translation>Navrhnout kvádry oblastí, jejichž roviny procházejí mezi díly, s jejich údaji BSP</translation>
    </message>
    <message>
        <source>&amp;Accept Proposed Regions</source>
        <translation>&amp;Přijmout navržené oblasti</translation>
    </message>
    <message>
        <source>Replace the scene&apos;s regions by the proposed ones</source>
        <translation>Nahradit oblasti scény navrženými</translation>
    </message>
    <message>
        <source>D&amp;iscard Proposed Regions</source>
        <translation>&amp;Zahodit navržené oblasti</translation>
    </message>
    <message>
        <source>Show Region &amp;Boxes</source>
        <translation>Zobrazit &amp;kvádry oblastí</translation>
    </message>
    <message>
        <source>&amp;Colour Parts by Region</source>
        <translation>&amp;Obarvit díly podle oblasti</translation>
    </message>
    <message>
        <source>Each face in its region&apos;s colour; grey outside every region</source>
        <translation>Každá stěna v barvě své oblasti; šedě mimo všechny oblasti</translation>
    </message>
    <message>
        <source>Show &amp;Separating Planes</source>
        <translation>Zobrazit &amp;dělicí roviny</translation>
    </message>
    <message>
        <source>The planes of the solver&apos;s regional tree between the region boxes</source>
        <translation>Roviny regionálního stromu řešiče mezi kvádry oblastí</translation>
    </message>
    <message>
        <source>The scene changed: the proposed regions were discarded</source>
        <translation>Scéna se změnila: navržené oblasti byly zahozeny</translation>
    </message>
    <message>
        <source>Clip Part to Regions</source>
        <translation>Oříznout díl podle oblastí</translation>
    </message>
    <message>
        <source>Cut the straddling part into one piece per region</source>
        <translation>Rozříznout přesahující díl na jeden kus v každé oblasti</translation>
    </message>
    <message>
        <source>The scene is empty: draw a region with the region tool</source>
        <translation>Scéna je prázdná: nakreslete oblast nástrojem oblasti</translation>
    </message>
    <message>
        <source>No selected part straddles a region boundary</source>
        <translation>Žádný vybraný díl nepřesahuje hranici oblasti</translation>
    </message>
    <message numerus="yes">
        <source>Clip %n part(s) to regions</source>
        <translation>
            <numerusform>Oříznout %n díl podle oblastí</numerusform>
            <numerusform>Oříznout %n díly podle oblastí</numerusform>
            <numerusform>Oříznout %n dílů podle oblastí</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Clipped to regions: %n piece(s)</source>
        <translation>
            <numerusform>Oříznuto podle oblastí: %n kus</numerusform>
            <numerusform>Oříznuto podle oblastí: %n kusy</numerusform>
            <numerusform>Oříznuto podle oblastí: %n kusů</numerusform>
        </translation>
    </message>
    <message>
        <source>no regions could be proposed</source>
        <translation>nebylo možné navrhnout žádné oblasti</translation>
    </message>
    <message>
        <source>No proposal: %1</source>
        <translation>Žádný návrh: %1</translation>
    </message>
    <message numerus="yes">
        <source>&lt;b&gt;Proposed: %n region(s)&lt;/b&gt;</source>
        <translation>
            <numerusform>&lt;b&gt;Navrženo: %n oblast&lt;/b&gt;</numerusform>
            <numerusform>&lt;b&gt;Navrženo: %n oblasti&lt;/b&gt;</numerusform>
            <numerusform>&lt;b&gt;Navrženo: %n oblastí&lt;/b&gt;</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 fragments, %2 splits, depth %3</source>
        <translation>%1 fragmentů, %2 dělení, hloubka %3</translation>
    </message>
    <message>
        <source>Current regions: %1 fragments, %2 splits</source>
        <translation>Současné oblasti: %1 fragmentů, %2 dělení</translation>
    </message>
    <message>
        <source>Single BSP: %1 fragments, %2 splits</source>
        <translation>Jediný BSP: %1 fragmentů, %2 dělení</translation>
    </message>
    <message numerus="yes">
        <source>%n part(s) cross the proposed planes; after accepting, clip them from the Diagnostics panel or the Regions menu.</source>
        <translation>
            <numerusform>%n díl protíná navržené roviny; po přijetí ho ořízněte z panelu Diagnostika nebo z nabídky Oblasti.</numerusform>
            <numerusform>%n díly protínají navržené roviny; po přijetí je ořízněte z panelu Diagnostika nebo z nabídky Oblasti.</numerusform>
            <numerusform>%n dílů protíná navržené roviny; po přijetí je ořízněte z panelu Diagnostika nebo z nabídky Oblasti.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Proposed %n region(s): accept or discard them in the Regions panel</source>
        <translation>
            <numerusform>Navržena %n oblast: přijměte ji nebo zahoďte v panelu Oblasti</numerusform>
            <numerusform>Navrženy %n oblasti: přijměte je nebo zahoďte v panelu Oblasti</numerusform>
            <numerusform>Navrženo %n oblastí: přijměte je nebo zahoďte v panelu Oblasti</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Accept %n proposed region(s)</source>
        <translation>
            <numerusform>Přijmout %n navrženou oblast</numerusform>
            <numerusform>Přijmout %n navržené oblasti</numerusform>
            <numerusform>Přijmout %n navržených oblastí</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Accepted %n region(s)</source>
        <translation>
            <numerusform>Přijata %n oblast</numerusform>
            <numerusform>Přijaty %n oblasti</numerusform>
            <numerusform>Přijato %n oblastí</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>regio::editor::RegionBoxTool</name>
    <message>
        <source>Region tool: drag on the ground or a horizontal face to draw a box; drag a handle of the selected region to resize it; Esc leaves the tool</source>
        <translation>Nástroj oblasti: tažením po zemi nebo vodorovné stěně nakreslíte kvádr; tažením úchytu vybrané oblasti změníte její velikost; Esc nástroj opustí</translation>
    </message>
    <message>
        <source>Aim at the ground grid or a horizontal face to start a region</source>
        <translation>Oblast začněte na mřížce země nebo na vodorovné stěně</translation>
    </message>
    <message>
        <source>Region %1 × %2 × %3 m</source>
        <translation>Oblast %1 × %2 × %3 m</translation>
    </message>
    <message>
        <source>Region %1: %2 %3 = %4 m</source>
        <translation>Oblast %1: %2 %3 = %4 m</translation>
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
        <translation>Kreslení oblasti zrušeno</translation>
    </message>
    <message>
        <source>The box is too thin; drag a larger rectangle</source>
        <translation>Kvádr je příliš tenký; táhněte větší obdélník</translation>
    </message>
    <message>
        <source>Added region %1</source>
        <translation>Přidána oblast %1</translation>
    </message>
</context>
<context>
    <name>regio::editor::RegionsDock</name>
    <message>
        <source>Regions</source>
        <translation>Oblasti</translation>
    </message>
    <message>
        <source>Region</source>
        <translation>Oblast</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Název</translation>
    </message>
    <message>
        <source>Parts</source>
        <translation>Díly</translation>
    </message>
    <message>
        <source>Faces</source>
        <translation>Stěny</translation>
    </message>
    <message>
        <source>Fragments</source>
        <translation>Fragmenty</translation>
    </message>
    <message>
        <source>Polygons in the region&apos;s BSP tree after clipping and splitting, as the solver builds it (fewer is better)</source>
        <translation>Mnohoúhelníky ve stromu BSP oblasti po ořezu a dělení, jak jej sestaví řešič (méně je lépe)</translation>
    </message>
    <message>
        <source>Node</source>
        <translation>Uzel</translation>
    </message>
    <message>
        <source>Side</source>
        <translation>Strana</translation>
    </message>
    <message>
        <source>Regional Tree</source>
        <translation>Regionální strom</translation>
    </message>
    <message>
        <source>Accept</source>
        <translation>Přijmout</translation>
    </message>
    <message>
        <source>Discard</source>
        <translation>Zahodit</translation>
    </message>
    <message>
        <source>min %1, max %2</source>
        <translation>min %1, max %2</translation>
    </message>
    <message>
        <source>Overlaps %1: regions must not share volume</source>
        <translation>Překrývá %1: oblasti nesmějí sdílet objem</translation>
    </message>
    <message>
        <source>Computing BSP figures…</source>
        <translation>Počítají se údaje BSP…</translation>
    </message>
    <message>
        <source>No BSP figures: the solver cannot prepare this scene (see Diagnostics).</source>
        <translation>Žádné údaje BSP: řešič tuto scénu nedokáže připravit (viz Diagnostika).</translation>
    </message>
    <message>
        <source>No regions: one BSP tree, %1 fragments, %2 splits, depth %3.</source>
        <translation>Bez oblastí: jeden strom BSP, %1 fragmentů, %2 dělení, hloubka %3.</translation>
    </message>
    <message>
        <source>%1 regions: %2 fragments, %3 splits, depth %4.</source>
        <translation>Oblastí: %1; %2 fragmentů, %3 dělení, hloubka %4.</translation>
    </message>
    <message>
        <source>Single BSP: %1 fragments, %2 splits, depth %3.</source>
        <translation>Jediný BSP: %1 fragmentů, %2 dělení, hloubka %3.</translation>
    </message>
    <message>
        <source>(updating…)</source>
        <translation>(aktualizuje se…)</translation>
    </message>
    <message>
        <source>No regions: the whole scene is one BSP tree</source>
        <translation>Bez oblastí: celá scéna je jeden strom BSP</translation>
    </message>
    <message>
        <source>No regional tree: the region boxes overlap or cannot be separated</source>
        <translation>Žádný regionální strom: kvádry oblastí se překrývají nebo je nelze oddělit</translation>
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
        <translation>vpředu (%1 ≥ %2)</translation>
    </message>
    <message>
        <source>back (%1 ≤ %2)</source>
        <translation>vzadu (%1 ≤ %2)</translation>
    </message>
</context>
<context>
    <name>regio::editor::SceneDocument</name>
    <message>
        <source>Untitled</source>
        <translation>Bez názvu</translation>
    </message>
    <message>
        <source>the scene has never been saved</source>
        <translation>scéna ještě nebyla uložena</translation>
    </message>
</context>
<context>
    <name>regio::editor::SceneTreeDock</name>
    <message>
        <source>Scene</source>
        <translation>Scéna</translation>
    </message>
    <message>
        <source>Filter by id or name</source>
        <translation>Filtrovat podle id nebo názvu</translation>
    </message>
</context>
<context>
    <name>regio::editor::SceneTreeModel</name>
    <message numerus="yes">
        <source>%n vertices</source>
        <translation>
            <numerusform>%n vrchol</numerusform>
            <numerusform>%n vrcholy</numerusform>
            <numerusform>%n vrcholů</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 (part)</source>
        <translation>%1 (část)</translation>
    </message>
    <message>
        <source>Unknown material &quot;%1&quot;</source>
        <translation>Neznámý materiál „%1“</translation>
    </message>
    <message>
        <source>Id</source>
        <translation>Id</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Název</translation>
    </message>
    <message>
        <source>Material</source>
        <translation>Materiál</translation>
    </message>
</context>
<context>
    <name>regio::editor::ScreenshotRunner</name>
    <message>
        <source>no frame was rendered within %1 s</source>
        <translation>během %1 s nebyl vykreslen žádný snímek</translation>
    </message>
    <message>
        <source>the viewport cannot render: %1</source>
        <translation>pohled nemůže kreslit: %1</translation>
    </message>
    <message>
        <source>the viewport&apos;s framebuffer could not be read</source>
        <translation>obsah pohledu nelze přečíst</translation>
    </message>
</context>
<context>
    <name>regio::editor::SolverDock</name>
    <message>
        <source>Solver</source>
        <translation>Řešič</translation>
    </message>
    <message>
        <source>Settings</source>
        <translation>Nastavení</translation>
    </message>
    <message>
        <source>Custom</source>
        <translation>Vlastní</translation>
    </message>
    <message>
        <source>Preset:</source>
        <translation>Předvolba:</translation>
    </message>
    <message>
        <source>Resolution of the hemicube&apos;s top face (the sides are half as high)</source>
        <translation>Rozlišení horní stěny polokrychle (boky jsou poloviční výšky)</translation>
    </message>
    <message>
        <source>Hemicube:</source>
        <translation>Polokrychle:</translation>
    </message>
    <message>
        <source> m</source>
        <translation> m</translation>
    </message>
    <message>
        <source>Patch size:</source>
        <translation>Velikost plošky:</translation>
    </message>
    <message>
        <source>Elements per patch:</source>
        <translation>Prvků na plošku:</translation>
    </message>
    <message>
        <source>Adaptive subdivision</source>
        <translation>Adaptivní dělení</translation>
    </message>
    <message>
        <source>Relative radiosity difference to a neighbour that splits an element</source>
        <translation>Relativní rozdíl radiozity vůči sousedovi, při kterém se prvek rozdělí</translation>
    </message>
    <message>
        <source>Threshold:</source>
        <translation>Práh:</translation>
    </message>
    <message>
        <source>Minimum edge:</source>
        <translation>Nejkratší hrana:</translation>
    </message>
    <message>
        <source>Anchor T-vertices</source>
        <translation>Ukotvit T-vrcholy</translation>
    </message>
    <message>
        <source>Maximum iterations:</source>
        <translation>Nejvýše iterací:</translation>
    </message>
    <message>
        <source>Stop when the unshot power falls below this fraction of the emitted power</source>
        <translation>Skončit, když nevyzářený výkon klesne pod tento podíl vyzářeného výkonu</translation>
    </message>
    <message>
        <source>Convergence:</source>
        <translation>Konvergence:</translation>
    </message>
    <message>
        <source>Painter (no z-buffer)</source>
        <translation>Malíř (bez z-bufferu)</translation>
    </message>
    <message>
        <source>Z-buffer</source>
        <translation>Z-buffer</translation>
    </message>
    <message>
        <source>Visibility:</source>
        <translation>Viditelnost:</translation>
    </message>
    <message>
        <source>Authored</source>
        <translation>Autorské</translation>
    </message>
    <message>
        <source>None (one BSP tree)</source>
        <translation>Žádné (jeden strom BSP)</translation>
    </message>
    <message>
        <source>Automatic</source>
        <translation>Automatické</translation>
    </message>
    <message>
        <source>Regions:</source>
        <translation>Oblasti:</translation>
    </message>
    <message>
        <source>Display</source>
        <translation>Zobrazení</translation>
    </message>
    <message>
        <source> EV</source>
        <translation> EV</translation>
    </message>
    <message>
        <source>Exposure:</source>
        <translation>Expozice:</translation>
    </message>
    <message>
        <source>Gamma:</source>
        <translation>Gama:</translation>
    </message>
    <message>
        <source>Ambient term</source>
        <translation>Ambientní složka</translation>
    </message>
    <message>
        <source>Show the not yet shot energy as a uniform ambient light (Cohen et al. 1988)</source>
        <translation>Zobrazit dosud nevyzářenou energii jako rovnoměrné okolní světlo (Cohen a kol. 1988)</translation>
    </message>
    <message>
        <source>False colour</source>
        <translation>Nepravé barvy</translation>
    </message>
    <message>
        <source>Logarithmic</source>
        <translation>Logaritmická</translation>
    </message>
    <message>
        <source>Linear</source>
        <translation>Lineární</translation>
    </message>
    <message>
        <source>Element mesh</source>
        <translation>Síť prvků</translation>
    </message>
    <message>
        <source>Inspector</source>
        <translation>Inspektor</translation>
    </message>
    <message>
        <source>Turn on Inspect and click a surface of the solution.</source>
        <translation>Zapněte Prozkoumat a klepněte na povrch řešení.</translation>
    </message>
    <message>
        <source>White at exposure 0: %1 W/m²</source>
        <translation>Bílá při expozici 0: %1 W/m²</translation>
    </message>
    <message>
        <source>Draw the element edges (where adaptive subdivision split elements) and, in orange (magenta on false colour), the edges anchoring adds to close T-vertices</source>
        <translation>Kreslit hrany elementů (kde adaptivní dělení elementy rozdělilo) a oranžově (ve falešných barvách purpurově) hrany, které ukotvení přidává k uzavření T-vrcholů</translation>
    </message>
</context>
<context>
    <name>regio::editor::Viewport</name>
    <message>
        <source>Clip: click three points on surfaces to define the cutting plane (Esc cancels)</source>
        <translation>Ořez: klikněte na tři body na plochách, které určí řeznou rovinu (Esc ruší)</translation>
    </message>
    <message>
        <source>OpenGL 3.3 is needed, this system offers %1.%2</source>
        <translation>Je potřeba OpenGL 3.3, tento systém nabízí %1.%2</translation>
    </message>
    <message>
        <source>The viewport shaders do not compile: %1</source>
        <translation>Shadery pohledu nelze přeložit: %1</translation>
    </message>
    <message>
        <source>%1 › %2 › %3</source>
        <translation>%1 › %2 › %3</translation>
    </message>
    <message>
        <source>Cancelled</source>
        <translation>Zrušeno</translation>
    </message>
</context>
</TS>
