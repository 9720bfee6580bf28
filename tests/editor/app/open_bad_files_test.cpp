// The editor's File > Open against every file of the bad-file catalogue
// (tests/data/bad, with check.tsv: what `regio-solve check` prints for
// each): a file the reader refuses leaves the open scene exactly as it was
// and reports the same diagnostics as the command line; a readable scene
// with errors opens, and its validation finds the same problems.
#include "editor/app/main_window.h"
#include "editor/document/scene_document.h"
#include "model/io/printable.h"
#include "model/io/scene_json.h"
#include "model/validation/validation.h"
#include "support/editor_documents.h"
#include "support/qt_test_registry.h"

#include <QDir>
#include <QTest>

#include <fstream>
#include <map>
#include <memory>
#include <set>
#include <string>

using namespace regio;
using namespace regio::editor;

namespace {

// check.tsv: file -> the messages of its diagnostics, as printed.
std::map<std::string, std::multiset<std::string>> expectedMessages()
{
    std::map<std::string, std::multiset<std::string>> table;
    std::ifstream in(std::string(REGIO_TEST_DATA) + "/bad/check.tsv");
    for (std::string row; std::getline(in, row);) {
        if (row.empty() || row[0] == '#')
            continue;
        const size_t tab1 = row.find('\t');
        const std::string file = row.substr(0, tab1);
        const std::string line = row.substr(row.find('\t', tab1 + 1) + 1);
        auto& messages = table[file];
        for (const char* severity : {": error: ", ": warning: "})
            if (const size_t at = line.find(severity); at != std::string::npos) {
                messages.insert(line.substr(at + std::string(severity).size()));
                break;
            }
    }
    return table;
}

} // namespace

class OpenBadFilesTest : public QObject {
    Q_OBJECT
private slots:
    void everyBadFileIsRefusedWithTheCommandLinesDiagnosticsOrOpensWithItsProblems()
    {
        const auto table = expectedMessages();
        QVERIFY(table.size() >= 60);
        MainWindowOptions options;
        options.persistent = false;
        options.interactive = false;
        options.autosave = false;
        MainWindow window(options);
        QVERIFY(window.openFile(test::sampleFile("cornell-box")));
        const std::string sample = model::serializeScene(window.document()->scene());
        const QString title = window.windowTitle();
        int refused = 0;
        int opened = 0;
        for (const auto& [file, expected] : table) {
            const QString path = QDir(QStringLiteral(REGIO_TEST_DATA "/bad")).filePath(QString::fromStdString(file));
            model::Diagnostics diagnostics;
            const bool ok = window.openFile(path, &diagnostics);
            std::multiset<std::string> messages;
            for (const model::Diagnostic& d : diagnostics)
                messages.insert(model::printable(d.message));
            if (ok) {
                ++opened;
                for (const model::Diagnostic& d : model::validateScene(window.document()->scene()))
                    messages.insert(model::printable(d.message));
                // Back to the sample for the next file.
                QVERIFY(window.openFile(test::sampleFile("cornell-box")));
            } else {
                ++refused;
                QVERIFY2(model::serializeScene(window.document()->scene()) == sample, file.c_str());
                QCOMPARE(window.windowTitle(), title);
            }
            QVERIFY2(messages == expected, file.c_str());
        }
        QVERIFY(refused >= 40);
        QVERIFY(opened >= 20);
    }
};

REGIO_QTEST_MAIN(OpenBadFilesTest)
#include "open_bad_files_test.moc"
