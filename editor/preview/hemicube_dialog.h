#pragma once
// The hemicube of one patch: the five faces of its item
// buffer unfolded around the top face, every element in its own colour, so
// one sees what a shot of that patch paints and in which order it hides.
#include "editor/preview/hemicube_images.h"

#include <QDialog>

class QLabel;

namespace regio::editor {

class HemicubeDialog : public QDialog {
    Q_OBJECT
public:
    explicit HemicubeDialog(QWidget* parent = nullptr);
    void setImages(const HemicubeImages& images);
    const HemicubeImages& images() const { return m_images; }

private:
    HemicubeImages m_images;
    QLabel* m_faces[5]{};
    QLabel* m_summary = nullptr;
};

} // namespace regio::editor
