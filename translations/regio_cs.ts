<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="cs_CZ">
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
    <message>
        <source>unreadable</source>
        <translation>nečitelný</translation>
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
        <source>User interface language for this run (en, cs).</source>
        <translation>Jazyk uživatelského rozhraní pro toto spuštění (en, cs).</translation>
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
        <source>Resolution N of the hemicube&apos;s top face (sides are N × N/2); even</source>
        <translation>Rozlišení N horní stěny polokrychle (boční stěny mají N × N/2); sudé</translation>
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
        <source>Threshold:</source>
        <translation>Práh:</translation>
    </message>
    <message>
        <source>Minimum edge:</source>
        <translation>Nejkratší hrana:</translation>
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
    <message>
        <source>cannot write %1: %2</source>
        <translation>nelze zapsat %1: %2</translation>
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
