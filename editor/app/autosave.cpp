#include "editor/app/autosave.h"

#include "editor/document/qt_conversions.h"
#include "editor/document/scene_document.h"
#include "model/io/file_io.h"
#include "model/io/scene_json.h"

#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QStandardPaths>
#include <QUndoStack>
#include <QUuid>

namespace regio::editor {

namespace {

// Beside each recovery scene: "<id>.json", "<id>.origin" (the original file
// path, UTF-8) and "<id>.lock" (held while the editor runs).
QString sibling(const QString& scenePath, const QString& suffix)
{
    QString base = scenePath;
    base.chop(5); // ".json"
    return base + suffix;
}

} // namespace

Autosave::Autosave(SceneDocument* document, const QString& directory, QObject* parent)
    : QObject(parent)
    , m_document(document)
    , m_directory(directory.isEmpty() ? defaultDirectory() : directory)
{
    QDir().mkpath(m_directory);
    const QString id = QUuid::createUuid().toString(QUuid::WithoutBraces);
    m_scenePath = QDir(m_directory).filePath(id + QStringLiteral(".json"));
    m_originPath = sibling(m_scenePath, QStringLiteral(".origin"));
    m_lock = std::make_unique<QLockFile>(sibling(m_scenePath, QStringLiteral(".lock")));
    m_lock->setStaleLockTime(0); // only a dead owner makes it stale
    m_lock->tryLock(0);

    auto markDirty = [this] { m_dirty = true; };
    connect(document->undoStack(), &QUndoStack::indexChanged, this, markDirty);
    connect(document, &SceneDocument::sceneReset, this, markDirty);
    connect(document, &SceneDocument::modifiedChanged, this, [this](bool modified) {
        if (!modified)
            discard(); // saved: nothing left to recover
    });
    connect(&m_timer, &QTimer::timeout, this, [this] {
        if (m_dirty)
            saveNow();
    });
}

Autosave::~Autosave()
{
    discard();
    m_lock->unlock();
}

QString Autosave::defaultDirectory()
{
    return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) + QStringLiteral("/recovery");
}

void Autosave::setIntervalMinutes(int minutes) { setIntervalMs(minutes * 60 * 1000); }

void Autosave::setIntervalMs(int ms)
{
    if (ms <= 0) {
        m_timer.stop();
        return;
    }
    m_timer.start(ms);
}

bool Autosave::saveNow()
{
    if (!m_document->isModified()) {
        discard();
        return true;
    }
    // The origin first: a recovery scene is never without the name of the
    // file it belongs to, whenever the editor is killed (the scene alone
    // would come back as an unsaved scene of no file).
    model::Check written =
        model::writeFileAtomically(toStd(m_originPath), m_document->filePath().toUtf8().toStdString());
    if (written)
        written = model::writeFileAtomically(toStd(m_scenePath), model::serializeScene(m_document->scene()));
    if (!written) {
        emit saveFailed(tr("Autosave to %1 failed: %2").arg(m_scenePath, toQString(written.error().message)));
        return false;
    }
    m_dirty = false;
    return true;
}

void Autosave::discard()
{
    QFile::remove(m_scenePath);
    QFile::remove(m_originPath);
}

QList<RecoveryFile> Autosave::findOrphans(const QString& directory)
{
    const QDir dir(directory.isEmpty() ? defaultDirectory() : directory);
    QList<RecoveryFile> out;
    const QFileInfoList scenes = dir.entryInfoList({QStringLiteral("*.json")}, QDir::Files, QDir::Time);
    for (const QFileInfo& info : scenes) {
        RecoveryFile file;
        file.scenePath = info.absoluteFilePath();
        file.lockPath = sibling(file.scenePath, QStringLiteral(".lock"));
        QLockFile lock(file.lockPath);
        lock.setStaleLockTime(0);
        if (!lock.tryLock(0))
            continue; // its editor is still running
        lock.unlock();
        QFile origin(sibling(file.scenePath, QStringLiteral(".origin")));
        if (origin.open(QIODevice::ReadOnly))
            file.originalPath = QString::fromUtf8(origin.readAll());
        file.savedAtMs = info.lastModified().toMSecsSinceEpoch();
        out << file;
    }
    return out;
}

bool Autosave::restore(const RecoveryFile& file, SceneDocument* document, QString* error)
{
    model::Result<model::Scene> read = model::loadSceneFile(toStd(file.scenePath));
    if (!read) {
        if (error)
            *error = toQString(read.error().message);
        return false;
    }
    document->reset(std::move(*read), file.originalPath, true);
    remove(file);
    return true;
}

void Autosave::remove(const RecoveryFile& file)
{
    QFile::remove(file.scenePath);
    QFile::remove(sibling(file.scenePath, QStringLiteral(".origin")));
    QFile::remove(file.lockPath);
}

} // namespace regio::editor
