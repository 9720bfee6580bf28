#include "editor/preview/preview_inspector.h"

#include "editor/viewport/viewport.h"

#include <QMouseEvent>

#include <glm/geometric.hpp>

#include <cmath>
#include <limits>

namespace regio::editor {

namespace {

// Möller-Trumbore, both sides; the distance along the ray or nothing.
std::optional<double> hitTriangle(const Ray& ray, const model::Vec3& a, const model::Vec3& b, const model::Vec3& c)
{
    const model::Vec3 e1 = b - a, e2 = c - a;
    const model::Vec3 p = glm::cross(ray.direction, e2);
    const double det = glm::dot(e1, p);
    if (std::abs(det) < 1e-14)
        return std::nullopt;
    const double inv = 1.0 / det;
    const model::Vec3 s = ray.origin - a;
    const double u = glm::dot(s, p) * inv;
    if (u < 0.0 || u > 1.0)
        return std::nullopt;
    const model::Vec3 q = glm::cross(s, e1);
    const double v = glm::dot(ray.direction, q) * inv;
    if (v < 0.0 || u + v > 1.0)
        return std::nullopt;
    const double t = glm::dot(e2, q) * inv;
    if (t <= 1e-9)
        return std::nullopt;
    return t;
}

QString rgbText(const model::Rgb& c)
{
    return QStringLiteral("%1, %2, %3").arg(c.r, 0, 'g', 4).arg(c.g, 0, 'g', 4).arg(c.b, 0, 'g', 4);
}

} // namespace

std::optional<Inspection> inspectElement(const PreviewFrame& frame, const Ray& ray)
{
    const solver::SolutionSnapshot& s = frame.snapshot;
    if (!s.mesh)
        return std::nullopt;
    const solver::SolutionMesh& m = *s.mesh;
    double best = std::numeric_limits<double>::infinity();
    int hit = -1;
    for (size_t e = 0; e < m.triangles.size(); ++e) {
        const auto& t = m.triangles[e];
        if (auto d = hitTriangle(ray, m.vertices[size_t(t[0])], m.vertices[size_t(t[1])], m.vertices[size_t(t[2])]);
            d && *d < best) {
            best = *d;
            hit = int(e);
        }
    }
    if (hit < 0 || size_t(hit) >= s.radiosity.size())
        return std::nullopt;
    const size_t e = size_t(hit);
    Inspection out;
    out.element = hit;
    const auto& t = m.triangles[e];
    out.corners = {m.vertices[size_t(t[0])], m.vertices[size_t(t[1])], m.vertices[size_t(t[2])]};
    out.area = 0.5 * glm::length(glm::cross(out.corners[1] - out.corners[0], out.corners[2] - out.corners[0]));
    out.point = ray.origin + best * ray.direction;
    out.faceId = m.faceIds[size_t(m.elementFace[e])];
    out.radiosity = s.radiosity[e];
    out.displayed = s.displayRadiosity(e);
    if (e < frame.unshot.size())
        out.unshot = frame.unshot[e];
    if (e < frame.elementPatch.size())
        out.patch = frame.elementPatch[e];
    if (e < frame.elementRegion.size()) {
        const int r = frame.elementRegion[e];
        if (r >= 0 && size_t(r) < frame.regionIds.size())
            out.regionId = frame.regionIds[size_t(r)];
    }
    return out;
}

QString describeInspection(const Inspection& i)
{
    QStringList lines;
    lines << PreviewInspector::tr("Element %1 of face %2").arg(i.element).arg(QString::fromStdString(i.faceId));
    lines << PreviewInspector::tr("Patch: %1; region: %2")
                 .arg(i.patch >= 0 ? QString::number(i.patch) : PreviewInspector::tr("unknown"))
                 .arg(i.regionId.empty() ? PreviewInspector::tr("unknown") : QString::fromStdString(i.regionId));
    lines << PreviewInspector::tr("Radiosity: %1 W/m²").arg(rgbText(i.radiosity));
    lines << PreviewInspector::tr("Unshot: %1 W/m²").arg(rgbText(i.unshot));
    lines << PreviewInspector::tr("Shown (with ambient): %1 W/m²").arg(rgbText(i.displayed));
    lines << PreviewInspector::tr("Area: %1 m²").arg(i.area, 0, 'g', 4);
    return lines.join(QLatin1Char('\n'));
}

PreviewInspector::PreviewInspector(FrameSource frames, QObject* parent)
    : QObject(parent)
    , m_frames(std::move(frames))
{
}

bool PreviewInspector::mousePress(Viewport& viewport, QMouseEvent* event)
{
    if (event->button() != Qt::LeftButton || event->modifiers() != Qt::NoModifier)
        return false;
    const std::shared_ptr<const PreviewFrame> frame = m_frames();
    if (!frame)
        return false;
    const QPointF pos = event->position();
    const Ray ray = viewport.screenView().ray(pos.x(), pos.y());
    if (auto inspection = inspectElement(*frame, ray))
        emit inspected(*inspection);
    else
        emit missed();
    return true;
}

} // namespace regio::editor
