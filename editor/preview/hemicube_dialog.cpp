#include "editor/preview/hemicube_dialog.h"

#include <QGridLayout>
#include <QImage>
#include <QLabel>
#include <QPixmap>
#include <QVBoxLayout>

namespace regio::editor {

HemicubeDialog::HemicubeDialog(QWidget* parent)
    : QDialog(parent)
{
    setWindowTitle(tr("Hemicube"));
    auto* layout = new QVBoxLayout(this);
    auto* grid = new QGridLayout;
    grid->setSpacing(2);
    // Unfolded: +y above the top face, -y below, -x left, +x right.
    const int positions[5][2] = {{1, 1}, {1, 2}, {1, 0}, {0, 1}, {2, 1}};
    for (int i = 0; i < 5; ++i) {
        m_faces[i] = new QLabel;
        m_faces[i]->setAlignment(Qt::AlignCenter);
        grid->addWidget(m_faces[i], positions[i][0], positions[i][1]);
    }
    layout->addLayout(grid);
    m_summary = new QLabel;
    m_summary->setWordWrap(true);
    layout->addWidget(m_summary);
}

void HemicubeDialog::setImages(const HemicubeImages& images)
{
    m_images = images;
    const int side = 256; // display size of the top face
    const char* names[5] = {"top", "+x", "-x", "+y", "-y"};
    for (int i = 0; i < 5; ++i) {
        const HemicubeFaceImage& f = images.faces[size_t(i)];
        QImage image(reinterpret_cast<const uchar*>(f.argb.data()), f.width, f.height, f.width * 4,
                     QImage::Format_ARGB32);
        QImage scaled = image.copy();
        // Side faces stand on the top face's edges: rotate them so that their
        // base (the patch plane) points away from the top face.
        if (i == 1)
            scaled = scaled.transformed(QTransform().rotate(90));
        else if (i == 2)
            scaled = scaled.transformed(QTransform().rotate(-90));
        else if (i == 4)
            scaled = scaled.transformed(QTransform().rotate(180));
        const QSize size = (i == 0)             ? QSize(side, side)
                           : (i == 1 || i == 2) ? QSize(side / 2, side)
                                                : QSize(side, side / 2);
        m_faces[i]->setPixmap(QPixmap::fromImage(scaled.scaled(size, Qt::IgnoreAspectRatio, Qt::FastTransformation)));
        m_faces[i]->setToolTip(tr("Face %1").arg(QLatin1String(names[i])));
    }
    m_summary->setText(tr("Patch %1 of face %2, %3 x %3 pixels: %4 elements seen; %5 % of the form factor "
                          "escapes, %6 % falls on back faces (black: nothing, grey: back faces).")
                           .arg(images.patch)
                           .arg(QString::fromStdString(images.faceId))
                           .arg(images.resolution)
                           .arg(images.elementsSeen)
                           .arg(100.0 * images.escaped, 0, 'f', 2)
                           .arg(100.0 * images.blocked, 0, 'f', 2));
}

} // namespace regio::editor
