<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>AcknowledgeDataLoss</name>
    <message>
        <location filename="../widgets/commands/acknowledge_data_loss_command.cpp" line="+20"/>
        <source>Acknowledge data loss</source>
        <translation>Datenverlust bestätigen</translation>
    </message>
</context>
<context>
    <name>CleaningStep</name>
    <message>
        <location filename="../widgets/panels/cleaning_step.cpp" line="+33"/>
        <source> on 1 marker</source>
        <translation> an 1 Marker</translation>
    </message>
    <message>
        <location line="+1"/>
        <source> on %1 markers</source>
        <translation> an %1 Markern</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>1 sample changed</source>
        <translation>1 Abtastwert geändert</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 samples changed</source>
        <translation>%1 Abtastwerte geändert</translation>
    </message>
</context>
<context>
    <name>FillRuleText</name>
    <message>
        <location filename="../widgets/models/fill_rule_text.cpp" line="+12"/>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message numerus="yes">
        <location line="+9"/>
        <source>over the %n-frame limit</source>
        <translation>
            <numerusform>über der Grenze von %n Frame</numerusform>
            <numerusform>über der Grenze von %n Frames</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2"/>
        <source>over the %1 limit</source>
        <translation>über der Grenze von %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>at the take&apos;s start: no extrapolation</source>
        <translation>am Anfang der Aufnahme: keine Extrapolation</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>at the take&apos;s end: no extrapolation</source>
        <translation>am Ende der Aufnahme: keine Extrapolation</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>marker seen in %1 % of the take</source>
        <translation>Marker in %1 % der Aufnahme sichtbar</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>marker never seen</source>
        <translation>Marker nie sichtbar</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a model output, not a marker</source>
        <translation>eine Modellausgabe, kein Marker</translation>
    </message>
</context>
<context>
    <name>GapFillStep</name>
    <message>
        <location filename="../widgets/panels/gap_fill_step.cpp" line="+35"/>
        <source>No gap filled</source>
        <translation>Keine Lücke gefüllt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>1 gap filled</source>
        <translation>1 Lücke gefüllt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 gaps filled</source>
        <translation>%1 Lücken gefüllt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>, 1 sample</source>
        <translation>, 1 Abtastwert</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>, %1 samples</source>
        <translation>, %1 Abtastwerte</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1 longer than %2</source>
        <translation>%1 länger als %2</translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>%n edge gap(s)</source>
        <translation>
            <numerusform>%n Randlücke</numerusform>
            <numerusform>%n Randlücken</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>%n on rarely seen markers</source>
        <translation>
            <numerusform>%n an selten sichtbaren Markern</numerusform>
            <numerusform>%n an selten sichtbaren Markern</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>%n on markers never seen</source>
        <translation>
            <numerusform>%n an nie sichtbaren Markern</numerusform>
            <numerusform>%n an nie sichtbaren Markern</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>%n the method could not fill</source>
        <translation>
            <numerusform>%n, die die Methode nicht füllen konnte</numerusform>
            <numerusform>%n, die die Methode nicht füllen konnte</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>%n on model outputs</source>
        <translation>
            <numerusform>%n auf einer Modellausgabe</numerusform>
            <numerusform>%n auf Modellausgaben</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>; %n left open</source>
        <translation>
            <numerusform>; %n offen geblieben</numerusform>
            <numerusform>; %n offen geblieben</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>HeadStabilizationStep</name>
    <message>
        <location filename="../widgets/panels/head_stabilization_step.cpp" line="+65"/>
        <source>No reference markers: choose them in Marker ▸ Reference Markers…</source>
        <translation>Keine Referenzmarker: Wählen Sie sie unter Marker ▸ Referenzmarker… aus</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>head pose measured in %1 of %2 frames</source>
        <translation>Kopfhaltung in %1 von %2 Bildern gemessen</translation>
    </message>
</context>
<context>
    <name>LiveLinkRecordingImport</name>
    <message>
        <location filename="../widgets/actions/live_link_recording_import.cpp" line="+29"/>
        <source>Load a rig first: the recording&apos;s curves animate its shapes.</source>
        <translation>Laden Sie zuerst ein Rig: Die Kurven der Aufnahme animieren seine Shapes.</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1: a recording needs two rows or more with increasing timecodes.</source>
        <translation>%1: Eine Aufzeichnung braucht zwei oder mehr Zeilen mit steigenden Timecodes.</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Open Live Link Recording %1</source>
        <translation>Live-Link-Aufzeichnung %1 öffnen</translation>
    </message>
</context>
<context>
    <name>MarkerMenus</name>
    <message>
        <location filename="../widgets/actions/marker_menus.cpp" line="+24"/>
        <source>&amp;Marker</source>
        <translation>&amp;Marker</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Delete Markers</source>
        <translation>Marker &amp;löschen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Remove the selected markers from the take (undoable)</source>
        <translation>Die ausgewählten Marker aus der Aufnahme entfernen (rückgängig machbar)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Add &amp;Averaged Marker…</source>
        <translation>&amp;Gemittelten Marker hinzufügen…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>A virtual marker at the mean of the selected markers</source>
        <translation>Ein virtueller Marker im Mittel der ausgewählten Marker</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Swap Over Range</source>
        <translation>Im Bereich &amp;tauschen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Exchange the data of the two selected markers over the selected frame range</source>
        <translation>Die Daten der beiden ausgewählten Marker im ausgewählten Bildbereich vertauschen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Reference Markers…</source>
        <translation>&amp;Referenzmarker…</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The head-mounted markers that head stabilization, layout planning and the face mesh use</source>
        <translation>Die am Kopf befestigten Marker, die Kopfstabilisierung, Layoutplanung und Gesichtsnetz verwenden</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Set Selected as Reference &amp;Markers</source>
        <translation>Auswahl als Referenz&amp;marker festlegen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Make the selected markers (at least three) the take&apos;s reference markers (undoable)</source>
        <translation>Die ausgewählten Marker (mindestens drei) zu den Referenzmarkern der Aufnahme machen (rückgängig machbar)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Hide Selected</source>
        <translation>Auswahl &amp;ausblenden</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Show &amp;All</source>
        <translation>&amp;Alle einblenden</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&amp;Label</source>
        <translation>&amp;Beschriftung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Track and Label</source>
        <translation>&amp;Verfolgen und beschriften</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Re-track the unlabelled points and give them the labels of the take&apos;s labelled markers</source>
        <translation>Die unbeschrifteten Punkte neu verfolgen und ihnen die Namen der beschrifteten Marker der Aufnahme geben</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Fix &amp;Swaps…</source>
        <translation>&amp;Vertauschungen beheben…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Find frames where two labels exchange and repair the ones you accept</source>
        <translation>Bilder finden, in denen zwei Namen vertauscht sind, und die bestätigten reparieren</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Assign Label by Clicking</source>
        <translation>Namen per &amp;Klick zuweisen</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Select a marker in the table, then click a point in the 3D view to give it that label</source>
        <translation>Einen Marker in der Tabelle wählen, dann einen Punkt in der 3D-Ansicht anklicken, um ihm diesen Namen zu geben</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Labelling: select a marker in the table, then click the point that is it</source>
        <translation>Beschriften: einen Marker in der Tabelle wählen, dann den Punkt anklicken, der er ist</translation>
    </message>
</context>
<context>
    <name>OffscreenRenderWindow</name>
    <message>
        <location filename="../widgets/views/offscreen_render_window.cpp" line="+66"/>
        <source>there is no X display (DISPLAY is not set); run under xvfb-run</source>
        <translation>es gibt keine X-Anzeige (DISPLAY ist nicht gesetzt); unter xvfb-run ausführen</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>cannot connect to the X display %1</source>
        <translation>keine Verbindung zur X-Anzeige %1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>OpenGL 3.2 is not available on this display</source>
        <translation>OpenGL 3.2 ist auf dieser Anzeige nicht verfügbar</translation>
    </message>
</context>
<context>
    <name>QProgressDialog</name>
    <message>
        <location filename="../widgets/dialogs/job_dialog.cpp" line="+35"/>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
</context>
<context>
    <name>RebindMarkerCommand</name>
    <message>
        <location filename="../widgets/commands/rebind_marker_command.cpp" line="+14"/>
        <source>Unbind %1</source>
        <translation>Bindung von %1 lösen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Bind %1 to vertex %2</source>
        <translation>%1 an Scheitelpunkt %2 binden</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Bind %1 to the surface</source>
        <translation>%1 an die Oberfläche binden</translation>
    </message>
</context>
<context>
    <name>RecoveryOffer</name>
    <message>
        <location filename="../widgets/actions/recovery_offer.cpp" line="+42"/>
        <source>an untitled take</source>
        <translation>einer unbenannten Aufnahme</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Recover unsaved edits?</source>
        <translation>Ungesicherte Änderungen wiederherstellen?</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Mocap Studio did not close normally. Unsaved edits of %1 were kept at %2. Recover them?</source>
        <translation>Mocap Studio wurde nicht normal beendet. Ungesicherte Änderungen von %1 wurden am %2 aufbewahrt. Wiederherstellen?</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Cannot recover</source>
        <translation>Wiederherstellen nicht möglich</translation>
    </message>
</context>
<context>
    <name>RemoveMarkersCommand</name>
    <message>
        <location filename="../widgets/commands/remove_markers_command.cpp" line="+19"/>
        <source>Delete marker %1</source>
        <translation>Marker %1 löschen</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Delete %1 markers</source>
        <translation>%1 Marker löschen</translation>
    </message>
</context>
<context>
    <name>RenameMarkerCommand</name>
    <message>
        <location filename="../widgets/commands/rename_marker_command.cpp" line="+12"/>
        <source>Rename %1 to %2</source>
        <translation>%1 in %2 umbenennen</translation>
    </message>
</context>
<context>
    <name>ReviewExport</name>
    <message>
        <location filename="../widgets/dialogs/review_export.cpp" line="+142"/>
        <source>No video at this frame</source>
        <translation>Kein Video bei diesem Frame</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>There is no take to review.</source>
        <translation>Es ist keine Aufnahme zum Prüfen geöffnet.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The frames to review are outside the take.</source>
        <translation>Die zu prüfenden Frames liegen außerhalb der Aufnahme.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The 3D view cannot render here: %1</source>
        <translation>Die 3D-Ansicht kann hier nicht rendern: %1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>The 3D view did not render frame %1.</source>
        <translation>Die 3D-Ansicht hat Frame %1 nicht gerendert.</translation>
    </message>
</context>
<context>
    <name>SampleState</name>
    <message>
        <location filename="../widgets/views/sample_colors.cpp" line="+55"/>
        <source>measured</source>
        <translation>gemessen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>filled</source>
        <translation>gefüllt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>edited</source>
        <translation>bearbeitet</translation>
    </message>
    <message>
        <location line="-12"/>
        <source>smoothed</source>
        <translation>geglättet</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>stabilized</source>
        <translation>stabilisiert</translation>
    </message>
</context>
<context>
    <name>SmoothingStep</name>
    <message>
        <location filename="../widgets/panels/smoothing_step.cpp" line="+135"/>
        <source>%1 smoothing</source>
        <translation>Glättung: %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>: moves samples by RMS %1 %3, at most %2 %3 (%4, frame %5)</source>
        <translation>: verschiebt Abtastwerte um RMS %1 %3, höchstens %2 %3 (%4, Bild %5)</translation>
    </message>
</context>
<context>
    <name>SpikeStep</name>
    <message numerus="yes">
        <location filename="../widgets/panels/spike_step.cpp" line="+122"/>
        <source>%n bad point(s) found</source>
        <translation>
            <numerusform>%n Ausreißer gefunden</numerusform>
            <numerusform>%n Ausreißer gefunden</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>; %n beside samples just repaired: a glitch longer than a few frames is found a part at a time (its worst samples first). Repair these too, or turn on &quot;Look again until nothing new&quot; to flag whole glitches at once</source>
        <translation>
            <numerusform>; %n davon neben gerade reparierten Abtastwerten: Eine Störung, die länger als einige Bilder dauert, wird stückweise gefunden (ihre schlimmsten Abtastwerte zuerst). Reparieren Sie auch diese, oder schalten Sie „Wiederholen, bis nichts Neues kommt“ ein, um ganze Störungen auf einmal zu markieren</numerusform>
            <numerusform>; %n davon neben gerade reparierten Abtastwerten: Eine Störung, die länger als einige Bilder dauert, wird stückweise gefunden (ihre schlimmsten Abtastwerte zuerst). Reparieren Sie auch diese, oder schalten Sie „Wiederholen, bis nichts Neues kommt“ ein, um ganze Störungen auf einmal zu markieren</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>TakeUnitsMenu</name>
    <message>
        <location filename="../widgets/actions/take_units_menu.cpp" line="+30"/>
        <source>Positions Are In %1 (were read as %2)</source>
        <translation>Positionen sind in %1 (gelesen als %2)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Positions Are &amp;In</source>
        <translation>Positionen sind &amp;in</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The file&apos;s numbers are in this unit (nothing is rescaled; undoable)</source>
        <translation>Die Zahlen der Datei sind in dieser Einheit (nichts wird umgerechnet; rückgängig machbar)</translation>
    </message>
</context>
<context>
    <name>ViewOptionActions</name>
    <message>
        <location filename="../widgets/actions/view_option_actions.cpp" line="+28"/>
        <source>Y Axis Up</source>
        <translation>Y-Achse nach oben</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Z Axis Up</source>
        <translation>Z-Achse nach oben</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>&amp;Reset Camera</source>
        <translation>Kamera &amp;zurücksetzen</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Trails</source>
        <translation>&amp;Spuren</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Marker &amp;Links</source>
        <translation>Marker&amp;verbindungen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Show &amp;Model Outputs</source>
        <translation>&amp;Modellausgaben anzeigen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Draw and gap-list the joint angles, forces, moments, powers and virtual points a C3D file stores as points (they are never cleaned)</source>
        <translation>Die Gelenkwinkel, Kräfte, Momente, Leistungen und virtuellen Punkte, die eine C3D-Datei als Punkte speichert, zeichnen und in der Lückenliste zeigen (sie werden nie bereinigt)</translation>
    </message>
    <message>
        <source>Draw and gap-list the joint angles, forces, moments and powers a C3D file stores as points (they are never cleaned)</source>
        <translation type="vanished">Gelenkwinkel, Kräfte, Momente und Leistungen, die eine C3D-Datei als Punkte speichert, zeichnen und in der Lückenliste zeigen (sie werden nie bereinigt)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Follow Head</source>
        <translation>Kopf &amp;folgen</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Keep the camera on the head as it moves (the centroid of the head markers)</source>
        <translation>Die Kamera folgt dem Kopf, wenn er sich bewegt (dem Schwerpunkt der Kopfmarker)</translation>
    </message>
</context>
<context>
    <name>mocap::studio::MainWindow</name>
    <message>
        <location filename="../app/studio/main_window.cpp" line="+104"/>
        <source>Timeline</source>
        <translation>Zeitleiste</translation>
    </message>
    <message>
        <source>Frame %1 of %2–%3 — %4 markers selected</source>
        <translation type="vanished">Frame %1 von %2–%3 — %4 Marker ausgewählt</translation>
    </message>
    <message>
        <location line="+40"/>
        <source>Autosave failed: %1</source>
        <translation>Automatisches Sichern fehlgeschlagen: %1</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Markers</source>
        <translation>Marker</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Curves</source>
        <translation>Kurven</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>History</source>
        <translation>Verlauf</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Cleaning</source>
        <translation>Bereinigung</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Layout planning</source>
        <translation>Layoutplanung</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Gaps</source>
        <translation>Lücken</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Face Mesh</source>
        <translation>Gesichtsnetz</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Blendshape Solve</source>
        <translation>Blendshape-Solve</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Reference Video</source>
        <translation>Referenzvideo</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Live Stream</source>
        <translation>Live-Stream</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Weights</source>
        <translation>Gewichte</translation>
    </message>
    <message>
        <source>Export Animation</source>
        <translation type="vanished">Animation exportieren</translation>
    </message>
    <message>
        <source>The face mesh cannot be exported: %1</source>
        <translation type="vanished">Das Gesichtsnetz kann nicht exportiert werden: %1</translation>
    </message>
    <message>
        <source>Rendering the review video…</source>
        <translation type="vanished">Das Prüfvideo wird gerendert…</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation type="vanished">Abbrechen</translation>
    </message>
    <message>
        <source>Review video cancelled; nothing was written.</source>
        <translation type="vanished">Prüfvideo abgebrochen; es wurde nichts geschrieben.</translation>
    </message>
    <message>
        <source>Export Review Video</source>
        <translation type="vanished">Prüfvideo exportieren</translation>
    </message>
    <message>
        <source>The review video was not written: %1</source>
        <translation type="vanished">Das Prüfvideo wurde nicht geschrieben: %1</translation>
    </message>
    <message>
        <source>This system has no MP4 encoder, so the video was written as Motion JPEG AVI: %1</source>
        <translation type="vanished">Dieses System hat keinen MP4-Encoder, daher wurde das Video als Motion-JPEG-AVI geschrieben: %1</translation>
    </message>
    <message>
        <source>Wrote %1 (%2 frames, %3)</source>
        <translation type="vanished">%1 geschrieben (%2 Frames, %3)</translation>
    </message>
    <message>
        <location line="+63"/>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Open…</source>
        <translation>Ö&amp;ffnen…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Open &amp;Recent</source>
        <translation>&amp;Zuletzt geöffnet</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Keep Face Rig for the Next Take</source>
        <translation>Gesichts-&amp;Rig für den nächsten Take behalten</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Opening another take keeps the face mesh, its marker binding and the blendshape rig (the actor&apos;s), bound to the markers the new take has; off, every take starts without them</source>
        <translation>Beim Öffnen eines anderen Takes bleiben das Gesichtsnetz, seine Markerbindung und das Blendshape-Rig (die des Darstellers) erhalten, gebunden an die Marker des neuen Takes; aus: jeder Take beginnt ohne sie</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Face rig kept for this take: %1</source>
        <translation>Gesichts-Rig für diesen Take behalten: %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Save</source>
        <translation>&amp;Speichern</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save &amp;As…</source>
        <translation>Speichern &amp;unter…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Export…</source>
        <translation>&amp;Exportieren…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Export Ani&amp;mation…</source>
        <translation>Ani&amp;mation exportieren…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Export Re&amp;view Video…</source>
        <translation>&amp;Prüfvideo exportieren…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Export Ri&amp;g…</source>
        <translation>Ri&amp;g exportieren…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The solved rig as FBX or glTF, or its curves as CSV, through a retarget map (Blendshape Solve)</source>
        <translation>Das gelöste Rig als FBX oder glTF oder seine Kurven als CSV, über eine Retarget-Zuordnung (Blendshape-Solve)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save &amp;Cleaning Preset…</source>
        <translation>&amp;Bereinigungsvorgabe speichern…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Load Cleaning Preset…</source>
        <translation>Bereinigungsvorgabe &amp;laden…</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Edit</source>
        <translation>&amp;Bearbeiten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Undo</source>
        <translation>&amp;Rückgängig</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Redo</source>
        <translation>&amp;Wiederherstellen</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;Delete Range</source>
        <translation>Bereich &amp;löschen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Make the selected frame range of the selected markers a gap (Shift-drag on the curves)</source>
        <translation>Den ausgewählten Frame-Bereich der ausgewählten Marker zur Lücke machen (Umschalt-Ziehen auf den Kurven)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Rename Marker…</source>
        <translation>Marker &amp;umbenennen…</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Preferences…</source>
        <translation>&amp;Einstellungen…</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <location line="+61"/>
        <source>%1 (%2)[*] — Mocap Studio</source>
        <translation>%1 (%2)[*] — Mocap Studio</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Recovered unsaved edits of %1; not restored: %2</source>
        <translation>Nicht gespeicherte Änderungen von %1 wiederhergestellt; nicht wiederhergestellt: %2</translation>
    </message>
    <message>
        <source>&amp;Reset Camera</source>
        <translation type="vanished">Kamera &amp;zurücksetzen</translation>
    </message>
    <message>
        <source>Y Axis Up</source>
        <translation type="vanished">Y-Achse nach oben</translation>
    </message>
    <message>
        <source>Z Axis Up</source>
        <translation type="vanished">Z-Achse nach oben</translation>
    </message>
    <message>
        <source>&amp;Trails</source>
        <translation type="vanished">&amp;Spuren</translation>
    </message>
    <message>
        <source>Marker &amp;Links</source>
        <translation type="vanished">Marker&amp;verbindungen</translation>
    </message>
    <message>
        <source>Show &amp;Model Outputs</source>
        <translation type="vanished">&amp;Modellausgaben anzeigen</translation>
    </message>
    <message>
        <source>Draw and gap-list the joint angles, forces, moments and powers a C3D file stores as points (they are never cleaned)</source>
        <translation type="vanished">Gelenkwinkel, Kräfte, Momente und Leistungen, die eine C3D-Datei als Punkte speichert, zeichnen und in der Lückenliste zeigen (sie werden nie bereinigt)</translation>
    </message>
    <message>
        <source>&amp;Follow Head</source>
        <translation type="vanished">Kopf &amp;folgen</translation>
    </message>
    <message>
        <source>Keep the camera on the head as it moves (the centroid of the head markers)</source>
        <translation type="vanished">Die Kamera folgt dem Kopf, wenn er sich bewegt (dem Schwerpunkt der Kopfmarker)</translation>
    </message>
    <message>
        <location line="-82"/>
        <source>&amp;Language</source>
        <translation>&amp;Sprache</translation>
    </message>
    <message>
        <source>Language</source>
        <translation type="vanished">Sprache</translation>
    </message>
    <message>
        <source>The new language is used from the next start.</source>
        <translation type="vanished">Die neue Sprache wird ab dem nächsten Start verwendet.</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Manual</source>
        <translation>&amp;Handbuch</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;About Mocap Studio</source>
        <translation>&amp;Über Mocap Studio</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>About Mocap Studio</source>
        <translation>Über Mocap Studio</translation>
    </message>
    <message>
        <source>3D view in the lab frame</source>
        <translation type="vanished">3D-Ansicht im Laborkoordinatensystem</translation>
    </message>
    <message>
        <source>Head-Stabilized View</source>
        <translation type="vanished">Kopfstabilisierte Ansicht</translation>
    </message>
    <message>
        <source>&amp;Head-Stabilized View</source>
        <translation type="vanished">&amp;Kopfstabilisierte Ansicht</translation>
    </message>
    <message>
        <source>Show the markers in the head frame of the reference markers (a view setting; the take is not changed)</source>
        <translation type="vanished">Die Marker im Kopfkoordinatensystem der Referenzmarker anzeigen (eine Ansichtseinstellung; die Aufnahme wird nicht verändert)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&lt;b&gt;Mocap Studio %1&lt;/b&gt;&lt;p&gt;Cleaning and using facial optical motion capture.&lt;/p&gt;</source>
        <translation>&lt;b&gt;Mocap Studio %1&lt;/b&gt;&lt;p&gt;Bereinigung und Nutzung optischer Gesichts-Motion-Capture-Daten.&lt;/p&gt;</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&lt;p&gt;Keys: Space play/pause, ←/→ step (Shift: 10), Home/End, PgUp/PgDn previous/next gap, Ctrl+PgUp/PgDn previous/next bad point, Ctrl+R reset camera, L marker links, H hide, Shift+H show all, Ctrl+drag rubber-band selection, Ctrl+B head-stabilized view, F camera follows the head, Ctrl+Shift+S save as.&lt;/p&gt;</source>
        <translation>&lt;p&gt;Tasten: Leertaste Wiedergabe/Pause, ←/→ Einzelbild (Umschalt: 10), Pos1/Ende, Bild↑/Bild↓ vorherige/nächste Lücke, Strg+Bild↑/Bild↓ vorheriger/nächster Ausreißer, Strg+R Kamera zurücksetzen, L Markerverbindungen, H ausblenden, Umschalt+H alle einblenden, Strg+Ziehen Rahmenauswahl, Strg+B kopfstabilisierte Ansicht, F Kamera folgt dem Kopf, Strg+Umschalt+S Speichern unter.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>Choose at least three reference markers first (Marker ▸ Reference Markers…).</source>
        <translation type="vanished">Wählen Sie zuerst mindestens drei Referenzmarker (Marker ▸ Referenzmarker…).</translation>
    </message>
    <message>
        <source>3D view stabilized on the reference markers (Ctrl+B again for the lab frame)</source>
        <translation type="vanished">3D-Ansicht auf die Referenzmarker stabilisiert (Strg+B erneut für das Laborkoordinatensystem)</translation>
    </message>
    <message>
        <source>3D view back in the lab frame: the reference markers cannot carry a head pose</source>
        <translation type="vanished">3D-Ansicht wieder im Laborkoordinatensystem: Aus den Referenzmarkern lässt sich keine Kopfhaltung bestimmen</translation>
    </message>
    <message>
        <source>Head markers set; Edit ▸ Undo takes them back</source>
        <translation type="vanished">Kopfmarker gesetzt; Bearbeiten ▸ Rückgängig nimmt sie zurück</translation>
    </message>
    <message>
        <source>Reference markers unchanged</source>
        <translation type="vanished">Referenzmarker unverändert</translation>
    </message>
    <message>
        <source>Select at least three head-mounted markers first</source>
        <translation type="vanished">Wählen Sie zuerst mindestens drei am Kopf befestigte Marker aus</translation>
    </message>
    <message>
        <source>The selected markers already are the reference markers</source>
        <translation type="vanished">Die ausgewählten Marker sind bereits die Referenzmarker</translation>
    </message>
    <message>
        <source>&amp;Marker</source>
        <translation type="vanished">&amp;Marker</translation>
    </message>
    <message>
        <source>&amp;Delete Markers</source>
        <translation type="vanished">Marker &amp;löschen</translation>
    </message>
    <message>
        <source>Remove the selected markers from the take (undoable)</source>
        <translation type="vanished">Die ausgewählten Marker aus der Aufnahme entfernen (rückgängig machbar)</translation>
    </message>
    <message>
        <source>Add &amp;Averaged Marker…</source>
        <translation type="vanished">&amp;Gemittelten Marker hinzufügen…</translation>
    </message>
    <message>
        <source>A virtual marker at the mean of the selected markers</source>
        <translation type="vanished">Ein virtueller Marker im Mittel der ausgewählten Marker</translation>
    </message>
    <message>
        <source>&amp;Swap Over Range</source>
        <translation type="vanished">Im Bereich &amp;tauschen</translation>
    </message>
    <message>
        <source>Exchange the data of the two selected markers over the selected frame range</source>
        <translation type="vanished">Die Daten der beiden ausgewählten Marker im ausgewählten Bildbereich vertauschen</translation>
    </message>
    <message>
        <source>&amp;Reference Markers…</source>
        <translation type="vanished">&amp;Referenzmarker…</translation>
    </message>
    <message>
        <source>The head-mounted markers that head stabilization, layout planning and the face mesh use</source>
        <translation type="vanished">Die am Kopf befestigten Marker, die Kopfstabilisierung, Layoutplanung und Gesichtsnetz verwenden</translation>
    </message>
    <message>
        <source>Set Selected as Reference &amp;Markers</source>
        <translation type="vanished">Auswahl als Referenz&amp;marker festlegen</translation>
    </message>
    <message>
        <source>Make the selected markers (at least three) the take&apos;s reference markers (undoable)</source>
        <translation type="vanished">Die ausgewählten Marker (mindestens drei) zu den Referenzmarkern der Aufnahme machen (rückgängig machbar)</translation>
    </message>
    <message>
        <source>&amp;Hide Selected</source>
        <translation type="vanished">Auswahl &amp;ausblenden</translation>
    </message>
    <message>
        <source>Show &amp;All</source>
        <translation type="vanished">&amp;Alle einblenden</translation>
    </message>
    <message>
        <source>&amp;Label</source>
        <translation type="vanished">&amp;Beschriftung</translation>
    </message>
    <message>
        <source>&amp;Track and Label</source>
        <translation type="vanished">&amp;Verfolgen und beschriften</translation>
    </message>
    <message>
        <source>Re-track the unlabelled points and give them the labels of the take&apos;s labelled markers</source>
        <translation type="vanished">Die unbeschrifteten Punkte neu verfolgen und ihnen die Namen der beschrifteten Marker der Aufnahme geben</translation>
    </message>
    <message>
        <source>Fix &amp;Swaps…</source>
        <translation type="vanished">&amp;Vertauschungen beheben…</translation>
    </message>
    <message>
        <source>Find frames where two labels exchange and repair the ones you accept</source>
        <translation type="vanished">Bilder finden, in denen zwei Namen vertauscht sind, und die bestätigten reparieren</translation>
    </message>
    <message>
        <source>&amp;Assign Label by Clicking</source>
        <translation type="vanished">Namen per &amp;Klick zuweisen</translation>
    </message>
    <message>
        <source>Select a marker in the table, then click a point in the 3D view to give it that label</source>
        <translation type="vanished">Einen Marker in der Tabelle wählen, dann einen Punkt in der 3D-Ansicht anklicken, um ihm diesen Namen zu geben</translation>
    </message>
    <message>
        <source>Labelling: select a marker in the table, then click the point that is it</source>
        <translation type="vanished">Beschriften: einen Marker in der Tabelle wählen, dann den Punkt anklicken, der er ist</translation>
    </message>
    <message>
        <source>Opening %1…</source>
        <translation type="vanished">%1 wird geöffnet…</translation>
    </message>
    <message>
        <source>Cancelled</source>
        <translation type="vanished">Abgebrochen</translation>
    </message>
    <message>
        <source>Cannot open file</source>
        <translation type="vanished">Datei kann nicht geöffnet werden</translation>
    </message>
    <message numerus="yes">
        <source>⚠ Incomplete: %n warning(s)</source>
        <translation type="vanished">
            <numerusform>⚠ Unvollständig: %n Warnung</numerusform>
            <numerusform>⚠ Unvollständig: %n Warnungen</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>⚠ %n warning(s)</source>
        <translation type="vanished">
            <numerusform>⚠ %n Warnung</numerusform>
            <numerusform>⚠ %n Warnungen</numerusform>
        </translation>
    </message>
    <message>
        <source>Show every warning from reading the file</source>
        <translation type="vanished">Alle Warnungen beim Lesen der Datei anzeigen</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation type="vanished">%1 gespeichert</translation>
    </message>
    <message>
        <source>%1 — note: %2</source>
        <translation type="vanished">%1 — Hinweis: %2</translation>
    </message>
    <message>
        <source>Save Cleaning Preset</source>
        <translation type="vanished">Bereinigungsvorgabe speichern</translation>
    </message>
    <message>
        <source>Cleaning presets (*.json)</source>
        <translation type="vanished">Bereinigungsvorgaben (*.json)</translation>
    </message>
    <message>
        <source>Include this take&apos;s head markers (%1)</source>
        <translation type="vanished">Die Kopfmarker dieser Aufnahme mitspeichern (%1)</translation>
    </message>
    <message>
        <source>none chosen</source>
        <translation type="vanished">keine gewählt</translation>
    </message>
    <message>
        <source>A preset carries cleaning options; head markers belong to a take. Include them only when every take the preset is for names its head markers the same way: a take without them then fails with that reason.</source>
        <translation type="vanished">Eine Vorgabe enthält Bereinigungsoptionen; Kopfmarker gehören zu einer Aufnahme. Speichern Sie sie nur mit, wenn jede Aufnahme, für die die Vorgabe gedacht ist, ihre Kopfmarker gleich benennt: eine Aufnahme ohne sie schlägt dann mit diesem Grund fehl.</translation>
    </message>
    <message>
        <source>The preset was not saved: %1</source>
        <translation type="vanished">Die Vorgabe wurde nicht gespeichert: %1</translation>
    </message>
    <message>
        <source>Saved the cleaning preset %1</source>
        <translation type="vanished">Bereinigungsvorgabe %1 gespeichert</translation>
    </message>
    <message>
        <source>Loaded the cleaning preset %1 into the Cleaning panel; nothing changes the take until Apply</source>
        <translation type="vanished">Bereinigungsvorgabe %1 in das Bereinigungsfenster geladen; die Aufnahme ändert sich erst mit Anwenden</translation>
    </message>
    <message>
        <source>; it turns off %1 (left as they were)</source>
        <translation type="vanished">; sie schaltet %1 aus (unverändert gelassen)</translation>
    </message>
    <message>
        <source>; its head markers (%1) are not this take&apos;s: the take keeps its own</source>
        <translation type="vanished">; ihre Kopfmarker (%1) gehören nicht zu dieser Aufnahme: die Aufnahme behält ihre eigenen</translation>
    </message>
    <message>
        <source>Load Cleaning Preset</source>
        <translation type="vanished">Bereinigungsvorgabe laden</translation>
    </message>
    <message>
        <source>Cleaning presets (*.json);;All files (*)</source>
        <translation type="vanished">Bereinigungsvorgaben (*.json);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>The preset was not loaded: %1</source>
        <translation type="vanished">Die Vorgabe wurde nicht geladen: %1</translation>
    </message>
    <message>
        <source>The face mesh of the recovered session could not be restored: %1</source>
        <translation type="vanished">Das Gesichtsnetz der wiederhergestellten Sitzung konnte nicht geladen werden: %1</translation>
    </message>
    <message>
        <location line="+81"/>
        <source>Cancel the running job before closing</source>
        <translation>Vor dem Schließen den laufenden Auftrag abbrechen</translation>
    </message>
    <message>
        <source>Open take</source>
        <translation type="vanished">Take öffnen</translation>
    </message>
    <message>
        <source>Overwrite the original?</source>
        <translation type="vanished">Original überschreiben?</translation>
    </message>
    <message>
        <source>Save over %1? The original capture is replaced by the edited take.</source>
        <translation type="vanished">%1 überschreiben? Die Originalaufnahme wird durch den bearbeiteten Take ersetzt.</translation>
    </message>
    <message>
        <source>Cannot save</source>
        <translation type="vanished">Speichern nicht möglich</translation>
    </message>
    <message>
        <source>Save take as</source>
        <translation type="vanished">Take speichern unter</translation>
    </message>
    <message>
        <source>C3D (*.c3d);;TRC (*.trc)</source>
        <translation type="vanished">C3D (*.c3d);;TRC (*.trc)</translation>
    </message>
    <message>
        <source>Export</source>
        <translation type="vanished">Exportieren</translation>
    </message>
    <message>
        <source>C3D (*.c3d);;TRC (*.trc);;CSV (*.csv);;BVH (*.bvh);;FBX markers (*.fbx)</source>
        <translation type="vanished">C3D (*.c3d);;TRC (*.trc);;CSV (*.csv);;BVH (*.bvh);;FBX-Marker (*.fbx)</translation>
    </message>
    <message>
        <source>Cannot export</source>
        <translation type="vanished">Export nicht möglich</translation>
    </message>
    <message>
        <source>Exported %1</source>
        <translation type="vanished">%1 exportiert</translation>
    </message>
    <message>
        <source>Unsaved edits</source>
        <translation type="vanished">Ungespeicherte Änderungen</translation>
    </message>
    <message>
        <source>The take has unsaved edits. Save them?</source>
        <translation type="vanished">Der Take enthält ungespeicherte Änderungen. Speichern?</translation>
    </message>
    <message>
        <location line="-44"/>
        <source>Untitled</source>
        <translation>Unbenannt</translation>
    </message>
    <message>
        <source>%1 (incomplete)[*] — Mocap Studio</source>
        <translation type="vanished">%1 (unvollständig)[*] — Mocap Studio</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1[*] — Mocap Studio</source>
        <translation>%1[*] — Mocap Studio</translation>
    </message>
    <message>
        <source>an untitled take</source>
        <translation type="vanished">einer unbenannten Aufnahme</translation>
    </message>
    <message>
        <source>Recover unsaved edits?</source>
        <translation type="vanished">Ungesicherte Änderungen wiederherstellen?</translation>
    </message>
    <message>
        <source>Mocap Studio did not close normally. Unsaved edits of %1 were kept at %2. Recover them?</source>
        <translation type="vanished">Mocap Studio wurde nicht normal beendet. Ungesicherte Änderungen von %1 wurden am %2 aufbewahrt. Wiederherstellen?</translation>
    </message>
    <message>
        <source>Cannot recover</source>
        <translation type="vanished">Wiederherstellen nicht möglich</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Recovered unsaved edits of %1; save them to keep them</source>
        <translation>Ungesicherte Änderungen von %1 wiederhergestellt; speichern Sie sie, um sie zu behalten</translation>
    </message>
    <message>
        <source>Motion capture (*.c3d *.trc);;All files (*)</source>
        <translation type="vanished">Motion-Capture (*.c3d *.trc);;Alle Dateien (*)</translation>
    </message>
</context>
<context>
    <name>mocap::ui::ActorActions</name>
    <message>
        <location filename="../widgets/actions/actor_actions.cpp" line="+57"/>
        <source>&amp;Actor</source>
        <translation>&amp;Darsteller</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;New from Neutral Frame…</source>
        <translation>&amp;Neu aus neutralem Frame…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The bound markers at the current frame as an actor&apos;s neutral (mocap actor --neutral TAKE:FRAME)</source>
        <translation>Die gebundenen Marker im aktuellen Frame als Neutralpose eines Darstellers (mocap actor --neutral TAKE:FRAME)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Calibrate from ROM Take…</source>
        <translation>Aus ROM-Aufnahme &amp;kalibrieren…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Each shape&apos;s extent for the loaded actor from a range-of-motion take (mocap actor --rom)</source>
        <translation>Der Umfang jedes Shapes für den geladenen Darsteller aus einer Bewegungsumfang-Aufnahme (mocap actor --rom)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Load Actor…</source>
        <translation>Darsteller &amp;laden…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>An actor profile for the solve (mocap solve --actor)</source>
        <translation>Ein Darstellerprofil für den Solve (mocap solve --actor)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>C&amp;lear Actor</source>
        <translation>Darsteller &amp;entfernen</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Open a take, load a rig and bind the markers to its neutral first.</source>
        <translation>Öffnen Sie zuerst eine Aufnahme, laden Sie ein Rig und binden Sie die Marker an seine Neutralpose.</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>No actor made: %1</source>
        <translation>Kein Darsteller erstellt: %1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Load a rig and an actor (or make one from a neutral frame) first.</source>
        <translation>Laden Sie zuerst ein Rig und einen Darsteller (oder erstellen Sie einen aus einem neutralen Frame).</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Calibrating from %1…</source>
        <translation>Kalibrieren aus %1…</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Calibration cancelled; the actor is as it was.</source>
        <translation>Kalibrierung abgebrochen; der Darsteller bleibt unverändert.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Not calibrated: %1</source>
        <translation>Nicht kalibriert: %1</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Cannot load the actor: %1</source>
        <translation>Der Darsteller kann nicht geladen werden: %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Actor %1: the solve uses its neutral and range.</source>
        <translation>Darsteller %1: Der Solve verwendet seine Neutralpose und seinen Umfang.</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>New Actor from Neutral Frame</source>
        <translation>Neuer Darsteller aus neutralem Frame</translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+13"/>
        <source>Actor profiles (*.json)</source>
        <translation>Darstellerprofile (*.json)</translation>
    </message>
    <message>
        <location line="-5"/>
        <source>Range-of-Motion Take</source>
        <translation>Bewegungsumfang-Aufnahme</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Takes (*.c3d *.trc);;All files (*)</source>
        <translation>Aufnahmen (*.c3d *.trc);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Save the Calibrated Actor</source>
        <translation>Kalibrierten Darsteller speichern</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Load Actor</source>
        <translation>Darsteller laden</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Actor profiles (*.json);;All files (*)</source>
        <translation>Darstellerprofile (*.json);;Alle Dateien (*)</translation>
    </message>
</context>
<context>
    <name>mocap::ui::Autosave</name>
    <message>
        <location filename="../widgets/document/autosave.cpp" line="+117"/>
        <source>Cannot create the recovery folder %1</source>
        <translation>Der Wiederherstellungsordner %1 kann nicht angelegt werden</translation>
    </message>
</context>
<context>
    <name>mocap::ui::BlendshapeSolvePanel</name>
    <message>
        <location filename="../widgets/panels/blendshape_solve_panel.cpp" line="+134"/>
        <source>The take has changed since this solve; Solve again to update the weights.</source>
        <translation>Die Aufnahme hat sich seit diesem Lösen geändert; lösen Sie erneut, um die Gewichte anzupassen.</translation>
    </message>
    <message>
        <location line="+21"/>
        <location line="+277"/>
        <source>Load a rig, bind the markers to its neutral in the Face Mesh panel, then Solve.</source>
        <translation>Laden Sie ein Rig, binden Sie die Marker im Face-Mesh-Panel an seine Neutralform und lösen Sie dann.</translation>
    </message>
    <message>
        <location line="-272"/>
        <source>Rig</source>
        <translation>Rig</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+260"/>
        <source>No rig</source>
        <translation>Kein Rig</translation>
    </message>
    <message>
        <location line="-256"/>
        <source>Load glTF Rig…</source>
        <translation>glTF-Rig laden…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A .glb or .gltf with the neutral mesh and one morph target per shape</source>
        <translation>Eine .glb- oder .gltf-Datei mit dem neutralen Mesh und einem Morph-Target je Shape</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Load OBJ Rig…</source>
        <translation>OBJ-Rig laden…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A neutral OBJ/PLY and a folder with one OBJ per shape, named after it</source>
        <translation>Ein neutrales OBJ/PLY und ein Ordner mit einem OBJ je Shape, nach ihm benannt</translation>
    </message>
    <message>
        <location line="+10"/>
        <location line="+33"/>
        <source>Solve</source>
        <translation>Lösen</translation>
    </message>
    <message>
        <location line="-29"/>
        <source>Temporal (smooth over time)</source>
        <translation>Zeitlich (glatt über die Zeit)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ridge (per frame)</source>
        <translation>Ridge (je Frame)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Bounded least squares (per frame)</source>
        <translation>Beschränkte kleinste Quadrate (je Frame)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Method:</source>
        <translation>Methode:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Automatic (GCV)</source>
        <translation>Automatisch (GCV)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Ridge weight λ, relative to the shapes&apos; mean squared motion</source>
        <translation>Ridge-Gewicht λ, relativ zur mittleren quadratischen Bewegung der Shapes</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>λ:</source>
        <translation>λ:</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Weight of the weights&apos; second differences over time, as at 100 Hz</source>
        <translation>Gewicht der zweiten Differenzen der Gewichte über die Zeit, wie bei 100 Hz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Smoothness:</source>
        <translation>Glätte:</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>L1 weight pulling unused shapes to zero</source>
        <translation>L1-Gewicht, das unbenutzte Shapes auf null zieht</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sparsity:</source>
        <translation>Sparsamkeit:</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Solve every frame of the take to the rig&apos;s weights (on a worker; Cancel stops it)</source>
        <translation>Jeden Frame der Aufnahme auf die Gewichte des Rigs lösen (im Hintergrund; Abbrechen stoppt es)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Cancelling…</source>
        <translation>Wird abgebrochen…</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Shapes</source>
        <translation>Shapes</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Filter shapes (e.g. mouth)</source>
        <translation>Shapes filtern (z. B. mouth)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Selected shapes are drawn in the Weights view and edited below</source>
        <translation>Ausgewählte Shapes werden in der Gewichtsansicht gezeichnet und unten bearbeitet</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Scale</source>
        <translation>Skalieren</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Zero</source>
        <translation>Nullen</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Scale by:</source>
        <translation>Skalieren um:</translation>
    </message>
    <message>
        <location line="+5"/>
        <source> Hz</source>
        <translation> Hz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Smooth</source>
        <translation>Glätten</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Low-pass:</source>
        <translation>Tiefpass:</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Edits apply to the selected shapes over the frame range selected on the curves (Shift-drag), or the whole take; Ctrl+Z undoes them.</source>
        <translation>Bearbeitungen gelten für die ausgewählten Shapes im auf den Kurven gewählten Frame-Bereich (Umschalt-Ziehen) oder für die ganze Aufnahme; Strg+Z macht sie rückgängig.</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Display and export</source>
        <translation>Anzeige und Export</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Show the solved rig in the 3D view</source>
        <translation>Das gelöste Rig in der 3D-Ansicht zeigen</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Beside the markers (else over them)</source>
        <translation>Neben den Markern (sonst über ihnen)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Open Live Link Recording…</source>
        <translation>Live-Link-Aufzeichnung öffnen…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A Live Link Face CSV as the rig&apos;s weight curves, through a map (undoable)</source>
        <translation>Eine Live-Link-Face-CSV als Gewichtskurven des Rigs, über eine Zuordnung (rückgängig machbar)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Export Weights…</source>
        <translation>Gewichte exportieren…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Weight curves as CSV: one column per shape (plain or Live Link Face layout)</source>
        <translation>Gewichtskurven als CSV: eine Spalte je Shape (einfach oder im Live-Link-Face-Layout)</translation>
    </message>
    <message>
        <location line="+341"/>
        <source>Solve the take, or open a Live Link recording, first: there are no curves to export.</source>
        <translation>Lösen Sie zuerst die Aufnahme oder öffnen Sie eine Live-Link-Aufzeichnung: Es gibt keine Kurven zum Exportieren.</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Cannot open the recording: %1</source>
        <translation>Die Aufzeichnung kann nicht geöffnet werden: %1</translation>
    </message>
    <message numerus="yes">
        <location line="+4"/>
        <source>Opened %1: %n sample(s) at %2 Hz from %3 as the curves of %4 shapes; exports keep its rate and timecode.</source>
        <translation>
            <numerusform>%1 geöffnet: %n Abtastwert mit %2 Hz ab %3 als Kurven von %4 Shapes; Exporte behalten seine Rate und seinen Timecode.</numerusform>
            <numerusform>%1 geöffnet: %n Abtastwerte mit %2 Hz ab %3 als Kurven von %4 Shapes; Exporte behalten ihre Rate und ihren Timecode.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Recorded at %1 Hz: resampled to the take&apos;s rate.</source>
        <translation>Mit %1 Hz aufgezeichnet: auf die Rate der Aufnahme umgerechnet.</translation>
    </message>
    <message>
        <source>Export Rig GLB…</source>
        <translation type="vanished">Rig als GLB exportieren…</translation>
    </message>
    <message>
        <source>The rig with its morph targets and the weights as an animation (Blender, Unity, three.js)</source>
        <translation type="vanished">Das Rig mit seinen Morph-Targets und den Gewichten als Animation (Blender, Unity, three.js)</translation>
    </message>
    <message>
        <location line="-274"/>
        <source>Wait for the running job, or cancel it.</source>
        <translation>Warten Sie auf den laufenden Auftrag oder brechen Sie ihn ab.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Reading %1…</source>
        <translation>%1 wird gelesen…</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Cannot read the rig %1: %2</source>
        <translation>Das Rig %1 kann nicht gelesen werden: %2</translation>
    </message>
    <message numerus="yes">
        <location line="+14"/>
        <source>%1: %n shape(s), %2 vertices</source>
        <translation>
            <numerusform>%1: %n Shape, %2 Vertices</numerusform>
            <numerusform>%1: %n Shapes, %2 Vertices</numerusform>
        </translation>
    </message>
    <message>
        <location line="-8"/>
        <source>Rig loaded. Bind the markers to its neutral in the Face Mesh panel (Auto-Bind or Load Binding), then Solve.</source>
        <translation>Rig geladen. Binden Sie die Marker im Face-Mesh-Panel an seine Neutralform (Automatisch binden oder Bindung laden) und lösen Sie dann.</translation>
    </message>
    <message>
        <location line="-112"/>
        <source>Export Rig…</source>
        <translation>Rig exportieren…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The rig with its blend shapes and the weights as animation curves, FBX or glTF (Unreal, Maya, MotionBuilder, Blender, Unity), through a retarget map, keys reduced</source>
        <translation>Das Rig mit seinen Blendshapes und den Gewichten als Animationskurven, FBX oder glTF (Unreal, Maya, MotionBuilder, Blender, Unity), über eine Retarget-Zuordnung, mit reduzierten Keys</translation>
    </message>
    <message>
        <location line="+112"/>
        <source>Rig loaded. Solve when ready.</source>
        <translation>Rig geladen. Lösen, sobald bereit.</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Rig kept from the previous take: %1. Solve when ready.</source>
        <translation>Rig aus dem vorigen Take behalten: %1. Lösen, sobald bereit.</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>A job is already running.</source>
        <translation>Es läuft bereits ein Auftrag.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Open a take first.</source>
        <translation>Öffnen Sie zuerst eine Aufnahme.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Load a rig first.</source>
        <translation>Laden Sie zuerst ein Rig.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The Face Mesh panel shows another mesh than this rig&apos;s neutral; load the rig again.</source>
        <translation>Das Face-Mesh-Panel zeigt ein anderes Mesh als die Neutralform dieses Rigs; laden Sie das Rig erneut.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Bind the markers to the rig&apos;s neutral in the Face Mesh panel first (Auto-Bind or Load Binding).</source>
        <translation>Binden Sie zuerst die Marker im Face-Mesh-Panel an die Neutralform des Rigs (Automatisch binden oder Bindung laden).</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Solving…</source>
        <translation>Wird gelöst…</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Solve failed: %1</source>
        <translation>Lösen fehlgeschlagen: %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Cancelled; the weights are as they were.</source>
        <translation>Abgebrochen; die Gewichte sind unverändert.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cancelled</source>
        <translation>abgebrochen</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Solved %1 frames from %2 markers (%3, λ %4%5) in %6 s; marker residual %7 mm mean, %8 mm max.</source>
        <translation>%1 Frames aus %2 Markern gelöst (%3, λ %4%5) in %6 s; Marker-Residuum im Mittel %7 mm, höchstens %8 mm.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source> by GCV</source>
        <translation> per GCV</translation>
    </message>
    <message numerus="yes">
        <location line="+5"/>
        <source>Warning: %n frame(s) had too few markers and hold the previous frame&apos;s weights (shaded red in the Weights view).</source>
        <translation>
            <numerusform>Warnung: %n Frame hatte zu wenige Marker und behält die Gewichte des vorigen Frames (rot schattiert in der Gewichtsansicht).</numerusform>
            <numerusform>Warnung: %n Frames hatten zu wenige Marker und behalten die Gewichte des vorigen Frames (rot schattiert in der Gewichtsansicht).</numerusform>
        </translation>
    </message>
    <message>
        <location line="+20"/>
        <source>  (peak %1)</source>
        <translation>  (Spitze %1)</translation>
    </message>
    <message>
        <location line="+90"/>
        <source>Solve the take first.</source>
        <translation>Lösen Sie zuerst die Aufnahme.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Cannot write the weights: %1</source>
        <translation>Die Gewichte können nicht geschrieben werden: %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Wrote %1</source>
        <translation>%1 geschrieben</translation>
    </message>
    <message>
        <source>Cannot write the rig: %1</source>
        <translation type="vanished">Das Rig kann nicht geschrieben werden: %1</translation>
    </message>
    <message>
        <location line="+66"/>
        <source>Load glTF rig</source>
        <translation>glTF-Rig laden</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>glTF rigs (*.glb *.gltf);;All files (*)</source>
        <translation>glTF-Rigs (*.glb *.gltf);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Load the rig&apos;s neutral mesh</source>
        <translation>Das neutrale Mesh des Rigs laden</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Meshes (*.obj *.ply);;All files (*)</source>
        <translation>Meshes (*.obj *.ply);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The folder with one OBJ per shape</source>
        <translation>Der Ordner mit einem OBJ je Shape</translation>
    </message>
    <message>
        <source>Weight curves (*.csv)</source>
        <translation type="vanished">Gewichtskurven (*.csv)</translation>
    </message>
    <message>
        <source>Live Link Face CSV (*.csv)</source>
        <translation type="vanished">Live-Link-Face-CSV (*.csv)</translation>
    </message>
    <message>
        <source>Export weights</source>
        <translation type="vanished">Gewichte exportieren</translation>
    </message>
    <message>
        <source>Export animated rig</source>
        <translation type="vanished">Animiertes Rig exportieren</translation>
    </message>
    <message>
        <source>glTF binary (*.glb)</source>
        <translation type="vanished">glTF binär (*.glb)</translation>
    </message>
</context>
<context>
    <name>mocap::ui::CleaningPanel</name>
    <message>
        <location filename="../widgets/panels/cleaning_panel.cpp" line="+110"/>
        <source>Live preview</source>
        <translation>Live-Vorschau</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Selected markers only</source>
        <translation>Nur ausgewählte Marker</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Selected frame range only</source>
        <translation>Nur ausgewählter Bildbereich</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Change only the frames selected on the curves (Shift+drag)</source>
        <translation>Nur die in den Kurven ausgewählten Bilder ändern (Umschalt+Ziehen)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Apply</source>
        <translation>Anwenden</translation>
    </message>
    <message>
        <location line="+122"/>
        <source>Computing…</source>
        <translation>Wird berechnet…</translation>
    </message>
    <message numerus="yes">
        <location line="+31"/>
        <source>%1 — %n sample(s) would change</source>
        <translation>
            <numerusform>%1 — %n Abtastwert würde sich ändern</numerusform>
            <numerusform>%1 — %n Abtastwerte würden sich ändern</numerusform>
        </translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Next pass: %1</source>
        <translation>Nächster Durchgang: %1</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Cancelled</source>
        <translation>Abgebrochen</translation>
    </message>
    <message>
        <location line="+70"/>
        <source>Nothing to apply</source>
        <translation>Nichts anzuwenden</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Applied: %1</source>
        <translation>Angewendet: %1</translation>
    </message>
</context>
<context>
    <name>mocap::ui::CleaningPresetActions</name>
    <message>
        <location filename="../widgets/actions/cleaning_preset_actions.cpp" line="+52"/>
        <location line="+22"/>
        <source>Save Cleaning Preset</source>
        <translation>Bereinigungsvorgabe speichern</translation>
    </message>
    <message>
        <location line="-21"/>
        <source>Cleaning presets (*.json)</source>
        <translation>Bereinigungsvorgaben (*.json)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Include this take&apos;s head markers (%1)</source>
        <translation>Die Kopfmarker dieser Aufnahme mitspeichern (%1)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>none chosen</source>
        <translation>keine gewählt</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>A preset carries cleaning options; head markers belong to a take. Include them only when every take the preset is for names its head markers the same way: a take without them then fails with that reason.</source>
        <translation>Eine Vorgabe enthält Bereinigungsoptionen; Kopfmarker gehören zu einer Aufnahme. Speichern Sie sie nur mit, wenn jede Aufnahme, für die die Vorgabe gedacht ist, ihre Kopfmarker gleich benennt: eine Aufnahme ohne sie schlägt dann mit diesem Grund fehl.</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>The preset was not saved: %1</source>
        <translation>Die Vorgabe wurde nicht gespeichert: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Saved the cleaning preset %1</source>
        <translation>Bereinigungsvorgabe %1 gespeichert</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Loaded the cleaning preset %1 into the Cleaning panel; nothing changes the take until Apply</source>
        <translation>Bereinigungsvorgabe %1 in das Bereinigungsfenster geladen; die Aufnahme ändert sich erst mit Anwenden</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>; it turns off %1 (left as they were)</source>
        <translation>; sie schaltet %1 aus (unverändert gelassen)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>; its head markers (%1) are not this take&apos;s: the take keeps its own</source>
        <translation>; ihre Kopfmarker (%1) gehören nicht zu dieser Aufnahme: die Aufnahme behält ihre eigenen</translation>
    </message>
    <message>
        <location line="+7"/>
        <location line="+6"/>
        <source>Load Cleaning Preset</source>
        <translation>Bereinigungsvorgabe laden</translation>
    </message>
    <message>
        <location line="-4"/>
        <source>Cleaning presets (*.json);;All files (*)</source>
        <translation>Bereinigungsvorgaben (*.json);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The preset was not loaded: %1</source>
        <translation>Die Vorgabe wurde nicht geladen: %1</translation>
    </message>
</context>
<context>
    <name>mocap::ui::CurveView</name>
    <message>
        <location filename="../widgets/views/curve_view.cpp" line="+143"/>
        <source>Select a marker to see its curves</source>
        <translation>Marker auswählen, um seine Kurven anzuzeigen</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation type="vanished">%1 s</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>preview</source>
        <translation>Vorschau</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>filled</source>
        <translation>gefüllt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>smoothed</source>
        <translation>geglättet</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>edited</source>
        <translation>bearbeitet</translation>
    </message>
    <message>
        <source>+%1 more</source>
        <translation type="vanished">+%1 weitere</translation>
    </message>
    <message>
        <location line="+315"/>
        <source>%1 · frame %2 (%3 s) · %4 %5 %6</source>
        <translation>%1 · Bild %2 (%3 s) · %4 %5 %6</translation>
    </message>
    <message>
        <location line="+17"/>
        <source> → preview %1</source>
        <translation> → Vorschau %1</translation>
    </message>
    <message>
        <location line="+100"/>
        <source>Move %1 %2 at frame %3</source>
        <translation>%1 %2 in Bild %3 verschieben</translation>
    </message>
</context>
<context>
    <name>mocap::ui::ExportDialog</name>
    <message>
        <location filename="../widgets/actions/animation_export.cpp" line="+19"/>
        <location filename="../widgets/dialogs/export_dialog.cpp" line="+90"/>
        <source>Export Animation</source>
        <translation>Animation exportieren</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The face mesh cannot be exported: %1</source>
        <translation>Das Gesichtsnetz kann nicht exportiert werden: %1</translation>
    </message>
    <message>
        <location filename="../widgets/dialogs/export_dialog.cpp" line="+14"/>
        <source>BVH of the markers (.bvh)</source>
        <translation>BVH der Marker (.bvh)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>FBX of the markers as animated nulls (.fbx)</source>
        <translation>FBX der Marker als animierte Nulls (.fbx)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>OBJ sequence of the deformed mesh (folder)</source>
        <translation>OBJ-Sequenz des verformten Netzes (Ordner)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>OBJ + PC2 point cache of the deformed mesh (.pc2)</source>
        <translation>OBJ + PC2-Punktcache des verformten Netzes (.pc2)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Format:</source>
        <translation>&amp;Format:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>FB&amp;X:</source>
        <translation>FB&amp;X:</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The units of the markers&apos; positions in the file (as mocap convert --units): Maya and MotionBuilder work in centimetres, Blender, Unreal and Unity read the declared units</source>
        <translation>Die Einheit der Markerpositionen in der Datei (wie mocap convert --units): Maya und MotionBuilder arbeiten in Zentimetern, Blender, Unreal und Unity lesen die angegebene Einheit</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Units:</source>
        <translation>&amp;Einheit:</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&amp;Browse…</source>
        <translation>&amp;Durchsuchen…</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Output:</source>
        <translation>&amp;Ausgabe:</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>R&amp;ange:</source>
        <translation>Be&amp;reich:</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>to</source>
        <translation>bis</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>F&amp;rames:</source>
        <translation>&amp;Bilder:</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>&amp;Export</source>
        <translation>&amp;Exportieren</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+412"/>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location line="-391"/>
        <source>Z up</source>
        <translation>Z oben</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Y up</source>
        <translation>Y oben</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The take&apos;s up axis, declared in the file so the importer turns the scene upright</source>
        <translation>Die Hochachse der Aufnahme, in der Datei angegeben, damit der Import die Szene aufrecht stellt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Keep the fewest keys within</source>
        <translation>Die wenigsten Keys behalten innerhalb von</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Each marker keeps the fewest keys whose linear interpolation stays within this distance of every frame (as mocap convert --reduce); otherwise every frame is a key</source>
        <translation>Jeder Marker behält die wenigsten Keys, deren lineare Interpolation innerhalb dieses Abstands zu jedem Frame bleibt (wie mocap convert --reduce); sonst ist jeder Frame ein Key</translation>
    </message>
    <message>
        <location line="+6"/>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>As the take (%1)</source>
        <translation>Wie die Aufnahme (%1)</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>Whole take (%1–%2)</source>
        <translation>Gesamte Aufnahme (%1–%2)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Selected range (%1–%2)</source>
        <translation>Ausgewählter Bereich (%1–%2)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Custom</source>
        <translation>Benutzerdefiniert</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>Load a face mesh first: these formats export the deformed mesh.</source>
        <translation>Laden Sie zuerst ein Gesichtsnetz: Diese Formate exportieren das verformte Netz.</translation>
    </message>
    <message numerus="yes">
        <location line="+112"/>
        <source>Replace %n existing file(s)?</source>
        <translation>
            <numerusform>%n vorhandene Datei ersetzen?</numerusform>
            <numerusform>%n vorhandene Dateien ersetzen?</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>… and %n more</source>
        <translation>
            <numerusform>… und %n weitere</numerusform>
            <numerusform>… und %n weitere</numerusform>
        </translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Replace Files?</source>
        <translation>Dateien ersetzen?</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Folder for the OBJ sequence</source>
        <translation>Ordner für die OBJ-Sequenz</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Export BVH</source>
        <translation>BVH exportieren</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>BVH (*.bvh)</source>
        <translation>BVH (*.bvh)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Export FBX</source>
        <translation>FBX exportieren</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>FBX (*.fbx)</source>
        <translation>FBX (*.fbx)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Export Point Cache</source>
        <translation>Punktcache exportieren</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>PC2 point cache (*.pc2)</source>
        <translation>PC2-Punktcache (*.pc2)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Open a take first.</source>
        <translation>Öffnen Sie zuerst eine Aufnahme.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Choose where to export.</source>
        <translation>Wählen Sie das Exportziel.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Load a face mesh first: this format exports the deformed mesh.</source>
        <translation>Laden Sie zuerst ein Gesichtsnetz: Dieses Format exportiert das verformte Netz.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The first frame (%1) is after the last (%2).</source>
        <translation>Das erste Bild (%1) liegt nach dem letzten (%2).</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The folder %1 does not exist.</source>
        <translation>Der Ordner %1 existiert nicht.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 is a folder; choose a file name.</source>
        <translation>%1 ist ein Ordner; wählen Sie einen Dateinamen.</translation>
    </message>
    <message>
        <location line="+44"/>
        <source>Not exported: the existing files are kept.</source>
        <translation>Nicht exportiert: Die vorhandenen Dateien bleiben erhalten.</translation>
    </message>
    <message numerus="yes">
        <location line="+16"/>
        <source>Exporting %n frame(s)…</source>
        <translation>
            <numerusform>%n Bild wird exportiert…</numerusform>
            <numerusform>%n Bilder werden exportiert…</numerusform>
        </translation>
    </message>
    <message>
        <location line="+86"/>
        <source>Kept %1 of %2 keys (%3 %), largest error %4 mm (tolerance %5 mm).</source>
        <translation>%1 von %2 Keys behalten (%3 %), größter Fehler %4 mm (Toleranz %5 mm).</translation>
    </message>
    <message>
        <location line="-485"/>
        <source>Cancelling…</source>
        <translation>Wird abgebrochen…</translation>
    </message>
    <message numerus="yes">
        <location line="+444"/>
        <source>Exported %n frame(s) to %1.</source>
        <translation>
            <numerusform>%n Bild nach %1 exportiert.</numerusform>
            <numerusform>%n Bilder nach %1 exportiert.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Note: %1.</source>
        <translation>Hinweis: %1.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Export cancelled; nothing was written.</source>
        <translation>Export abgebrochen; es wurde nichts geschrieben.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Export failed: %1</source>
        <translation>Export fehlgeschlagen: %1</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Close</source>
        <translation>Schließen</translation>
    </message>
</context>
<context>
    <name>mocap::ui::FaceMeshModel</name>
    <message numerus="yes">
        <location filename="../widgets/document/face_mesh_model.cpp" line="+118"/>
        <source>%n marker(s) bound</source>
        <translation>
            <numerusform>%n Marker gebunden</numerusform>
            <numerusform>%n Marker gebunden</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>%1 of %n rig marker(s) found in this take</source>
        <translation>
            <numerusform>%1 von %n Rig-Marker in diesem Take gefunden</numerusform>
            <numerusform>%1 von %n Rig-Markern in diesem Take gefunden</numerusform>
        </translation>
    </message>
    <message>
        <location line="+38"/>
        <source>Load a mesh first.</source>
        <translation>Laden Sie zuerst ein Netz.</translation>
    </message>
    <message>
        <location line="+53"/>
        <source>Head stabilization: %1</source>
        <translation>Kopfstabilisierung: %1</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>No marker is bound to the mesh: auto-bind, load a binding or pick vertices.</source>
        <translation>Kein Marker ist an das Netz gebunden: Binden Sie automatisch, laden Sie eine Bindung oder wählen Sie Scheitelpunkte.</translation>
    </message>
</context>
<context>
    <name>mocap::ui::FaceMeshPanel</name>
    <message>
        <location filename="../widgets/panels/face_mesh_panel.cpp" line="+102"/>
        <source>Mesh and binding</source>
        <translation>Netz und Bindung</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+227"/>
        <source>No mesh</source>
        <translation>Kein Netz</translation>
    </message>
    <message>
        <location line="-223"/>
        <source>Load Mesh…</source>
        <translation>Netz laden…</translation>
    </message>
    <message>
        <source>A face mesh as OBJ or PLY</source>
        <translation type="vanished">Ein Gesichtsnetz als OBJ oder PLY</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A face mesh as OBJ or PLY, or a glTF rig&apos;s neutral</source>
        <translation>Ein Gesichts-Mesh als OBJ oder PLY oder die Neutralform eines glTF-Rigs</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Load Binding…</source>
        <translation>Bindung laden…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Save Binding…</source>
        <translation>Bindung speichern…</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Auto-Bind</source>
        <translation>Automatisch binden</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Align the neutral frame to the mesh and bind each marker to its nearest surface point (the selected markers when three or more are selected)</source>
        <translation>Das Neutralbild am Netz ausrichten und jeden Marker an seinen nächstgelegenen Oberflächenpunkt binden (nur die ausgewählten Marker, wenn drei oder mehr ausgewählt sind)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Pick Vertex</source>
        <translation>Scheitelpunkt wählen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Select a marker, then click the mesh vertex it sits on</source>
        <translation>Wählen Sie einen Marker aus und klicken Sie dann auf den Scheitelpunkt des Netzes, auf dem er sitzt</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+276"/>
        <source>Select a marker, then click its vertex on the mesh</source>
        <translation>Wählen Sie einen Marker aus und klicken Sie dann auf seinen Scheitelpunkt im Netz</translation>
    </message>
    <message>
        <location line="-273"/>
        <source>Undo</source>
        <translation>Rückgängig</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Redo</source>
        <translation>Wiederholen</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Deformation</source>
        <translation>Verformung</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Head motion is removed with these markers before binding and deforming; they are not bound.</source>
        <translation>Mit diesen Markern wird die Kopfbewegung vor dem Binden und Verformen entfernt; sie selbst werden nicht gebunden.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Reference markers:</source>
        <translation>Referenzmarker:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The frame whose marker positions are the rest mesh</source>
        <translation>Das Bild, dessen Markerpositionen das Ruhenetz bilden</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Neutral frame:</source>
        <translation>Neutralbild:</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+327"/>
        <source>RBF</source>
        <translation>RBF</translation>
    </message>
    <message>
        <location line="-326"/>
        <location line="+326"/>
        <source>Laplacian</source>
        <translation>Laplace</translation>
    </message>
    <message>
        <location line="-325"/>
        <source>Method:</source>
        <translation>Methode:</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Kernel:</source>
        <translation>Kern:</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Kernel radius c, in mesh units</source>
        <translation>Kernradius c, in Netzeinheiten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Radius:</source>
        <translation>Radius:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Top, middle and bottom regions</source>
        <translation>Oberer, mittlerer und unterer Bereich</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Weights:</source>
        <translation>Gewichte:</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Constraint weight:</source>
        <translation>Gewicht der Nebenbedingungen:</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Rotation-aware iterations per frame (0: linear)</source>
        <translation>Rotationsberücksichtigende Iterationen pro Bild (0: linear)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Rotations:</source>
        <translation>Rotationen:</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Compare RBF and Laplacian side by side</source>
        <translation>RBF und Laplace nebeneinander vergleichen</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Display</source>
        <translation>Anzeige</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Edges</source>
        <translation>Kanten</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Opacity:</source>
        <translation>Deckkraft:</translation>
    </message>
    <message>
        <location line="+84"/>
        <source>first complete</source>
        <translation>erstes vollständiges</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Cannot read the mesh %1: %2</source>
        <translation>Das Netz %1 kann nicht gelesen werden: %2</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Mesh</source>
        <translation>Netz</translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>%1: %n vertices</source>
        <translation>
            <numerusform>%1: %n Scheitelpunkt</numerusform>
            <numerusform>%1: %n Scheitelpunkte</numerusform>
        </translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Load the mesh the binding is for first.</source>
        <translation>Laden Sie zuerst das Netz, zu dem die Bindung gehört.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Cannot read the binding %1: %2</source>
        <translation>Die Bindung %1 kann nicht gelesen werden: %2</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Cannot save the binding: %1</source>
        <translation>Die Bindung kann nicht gespeichert werden: %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Saved %1</source>
        <translation>%1 gespeichert</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Auto-bind: %1</source>
        <translation>Automatische Bindung: %1</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Click the vertex for %1</source>
        <translation>Klicken Sie auf den Scheitelpunkt für %1</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>%1 bound to vertex %2</source>
        <translation>%1 an Scheitelpunkt %2 gebunden</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>; residual %1 mm (was %2 mm)</source>
        <translation>; Residuum %1 mm (vorher %2 mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>; residual %1 mm</source>
        <translation>; Residuum %1 mm</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>Deform per frame: %1 %2 ms</source>
        <translation>Verformung pro Bild: %1 %2 ms</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>, %1 %2 ms</source>
        <translation>, %1 %2 ms</translation>
    </message>
    <message numerus="yes">
        <source>%n marker(s) bound</source>
        <translation type="vanished">
            <numerusform>%n Marker gebunden</numerusform>
            <numerusform>%n Marker gebunden</numerusform>
        </translation>
    </message>
    <message>
        <location line="+16"/>
        <source>; mean residual %1 mm</source>
        <translation>; mittleres Residuum %1 mm</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Neutral frame %1; set-up %2 ms</source>
        <translation>Neutralbild %1; Vorbereitung %2 ms</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Load face mesh</source>
        <translation>Gesichtsnetz laden</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Meshes (*.obj *.ply *.glb *.gltf);;All files (*)</source>
        <translation>Meshes (*.obj *.ply *.glb *.gltf);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Meshes (*.obj *.ply);;All files (*)</source>
        <translation type="vanished">Netze (*.obj *.ply);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Load marker binding</source>
        <translation>Markerbindung laden</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Bindings (*.json);;All files (*)</source>
        <translation>Bindungen (*.json);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Save marker binding</source>
        <translation>Markerbindung speichern</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Bindings (*.json)</source>
        <translation>Bindungen (*.json)</translation>
    </message>
</context>
<context>
    <name>mocap::ui::FrameStatusLabel</name>
    <message>
        <location filename="../widgets/views/frame_status_label.cpp" line="+21"/>
        <source>Frame %1 of %2–%3 — %4 markers selected</source>
        <translation>Frame %1 von %2–%3 — %4 Marker ausgewählt</translation>
    </message>
</context>
<context>
    <name>mocap::ui::FrameStripView</name>
    <message>
        <location filename="../widgets/views/frame_strip_view.cpp" line="+132"/>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>+%1 more</source>
        <translation>+%1 weitere</translation>
    </message>
</context>
<context>
    <name>mocap::ui::GapFillStep</name>
    <message>
        <location filename="../widgets/panels/gap_fill_step.cpp" line="+19"/>
        <source>Method</source>
        <translation>Methode</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Neighbours</source>
        <translation>Nachbarn</translation>
    </message>
    <message>
        <location line="+8"/>
        <location line="+5"/>
        <source>unlimited</source>
        <translation>unbegrenzt</translation>
    </message>
    <message>
        <location line="-4"/>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <location line="+5"/>
        <source> frames</source>
        <translation> Frames</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Longer gaps are left open: filling them would invent motion</source>
        <translation>Längere Lücken bleiben offen: Sie zu füllen, würde Bewegung erfinden</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Longest gap</source>
        <translation>Längste Lücke</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>= frames</source>
        <translation>= Frames</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Extrapolate edge gaps</source>
        <translation>Randlücken extrapolieren</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Fill before a marker&apos;s first and after its last valid sample (invents motion nobody measured; off by default)</source>
        <translation>Vor dem ersten und nach dem letzten gültigen Abtastwert eines Markers füllen (erfindet Bewegung, die niemand gemessen hat; standardmäßig aus)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source> % of the take</source>
        <translation> % der Aufnahme</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>fill every marker</source>
        <translation>alle Marker füllen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Markers seen in fewer frames are left open, unless they are selected and &quot;Selected markers only&quot; is on</source>
        <translation>Marker, die in weniger Bildern sichtbar sind, bleiben offen, außer sie sind ausgewählt und „Nur ausgewählte Marker“ ist aktiviert</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Skip markers seen under</source>
        <translation>Marker auslassen, sichtbar in unter</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Gaps left open and why; click one to go there</source>
        <translation>Offen gebliebene Lücken und der Grund; klicken Sie auf eine, um dorthin zu springen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Left open</source>
        <translation>Offen geblieben</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>Gaps</source>
        <translation>Lücken</translation>
    </message>
    <message>
        <location line="+81"/>
        <source>%1, frames %2–%3 (%4)</source>
        <translation>%1, Frames %2–%3 (%4)</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>; %1 left open: </source>
        <translation>; %1 offen gelassen: </translation>
    </message>
</context>
<context>
    <name>mocap::ui::GapListPanel</name>
    <message>
        <location filename="../widgets/panels/gap_list_panel.cpp" line="+132"/>
        <source>Filter markers…</source>
        <translation>Marker filtern…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Only open gaps</source>
        <translation>Nur offene Lücken</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>Check Shown</source>
        <translation>Angezeigte abhaken</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Check every open gap the filter shows</source>
        <translation>Jede offene Lücke abhaken, die der Filter anzeigt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Uncheck All</source>
        <translation>Alle Häkchen entfernen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Live preview</source>
        <translation>Live-Vorschau</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Show the fill of the checked (or selected) gaps over the views before filling</source>
        <translation>Die Füllung der abgehakten (oder ausgewählten) Lücken vor dem Füllen in den Ansichten anzeigen</translation>
    </message>
    <message>
        <location line="+13"/>
        <location line="+144"/>
        <source>Fill</source>
        <translation>Füllen</translation>
    </message>
    <message>
        <location line="-99"/>
        <source>Show Gap</source>
        <translation>Lücke anzeigen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Fill This Gap</source>
        <translation>Diese Lücke füllen</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Allow Filling This Gap</source>
        <translation>Füllen dieser Lücke erlauben</translation>
    </message>
    <message>
        <location line="+45"/>
        <source>Check gaps, or select rows, to preview their fill; double-click a gap to go to it.</source>
        <translation>Haken Sie Lücken ab oder wählen Sie Zeilen aus, um ihre Füllung in der Vorschau zu sehen; ein Doppelklick auf eine Lücke springt zu ihr.</translation>
    </message>
    <message>
        <location line="+52"/>
        <source>Fill 1 Checked Gap</source>
        <translation>1 abgehakte Lücke füllen</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Fill %1 Checked Gaps</source>
        <translation>%1 abgehakte Lücken füllen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Fill Selected Gap</source>
        <translation>Ausgewählte Lücke füllen</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Fill %1 Selected Gaps</source>
        <translation>%1 ausgewählte Lücken füllen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Fill the checked gaps, or else the selected ones, each with its method (Ctrl+Return)</source>
        <translation>Die abgehakten Lücken füllen, sonst die ausgewählten, jede mit ihrer Methode (Strg+Eingabe)</translation>
    </message>
    <message>
        <location line="+57"/>
        <source>No open gap to fill</source>
        <translation>Keine offene Lücke zu füllen</translation>
    </message>
    <message numerus="yes">
        <location line="+20"/>
        <source>Computing the fill of %n gap(s)…</source>
        <translation>
            <numerusform>Füllung von %n Lücke wird berechnet…</numerusform>
            <numerusform>Füllung von %n Lücken wird berechnet…</numerusform>
        </translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Cancelled</source>
        <translation>Abgebrochen</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>1 gap filled</source>
        <translation>1 Lücke gefüllt</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1 gaps filled</source>
        <translation>%1 Lücken gefüllt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>1 gap previewed</source>
        <translation>1 Lücke in der Vorschau</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1 gaps previewed</source>
        <translation>%1 Lücken in der Vorschau</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>, 1 sample</source>
        <translation>, 1 Abtastwert</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>, %1 samples</source>
        <translation>, %1 Abtastwerte</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>1 gap left open: %1</source>
        <translation>1 Lücke offen gelassen: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 gaps left open (the first: %2)</source>
        <translation>%1 Lücken offen gelassen (die erste: %2)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1; %2</source>
        <translation>%1; %2</translation>
    </message>
    <message>
        <location line="+42"/>
        <source>%1 frames %2–%3</source>
        <translation>%1 Frames %2–%3</translation>
    </message>
    <message>
        <location line="+7"/>
        <source> and 1 more gap</source>
        <translation> und 1 weitere Lücke</translation>
    </message>
    <message>
        <location line="+0"/>
        <source> and %1 more gaps</source>
        <translation> und %1 weitere Lücken</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Fill Past the Rules?</source>
        <translation>Über die Regeln hinaus füllen?</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Invent 1 sample: %1?</source>
        <translation>1 Abtastwert erfinden: %1?</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Invent %1 samples: %2?</source>
        <translation>%1 Abtastwerte erfinden: %2?</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>These gaps are longer than the limit, at the take&apos;s ends or on a marker seen too rarely: nothing measured them.</source>
        <translation>Diese Lücken sind länger als die Grenze, liegen an den Enden der Aufnahme oder gehören zu einem zu selten sichtbaren Marker: nichts hat sie gemessen.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Nothing filled: filling past the rules was not confirmed</source>
        <translation>Nichts gefüllt: das Füllen über die Regeln hinaus wurde nicht bestätigt</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Fill 1 gap: %1</source>
        <translation>1 Lücke füllen: %1</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Fill %1 gaps: %2</source>
        <translation>%1 Lücken füllen: %2</translation>
    </message>
</context>
<context>
    <name>mocap::ui::GapTableModel</name>
    <message>
        <location filename="../widgets/models/gap_table_model.cpp" line="+31"/>
        <source>Auto (best blend)</source>
        <translation>Automatisch (beste Überblendung)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Rigid neighbours</source>
        <translation>Starre Nachbarn</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PCA (marker correlations)</source>
        <translation>PCA (Marker-Korrelationen)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cubic spline</source>
        <translation>Kubischer Spline</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Linear</source>
        <translation>Linear</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Paper method: three neighbours (Zhang et al., muscle mechanism)</source>
        <translation>Paper-Methode: drei Nachbarn (Zhang et al., Muskelmechanismus)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Paper method: n neighbours (Zhang et al., muscle mechanism)</source>
        <translation>Paper-Methode: n Nachbarn (Zhang et al., Muskelmechanismus)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Neighbour average (Guenter)</source>
        <translation>Nachbarmittelwert (Guenter)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Distance-weighted neighbours (Lin–Ouhyoung)</source>
        <translation>Distanzgewichtete Nachbarn (Lin–Ouhyoung)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Blends regression on the markers moving most alike and the rigid motion of the nearest ones, weighted by how well each predicts the marker&apos;s own data beside the gap</source>
        <translation>Mischt eine Regression auf die am ähnlichsten bewegten Marker und die starre Bewegung der nächsten, gewichtet danach, wie gut jede die eigenen Daten des Markers neben der Lücke vorhersagt</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Carries the rigid motion of the nearest markers seen through the gap</source>
        <translation>Überträgt die starre Bewegung der nächsten Marker, die während der Lücke sichtbar sind</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Rebuilds the gap from a low-rank model of how all markers move together</source>
        <translation>Rekonstruiert die Lücke aus einem Modell niedrigen Rangs, wie sich alle Marker gemeinsam bewegen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A cubic curve through two seen samples on each side of the gap</source>
        <translation>Eine kubische Kurve durch je zwei sichtbare Abtastwerte auf beiden Seiten der Lücke</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A straight line between the samples on each side of the gap</source>
        <translation>Eine Gerade zwischen den Abtastwerten auf beiden Seiten der Lücke</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Follows the displacements of the three nearest markers, as skin moves with the muscle below it</source>
        <translation>Folgt den Verschiebungen der drei nächsten Marker, wie sich die Haut mit dem Muskel darunter bewegt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Like three neighbours, with the n nearest markers weighted by distance</source>
        <translation>Wie drei Nachbarn, mit den n nächsten Markern nach Abstand gewichtet</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Moves the marker by the average displacement of its nearest neighbours</source>
        <translation>Bewegt den Marker um die mittlere Verschiebung seiner nächsten Nachbarn</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Moves the marker by its neighbours&apos; displacements, nearer ones weighing more</source>
        <translation>Bewegt den Marker um die Verschiebungen seiner Nachbarn, nähere zählen mehr</translation>
    </message>
    <message>
        <location line="+274"/>
        <source>filled</source>
        <translation>gefüllt</translation>
    </message>
    <message>
        <location line="-2"/>
        <source>filled (%1)</source>
        <translation>gefüllt (%1)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>previewed</source>
        <translation>in der Vorschau</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>cannot fill: %1</source>
        <translation>nicht füllbar: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>allowed: %1</source>
        <translation>erlaubt: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>open</source>
        <translation>offen</translation>
    </message>
    <message>
        <location line="+42"/>
        <source>Left open by the fill rules (%1). Check to fill it anyway: Fill asks before inventing its samples</source>
        <translation>Von den Füllregeln offen gelassen (%1). Abhaken, um sie trotzdem zu füllen: Füllen fragt, bevor es Abtastwerte erfindet</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Filled by: %1</source>
        <translation>Gefüllt mit: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: %2. Double-click to choose how this gap is filled</source>
        <translation>%1: %2. Doppelklicken, um zu wählen, wie diese Lücke gefüllt wird</translation>
    </message>
    <message>
        <source>Fill a gap the rules leave open (too long, at the take&apos;s ends, a marker seen too rarely)</source>
        <translation type="vanished">Eine Lücke füllen, die die Regeln offen lassen (zu lang, an den Enden der Aufnahme, ein zu selten sichtbarer Marker)</translation>
    </message>
    <message>
        <source>Open, previewed, filled, or why it is not filled</source>
        <translation type="vanished">Offen, in der Vorschau, gefüllt oder warum sie nicht gefüllt wird</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Check the gaps to fill together</source>
        <translation>Die gemeinsam zu füllenden Lücken abhaken</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>First missing frame (the file&apos;s numbering)</source>
        <translation>Erstes fehlendes Bild (Nummerierung der Datei)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Length in frames</source>
        <translation>Länge in Bildern</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Length in seconds</source>
        <translation>Länge in Sekunden</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>How the gap is filled (double-click to choose)</source>
        <translation>Wie die Lücke gefüllt wird (Doppelklick zum Wählen)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Open, previewed, filled, or why it is not filled. A gap the rules leave open (too long, at the take&apos;s ends, a marker seen too rarely) has a box: check it to fill the gap anyway</source>
        <translation>Offen, in der Vorschau, gefüllt oder warum nicht gefüllt. Eine Lücke, die die Regeln offen lassen (zu lang, an den Enden der Aufnahme, ein zu selten gesehener Marker), hat ein Kästchen: ankreuzen, um sie trotzdem zu füllen</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Marker</source>
        <translation>Marker</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>First</source>
        <translation>Erstes</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Frames</source>
        <translation>Bilder</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>s</source>
        <translation>s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Method</source>
        <translation>Methode</translation>
    </message>
    <message>
        <source>Allow</source>
        <translation type="vanished">Erlauben</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>State</source>
        <translation>Status</translation>
    </message>
</context>
<context>
    <name>mocap::ui::HeadMarkersProposalBar</name>
    <message>
        <location filename="../widgets/panels/head_markers_proposal_bar.cpp" line="+30"/>
        <source>The take names no head markers (root… or head…) and has none saved: these move together as one rigid body. Nothing uses them until you accept them.</source>
        <translation>Die Aufnahme benennt keine Kopfmarker (root… oder head…) und hat keine gespeichert: diese bewegen sich gemeinsam als ein starrer Körper. Nichts verwendet sie, bevor Sie sie annehmen.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Accept</source>
        <translation>Annehmen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Use these markers for head stabilization, the head-stabilized view, layout planning and the face mesh, and save them with the take (undoable)</source>
        <translation>Diese Marker für die Kopfstabilisierung, die kopfstabilisierte Ansicht, die Layoutplanung und das Gesichtsnetz verwenden und mit der Aufnahme speichern (rückgängig machbar)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Choose…</source>
        <translation>Wählen…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Choose the head markers yourself (Marker ▸ Reference Markers…)</source>
        <translation>Die Kopfmarker selbst wählen (Marker ▸ Referenzmarker…)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Not now: no head markers for this take</source>
        <translation>Nicht jetzt: keine Kopfmarker für diese Aufnahme</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>Head markers guessed: %1</source>
        <translation>Kopfmarker vermutet: %1</translation>
    </message>
</context>
<context>
    <name>mocap::ui::HeadStabilizationStep</name>
    <message>
        <location filename="../widgets/panels/head_stabilization_step.cpp" line="-51"/>
        <source>Head-mounted markers that move only with the head: the head pose of every frame is measured on them.</source>
        <translation>Am Kopf befestigte Marker, die sich nur mit dem Kopf bewegen: An ihnen wird die Kopfhaltung jedes Bildes gemessen.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Reference markers</source>
        <translation>Referenzmarker</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>First complete frame</source>
        <translation>Erstes vollständiges Bild</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Frame whose head pose becomes the stabilized pose</source>
        <translation>Bild, dessen Kopfhaltung zur stabilisierten Haltung wird</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reference frame</source>
        <translation>Referenzbild</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Moves all markers in all frames into the head frame: &quot;Selected markers only&quot; and &quot;Selected frame range only&quot; do not apply to this step.</source>
        <translation>Verschiebt alle Marker in allen Bildern in das Kopfkoordinatensystem: „Nur ausgewählte Marker“ und „Nur ausgewählter Bildbereich“ gelten für diesen Schritt nicht.</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Stabilize head</source>
        <translation>Kopf stabilisieren</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Head</source>
        <comment>the Cleaning panel&apos;s tab of Stabilize head</comment>
        <translation>Kopf</translation>
    </message>
</context>
<context>
    <name>mocap::ui::HeadStabilizedViewAction</name>
    <message>
        <location filename="../widgets/actions/head_stabilized_view_action.cpp" line="+19"/>
        <source>&amp;Head-Stabilized View</source>
        <translation>&amp;Kopfstabilisierte Ansicht</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Show the markers in the head frame of the reference markers (a view setting; the take is not changed)</source>
        <translation>Die Marker im Kopfkoordinatensystem der Referenzmarker anzeigen (eine Ansichtseinstellung; die Aufnahme wird nicht verändert)</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>3D view in the lab frame</source>
        <translation>3D-Ansicht im Laborkoordinatensystem</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Choose at least three reference markers first (Marker ▸ Reference Markers…).</source>
        <translation>Wählen Sie zuerst mindestens drei Referenzmarker (Marker ▸ Referenzmarker…).</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Head-Stabilized View</source>
        <translation>Kopfstabilisierte Ansicht</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>3D view stabilized on the reference markers (Ctrl+B again for the lab frame)</source>
        <translation>3D-Ansicht auf die Referenzmarker stabilisiert (Strg+B erneut für das Laborkoordinatensystem)</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>3D view back in the lab frame: the reference markers cannot carry a head pose</source>
        <translation>3D-Ansicht wieder im Laborkoordinatensystem: Aus den Referenzmarkern lässt sich keine Kopfhaltung bestimmen</translation>
    </message>
</context>
<context>
    <name>mocap::ui::HistoryPanel</name>
    <message>
        <location filename="../widgets/panels/history_panel.cpp" line="+19"/>
        <location line="+7"/>
        <source>all</source>
        <translation>alle</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>Processing history (saved with the take)</source>
        <translation>Bearbeitungsverlauf (mit der Aufnahme gespeichert)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Step</source>
        <translation>Schritt</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Parameters</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Markers</source>
        <translation>Marker</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Frames</source>
        <translation>Bilder</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Samples</source>
        <translation>Abtastwerte</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Time</source>
        <translation>Zeit</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Undo history (this session)</source>
        <translation>Rückgängig-Verlauf (diese Sitzung)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&lt;opened take&gt;</source>
        <translation>&lt;geöffnete Aufnahme&gt;</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>%1 by %2 at %3</source>
        <translation>%1 durch %2 am %3</translation>
    </message>
</context>
<context>
    <name>mocap::ui::JobProgressRow</name>
    <message>
        <source>about %1 s left</source>
        <translation type="vanished">noch etwa %1 s</translation>
    </message>
    <message>
        <source>about %1 min left</source>
        <translation type="vanished">noch etwa %1 min</translation>
    </message>
    <message>
        <location filename="../widgets/panels/job_progress_row.cpp" line="+22"/>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stop the computation (Esc)</source>
        <translation>Berechnung abbrechen (Esc)</translation>
    </message>
</context>
<context>
    <name>mocap::ui::JobRunner</name>
    <message>
        <location filename="../widgets/document/job_runner.cpp" line="+17"/>
        <source>about %1 s left</source>
        <translation>noch etwa %1 s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>about %1 min left</source>
        <translation>noch etwa %1 min</translation>
    </message>
    <message>
        <location line="+42"/>
        <source>unknown error</source>
        <translation>unbekannter Fehler</translation>
    </message>
</context>
<context>
    <name>mocap::ui::LabellingActions</name>
    <message>
        <location filename="../widgets/actions/labelling_actions.cpp" line="+38"/>
        <source>Tracking and labelling…</source>
        <translation>Verfolgen und Beschriften…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Track and Label cancelled; the take is unchanged</source>
        <translation>Verfolgen und Beschriften abgebrochen; die Aufnahme ist unverändert</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Track and Label</source>
        <translation>Verfolgen und beschriften</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Nothing to label: every marker has a label</source>
        <translation>Nichts zu beschriften: Jeder Marker hat einen Namen</translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>Nothing to label: none of the %n unlabelled fragment(s) matches a marker</source>
        <translation>
            <numerusform>Nichts zu beschriften: %n unbeschriftetes Fragment passt zu keinem Marker</numerusform>
            <numerusform>Nichts zu beschriften: Keines der %n unbeschrifteten Fragmente passt zu einem Marker</numerusform>
        </translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Track and label (%1 of %2 fragments labelled)</source>
        <translation>Verfolgen und beschriften (%1 von %2 Fragmenten beschriftet)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 of %2 fragments labelled; %3 samples left unlabelled</source>
        <translation>%1 von %2 Fragmenten beschriftet; %3 Abtastwerte unbeschriftet</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Looking for label swaps…</source>
        <translation>Suche nach Namensvertauschungen…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Swap search cancelled</source>
        <translation>Suche nach Vertauschungen abgebrochen</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Fix Swaps</source>
        <translation>Vertauschungen beheben</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>No label swaps found</source>
        <translation>Keine vertauschten Namen gefunden</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>No swap accepted; the take is unchanged</source>
        <translation>Keine Vertauschung übernommen; die Aufnahme ist unverändert</translation>
    </message>
    <message numerus="yes">
        <location line="+8"/>
        <source>Repair %n label swap(s)</source>
        <translation>
            <numerusform>%n Namensvertauschung reparieren</numerusform>
            <numerusform>%n Namensvertauschungen reparieren</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>mocap::ui::LayoutErrorPlot</name>
    <message>
        <location filename="../widgets/views/layout_error_plot.cpp" line="+56"/>
        <source>Click a marker count (or use ←/→) to show its layout</source>
        <translation>Klicken Sie auf eine Markeranzahl (oder verwenden Sie ←/→), um ihr Layout anzuzeigen</translation>
    </message>
    <message>
        <location line="+117"/>
        <source>Run the plan to see the error for each marker count.</source>
        <translation>Führen Sie die Planung aus, um den Fehler für jede Markeranzahl zu sehen.</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>markers</source>
        <translation>Marker</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>PFA</source>
        <translation>PFA</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Greedy</source>
        <translation>Greedy</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Random (mean)</source>
        <translation>Zufällig (Mittelwert)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Recommended</source>
        <translation>Empfohlen</translation>
    </message>
    <message>
        <location line="+63"/>
        <source>Marker reconstruction RMSE (mm)</source>
        <translation>RMSE der Markerrekonstruktion (mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Blend-weight MSE (key poses)</source>
        <translation>Blend-Gewichts-MSE (Schlüsselposen)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Rig-weight MSE (blendshape rig)</source>
        <translation>Rig-Gewichts-MSE (Blendshape-Rig)</translation>
    </message>
    <message>
        <source>Blend-weight MSE</source>
        <translation type="vanished">MSE der Blend-Gewichte</translation>
    </message>
</context>
<context>
    <name>mocap::ui::LayoutPlanningPanel</name>
    <message>
        <location filename="../widgets/panels/layout_planning_panel.cpp" line="+116"/>
        <source>detected</source>
        <translation>erkannt</translation>
    </message>
    <message>
        <location line="+61"/>
        <source>Take files planned together with the open take (they must have its markers)</source>
        <translation>Aufnahmedateien, die zusammen mit der geöffneten Aufnahme geplant werden (sie müssen deren Marker enthalten)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Add…</source>
        <translation>Hinzufügen…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Remove</source>
        <translation>Entfernen</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>More takes:</source>
        <translation>Weitere Aufnahmen:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Add takes</source>
        <translation>Aufnahmen hinzufügen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Motion capture (*.c3d *.trc);;All files (*)</source>
        <translation>Motion-Capture (*.c3d *.trc);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>PFA (principal feature analysis)</source>
        <translation>PFA (Hauptmerkmalsanalyse)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Greedy (least reconstruction error)</source>
        <translation>Greedy (kleinster Rekonstruktionsfehler)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Method:</source>
        <translation>Methode:</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Share of the motion&apos;s variance the PCA keeps (the paper: 0.98)</source>
        <translation>Anteil der Bewegungsvarianz, den die PCA behält (im Paper: 0,98)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Variance kept:</source>
        <translation>Erhaltene Varianz:</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>k-means restarts per cluster count (the paper: 1000; fewer run faster)</source>
        <translation>k-Means-Neustarts je Clusteranzahl (im Paper: 1000; weniger laufen schneller)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Restarts:</source>
        <translation>Neustarts:</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>all</source>
        <translation>alle</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>to</source>
        <translation>bis</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Clusters k:</source>
        <translation>Cluster k:</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Seed:</source>
        <translation>Startwert:</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Random marker sets scored at every size, the baseline a plan must beat</source>
        <translation>Zufällige Markersätze, bei jeder Größe bewertet: die Messlatte, die ein Plan schlagen muss</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Random sets:</source>
        <translation>Zufallssätze:</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>automatic</source>
        <translation>automatisch</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Key poses of the blendshape basis: frame numbers, comma-separated (TAKE:FRAME for a further take, TAKE from 1); blank: the most extreme frames</source>
        <translation>Schlüsselposen der Blendshape-Basis: Bildnummern, durch Kommas getrennt (TAKE:BILD für eine weitere Aufnahme, TAKE ab 1); leer: die extremsten Bilder</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Key poses:</source>
        <translation>Schlüsselposen:</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>detected automatically</source>
        <translation>automatisch erkannt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Mirror pairs: a text file (two labels a line) or a marker-set file (.json)</source>
        <translation>Spiegelpaare: eine Textdatei (zwei Namen pro Zeile) oder eine Markersatz-Datei (.json)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>…</source>
        <translation>…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Choose a pairs file</source>
        <translation>Paardatei wählen</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Pairs file:</source>
        <translation>Paardatei:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Pairs file</source>
        <translation>Paardatei</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Pairs (*.txt *.json);;All files (*)</source>
        <translation>Paare (*.txt *.json);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Head motion is removed with these markers before planning, and they are not planned over (a reduced capture still needs them).</source>
        <translation>Mit diesen Markern wird die Kopfbewegung vor der Planung entfernt, und sie werden nicht wegoptimiert (auch eine reduzierte Aufnahme braucht sie).</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>all but the reference markers</source>
        <translation>alle außer den Referenzmarkern</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Markers to plan over, comma-separated; * and ? match any run and any character (e.g. section1-*, lip?)</source>
        <translation>Zu planende Marker, durch Kommas getrennt; * und ? stehen für beliebig viele bzw. ein beliebiges Zeichen (z. B. section1-*, lip?)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Plan markers:</source>
        <translation>Marker planen:</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Markers left out of the plan, comma-separated; * and ? match any run and any character (unlabelled points and the reference markers always are)</source>
        <translation>Aus dem Plan ausgelassene Marker, durch Kommas getrennt; * und ? stehen für beliebig viele bzw. ein beliebiges Zeichen (unbenannte Punkte und die Referenzmarker werden immer ausgelassen)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Judge layouts on the blendshape rig</source>
        <translation>Layouts am Blendshape-Rig beurteilen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Also solve the loaded rig&apos;s weights from each layout and from every bound marker, and plot their MSE (the seed paper&apos;s measure on a semantic rig; mocap pfa --rig)</source>
        <translation>Außerdem die Gewichte des geladenen Rigs aus jedem Layout und aus allen gebundenen Markern lösen und ihren MSE zeichnen (das Maß des Ausgangsartikels an einem semantischen Rig; mocap pfa --rig)</translation>
    </message>
    <message>
        <location line="+167"/>
        <source>Judging on the rig needs a blendshape rig (Blendshape Solve panel) and the markers bound to its neutral (Face Mesh panel); or switch it off.</source>
        <translation>Die Beurteilung am Rig braucht ein Blendshape-Rig (Blendshape-Solve-Panel) und an seine Neutralform gebundene Marker (Face-Mesh-Panel); oder schalten Sie sie aus.</translation>
    </message>
    <message>
        <location line="+102"/>
        <source>%1 markers, %2 frames (%7), %3 pairs (%4), %5 PCA components. Recommended: %6 markers.</source>
        <translation>%1 Marker, %2 Bilder (%7), %3 Paare (%4), %5 PCA-Komponenten. Empfohlen: %6 Marker.</translation>
    </message>
    <message numerus="yes">
        <location line="+7"/>
        <source>head motion removed with %n reference marker(s)</source>
        <translation>
            <numerusform>Kopfbewegung mit %n Referenzmarker entfernt</numerusform>
            <numerusform>Kopfbewegung mit %n Referenzmarkern entfernt</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2"/>
        <source>head motion not removed: no reference markers</source>
        <translation>Kopfbewegung nicht entfernt: keine Referenzmarker</translation>
    </message>
    <message>
        <location line="-292"/>
        <source>Reference markers:</source>
        <translation>Referenzmarker:</translation>
    </message>
    <message>
        <location line="-32"/>
        <location line="+41"/>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Leave out:</source>
        <translation>Auslassen:</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Run</source>
        <translation>Ausführen</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation type="vanished">Abbrechen</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Marker</source>
        <translation>Marker</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Mirror</source>
        <translation>Spiegelpartner</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Pair frequency</source>
        <translation>Paarhäufigkeit</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The selected layout&apos;s markers; the frequency is the share of k-means restarts that chose the marker&apos;s pair (PFA only)</source>
        <translation>Die Marker des gewählten Layouts; die Häufigkeit ist der Anteil der k-Means-Neustarts, die das Paar des Markers gewählt haben (nur PFA)</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Export Labels…</source>
        <translation>Namen exportieren…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Export Marker Set…</source>
        <translation>Markersatz exportieren…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Export Take…</source>
        <translation>Aufnahme exportieren…</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Export marker labels</source>
        <translation>Markernamen exportieren</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Label list (*.txt)</source>
        <translation>Namensliste (*.txt)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Export marker set</source>
        <translation>Markersatz exportieren</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Marker set (*.json)</source>
        <translation>Markersatz (*.json)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Export reduced take</source>
        <translation>Reduzierte Aufnahme exportieren</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>C3D (*.c3d);;TRC (*.trc)</source>
        <translation>C3D (*.c3d);;TRC (*.trc)</translation>
    </message>
    <message>
        <location line="+89"/>
        <source>A plan is already running.</source>
        <translation>Eine Planung läuft bereits.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Open a take first.</source>
        <translation>Öffnen Sie zuerst eine Aufnahme.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The smallest cluster count (%1) is larger than the largest (%2).</source>
        <translation>Die kleinste Clusteranzahl (%1) ist größer als die größte (%2).</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The pairs file %1 does not exist.</source>
        <translation>Die Paardatei %1 existiert nicht.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Head motion needs at least three reference markers (Marker ▸ Reference Markers…).</source>
        <translation>Zum Entfernen der Kopfbewegung sind mindestens drei Referenzmarker nötig (Marker ▸ Referenzmarker…).</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Planning…</source>
        <translation>Planung läuft…</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Key poses</source>
        <translation>Schlüsselposen</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Plan markers</source>
        <translation>Marker planen</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Leave out</source>
        <translation>Auslassen</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location line="-191"/>
        <source>Cancelling…</source>
        <translation>Wird abgebrochen…</translation>
    </message>
    <message>
        <location line="+235"/>
        <source>Planning failed: %1</source>
        <translation>Planung fehlgeschlagen: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Cancelled; the previous result is kept.</source>
        <translation>Abgebrochen; das vorherige Ergebnis bleibt erhalten.</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>%1 frames dropped for a missing marker; the PCA explains %2 % of the variance; recommended by the %3</source>
        <translation>%1 Bilder wegen eines fehlenden Markers verworfen; die PCA erklärt %2 % der Varianz; Empfehlung gemäß %3</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Not judged on the rig: %1</source>
        <translation>Nicht am Rig beurteilt: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Judging on the rig was cancelled.</source>
        <translation>Die Beurteilung am Rig wurde abgebrochen.</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>PFA %1 · greedy %2 · random %3</source>
        <translation>PFA %1 · Greedy %2 · Zufall %3</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Rig-weight MSE at %1 markers (%2 of them bound; all %3 bound markers: 0): %4</source>
        <translation>Rig-Gewichts-MSE bei %1 Markern (%2 davon gebunden; alle %3 gebundenen Marker: 0): %4</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>—</source>
        <translation>—</translation>
    </message>
    <message>
        <location line="+10"/>
        <location line="+16"/>
        <location line="+27"/>
        <source>There is no layout to export: run the plan and pick a marker count.</source>
        <translation>Es gibt kein Layout zum Exportieren: Führen Sie die Planung aus und wählen Sie eine Markeranzahl.</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>Could not write %1:
%2</source>
        <translation>%1 konnte nicht geschrieben werden:
%2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Wrote %1</source>
        <translation>%1 geschrieben</translation>
    </message>
</context>
<context>
    <name>mocap::ui::LiveLinkOpenDialog</name>
    <message>
        <location filename="../widgets/dialogs/live_link_open_dialog.cpp" line="+34"/>
        <location line="+60"/>
        <source>Open Live Link Recording</source>
        <translation>Live-Link-Aufzeichnung öffnen</translation>
    </message>
    <message>
        <location line="-55"/>
        <source>The CSV the Live Link Face app recorded</source>
        <translation>Die CSV, die die Live-Link-Face-App aufgezeichnet hat</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Browse…</source>
        <translation>&amp;Durchsuchen…</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Recording:</source>
        <translation>&amp;Aufzeichnung:</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>By name (arkit_to_ict for ICT names)</source>
        <translation>Nach Namen (arkit_to_ict für ICT-Namen)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Map onto the rig:</source>
        <translation>&amp;Zuordnung auf das Rig:</translation>
    </message>
    <message>
        <location line="+49"/>
        <source>Live Link Face CSV (*.csv);;All files (*)</source>
        <translation>Live-Link-Face-CSV (*.csv);;Alle Dateien (*)</translation>
    </message>
</context>
<context>
    <name>mocap::ui::LiveStreamPanel</name>
    <message>
        <location filename="../widgets/panels/live_stream_panel.cpp" line="+74"/>
        <source>Live Link Face (Unreal, MetaHuman)</source>
        <translation>Live Link Face (Unreal, MetaHuman)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>VMC / OSC (VSeeFace, Blender add-ons)</source>
        <translation>VMC / OSC (VSeeFace, Blender-Add-ons)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Live Link Face: the datagrams Epic&apos;s iPhone app sends, the 52 ARKit curves and the head&apos;s turn.
VMC: OSC bundles of the weights under ARKit names, and the markers as trackers.</source>
        <translation>Live Link Face: die Datagramme der iPhone-App von Epic, die 52 ARKit-Kurven und die Kopfdrehung.
VMC: OSC-Bündel der Gewichte unter ARKit-Namen und die Marker als Tracker.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The computer the engine runs on: a name or an address</source>
        <translation>Der Rechner, auf dem die Engine läuft: ein Name oder eine Adresse</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The Live Link subject name the engine lists</source>
        <translation>Der Live-Link-Subjektname, den die Engine anzeigt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Solved weights</source>
        <translation>Gelöste Gewichte</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The Blendshape Solve dock&apos;s weights on ARKit&apos;s 52 curves (ICT FaceKit names by the shipped ict_to_arkit map)</source>
        <translation>Die Gewichte des Blendshape-Solve-Docks auf den 52 ARKit-Kurven (ICT-FaceKit-Namen über die mitgelieferte Zuordnung ict_to_arkit)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Markers (VMC)</source>
        <translation>Marker (VMC)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Each marker as a VMC tracker, in metres; a missing sample is not sent</source>
        <translation>Jeder Marker als VMC-Tracker, in Metern; ein fehlender Abtastwert wird nicht gesendet</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The take&apos;s rate</source>
        <translation>Rate der Aufnahme</translation>
    </message>
    <message>
        <location line="+3"/>
        <source> Hz</source>
        <translation> Hz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Datagrams per second; each carries the frame shown at that moment</source>
        <translation>Datagramme pro Sekunde; jedes trägt das in diesem Moment gezeigte Bild</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Start or stop the stream (Ctrl+Shift+L)</source>
        <translation>Stream starten oder stoppen (Strg+Umschalt+L)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Protocol</source>
        <translation>Protokoll</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Host</source>
        <translation>Host</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Port</source>
        <translation>Port</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Subject</source>
        <translation>Subjekt</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Send</source>
        <translation>Senden</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Rate</source>
        <translation>Rate</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Ctrl+Shift+L</source>
        <translation>Ctrl+Shift+L</translation>
    </message>
    <message>
        <location line="+84"/>
        <source>Connecting to %1…</source>
        <translation>Verbindung zu %1…</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+7"/>
        <source>Stop</source>
        <translation>Stopp</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Start</source>
        <translation>Start</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Not streaming.</source>
        <translation>Kein Stream.</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Streaming to %1: %2 datagrams/s, %3 sent</source>
        <translation>Stream an %1: %2 Datagramme/s, %3 gesendet</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>, %1 refused: %2</source>
        <translation>, %1 abgewiesen: %2</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Cannot stream: %1</source>
        <translation>Stream nicht möglich: %1</translation>
    </message>
</context>
<context>
    <name>mocap::ui::ManualWindow</name>
    <message>
        <location filename="../widgets/dialogs/manual_window.cpp" line="+27"/>
        <source>Mocap Studio Manual</source>
        <translation>Mocap-Studio-Handbuch</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>The manual is not part of this build (:/manual/manual.md is missing).</source>
        <translation>Das Handbuch ist nicht Teil dieses Builds (:/manual/manual.md fehlt).</translation>
    </message>
</context>
<context>
    <name>mocap::ui::MarkerEditActions</name>
    <message>
        <location filename="../widgets/actions/marker_edit_actions.cpp" line="+30"/>
        <source>Select the markers to delete first</source>
        <translation>Wählen Sie zuerst die zu löschenden Marker aus</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Select the markers to average first</source>
        <translation>Wählen Sie zuerst die zu mittelnden Marker aus</translation>
    </message>
    <message>
        <location line="+8"/>
        <location line="+7"/>
        <source>Add Averaged Marker</source>
        <translation>Gemittelten Marker hinzufügen</translation>
    </message>
    <message>
        <location line="-6"/>
        <source>Label of the marker at the mean of %1:</source>
        <translation>Name des Markers im Mittel von %1:</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&apos;%1&apos; is empty or already a marker label; choose another.</source>
        <translation>„%1“ ist leer oder bereits ein Markername; wählen Sie einen anderen.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Add averaged marker %1</source>
        <translation>Gemittelten Marker %1 hinzufügen</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Select exactly two markers and Shift-drag a frame range on the curves first</source>
        <translation>Wählen Sie genau zwei Marker aus und ziehen Sie zuerst mit Umschalt einen Bildbereich in den Kurven auf</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Nothing to swap: both markers are gaps over the selected range</source>
        <translation>Nichts zu tauschen: Beide Marker sind im ausgewählten Bereich Lücken</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Swap %1 and %2 over frames %3–%4</source>
        <translation>%1 und %2 in den Bildern %3–%4 tauschen</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Select markers and Shift-drag a frame range on the curves first</source>
        <translation>Zuerst Marker auswählen und auf den Kurven per Umschalt-Ziehen einen Frame-Bereich markieren</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Nothing to delete: the selected range is already a gap</source>
        <translation>Nichts zu löschen: Der ausgewählte Bereich ist bereits eine Lücke</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Delete frames %1–%2</source>
        <translation>Frames %1–%2 löschen</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Select the one marker whose label the point gets, then click the point</source>
        <translation>Den einen Marker wählen, dessen Namen der Punkt erhält, dann den Punkt anklicken</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Label %1 as %2</source>
        <translation>%1 als %2 beschriften</translation>
    </message>
</context>
<context>
    <name>mocap::ui::MarkerTableModel</name>
    <message>
        <location filename="../widgets/models/marker_table_model.cpp" line="+72"/>
        <source>A model output (%1), not a marker: never cleaned; drawn and gap-listed only with View ▸ Show Model Outputs</source>
        <translation>Eine Modellausgabe (%1), kein Marker: wird nie bereinigt; gezeichnet und in der Lückenliste nur mit Ansicht ▸ Modellausgaben anzeigen</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Longest gap, in frames</source>
        <translation>Längste Lücke, in Frames</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Marker</source>
        <translation>Marker</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Valid %</source>
        <translation>Gültig %</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Gaps</source>
        <translation>Lücken</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Longest</source>
        <comment>the longest gap</comment>
        <translation>Längste</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Bad</source>
        <comment>bad points</comment>
        <translation>Fehlp.</translation>
    </message>
    <message>
        <source>Longest gap</source>
        <translation type="vanished">Längste Lücke</translation>
    </message>
    <message>
        <location line="-12"/>
        <source>Bad points</source>
        <translation>Fehlpunkte</translation>
    </message>
</context>
<context>
    <name>mocap::ui::MarkerView3d</name>
    <message>
        <location filename="../widgets/views/marker_view_3d.cpp" line="+273"/>
        <source>%1
%2, %3, %4 %5</source>
        <translation>%1
%2, %3, %4 %5</translation>
    </message>
    <message numerus="yes">
        <location line="-69"/>
        <source>Head-stabilized on %n marker(s) — Ctrl+B for the lab frame</source>
        <translation>
            <numerusform>Kopfstabilisiert auf %n Marker — Strg+B für das Laborkoordinatensystem</numerusform>
            <numerusform>Kopfstabilisiert auf %n Marker — Strg+B für das Laborkoordinatensystem</numerusform>
        </translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Camera follows the head</source>
        <translation>Kamera folgt dem Kopf</translation>
    </message>
</context>
<context>
    <name>mocap::ui::ModelOutputsNote</name>
    <message>
        <location filename="../widgets/views/model_outputs_note.cpp" line="+28"/>
        <source>%1 shown</source>
        <translation>%1 angezeigt</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1 hidden</source>
        <translation>%1 ausgeblendet</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 shown; never cleaned</source>
        <translation>%1 angezeigt; nie bereinigt</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1 hidden; View ▸ Show Model Outputs</source>
        <translation>%1 ausgeblendet; Ansicht ▸ Modellausgaben anzeigen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Model outputs are joint angles, forces, moments, powers and virtual points (a model&apos;s segment axes, centre of mass) the capture software stored as points. They are kept and saved, but not cleaned, gap-listed or counted in statistics.</source>
        <translation>Modellausgaben sind Gelenkwinkel, Kräfte, Momente, Leistungen und virtuelle Punkte (Segmentachsen eines Modells, Körperschwerpunkt), die die Aufnahmesoftware als Punkte gespeichert hat. Sie bleiben erhalten und werden gespeichert, aber nicht bereinigt, nicht in der Lückenliste geführt und nicht in Statistiken gezählt.</translation>
    </message>
    <message>
        <source>Model outputs are joint angles, forces, moments and powers the capture software stored as points. They are kept and saved, but not cleaned, gap-listed or counted in statistics.</source>
        <translation type="vanished">Modellausgaben sind Gelenkwinkel, Kräfte, Momente und Leistungen, die die Aufnahmesoftware als Punkte gespeichert hat. Sie bleiben erhalten und werden gespeichert, aber nicht bereinigt, in der Lückenliste gezeigt oder in Statistiken gezählt.</translation>
    </message>
</context>
<context>
    <name>mocap::ui::PreferencesDialog</name>
    <message>
        <location filename="../widgets/dialogs/preferences_dialog.cpp" line="+26"/>
        <source>Preferences</source>
        <translation>Einstellungen</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Radius of the marker spheres as a share of the take&apos;s size</source>
        <translation>Radius der Markerkugeln als Anteil der Größe der Aufnahme</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Marker size:</source>
        <translation>Markergröße:</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Off</source>
        <translation>Aus</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Frames before and after the current one drawn as trails of the selected markers</source>
        <translation>Bilder vor und nach dem aktuellen, die als Spuren der ausgewählten Marker gezeichnet werden</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Trail length (frames):</source>
        <translation>Spurlänge (Bilder):</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Y up</source>
        <translation>Y oben</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Z up</source>
        <translation>Z oben</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Up axis:</source>
        <translation>Hochachse:</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Unit of the curve labels and read-outs; the take keeps its own units</source>
        <translation>Einheit der Kurvenbeschriftungen und Anzeigen; die Aufnahme behält ihre eigenen Einheiten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Display units:</source>
        <translation>Anzeigeeinheit:</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Used from the next start</source>
        <translation>Wird ab dem nächsten Start verwendet</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Language:</source>
        <translation>Sprache:</translation>
    </message>
    <message>
        <location line="+3"/>
        <source> min</source>
        <translation> min</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>How often unsaved edits are copied to a recovery file</source>
        <translation>Wie oft ungesicherte Änderungen in eine Wiederherstellungsdatei kopiert werden</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Autosave every:</source>
        <translation>Automatisch sichern alle:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Captured samples:</source>
        <translation>Erfasste Abtastwerte:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Filled samples:</source>
        <translation>Gefüllte Abtastwerte:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Smoothed samples:</source>
        <translation>Geglättete Abtastwerte:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Edited samples:</source>
        <translation>Bearbeitete Abtastwerte:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Selection:</source>
        <translation>Auswahl:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Bad points:</source>
        <translation>Fehlerhafte Punkte:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>3D background:</source>
        <translation>3D-Hintergrund:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Default Colours</source>
        <translation>Standardfarben</translation>
    </message>
    <message>
        <location line="+58"/>
        <source>Language</source>
        <translation>Sprache</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The new language is used from the next start.</source>
        <translation>Die neue Sprache wird ab dem nächsten Start verwendet.</translation>
    </message>
</context>
<context>
    <name>mocap::ui::ReadWarningsButton</name>
    <message numerus="yes">
        <location filename="../widgets/dialogs/read_warnings_button.cpp" line="+55"/>
        <source>⚠ Incomplete, wrong data: %n warning(s)</source>
        <translation>
            <numerusform>⚠ Unvollständig, falsche Daten: %n Warnung</numerusform>
            <numerusform>⚠ Unvollständig, falsche Daten: %n Warnungen</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>⚠ Incomplete: %n warning(s)</source>
        <translation>
            <numerusform>⚠ Unvollständig: %n Warnung</numerusform>
            <numerusform>⚠ Unvollständig: %n Warnungen</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>⚠ Wrong data: %n warning(s)</source>
        <translation>
            <numerusform>⚠ Falsche Daten: %n Warnung</numerusform>
            <numerusform>⚠ Falsche Daten: %n Warnungen</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>⚠ %n warning(s)</source>
        <translation>
            <numerusform>⚠ %n Warnung</numerusform>
            <numerusform>⚠ %n Warnungen</numerusform>
        </translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Show every warning from reading the file</source>
        <translation>Alle Warnungen beim Lesen der Datei anzeigen</translation>
    </message>
</context>
<context>
    <name>mocap::ui::ReadWarningsDialog</name>
    <message>
        <location filename="../widgets/dialogs/read_warnings_dialog.cpp" line="+31"/>
        <source>%1 is incomplete and has wrong data</source>
        <translation>%1 ist unvollständig und enthält falsche Daten</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 is incomplete</source>
        <translation>%1 ist unvollständig</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 has wrong data</source>
        <translation>%1 enthält falsche Daten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Warnings reading %1</source>
        <translation>Warnungen beim Lesen von %1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>&lt;b&gt;Data is missing from %1, and some that was read is wrong.&lt;/b&gt; The take opened with what could be read; the rest is not in it, and the samples named below are not what was captured. Saving writes only what was read, with these findings.</source>
        <translation>&lt;b&gt;In %1 fehlen Daten, und einige gelesene sind falsch.&lt;/b&gt; Die Aufnahme wurde mit dem geöffnet, was gelesen werden konnte; der Rest fehlt, und die unten genannten Abtastwerte sind nicht das, was aufgenommen wurde. Beim Speichern wird nur das Gelesene geschrieben, mit diesen Befunden.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&lt;b&gt;Data is missing from %1.&lt;/b&gt; The take opened with what could be read; the rest is not in it. Saving writes only what was read.</source>
        <translation>&lt;b&gt;In %1 fehlen Daten.&lt;/b&gt; Die Aufnahme wurde mit dem geöffnet, was gelesen werden konnte; der Rest ist nicht enthalten. Beim Speichern wird nur das Gelesene geschrieben.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&lt;b&gt;Some data in %1 is wrong.&lt;/b&gt; The take opened with every sample as it was read, but the samples named below are not what was captured. Saving keeps them as they are, with this finding.</source>
        <translation>&lt;b&gt;Einige Daten in %1 sind falsch.&lt;/b&gt; Die Aufnahme wurde mit jedem Abtastwert so geöffnet, wie er gelesen wurde, aber die unten genannten Abtastwerte sind nicht das, was aufgenommen wurde. Beim Speichern bleiben sie, wie sie sind, mit diesem Befund.</translation>
    </message>
    <message numerus="yes">
        <location line="+4"/>
        <source>%n warning(s) while reading %1. The take opened; these are quirks of the file that were tolerated.</source>
        <translation>
            <numerusform>%n Warnung beim Lesen von %1. Die Aufnahme wurde geöffnet; es handelt sich um eine tolerierte Eigenheit der Datei.</numerusform>
            <numerusform>%n Warnungen beim Lesen von %1. Die Aufnahme wurde geöffnet; es handelt sich um tolerierte Eigenheiten der Datei.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+11"/>
        <source>incomplete, wrong data</source>
        <translation>unvollständig, falsche Daten</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>incomplete</source>
        <translation>unvollständig</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>wrong data</source>
        <translation>falsche Daten</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>%1 (acknowledged)</source>
        <translation>%1 (bestätigt)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>I understand</source>
        <translation>Verstanden</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Close</source>
        <translation>Schließen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Acknowledge</source>
        <translation>Bestätigen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Record in the take&apos;s history that a person has seen these findings (undoable): they stay in the history and in mocap info, but reading a saved copy no longer raises them as warnings</source>
        <translation>Im Verlauf der Aufnahme festhalten, dass ein Mensch diese Befunde gesehen hat (rückgängig machbar): Sie bleiben im Verlauf und in mocap info, aber beim Lesen einer gespeicherten Kopie werden sie nicht mehr als Warnungen gemeldet</translation>
    </message>
</context>
<context>
    <name>mocap::ui::ReferenceMarkerActions</name>
    <message>
        <location filename="../widgets/actions/reference_marker_actions.cpp" line="+39"/>
        <source>Reference markers unchanged</source>
        <translation>Referenzmarker unverändert</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Select at least three head-mounted markers first</source>
        <translation>Wählen Sie zuerst mindestens drei am Kopf befestigte Marker aus</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The selected markers already are the reference markers</source>
        <translation>Die ausgewählten Marker sind bereits die Referenzmarker</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Head markers set; Edit ▸ Undo takes them back</source>
        <translation>Kopfmarker gesetzt; Bearbeiten ▸ Rückgängig nimmt sie zurück</translation>
    </message>
</context>
<context>
    <name>mocap::ui::ReferenceMarkersDialog</name>
    <message>
        <location filename="../widgets/dialogs/reference_markers_dialog.cpp" line="+34"/>
        <source>Reference Markers</source>
        <translation>Referenzmarker</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Head-mounted markers that move only with the head (at least three). Head stabilization, the head-stabilized view, layout planning and the face mesh remove the head&apos;s motion with them; layout planning leaves them out.</source>
        <translation>Am Kopf befestigte Marker, die sich nur mit dem Kopf bewegen (mindestens drei). Kopfstabilisierung, kopfstabilisierte Ansicht, Layoutplanung und Gesichtsnetz entfernen mit ihnen die Bewegung des Kopfes; die Layoutplanung lässt sie aus.</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Valid in %1 % of the frames</source>
        <translation>Gültig in %1 % der Bilder</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>A model output, not a marker</source>
        <translation>Eine Modellausgabe, kein Marker</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&amp;Guess</source>
        <translation>&amp;Vorschlagen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Markers named root… or head…, else the markers that move together as one rigid body</source>
        <translation>Marker namens root… oder head…, sonst die Marker, die sich gemeinsam als ein starrer Körper bewegen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Use &amp;Selection</source>
        <translation>&amp;Auswahl verwenden</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>C&amp;lear</source>
        <translation>&amp;Leeren</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>No reference markers: head motion is not removed anywhere</source>
        <translation>Keine Referenzmarker: Die Kopfbewegung wird nirgends entfernt</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>No reference markers: head motion is not removed, and layout planning plans every labelled marker.</source>
        <translation>Keine Referenzmarker: Die Kopfbewegung wird nicht entfernt, und die Layoutplanung bezieht jeden beschrifteten Marker ein.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1: a head pose needs at least three markers (or none).</source>
        <translation>%1: Eine Kopfhaltung braucht mindestens drei Marker (oder keinen).</translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>%n reference marker(s): %1</source>
        <translation>
            <numerusform>%n Referenzmarker: %1</numerusform>
            <numerusform>%n Referenzmarker: %1</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>mocap::ui::ReferenceMarkersRow</name>
    <message>
        <location filename="../widgets/panels/reference_markers_row.cpp" line="+21"/>
        <source>One set per take, chosen in Marker ▸ Reference Markers…</source>
        <translation>Ein Satz pro Aufnahme, gewählt unter Marker ▸ Referenzmarker…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Edit…</source>
        <translation>Bearbeiten…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Choose the reference markers (Marker ▸ Reference Markers…)</source>
        <translation>Referenzmarker wählen (Marker ▸ Referenzmarker…)</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>none (head motion is not removed)</source>
        <translation>keine (Kopfbewegung wird nicht entfernt)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
</context>
<context>
    <name>mocap::ui::ReferenceVideoPanel</name>
    <message>
        <location filename="../widgets/panels/reference_video_panel.cpp" line="+48"/>
        <source>The take&apos;s reference videos: the one picked here is shown</source>
        <translation>Die Referenzvideos der Aufnahme: Das hier gewählte wird angezeigt</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Add Reference Video…</source>
        <translation>Referenzvideo hinzufügen…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A video of the session (MP4, MOV, AVI, MKV) shown at the take&apos;s current frame</source>
        <translation>Ein Video der Aufnahmesitzung (MP4, MOV, AVI, MKV), gezeigt beim aktuellen Frame der Aufnahme</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Locate…</source>
        <translation>Suchen…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Find a video that is no longer where the take remembers it</source>
        <translation>Ein Video suchen, das nicht mehr dort liegt, wo die Aufnahme es erwartet</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Remove</source>
        <translation>Entfernen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Remove the shown video from the take</source>
        <translation>Das angezeigte Video aus der Aufnahme entfernen</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>Offset:</source>
        <translation>Versatz:</translation>
    </message>
    <message>
        <location line="-14"/>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Video time at the take&apos;s first frame: video time = (take frame − first) / take rate + offset</source>
        <translation>Videozeit beim ersten Frame der Aufnahme: Videozeit = (Aufnahme-Frame − erster) / Aufnahmerate + Versatz</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>−1 frame</source>
        <translation>−1 Frame</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Show the video one of its frames earlier (Alt+,)</source>
        <translation>Das Video um einen seiner Frames früher zeigen (Alt+,)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Show the video one of its frames later (Alt+.)</source>
        <translation>Das Video um einen seiner Frames später zeigen (Alt+.)</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>Video frame:</source>
        <translation>Videoframe:</translation>
    </message>
    <message>
        <location line="-16"/>
        <source>none</source>
        <translation>keines</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The video frame shown. Type or step it to hold the video at a moment, step the take to the same moment, then press Sync here</source>
        <translation>Der angezeigte Videoframe. Eingeben oder schrittweise ändern, um das Video an einem Moment anzuhalten, die Aufnahme auf denselben Moment stellen und dann „Hier synchronisieren“ drücken</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Sync here</source>
        <translation>Hier synchronisieren</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Set the offset so the held video frame shows at the take&apos;s current frame</source>
        <translation>Den Versatz so setzen, dass der angehaltene Videoframe beim aktuellen Frame der Aufnahme erscheint</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Follow take</source>
        <translation>Aufnahme folgen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stop holding the video: show the frame for the take&apos;s current frame again</source>
        <translation>Das Video nicht mehr anhalten: wieder den Frame zum aktuellen Frame der Aufnahme zeigen</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Event:</source>
        <translation>Ereignis:</translation>
    </message>
    <message>
        <location line="-10"/>
        <source>The take&apos;s events (C3D EVENT parameters); a sync event is picked first</source>
        <translation>Die Ereignisse der Aufnahme (C3D-EVENT-Parameter); ein Sync-Ereignis wird zuerst gewählt</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Sync to event</source>
        <translation>Auf Ereignis synchronisieren</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Set the offset so the event shows the video&apos;s first frame, or the held one</source>
        <translation>Den Versatz so setzen, dass beim Ereignis der erste Videoframe erscheint, oder der angehaltene</translation>
    </message>
    <message>
        <location line="+278"/>
        <source>Locate %1</source>
        <translation>%1 suchen</translation>
    </message>
    <message>
        <source>Move the video one of its frames earlier (Alt+,)</source>
        <translation type="vanished">Das Video um eines seiner Frames früher setzen (Alt+,)</translation>
    </message>
    <message>
        <location line="-314"/>
        <source>+1 frame</source>
        <translation>+1 Frame</translation>
    </message>
    <message>
        <source>Move the video one of its frames later (Alt+.)</source>
        <translation type="vanished">Das Video um eines seiner Frames später setzen (Alt+.)</translation>
    </message>
    <message>
        <source>Cannot show %1: %2</source>
        <translation type="vanished">%1 kann nicht gezeigt werden: %2</translation>
    </message>
    <message>
        <location line="+154"/>
        <source>First hold the video at a moment: type its frame or step it, then step the take to the same moment</source>
        <translation>Halten Sie das Video zuerst an einem Moment an: Frame eingeben oder schrittweise ändern, dann die Aufnahme auf denselben Moment stellen</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Video frame %1 now shows at take frame %2 (offset %3 s)</source>
        <translation>Videoframe %1 erscheint jetzt bei Aufnahme-Frame %2 (Versatz %3 s)</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>The event “%1” (%2 s) lies outside the take&apos;s frames</source>
        <translation>Das Ereignis „%1“ (%2 s) liegt außerhalb der Frames der Aufnahme</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Video frame %1 now shows at the event “%2” (take frame %3; offset %4 s)</source>
        <translation>Videoframe %1 erscheint jetzt beim Ereignis „%2“ (Aufnahme-Frame %3; Versatz %4 s)</translation>
    </message>
    <message>
        <location line="+44"/>
        <source>%1 (missing)</source>
        <translation>%1 (fehlt)</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+3"/>
        <source>No reference video</source>
        <translation>Kein Referenzvideo</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>%1 is not available</source>
        <translation>%1 ist nicht verfügbar</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: %2×%3, %4 fps, %5 frames (%6 s), %7</source>
        <translation>%1: %2×%3, %4 fps, %5 Frames (%6 s), %7</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>; variable frame rate: frames are placed by their timestamps</source>
        <translation>; variable Bildrate: Frames werden nach ihren Zeitstempeln platziert</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>%1%2 · frame %3</source>
        <translation>%1%2 · Frame %3</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The take has no events</source>
        <translation>Die Aufnahme hat keine Ereignisse</translation>
    </message>
    <message>
        <source>The videos remembered for this take cannot be read (%1); that file is left as it is and changes here are not remembered.</source>
        <translation type="vanished">Die für diese Aufnahme gemerkten Videos können nicht gelesen werden (%1); die Datei bleibt unverändert, und Änderungen hier werden nicht gemerkt.</translation>
    </message>
    <message>
        <source>%1 is missing: the take remembers it at %2. Locate… finds it; until then it stays linked to the take.</source>
        <translation type="vanished">%1 fehlt: Die Aufnahme erwartet es unter %2. „Suchen…“ findet es; bis dahin bleibt es mit der Aufnahme verknüpft.</translation>
    </message>
    <message numerus="yes">
        <location line="+10"/>
        <source>%n of the take&apos;s reference videos cannot be found where the take remembers them. Pick one and press Locate… to find it; they stay remembered meanwhile.</source>
        <translation>
            <numerusform>%n Referenzvideo der Aufnahme ist nicht dort, wo die Aufnahme es erwartet. Wählen Sie es und drücken Sie „Suchen…“; es bleibt so lange gemerkt.</numerusform>
            <numerusform>%n Referenzvideos der Aufnahme sind nicht dort, wo die Aufnahme sie erwartet. Wählen Sie eines und drücken Sie „Suchen…“; sie bleiben so lange gemerkt.</numerusform>
        </translation>
    </message>
    <message>
        <source>Cannot remember the videos beside the take: %1</source>
        <translation type="vanished">Die Videos können nicht neben der Aufnahme gemerkt werden: %1</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Add reference video</source>
        <translation>Referenzvideo hinzufügen</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+16"/>
        <source>Videos (*.mp4 *.mov *.avi *.mkv *.m4v *.webm);;All files (*)</source>
        <translation>Videos (*.mp4 *.mov *.avi *.mkv *.m4v *.webm);;Alle Dateien (*)</translation>
    </message>
</context>
<context>
    <name>mocap::ui::ReferenceVideos</name>
    <message>
        <location filename="../widgets/document/reference_videos.cpp" line="+125"/>
        <location line="+27"/>
        <location line="+18"/>
        <source>Cannot show %1: %2</source>
        <translation>%1 kann nicht gezeigt werden: %2</translation>
    </message>
    <message>
        <location line="-4"/>
        <source>%1 is missing: the take remembers it at %2. Locate… finds it; until then it stays linked to the take.</source>
        <translation>%1 fehlt: Die Aufnahme erwartet es unter %2. „Suchen…“ findet es; bis dahin bleibt es mit der Aufnahme verknüpft.</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>The videos remembered for this take cannot be read (%1); that file is left as it is and changes here are not remembered.</source>
        <translation>Die für diese Aufnahme gemerkten Videos können nicht gelesen werden (%1); die Datei bleibt unverändert, und Änderungen hier werden nicht gemerkt.</translation>
    </message>
    <message>
        <location line="+64"/>
        <source>Cannot remember the videos beside the take: %1</source>
        <translation>Die Videos können nicht neben der Aufnahme gemerkt werden: %1</translation>
    </message>
</context>
<context>
    <name>mocap::ui::RetargetMapChooser</name>
    <message>
        <location filename="../widgets/dialogs/retarget_map_chooser.cpp" line="+31"/>
        <source>%1 (shipped)</source>
        <translation>%1 (mitgeliefert)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Map file…</source>
        <translation>Zuordnungsdatei…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Our shape names onto the target rig&apos;s channels, with gains, offsets and clamps (as the command line&apos;s --map)</source>
        <translation>Unsere Shape-Namen auf die Kanäle des Ziel-Rigs, mit Verstärkungen, Versätzen und Begrenzungen (wie --map der Kommandozeile)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Br&amp;owse…</source>
        <translation>Dur&amp;chsuchen…</translation>
    </message>
    <message>
        <location line="+84"/>
        <source>Retarget map</source>
        <translation>Retarget-Zuordnung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Retarget maps (*.json);;All files (*)</source>
        <translation>Retarget-Zuordnungen (*.json);;Alle Dateien (*)</translation>
    </message>
</context>
<context>
    <name>mocap::ui::RetargetSection</name>
    <message>
        <location filename="../widgets/panels/retarget_section.cpp" line="+56"/>
        <source>Retarget</source>
        <translation>Retarget</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>No map</source>
        <translation>Keine Zuordnung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save Map As…</source>
        <translation>Zuordnung speichern unter…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The map with its edited gains as JSON, for Export Rig and mocap solve --map</source>
        <translation>Die Zuordnung mit ihren bearbeiteten Verstärkungen als JSON, für „Rig exportieren“ und mocap solve --map</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Channel</source>
        <translation>Kanal</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Source</source>
        <translation>Quelle</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Gain</source>
        <translation>Verstärkung</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Peak</source>
        <translation>Maximum</translation>
    </message>
    <message>
        <location line="+43"/>
        <source>Cannot read the map: %1</source>
        <translation>Die Zuordnung kann nicht gelesen werden: %1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Load a map first.</source>
        <translation>Laden Sie zuerst eine Zuordnung.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Cannot write the map: %1</source>
        <translation>Die Zuordnung kann nicht geschrieben werden: %1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Saved the map to %1.</source>
        <translation>Zuordnung in %1 gespeichert.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>That row has no source to scale.</source>
        <translation>Diese Zeile hat keine Quelle zum Skalieren.</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+91"/>
        <source>A gain must be a number.</source>
        <translation>Eine Verstärkung muss eine Zahl sein.</translation>
    </message>
    <message>
        <location line="-86"/>
        <source>Gain of %1 in %2</source>
        <translation>Verstärkung von %1 in %2</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>(none)</source>
        <translation>(keine)</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Load a map to see the solve under a target rig&apos;s channels.</source>
        <translation>Laden Sie eine Zuordnung, um den Solve unter den Kanälen eines Ziel-Rigs zu sehen.</translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>%n channel(s). Load a rig to map its curves.</source>
        <translation>
            <numerusform>%n Kanal. Laden Sie ein Rig, um seine Kurven zuzuordnen.</numerusform>
            <numerusform>%n Kanäle. Laden Sie ein Rig, um seine Kurven zuzuordnen.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+5"/>
        <source>%n channel(s) from the rig&apos;s shapes.</source>
        <translation>
            <numerusform>%n Kanal aus den Shapes des Rigs.</numerusform>
            <numerusform>%n Kanäle aus den Shapes des Rigs.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The map does not fit the rig: %1</source>
        <translation>Die Zuordnung passt nicht zum Rig: %1</translation>
    </message>
    <message>
        <location line="+57"/>
        <source>Save Retarget Map</source>
        <translation>Retarget-Zuordnung speichern</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Retarget maps (*.json)</source>
        <translation>Retarget-Zuordnungen (*.json)</translation>
    </message>
</context>
<context>
    <name>mocap::ui::ReviewExportDialog</name>
    <message>
        <location filename="../widgets/actions/review_video_export.cpp" line="+34"/>
        <source>Rendering the review video…</source>
        <translation>Das Prüfvideo wird gerendert…</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Review video cancelled; nothing was written.</source>
        <translation>Prüfvideo abgebrochen; es wurde nichts geschrieben.</translation>
    </message>
    <message>
        <location line="+3"/>
        <location filename="../widgets/dialogs/review_export_dialog.cpp" line="+38"/>
        <location line="+55"/>
        <source>Export Review Video</source>
        <translation>Prüfvideo exportieren</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The review video was not written: %1</source>
        <translation>Das Prüfvideo wurde nicht geschrieben: %1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>This system has no MP4 encoder, so the video was written as Motion JPEG AVI: %1</source>
        <translation>Dieses System hat keinen MP4-Encoder, daher wurde das Video als Motion-JPEG-AVI geschrieben: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Wrote %1 (%2 frames, %3)</source>
        <translation>%1 geschrieben (%2 Frames, %3)</translation>
    </message>
    <message>
        <location filename="../widgets/dialogs/review_export_dialog.cpp" line="-45"/>
        <source>Browse…</source>
        <translation>Durchsuchen…</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1 × %2</source>
        <translation>%1 × %2</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>to</source>
        <translation>bis</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Reference video beside the 3D view</source>
        <translation>Referenzvideo neben der 3D-Ansicht</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Add a reference video in the Reference Video dock to draw it beside the view.</source>
        <translation>Fügen Sie im Dock „Referenzvideo“ ein Referenzvideo hinzu, um es neben der Ansicht zu zeigen.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Export</source>
        <translation>Exportieren</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>File:</source>
        <translation>Datei:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Size:</source>
        <translation>Größe:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Frames:</source>
        <translation>Frames:</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>MP4 video (*.mp4);;Motion JPEG AVI (*.avi)</source>
        <translation>MP4-Video (*.mp4);;Motion-JPEG-AVI (*.avi)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Name the video .mp4 or .avi.</source>
        <translation>Benennen Sie das Video mit .mp4 oder .avi.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The first frame comes after the last.</source>
        <translation>Der erste Frame liegt nach dem letzten.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 exists. Replace it?</source>
        <translation>%1 existiert. Ersetzen?</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>untitled take</source>
        <translation>unbenannte Aufnahme</translation>
    </message>
</context>
<context>
    <name>mocap::ui::RigExportDialog</name>
    <message>
        <location filename="../widgets/dialogs/rig_export_dialog.cpp" line="+90"/>
        <location line="+246"/>
        <source>Export Rig</source>
        <translation>Rig exportieren</translation>
    </message>
    <message>
        <location line="-233"/>
        <source>FBX rig with animated blend shapes (.fbx)</source>
        <translation>FBX-Rig mit animierten Blendshapes (.fbx)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>glTF rig with animated morph targets (.glb)</source>
        <translation>glTF-Rig mit animierten Morph-Targets (.glb)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Weight curves, one column per shape (.csv)</source>
        <translation>Gewichtskurven, eine Spalte pro Shape (.csv)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Live Link Face CSV (.csv)</source>
        <translation>Live-Link-Face-CSV (.csv)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Format:</source>
        <translation>&amp;Format:</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Browse…</source>
        <translation>&amp;Durchsuchen…</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Output:</source>
        <translation>&amp;Ausgabe:</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>None (the rig&apos;s own names)</source>
        <translation>Keine (die eigenen Namen des Rigs)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>For Live Link Face, none means the default map for the rig&apos;s names</source>
        <translation>Für Live Link Face bedeutet „Keine“ die Standardzuordnung für die Namen des Rigs</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Retarget &amp;map:</source>
        <translation>Retarget-&amp;Zuordnung:</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Keys:</source>
        <translation>&amp;Keys:</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Y up</source>
        <translation>Y oben</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Z up</source>
        <translation>Z oben</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The units the rig&apos;s coordinates are in, declared in the FBX&apos;s global settings</source>
        <translation>Die Einheit der Koordinaten des Rigs, in den globalen Einstellungen der FBX angegeben</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>FBX &amp;axes:</source>
        <translation>FBX-&amp;Achsen:</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>&amp;Export</source>
        <translation>&amp;Exportieren</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Close</source>
        <translation>Schließen</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Keep the fewest keys within</source>
        <translation>Die wenigsten Keys behalten innerhalb von</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Each curve keeps the fewest keys whose linear interpolation stays within the tolerance of every frame (as mocap solve --reduce); otherwise every frame is a key</source>
        <translation>Jede Kurve behält die wenigsten Keys, deren lineare Interpolation innerhalb der Toleranz zu jedem Frame bleibt (wie mocap solve --reduce); sonst ist jeder Frame ein Key</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>weight units</source>
        <translation>Gewichtseinheiten</translation>
    </message>
    <message>
        <location line="+83"/>
        <source>Retarget section&apos;s: %1, gains edited</source>
        <translation>Aus dem Retarget-Bereich: %1, Verstärkungen bearbeitet</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Retarget section&apos;s: %1</source>
        <translation>Aus dem Retarget-Bereich: %1</translation>
    </message>
    <message>
        <location line="+65"/>
        <source>FBX (*.fbx)</source>
        <translation>FBX (*.fbx)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>glTF binary (*.glb)</source>
        <translation>glTF binär (*.glb)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CSV (*.csv)</source>
        <translation>CSV (*.csv)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Solve the take first.</source>
        <translation>Lösen Sie zuerst die Aufnahme.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Choose the map file.</source>
        <translation>Wählen Sie die Zuordnungsdatei.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The map cannot be used: %1</source>
        <translation>Die Zuordnung kann nicht verwendet werden: %1</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Choose where to export.</source>
        <translation>Wählen Sie, wohin exportiert werden soll.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The folder %1 does not exist.</source>
        <translation>Der Ordner %1 existiert nicht.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Replace File?</source>
        <translation>Datei ersetzen?</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Replace %1?</source>
        <translation>%1 ersetzen?</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Not exported: the existing file is kept.</source>
        <translation>Nicht exportiert: Die vorhandene Datei bleibt erhalten.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Export failed: %1</source>
        <translation>Export fehlgeschlagen: %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Wrote %1.</source>
        <translation>%1 geschrieben.</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Every frame is a key: %1 frames.</source>
        <translation>Jeder Frame ist ein Key: %1 Frames.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Kept %1 of %2 keys (%3 %), largest error %4 (tolerance %5).</source>
        <translation>%1 von %2 Keys behalten (%3 %), größter Fehler %4 (Toleranz %5).</translation>
    </message>
</context>
<context>
    <name>mocap::ui::SmoothingStep</name>
    <message>
        <location filename="../widgets/panels/smoothing_step.cpp" line="-105"/>
        <source>GCV smoothing spline (Woltring)</source>
        <translation>GCV-Glättungsspline (Woltring)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>B-spline (Zhang et al., smoothing)</source>
        <translation>B-Spline (Zhang et al., Glättung)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Butterworth (zero lag)</source>
        <translation>Butterworth (ohne Phasenverzug)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Savitzky–Golay</source>
        <translation>Savitzky–Golay</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A smoothing spline whose stiffness is chosen per marker by generalized cross-validation: no setting to tune</source>
        <translation>Ein Glättungsspline, dessen Steifigkeit je Marker per verallgemeinerter Kreuzvalidierung gewählt wird: nichts einzustellen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>A least-squares B-spline with knots every few frames (the paper&apos;s smoothing)</source>
        <translation>Ein Kleinste-Quadrate-B-Spline mit Knoten alle paar Frames (die Glättung des Papers)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>A low-pass filter run forwards and backwards, so nothing lags; cuts motion faster than the cutoff</source>
        <translation>Ein Tiefpassfilter, vorwärts und rückwärts angewandt, damit nichts nachhinkt; entfernt Bewegung, die schneller als die Grenzfrequenz ist</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>A polynomial fitted in a sliding window: keeps peaks sharper than a low-pass filter</source>
        <translation>Ein Polynom, in einem gleitenden Fenster angepasst: erhält Spitzen schärfer als ein Tiefpassfilter</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Method</source>
        <translation>Methode</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>B-spline degree: 3 is cubic, the paper&apos;s &quot;third order&quot;</source>
        <translation>B-Spline-Grad: 3 ist kubisch, die „dritte Ordnung“ des Papers</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Degree</source>
        <translation>Grad</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+11"/>
        <source> frames</source>
        <translation> Frames</translation>
    </message>
    <message>
        <location line="-10"/>
        <source>Knot spacing</source>
        <translation>Knotenabstand</translation>
    </message>
    <message>
        <location line="+4"/>
        <source> Hz</source>
        <translation> Hz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cutoff</source>
        <translation>Grenzfrequenz</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Window</source>
        <translation>Fenster</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Smoothing</source>
        <translation>Glättung</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>1 sample smoothed</source>
        <translation>1 Abtastwert geglättet</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1 samples smoothed</source>
        <translation>%1 Abtastwerte geglättet</translation>
    </message>
</context>
<context>
    <name>mocap::ui::SpikeStep</name>
    <message>
        <location filename="../widgets/panels/spike_step.cpp" line="-97"/>
        <source>Robust (local fit + MAD)</source>
        <translation>Robust (lokale Anpassung + MAD)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Judges each sample against a robust local fit of its neighbours</source>
        <translation>Beurteilt jeden Abtastwert anhand einer robusten lokalen Anpassung an seine Nachbarn</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>Paper method: step test (Zhang et al., bad points)</source>
        <translation>Paper-Methode: Schritttest (Zhang et al., Ausreißer)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Flags a sample whose steps to both neighbours exceed a multiple of the mean step (the paper as written, one pass); repairs it from its neighbours</source>
        <translation>Markiert einen Abtastwert, dessen Schritte zu beiden Nachbarn ein Vielfaches des mittleren Schritts übersteigen (wie im Paper, ein Durchgang); repariert ihn aus seinen Nachbarn</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Method</source>
        <translation>Methode</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Paper: a sample is bad when both adjacent steps exceed this multiple of the mean step</source>
        <translation>Paper: Ein Abtastwert ist ein Ausreißer, wenn beide angrenzenden Schritte dieses Vielfache des mittleren Schritts überschreiten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Factor</source>
        <translation>Faktor</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Robust: flag samples this many robust standard deviations off the local fit</source>
        <translation>Robust: Abtastwerte markieren, die um so viele robuste Standardabweichungen von der lokalen Anpassung abweichen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Threshold</source>
        <translation>Schwellenwert</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Look again until nothing new</source>
        <translation>Wiederholen, bis nichts Neues kommt</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>A glitch longer than a few frames is found a part at a time, its worst samples first, so detecting again after a repair finds the rest beside the repaired samples. On, the robust detector repeats itself on the repaired curve until it finds nothing new: whole glitches are flagged at once (more flags), and a second detection finds next to nothing.</source>
        <translation>Eine Störung, die länger als einige Bilder dauert, wird stückweise gefunden, ihre schlimmsten Abtastwerte zuerst; eine erneute Erkennung nach einer Reparatur findet daher den Rest neben den reparierten Abtastwerten. Eingeschaltet wiederholt der robuste Detektor die Suche auf der reparierten Kurve, bis er nichts Neues findet: Ganze Störungen werden auf einmal markiert (mehr Markierungen), und eine zweite Erkennung findet so gut wie nichts.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Click to go to a flag; uncheck to keep that sample</source>
        <translation>Klicken, um zum markierten Abtastwert zu springen; Häkchen entfernen, um ihn zu behalten</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Bad points</source>
        <translation>Ausreißer</translation>
    </message>
    <message>
        <location line="+57"/>
        <source>%1 at frame %2</source>
        <translation>%1 bei Frame %2</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>1 sample repaired</source>
        <translation>1 Abtastwert repariert</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1 samples repaired</source>
        <translation>%1 Abtastwerte repariert</translation>
    </message>
</context>
<context>
    <name>mocap::ui::StudioSession</name>
    <message>
        <location filename="../widgets/document/studio_session.cpp" line="+150"/>
        <source>the binding</source>
        <translation>die Bindung</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the binding: %1</source>
        <translation>die Bindung: %1</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>the actor</source>
        <translation>der Darsteller</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the retarget map</source>
        <translation>die Retarget-Zuordnung</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>the weight curves: they were made for a rig that is not loaded</source>
        <translation>die Gewichtskurven: Sie wurden für ein Rig erstellt, das nicht geladen ist</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the weight curves: %1 frames solved, the take has %2</source>
        <translation>die Gewichtskurven: %1 Frames gelöst, die Aufnahme hat %2</translation>
    </message>
</context>
<context>
    <name>mocap::ui::SwapReviewDialog</name>
    <message>
        <location filename="../widgets/dialogs/swap_review_dialog.cpp" line="+16"/>
        <source>Review Label Swaps</source>
        <translation>Namensvertauschungen prüfen</translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>%n swap(s) found. Uncheck the ones to leave as they are; double-click one to see its frame.</source>
        <translation>
            <numerusform>%n Vertauschung gefunden. Abwählen, was bleiben soll; Doppelklick zeigt das Bild.</numerusform>
            <numerusform>%n Vertauschungen gefunden. Abwählen, was bleiben soll; Doppelklick zeigt das Bild.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Frame %1: %2 ↔ %3 (jump %4 mm, %5 mm when exchanged)</source>
        <translation>Bild %1: %2 ↔ %3 (Sprung %4 mm, %5 mm nach Tausch)</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Repair Checked</source>
        <translation>Ausgewählte reparieren</translation>
    </message>
</context>
<context>
    <name>mocap::ui::TakeFileActions</name>
    <message>
        <location filename="../widgets/actions/take_file_actions.cpp" line="+36"/>
        <source>Opening %1…</source>
        <translation>%1 wird geöffnet…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Cancelled</source>
        <translation>Abgebrochen</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Cannot open file</source>
        <translation>Datei kann nicht geöffnet werden</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Open take</source>
        <translation>Take öffnen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Motion capture (*.c3d *.trc);;All files (*)</source>
        <translation>Motion-Capture (*.c3d *.trc);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Overwrite the original?</source>
        <translation>Original überschreiben?</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save over %1? The original capture is replaced by the edited take.</source>
        <translation>%1 überschreiben? Die Originalaufnahme wird durch den bearbeiteten Take ersetzt.</translation>
    </message>
    <message>
        <location line="+8"/>
        <location line="+12"/>
        <source>Cannot save</source>
        <translation>Speichern nicht möglich</translation>
    </message>
    <message>
        <location line="-6"/>
        <source>Save take as</source>
        <translation>Take speichern unter</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>C3D (*.c3d);;TRC (*.trc)</source>
        <translation>C3D (*.c3d);;TRC (*.trc)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Saved %1</source>
        <translation>%1 gespeichert</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Export</source>
        <translation>Exportieren</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>C3D (*.c3d);;TRC (*.trc);;CSV (*.csv);;BVH (*.bvh);;FBX markers (*.fbx)</source>
        <translation>C3D (*.c3d);;TRC (*.trc);;CSV (*.csv);;BVH (*.bvh);;FBX-Marker (*.fbx)</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Cannot export</source>
        <translation>Export nicht möglich</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Exported %1</source>
        <translation>%1 exportiert</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 — note: %2</source>
        <translation>%1 — Hinweis: %2</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Unsaved edits</source>
        <translation>Ungespeicherte Änderungen</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>The take has unsaved edits. Save them?</source>
        <translation>Der Take enthält ungespeicherte Änderungen. Speichern?</translation>
    </message>
</context>
<context>
    <name>mocap::ui::TimelineWidget</name>
    <message>
        <location filename="../widgets/views/timeline_widget.cpp" line="+49"/>
        <source>Dark: gaps, red: bad points under review — of the selected markers, or of all when none is selected. Yellow: the selected frame range.</source>
        <translation>Dunkel: Lücken, rot: zu prüfende Ausreißer — der ausgewählten Marker oder aller, wenn keiner ausgewählt ist. Gelb: der ausgewählte Frame-Bereich.</translation>
    </message>
    <message>
        <location line="+134"/>
        <source>Previous gap</source>
        <translation>Vorherige Lücke</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Previous frame (Left)</source>
        <translation>Vorheriger Frame (Links)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Play / pause (Space)</source>
        <translation>Wiedergabe / Pause (Leertaste)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Next frame (Right)</source>
        <translation>Nächster Frame (Rechts)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Next gap</source>
        <translation>Nächste Lücke</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Loop</source>
        <translation>Schleife</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Frame</source>
        <translation>Frame</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Playback speed</source>
        <translation>Wiedergabegeschwindigkeit</translation>
    </message>
    <message>
        <location line="+145"/>
        <source>No gap after this frame</source>
        <translation>Keine Lücke nach diesem Frame</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>No gap before this frame</source>
        <translation>Keine Lücke vor diesem Frame</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Gap of %1 at frame %2 (%3 frames)</source>
        <translation>Lücke von %1 bei Frame %2 (%3 Frames)</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>No bad point after this frame</source>
        <translation>Kein Ausreißer nach diesem Frame</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>No bad point before this frame</source>
        <translation>Kein Ausreißer vor diesem Frame</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Bad point at frame %1: %2</source>
        <translation>Ausreißer bei Frame %1: %2</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>%1, %2 %3 off the mid-point of its neighbours</source>
        <translation>%1, %2 %3 neben der Mitte seiner Nachbarn</translation>
    </message>
</context>
<context>
    <name>mocap::ui::VideoView</name>
    <message>
        <location filename="../widgets/views/video_view.cpp" line="+37"/>
        <source>No reference video</source>
        <translation>Kein Referenzvideo</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>No video at this frame</source>
        <translation>Kein Video bei diesem Frame</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>video frame %1 · %2 s</source>
        <translation>Videoframe %1 · %2 s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 · held</source>
        <translation>%1 · angehalten</translation>
    </message>
</context>
<context>
    <name>mocap::ui::VtkViewport</name>
    <message>
        <location filename="../widgets/views/vtk_viewport.cpp" line="+255"/>
        <source>No OpenGL context is available, so the 3D view cannot be shown.</source>
        <translation>Es ist kein OpenGL-Kontext verfügbar, daher kann die 3D-Ansicht nicht angezeigt werden.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The 3D view needs OpenGL 3.2; this display offers %1.%2.</source>
        <translation>Die 3D-Ansicht benötigt OpenGL 3.2; diese Anzeige bietet %1.%2.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>The OpenGL context cannot be used, so the 3D view cannot be shown.</source>
        <translation>Der OpenGL-Kontext kann nicht verwendet werden, daher kann die 3D-Ansicht nicht angezeigt werden.</translation>
    </message>
</context>
<context>
    <name>mocap::ui::WeightCurveView</name>
    <message>
        <location filename="../widgets/views/weight_curve_view.cpp" line="+121"/>
        <source>Solve the take to see its weights</source>
        <translation>Lösen Sie die Aufnahme, um ihre Gewichte zu sehen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Load a blendshape rig in the Blendshape Solve panel</source>
        <translation>Laden Sie ein Blendshape-Rig im Blendshape-Solve-Panel</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Click a curve (or pick shapes in the panel) to select its shape</source>
        <translation>Klicken Sie auf eine Kurve (oder wählen Sie Shapes im Panel), um ihren Shape auszuwählen</translation>
    </message>
    <message>
        <location line="+48"/>
        <source>Weights through the map %1</source>
        <translation>Gewichte über die Zuordnung %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Weights</source>
        <translation>Gewichte</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Marker residual (%1)</source>
        <translation>Marker-Residuum (%1)</translation>
    </message>
    <message>
        <location line="+89"/>
        <source>%1 · frame %2 · %3</source>
        <translation>%1 · Frame %2 · %3</translation>
    </message>
</context>
<context>
    <name>mocap::ui::WeightEditActions</name>
    <message>
        <location filename="../widgets/actions/weight_edit_actions.cpp" line="+25"/>
        <source>Solve the take first.</source>
        <translation>Lösen Sie zuerst die Aufnahme.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Select the shapes to edit.</source>
        <translation>Wählen Sie die zu bearbeitenden Shapes.</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Scale weights by %1</source>
        <translation>Gewichte mit %1 skalieren</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Zero weights</source>
        <translation>Gewichte nullen</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>The cut-off must lie between 0 and %1 Hz (half the frame rate).</source>
        <translation>Die Grenzfrequenz muss zwischen 0 und %1 Hz liegen (die halbe Bildrate).</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The take is too short to smooth.</source>
        <translation>Die Aufnahme ist zu kurz zum Glätten.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Smooth weights (%1 Hz)</source>
        <translation>Gewichte glätten (%1 Hz)</translation>
    </message>
</context>
</TS>
