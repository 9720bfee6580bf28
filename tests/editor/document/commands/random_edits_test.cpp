// A long random sequence of edits through every command family, undone to
// the start, must give back exactly the scene that was loaded; redone to the
// end, exactly the scene the edits made.
#include "random_editor.h"

#include "support/editor_documents.h"
#include "support/qt_test_registry.h"

using namespace regio;
using namespace regio::editor;
using regio::test::RandomEditor;
using regio::test::runShortSequence;

class RandomEditsTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { test::initTestEnvironment(); }

    void thousandRandomEditsUndoneGiveBackTheLoadedSceneAndRedoneTheEditedOne_data()
    {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<unsigned>("seed");
        QTest::newRow("two-lights room, seed 1") << QStringLiteral("two-lights-room") << 1u;
        QTest::newRow("two-lights room, seed 2024") << QStringLiteral("two-lights-room") << 2024u;
        QTest::newRow("Cornell box, seed 7") << QStringLiteral("cornell-box") << 7u;
    }

    void thousandRandomEditsUndoneGiveBackTheLoadedSceneAndRedoneTheEditedOne()
    {
        QFETCH(QString, scene);
        QFETCH(unsigned, seed);
        SceneDocument document;
        model::Diagnostics diagnostics;
        QVERIFY(document.open(test::sampleFile(scene.toStdString()), diagnostics));
        const model::Scene loaded = document.scene();

        RandomEditor editor(document, seed);
        int accepted = 0, attempts = 0;
        while (accepted < 1000 && attempts < 20000) {
            ++attempts;
            if (editor.step())
                ++accepted;
        }
        QCOMPARE(accepted, 1000);
        // Every kind of edit took part.
        for (int kind = 0; kind < RandomEditor::kKinds; ++kind)
            QVERIFY2(editor.acceptedByKind()[size_t(kind)] > 0,
                     qPrintable(QStringLiteral("edit kind %1 never ran").arg(kind)));
        QVERIFY(!(document.scene() == loaded));
        const model::Scene edited = document.scene();

        while (document.undoStack()->canUndo())
            document.undoStack()->undo();
        QVERIFY2(document.scene() == loaded, "undoing everything did not give back the loaded scene");
        QVERIFY(!document.isModified());

        while (document.undoStack()->canRedo())
            document.undoStack()->redo();
        QVERIFY2(document.scene() == edited, "redoing everything did not give back the edited scene");
    }

    // Thousands of short sequences of edits, merging bursts, undos and redos
    // in random order: undone to the start the scene saves to exactly the
    // bytes it was loaded from, redone to the top exactly the bytes of the
    // edited scene.
    void thousandsOfShortSequencesMixedWithUndoAndRedoSaveByteForByte()
    {
        int sequences = 0;
        for (const char* sample : {"cornell-box", "two-lights-room"}) {
            SceneDocument document;
            model::Diagnostics diagnostics;
            QVERIFY(document.open(test::sampleFile(sample), diagnostics));
            const model::Scene loaded = document.scene();
            for (unsigned seed = 1; seed <= 1500; ++seed, ++sequences) {
                test::resetDocument(document, loaded);
                if (const QString failure = runShortSequence(document, seed, [] {}); !failure.isEmpty())
                    QFAIL(qPrintable(
                        QStringLiteral("%1, seed %2: %3").arg(QString::fromLatin1(sample)).arg(seed).arg(failure)));
            }
        }
        QCOMPARE(sequences, 3000);
    }
};

REGIO_QTEST_MAIN(RandomEditsTest)
#include "random_edits_test.moc"
