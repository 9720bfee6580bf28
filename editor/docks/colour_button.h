#pragma once
// A button showing a colour; clicking opens a colour picker. colourPicked
// fires as the user moves through the picker (live preview) and once more
// when they accept; a cancelled picker restores the original colour.
#include <QColor>
#include <QToolButton>

namespace regio::editor {

class ColourButton : public QToolButton {
    Q_OBJECT
public:
    explicit ColourButton(QWidget* parent = nullptr);
    QColor colour() const { return m_colour; }
    void setColour(const QColor& colour);

signals:
    void colourPicked(const QColor& colour);

private:
    void pick();
    QColor m_colour;
};

} // namespace regio::editor
