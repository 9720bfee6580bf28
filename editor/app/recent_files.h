#pragma once
// The most recently opened or saved scene files, newest first, in QSettings.
#include <QSettings>
#include <QStringList>

namespace regio::editor {

class RecentFiles {
public:
    static constexpr int kMaximum = 10;

    explicit RecentFiles(QSettings& settings)
        : m_settings(settings)
    {
    }
    QStringList files() const;
    // Moves `path` to the front (absolute, duplicates removed).
    void add(const QString& path);
    void remove(const QString& path);
    void clear();

private:
    void store(const QStringList& files);
    QSettings& m_settings;
};

} // namespace regio::editor
