#include "editor/docks/colour_button.h"

#include <QColorDialog>
#include <QPainter>
#include <QPixmap>

namespace regio::editor {

ColourButton::ColourButton(QWidget* parent)
    : QToolButton(parent)
{
    setToolTip(tr("Pick a colour"));
    connect(this, &QToolButton::clicked, this, &ColourButton::pick);
    setColour(Qt::gray);
}

void ColourButton::setColour(const QColor& colour)
{
    m_colour = colour;
    QPixmap pixmap(32, 16);
    pixmap.fill(colour);
    QPainter painter(&pixmap);
    painter.setPen(QColor(30, 30, 30));
    painter.drawRect(0, 0, 31, 15);
    setIcon(QIcon(pixmap));
    setIconSize(pixmap.size());
}

void ColourButton::pick()
{
    const QColor original = m_colour;
    QColorDialog dialog(original, this);
    connect(&dialog, &QColorDialog::currentColorChanged, this, [this](const QColor& c) {
        if (c.isValid())
            emit colourPicked(c);
    });
    if (dialog.exec() == QDialog::Accepted && dialog.selectedColor().isValid()) {
        setColour(dialog.selectedColor());
        emit colourPicked(dialog.selectedColor());
    } else {
        emit colourPicked(original);
    }
}

} // namespace regio::editor
