#pragma once
// Crash recovery. While a document has unsaved changes its scene is written
// every few minutes to a recovery file in the application's data folder; a
// lock file marks the recovery file as belonging to a running editor. After
// a crash the lock is stale, and the next start offers to restore the file.
#include <QLockFile>
#include <QObject>
#include <QString>
#include <QTimer>

#include <memory>

namespace regio::editor {

class SceneDocument;

struct RecoveryFile {
    QString scenePath;    // the autosaved scene
    QString originalPath; // the file the document was editing ("" if never saved)
    QString lockPath;
    qint64 savedAtMs = 0; // modification time of the autosave
};

class Autosave : public QObject {
    Q_OBJECT
public:
    // `directory` empty = QStandardPaths::AppDataLocation + "/recovery".
    Autosave(SceneDocument* document, const QString& directory = {}, QObject* parent = nullptr);
    ~Autosave() override; // a clean shutdown removes the recovery file

    static QString defaultDirectory();
    QString directory() const { return m_directory; }
    QString recoveryPath() const { return m_scenePath; }

    // Minutes between autosaves; 0 stops autosaving.
    void setIntervalMinutes(int minutes);
    void setIntervalMs(int milliseconds); // for tests
    // Writes the recovery file now if the document has unsaved changes (and
    // removes it if it has none). False if writing failed.
    bool saveNow();
    // Removes the recovery file (after a save, or when closing normally).
    void discard();

    // Recovery files left behind by editors that are no longer running.
    static QList<RecoveryFile> findOrphans(const QString& directory = {});
    // Loads an orphan into the document (marked modified, keeping the
    // original path) and deletes it. False if it cannot be read.
    static bool restore(const RecoveryFile& file, SceneDocument* document, QString* error = nullptr);
    static void remove(const RecoveryFile& file);

signals:
    void saveFailed(const QString& message);

private:
    SceneDocument* m_document;
    QString m_directory;
    QString m_scenePath;
    QString m_originPath;
    std::unique_ptr<QLockFile> m_lock;
    QTimer m_timer;
    bool m_dirty = false; // changed since the last autosave
};

} // namespace regio::editor
