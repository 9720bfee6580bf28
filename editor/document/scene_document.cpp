#include "editor/document/scene_document.h"

#include "editor/document/commands/scene_command.h"
#include "editor/document/qt_conversions.h"
#include "model/io/scene_json.h"

#include <QFileInfo>
#include <QUndoStack>

namespace regio::editor {

SceneDocument::SceneDocument(QObject* parent)
    : QObject(parent)
    , m_undoStack(new QUndoStack(this))
{
    connect(m_undoStack, &QUndoStack::cleanChanged, this, [this](bool clean) { emit modifiedChanged(!clean); });
}

SceneDocument::~SceneDocument() = default;

QString SceneDocument::displayName() const
{
    return m_filePath.isEmpty() ? tr("Untitled") : QFileInfo(m_filePath).fileName();
}

bool SceneDocument::isModified() const { return !m_undoStack->isClean(); }

void SceneDocument::setSelection(Selection selection)
{
    selection = selection.prunedTo(m_scene);
    if (selection == m_selection)
        return;
    m_selection = std::move(selection);
    emit selectionChanged();
}

void SceneDocument::setFilePath(const QString& path)
{
    const QString absolute = path.isEmpty() ? QString() : QFileInfo(path).absoluteFilePath();
    if (absolute == m_filePath)
        return;
    m_filePath = absolute;
    emit filePathChanged(m_filePath);
}

void SceneDocument::reset(model::Scene scene, const QString& filePath, bool modified)
{
    const bool wasModified = isModified();
    m_undoStack->clear();
    m_scene = std::move(scene);
    m_selection = {};
    setFilePath(filePath);
    if (modified)
        m_undoStack->resetClean(); // no state of the stack matches the file
    emit sceneReset();
    emit objectsChanged();
    emit materialsChanged();
    emit regionsChanged();
    emit settingsChanged();
    emit cameraChanged();
    emit selectionChanged();
    if (wasModified != isModified())
        emit modifiedChanged(isModified());
}

bool SceneDocument::open(const QString& path, model::Diagnostics& diagnostics)
{
    model::Result<model::Scene> read = model::loadSceneFile(toStd(path));
    diagnostics = read.takeDiagnostics();
    if (!read)
        return false;
    reset(std::move(*read), path);
    return true;
}

bool SceneDocument::revert(model::Diagnostics& diagnostics)
{
    if (m_filePath.isEmpty()) {
        diagnostics = {model::makeError(toStd(tr("the scene has never been saved")))};
        return false;
    }
    return open(m_filePath, diagnostics);
}

bool SceneDocument::save(const QString& path, QString* error)
{
    if (model::Check saved = model::saveSceneFile(m_scene, toStd(path)); !saved) {
        if (error)
            *error = toQString(saved.error().message);
        return false;
    }
    setFilePath(path);
    m_undoStack->setClean();
    return true;
}

bool SceneDocument::push(SceneCommand* command)
{
    m_lastPushFailed = false;
    m_undoStack->push(command); // runs redo(); a refused edit marks itself obsolete
    if (m_lastPushFailed && m_macroDepth > 0)
        m_macroFailed = true;
    return !m_lastPushFailed;
}

void SceneDocument::beginMacro(const QString& text)
{
    if (m_macroDepth++ == 0)
        m_macroFailed = false;
    m_undoStack->beginMacro(text);
}

bool SceneDocument::endMacro()
{
    m_undoStack->endMacro();
    if (--m_macroDepth > 0)
        return !m_macroFailed;
    if (!m_macroFailed)
        return true;
    // Roll the partial macro back, then drop it from the redo side: pushing a
    // command that is already obsolete discards every redoable command and
    // is itself deleted without running.
    m_undoStack->undo();
    auto* drop = new QUndoCommand;
    drop->setObsolete(true);
    m_undoStack->push(drop);
    emit m_undoStack->indexChanged(m_undoStack->index()); // refresh history views
    return false;
}

void SceneDocument::notify(Change changes)
{
    // Edits may remove selected elements (delete, ungroup, split). Views
    // read the selection while handling the change signals, so it must name
    // only what exists before any of them is emitted.
    Selection pruned = m_selection.prunedTo(m_scene);
    const bool selectionChanged = !(pruned == m_selection);
    m_selection = std::move(pruned);
    if (changes & Change::Objects)
        emit objectsChanged();
    else if (changes & Change::Geometry)
        emit geometryChanged();
    if (changes & Change::Materials)
        emit materialsChanged();
    if (changes & Change::Regions)
        emit regionsChanged();
    if (changes & Change::Settings)
        emit settingsChanged();
    if (changes & Change::Camera)
        emit cameraChanged();
    if (selectionChanged)
        emit this->selectionChanged();
}

void SceneDocument::reportFailure(const model::Diagnostic& diagnostic)
{
    m_lastPushFailed = true;
    emit editFailed(toQString(diagnostic.message));
}

} // namespace regio::editor
