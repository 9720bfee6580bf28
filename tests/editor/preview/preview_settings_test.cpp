// The solver dock's settings: every control edits through
// SetSolverSettings (undoable, saved in the file), presets, the dry run, and
// the --preview-iterations option.
#include "editor/app/command_line.h"
#include "editor/document/commands/solver_settings_commands.h"
#include "editor/document/scene_document.h"
#include "editor/preview/solver_dock.h"
#include "editor/preview/solver_presets.h"
#include "solver/prepare/prepare.h"
#include "support/editor_documents.h"
#include "support/qt_test_registry.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QGroupBox>
#include <QSpinBox>
#include <QTemporaryDir>

using namespace regio;
using namespace regio::editor;

namespace {

SolverDock::Actions dummyActions(QObject* owner)
{
    auto a = [owner] { return new QAction(QStringLiteral("x"), owner); };
    return {a(), a(), a(), a(), a(), a(), a(), a(), a()};
}

} // namespace

class PreviewSettingsTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { test::initTestEnvironment(); }

    void presetsSetResolutionMeshingAndStoppingButKeepTheScenesChoices()
    {
        model::SolverSettings s;
        s.visibility = model::Visibility::ZBuffer;
        s.regions = model::RegionsMode::Auto;
        s.adaptive.anchoring = false;
        const model::SolverSettings draft = applyPreset(s, SolverPreset::Draft);
        const model::SolverSettings final = applyPreset(s, SolverPreset::Final);
        QVERIFY(draft.hemicube < s.hemicube && final.hemicube > s.hemicube);
        QVERIFY(draft.patchSize > s.patchSize && final.patchSize < s.patchSize);
        QVERIFY(!draft.adaptive.enabled && final.adaptive.enabled);
        QVERIFY(final.convergence < s.convergence && draft.convergence > s.convergence);
        for (const model::SolverSettings& p : {draft, final, applyPreset(s, SolverPreset::Normal)}) {
            QCOMPARE(p.visibility, model::Visibility::ZBuffer);
            QCOMPARE(p.regions, model::RegionsMode::Auto);
            QCOMPARE(p.adaptive.anchoring, false);
            QVERIFY2(model::checkSolverSettings(p).ok(), "a preset must be valid");
        }
        QCOMPARE(presetOf(draft), std::optional(SolverPreset::Draft));
        QCOMPARE(presetOf(final), std::optional(SolverPreset::Final));
        QCOMPARE(presetOf(model::SolverSettings{}), std::optional(SolverPreset::Normal));
        model::SolverSettings custom;
        custom.hemicube = 202;
        QVERIFY(!presetOf(custom));
    }

    void aPresetIsOneUndoableEdit()
    {
        SceneDocument document;
        test::resetDocument(document, test::loadSample("cornell-box"));
        QObject owner;
        SolverDock dock(&document, dummyActions(&owner));
        const model::Scene before = document.scene();
        dock.applyPreset(SolverPreset::Draft);
        QCOMPARE(document.scene().solver, applyPreset(before.solver, SolverPreset::Draft));
        QCOMPARE(document.undoStack()->count(), 1);
        VERIFY_UNDO_REDO(document, before);
        auto* preset = dock.findChild<QComboBox*>(QStringLiteral("preset"));
        QVERIFY(preset);
        QCOMPARE(preset->currentText(), presetName(SolverPreset::Draft));
    }

    void everyControlEditsTheSceneThroughAnUndoCommand()
    {
        SceneDocument document;
        test::resetDocument(document, test::loadSample("two-lights-room"));
        QObject owner;
        SolverDock dock(&document, dummyActions(&owner));
        struct Case {
            const char* name;
            std::function<void()> edit;
            std::function<bool(const model::SolverSettings&)> check;
        };
        const std::vector<Case> cases = {
            {"hemicube", [&] { dock.findChild<QSpinBox*>("hemicube")->setValue(200); },
             [](const auto& s) { return s.hemicube == 200; }},
            {"patchSize", [&] { dock.findChild<QDoubleSpinBox*>("patchSize")->setValue(0.75); },
             [](const auto& s) { return s.patchSize == 0.75; }},
            {"elementsPerPatch", [&] { dock.findChild<QSpinBox*>("elementsPerPatch")->setValue(9); },
             [](const auto& s) { return s.elementsPerPatch == 9; }},
            {"adaptive",
             [&] { dock.findChild<QGroupBox*>("adaptive")->setChecked(!document.scene().solver.adaptive.enabled); },
             [&](const auto& s) {
                 return s.adaptive.enabled != test::loadSample("two-lights-room").solver.adaptive.enabled;
             }},
            {"threshold", [&] { dock.findChild<QDoubleSpinBox*>("threshold")->setValue(0.2); },
             [](const auto& s) { return std::abs(s.adaptive.threshold - 0.2) < 1e-12; }},
            {"minEdge", [&] { dock.findChild<QDoubleSpinBox*>("minEdge")->setValue(0.05); },
             [](const auto& s) { return std::abs(s.adaptive.minEdge - 0.05) < 1e-12; }},
            {"anchoring",
             [&] { dock.findChild<QCheckBox*>("anchoring")->setChecked(!document.scene().solver.adaptive.anchoring); },
             [&](const auto& s) {
                 return s.adaptive.anchoring != test::loadSample("two-lights-room").solver.adaptive.anchoring;
             }},
            {"maxIterations", [&] { dock.findChild<QSpinBox*>("maxIterations")->setValue(1234); },
             [](const auto& s) { return s.maxIterations == 1234; }},
            {"convergence", [&] { dock.findChild<QDoubleSpinBox*>("convergence")->setValue(0.002); },
             [](const auto& s) { return std::abs(s.convergence - 0.002) < 1e-12; }},
            {"visibility",
             [&] {
                 auto* c = dock.findChild<QComboBox*>("visibility");
                 c->setCurrentIndex(1);
                 emit c->activated(1);
             },
             [](const auto& s) { return s.visibility == model::Visibility::ZBuffer; }},
            {"regions",
             [&] {
                 auto* c = dock.findChild<QComboBox*>("regions");
                 c->setCurrentIndex(2);
                 emit c->activated(2);
             },
             [](const auto& s) { return s.regions == model::RegionsMode::Auto; }},
        };
        for (const Case& c : cases) {
            const model::Scene before = document.scene();
            const int commands = document.undoStack()->count();
            c.edit();
            QVERIFY2(c.check(document.scene().solver), c.name);
            QVERIFY2(document.undoStack()->count() == commands + 1 || document.undoStack()->count() == commands,
                     c.name);
            // Undo restores the previous settings (merged edits undo together).
            document.undoStack()->undo();
            QVERIFY2(!c.check(document.scene().solver) || document.scene().solver == before.solver, c.name);
            document.undoStack()->redo();
            QVERIFY2(c.check(document.scene().solver), c.name);
        }
    }

    void anOddHemicubeIsRoundedUpToEven()
    {
        SceneDocument document;
        test::resetDocument(document, test::loadSample("cornell-box"));
        QObject owner;
        SolverDock dock(&document, dummyActions(&owner));
        dock.findChild<QSpinBox*>("hemicube")->setValue(151);
        QCOMPARE(document.scene().solver.hemicube, 152);
    }

    void changingOneControlLeavesTheValuesTheOthersShowRoundedExactlyAsTheSceneHasThem()
    {
        // Values from a file or a sweep that the controls can only show
        // rounded (3 decimals of patch size, 6 of convergence) or clamped.
        model::Scene scene = test::loadSample("cornell-box");
        scene.solver.patchSize = 0.12345;
        scene.solver.convergence = 0.000123456;
        scene.solver.adaptive.minEdge = 0.00005; // below the control's minimum
        scene.solver.adaptive.threshold = 0.04567;
        SceneDocument document;
        test::resetDocument(document, scene);
        QObject owner;
        SolverDock dock(&document, dummyActions(&owner));
        dock.findChild<QSpinBox*>("hemicube")->setValue(240);
        model::SolverSettings expected = scene.solver;
        expected.hemicube = 240;
        QVERIFY(document.scene().solver == expected);
        // And one undo gives back exactly the scene as it was.
        document.undoStack()->undo();
        QVERIFY(document.scene() == scene);
        QCOMPARE(document.undoStack()->count(), 1);
    }

    void settingsSurviveSaveAndLoad()
    {
        SceneDocument document;
        test::resetDocument(document, test::loadSample("cornell-box"));
        QObject owner;
        SolverDock dock(&document, dummyActions(&owner));
        dock.applyPreset(SolverPreset::Final);
        dock.findChild<QComboBox*>("visibility")->setCurrentIndex(1);
        emit dock.findChild<QComboBox*>("visibility")->activated(1);
        const model::SolverSettings expected = document.scene().solver;
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("settings.json"));
        QVERIFY(document.save(path));
        SceneDocument reopened;
        model::Diagnostics diagnostics;
        QVERIFY(reopened.open(path, diagnostics));
        QCOMPARE(reopened.scene().solver, expected);
        SolverDock other(&reopened, dummyActions(&owner));
        QCOMPARE(other.findChild<QSpinBox*>("hemicube")->value(), expected.hemicube);
        // A preset keeps the visibility method: still the final preset.
        QCOMPARE(other.findChild<QComboBox*>("preset")->currentText(), presetName(SolverPreset::Final));
    }

    void theDryRunListsEffectiveSettingsAndTheCountsOfThePreparation()
    {
        model::Scene scene = test::loadSample("two-lights-room");
        scene.solver = applyPreset(scene.solver, SolverPreset::Draft);
        const DryRun run = dryRun(scene);
        QVERIFY(run.ok);
        solver::PrepareOptions options;
        options.regions = scene.solver.regions;
        const model::Result<solver::PreparedScene> prepared = solver::prepareScene(scene, options);
        QVERIFY(prepared.ok());
        QCOMPARE(run.stats.patches, prepared->stats.patches);
        QCOMPARE(run.stats.elements, prepared->stats.elements);
        QCOMPARE(run.regions, int(prepared->regions.size()));
        QCOMPARE(run.settings.hemicube, scene.solver.hemicube);
        const QString text = describeDryRun(run);
        QVERIFY2(text.contains(QString::number(run.stats.patches)), qPrintable(text));
        QVERIFY2(text.contains(QString::number(run.stats.elements)), qPrintable(text));
        QVERIFY2(text.contains(QStringLiteral("painter")), qPrintable(text));

        scene.objects[0].parts[0].faces[0].material = "missing";
        const DryRun broken = dryRun(scene);
        QVERIFY(!broken.ok);
        QVERIFY(describeDryRun(broken).contains(QStringLiteral("missing")));
    }

    void previewIterationsNeedsAScreenshotAndACount()
    {
        const QString app = QStringLiteral("regio");
        CommandLineOptions o =
            parseCommandLine({app, QStringLiteral("s.json"), QStringLiteral("--screenshot"), QStringLiteral("a.png"),
                              QStringLiteral("--preview-iterations"), QStringLiteral("25")});
        QVERIFY(o.ok);
        QCOMPARE(o.previewIterations, 25);
        QCOMPARE(parseCommandLine({app, QStringLiteral("--screenshot"), QStringLiteral("a.png")}).previewIterations,
                 -1);
        QVERIFY(!parseCommandLine({app, QStringLiteral("--preview-iterations"), QStringLiteral("5")}).ok);
        QVERIFY(!parseCommandLine({app, QStringLiteral("--screenshot"), QStringLiteral("a.png"),
                                   QStringLiteral("--preview-iterations"), QStringLiteral("-1")})
                     .ok);
        QVERIFY(!parseCommandLine({app, QStringLiteral("--screenshot"), QStringLiteral("a.png"),
                                   QStringLiteral("--preview-iterations"), QStringLiteral("many")})
                     .ok);
    }
};

REGIO_QTEST_MAIN(PreviewSettingsTest)
#include "preview_settings_test.moc"
