#pragma once
// The inspector: a viewport tool; a left click on the
// solution names the element under the cursor with its radiosity, unshot
// radiosity, area, patch, face and region. Other buttons keep navigating.
#include "editor/preview/preview_session.h"
#include "editor/viewport/camera.h"
#include "editor/viewport/viewport_tool.h"

#include <QObject>
#include <QString>

#include <functional>
#include <memory>
#include <optional>

namespace regio::editor {

struct Inspection {
    int element = -1;
    int patch = -1; // -1 when the frame has no element tables
    std::string faceId;
    std::string regionId;
    model::Rgb radiosity{0.0};
    model::Rgb unshot{0.0};
    model::Rgb displayed{0.0}; // radiosity + reflectance x ambient
    double area = 0.0;
    model::Vec3 point{0.0};
    std::array<model::Vec3, 3> corners{};
};

// The element of the frame's mesh nearest along the ray (front or back side).
std::optional<Inspection> inspectElement(const PreviewFrame& frame, const Ray& ray);
QString describeInspection(const Inspection& inspection);

class PreviewInspector : public QObject, public ViewportTool {
    Q_OBJECT
public:
    using FrameSource = std::function<std::shared_ptr<const PreviewFrame>()>;
    explicit PreviewInspector(FrameSource frames, QObject* parent = nullptr);

    bool mousePress(Viewport& viewport, QMouseEvent* event) override;
    void deactivated() override { emit dropped(); }

signals:
    void inspected(const regio::editor::Inspection& inspection);
    void missed();
    void dropped();

private:
    FrameSource m_frames;
};

} // namespace regio::editor
