#pragma once
// Shared fixtures of the editor tests: the sample scenes as the editor opens
// them, a small hand-built scene, and the do / undo / redo check every
// command test uses.
#include "editor/document/scene_document.h"
#include "model/edit/edit_objects.h"
#include "model/geometry/primitives.h"
#include "model/io/scene_json.h"
#include "support/sample_scenes.h"

#include <QStandardPaths>
#include <QString>
#include <QTest>
#include <QUndoStack>

#include <string>

namespace regio::test {

// The file of a sample scene (support/sample_scenes.h), as the editor's open
// functions take it: sampleFile("cornell-box").
inline QString sampleFile(const std::string& name) { return QString::fromStdString(samplePath(name).string()); }

// Materials white, red and light; a table (desk + legs), a crate, a lamp
// panel; a region around them with a BSP order. The scene is valid.
inline model::Scene smallScene()
{
    model::Scene scene;
    scene.materials = {
        {"white", "White", {0.7, 0.7, 0.7}, {0, 0, 0}},
        {"red", "", {0.6, 0.1, 0.1}, {0, 0, 0}},
        {"light", "Lamp light", {0.8, 0.8, 0.8}, {20, 18, 15}},
    };
    model::Object table{"table", "Table", {}};
    table.parts.push_back(*model::makeBox("table.desk", {0, 0.7, 0}, {1, 0.75, 1}, "white"));
    table.parts.push_back(*model::makeBox("table.legs", {0.1, 0, 0.1}, {0.9, 0.7, 0.9}, "white"));
    model::Object crate{"crate", "", {}};
    crate.parts.push_back(*model::makeBox("crate.body", {2, 0, 0}, {2.5, 0.5, 0.5}, "red"));
    model::Object lamp{"lamp", "", {}};
    lamp.parts.push_back(*model::makeBox("lamp.panel", {0.3, 2.0, 0.3}, {0.7, 2.02, 0.7}, "light"));
    scene.objects = {table, crate, lamp};
    model::Region region;
    region.id = "left";
    region.min = {-1, -1, -1};
    region.max = {3, 3, 2};
    region.bspOrder = {"table.desk.py", "table.legs.py"};
    scene.regions = {region};
    return scene;
}

// A document holding `scene`, unmodified, with an empty undo stack.
inline void resetDocument(editor::SceneDocument& document, model::Scene scene) { document.reset(std::move(scene)); }

inline void initTestEnvironment() { QStandardPaths::setTestModeEnabled(true); }

} // namespace regio::test

// After a command was pushed: undo must give back `before` exactly, redo the
// state after the command, and the stack must be back where it was.
#define VERIFY_UNDO_REDO(document, before)                                                                             \
    do {                                                                                                               \
        const regio::model::Scene regioAfter_ = (document).scene();                                                    \
        (document).undoStack()->undo();                                                                                \
        QVERIFY2((document).scene() == (before), "undo did not restore the scene");                                    \
        (document).undoStack()->redo();                                                                                \
        QVERIFY2((document).scene() == regioAfter_, "redo did not repeat the edit");                                   \
    } while (false)
