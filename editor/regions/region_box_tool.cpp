#include "editor/regions/region_box_tool.h"

#include "editor/document/commands/region_commands.h"
#include "editor/document/qt_conversions.h"
#include "editor/document/scene_document.h"
#include "editor/regions/region_drag_command.h"
#include "editor/regions/region_layers.h"
#include "editor/viewport/picking.h"
#include "editor/viewport/viewport.h"

#include <QKeyEvent>
#include <QMouseEvent>

#include <glm/geometric.hpp>

#include <cmath>
#include <limits>

namespace regio::editor {

namespace {

constexpr double kClickSlopPixels = 4.0;
constexpr double kHandlePickPixels = 10.0;
constexpr double kHandleSizePixels = 12.0;
// The smallest box side the tool makes without snapping (1 cm).
constexpr double kMinSide = 0.01;

bool isPlainLeft(const QMouseEvent* event)
{
    return event->button() == Qt::LeftButton && !(event->modifiers() & Qt::AltModifier);
}

model::Vec3 unitAxis(int axis)
{
    model::Vec3 v(0.0);
    v[axis] = 1.0;
    return v;
}

// Entry distance of the ray into the box (0 when it starts inside), or nullopt.
std::optional<double> rayEntersBox(const Ray& ray, const model::Box3& box)
{
    double t0 = 0.0, t1 = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a) {
        if (std::abs(ray.direction[a]) < 1e-15) {
            if (ray.origin[a] < box.min[a] || ray.origin[a] > box.max[a])
                return std::nullopt;
            continue;
        }
        double near = (box.min[a] - ray.origin[a]) / ray.direction[a];
        double far = (box.max[a] - ray.origin[a]) / ray.direction[a];
        if (near > far)
            std::swap(near, far);
        t0 = std::max(t0, near);
        t1 = std::min(t1, far);
        if (t0 > t1)
            return std::nullopt;
    }
    return t0;
}

} // namespace

RegionBoxTool::RegionBoxTool(SceneDocument* document, Viewport* viewport, QObject* parent)
    : QObject(parent)
    , m_document(document)
    , m_viewport(viewport)
{
    auto refresh = [this] {
        if (isActive())
            updateHandles();
    };
    connect(document, &SceneDocument::selectionChanged, this, refresh);
    connect(document, &SceneDocument::regionsChanged, this, refresh);
    connect(document, &SceneDocument::sceneReset, this, refresh);
    connect(viewport, &Viewport::viewChanged, this, refresh);
}

RegionBoxTool::~RegionBoxTool()
{
    if (Viewport* viewport = m_viewport; viewport && viewport->tool() == this)
        viewport->setTool(nullptr);
}

bool RegionBoxTool::isActive() const
{
    // The guarded pointer is read once: each read may find the viewport gone.
    const Viewport* viewport = m_viewport;
    return viewport && viewport->tool() == this;
}

void RegionBoxTool::setActive(bool on)
{
    if (!m_viewport || on == isActive())
        return;
    if (!on) {
        m_viewport->setTool(nullptr); // calls deactivated()
        return;
    }
    m_viewport->setTool(this);
    m_viewport->setCursor(Qt::CrossCursor);
    m_state = State::Idle;
    updateHandles();
    emit statusMessage(
        tr("Region tool: drag on the ground or a horizontal face to draw a box; drag a handle of "
           "the selected region to resize it; Esc leaves the tool"));
    emit activeChanged(true);
}

void RegionBoxTool::deactivated()
{
    m_state = State::Idle;
    m_handle = m_hoverHandle = -1;
    if (m_viewport) {
        m_viewport->unsetCursor();
        m_viewport->removeLayer(QString::fromLatin1(kRegionHandlesLayer));
        m_viewport->removeLayer(QString::fromLatin1(kRegionDraftLayer));
    }
    emit activeChanged(false);
}

double RegionBoxTool::snapped(double value, const GizmoSnap& snap)
{
    if (!snap.enabled || !(snap.step > 0.0))
        return value;
    return std::round(value / snap.step) * snap.step;
}

std::optional<double> RegionBoxTool::lineParameter(const model::Vec3& origin, const model::Vec3& axis, const Ray& ray)
{
    // Closest points of two lines: origin + t * axis and ray.origin + s * ray.direction.
    const model::Vec3 w = origin - ray.origin;
    const double a = glm::dot(axis, axis), b = glm::dot(axis, ray.direction),
                 c = glm::dot(ray.direction, ray.direction);
    const double d = glm::dot(axis, w), e = glm::dot(ray.direction, w);
    const double denominator = a * c - b * b;
    if (denominator < 1e-9 * a * c)
        return std::nullopt;
    return (b * e - c * d) / denominator;
}

const model::Region* RegionBoxTool::selectedRegion() const
{
    const Selection& s = m_document->selection();
    if (s.kind != SelectionKind::Region || s.ids.size() != 1)
        return nullptr;
    return m_document->scene().findRegion(s.ids.front());
}

int RegionBoxTool::handleAt(double px, double py) const
{
    const model::Region* region = selectedRegion();
    if (!region)
        return -1;
    const model::Box3 box = boxOf(*region);
    const ScreenView view = m_viewport->screenView();
    int best = -1;
    double bestDistance = kHandlePickPixels;
    for (int handle = 0; handle < 6; ++handle) {
        const std::optional<glm::dvec2> at = view.toPixels(handlePosition(box, handle));
        if (!at)
            continue;
        const double distance = glm::length(*at - glm::dvec2(px, py));
        if (distance <= bestDistance) {
            bestDistance = distance;
            best = handle;
        }
    }
    return best;
}

std::optional<model::Box3> RegionBoxTool::draft() const
{
    if (m_state != State::Drawing)
        return std::nullopt;
    return boxFromFootprint(m_start, m_end);
}

std::optional<model::Vec3> RegionBoxTool::planePoint(const Ray& ray) const
{
    std::optional<model::Vec3> p = intersectGround(ray, m_planeY);
    if (!p)
        return std::nullopt;
    const GizmoSnap& snap = m_viewport->snap();
    return model::Vec3(snapped(p->x, snap), m_planeY, snapped(p->z, snap));
}

model::Box3 RegionBoxTool::boxFromFootprint(const model::Vec3& a, const model::Vec3& b) const
{
    const model::Box3 extent = sceneExtent(m_document->scene());
    // Drawing happens in the viewport, so it is there; should it be gone, the
    // default snap step sets the height.
    const Viewport* viewport = m_viewport;
    const double step = viewport ? viewport->snap().step : GizmoSnap{}.step;
    const double defaultHeight = std::max(1.0, 10.0 * step);
    double low = m_planeY, high = m_planeY + defaultHeight;
    if (!extent.empty) {
        const double top = extent.max.y, bottom = extent.min.y;
        const bool roomAbove = top > m_planeY + kMinSide, roomBelow = bottom < m_planeY - kMinSide;
        // The box grows into the larger part of the scene: up from a floor or
        // a table top, down from a ceiling.
        if (roomAbove && (!roomBelow || top - m_planeY >= m_planeY - bottom))
            high = top;
        else if (roomBelow)
            low = bottom, high = m_planeY;
    }
    model::Box3 box;
    box.extend(model::Vec3(std::min(a.x, b.x), low, std::min(a.z, b.z)));
    box.extend(model::Vec3(std::max(a.x, b.x), high, std::max(a.z, b.z)));
    return box;
}

bool RegionBoxTool::mousePress(Viewport& viewport, QMouseEvent* event)
{
    if (!isPlainLeft(event))
        return false;
    const QPointF pos = event->position();
    m_pressPos = pos;
    const int handle = handleAt(pos.x(), pos.y());
    if (handle >= 0) {
        const model::Region* region = selectedRegion();
        const Ray ray = viewport.screenView().ray(pos.x(), pos.y());
        m_regionId = region->id;
        m_startBox = boxOf(*region);
        m_handle = handle;
        m_startParameter = lineParameter(handlePosition(m_startBox, handle), unitAxis(handle / 2), ray).value_or(0.0);
        m_state = State::Resizing;
        ++m_dragSerial;
        updateHandles();
        return true;
    }
    // The drawing plane: the top of a horizontal face under the cursor, else the grid.
    const Ray ray = viewport.screenView().ray(pos.x(), pos.y());
    m_planeY = 0.0;
    if (std::optional<PickHit> hit = pickFace(m_document->scene(), ray, viewport.cullBackFaces()))
        if (std::abs(hit->normal.y) > 0.99)
            m_planeY = hit->point.y;
    const std::optional<model::Vec3> start = planePoint(ray);
    m_startValid = start.has_value();
    m_start = m_end = start.value_or(model::Vec3(0.0));
    m_state = State::Pressed;
    return true;
}

bool RegionBoxTool::mouseMove(Viewport& viewport, QMouseEvent* event)
{
    const QPointF pos = event->position();
    switch (m_state) {
    case State::Idle: {
        const int hover = event->buttons() == Qt::NoButton ? handleAt(pos.x(), pos.y()) : -1;
        if (hover != m_hoverHandle) {
            m_hoverHandle = hover;
            updateHandles();
        }
        if (event->buttons() == Qt::NoButton) // a handle drags, anywhere else draws
            viewport.setCursor(hover >= 0 ? Qt::SizeAllCursor : Qt::CrossCursor);
        return false; // the viewport's own hover feedback goes on
    }
    case State::Pressed:
        if ((pos - m_pressPos).manhattanLength() <= kClickSlopPixels)
            return true;
        if (!m_startValid) {
            emit statusMessage(tr("Aim at the ground grid or a horizontal face to start a region"));
            return true;
        }
        m_state = State::Drawing;
        [[fallthrough]];
    case State::Drawing: {
        const Ray ray = viewport.screenView().ray(pos.x(), pos.y());
        if (std::optional<model::Vec3> p = planePoint(ray))
            m_end = *p;
        updateDraftLayer();
        const model::Box3 box = boxFromFootprint(m_start, m_end);
        emit statusMessage(
            tr("Region %1 × %2 × %3 m")
                .arg(formatNumber(box.size().x, 3), formatNumber(box.size().y, 3), formatNumber(box.size().z, 3)));
        return true;
    }
    case State::Resizing: {
        const model::Region* region = m_document->scene().findRegion(m_regionId);
        if (!region) {
            m_state = State::Idle;
            return true;
        }
        const int axis = m_handle / 2;
        const bool maxSide = m_handle % 2 == 1;
        const Ray ray = viewport.screenView().ray(pos.x(), pos.y());
        const std::optional<double> t = lineParameter(handlePosition(m_startBox, m_handle), unitAxis(axis), ray);
        if (!t)
            return true;
        const GizmoSnap& snap = viewport.snap();
        const double start = maxSide ? m_startBox.max[axis] : m_startBox.min[axis];
        double coordinate = snapped(start + (*t - m_startParameter), snap);
        const double minSide = snap.enabled && snap.step > 0.0 ? snap.step : kMinSide;
        model::Vec3 lo = region->min, hi = region->max;
        if (maxSide)
            hi[axis] = std::max(coordinate, lo[axis] + minSide);
        else
            lo[axis] = std::min(coordinate, hi[axis] - minSide);
        if (lo != region->min || hi != region->max)
            m_document->push(new ResizeRegionByHandle(m_document, m_regionId, lo, hi, m_dragSerial));
        static const char* kAxis[3] = {"x", "y", "z"};
        emit statusMessage(tr("Region %1: %2 %3 = %4 m")
                               .arg(toQString(m_regionId), maxSide ? tr("max") : tr("min"),
                                    QString::fromLatin1(kAxis[axis]), formatNumber(maxSide ? hi[axis] : lo[axis], 4)));
        return true;
    }
    }
    return false;
}

bool RegionBoxTool::mouseRelease(Viewport& viewport, QMouseEvent* event)
{
    if (event->button() != Qt::LeftButton || m_state == State::Idle)
        return false;
    const QPointF pos = event->position();
    const State state = m_state;
    m_state = State::Idle;
    switch (state) {
    case State::Pressed: selectRegionAt(pos.x(), pos.y()); break;
    case State::Drawing: {
        const Ray ray = viewport.screenView().ray(pos.x(), pos.y());
        if (std::optional<model::Vec3> p = planePoint(ray))
            m_end = *p;
        finishDrawing();
        break;
    }
    case State::Resizing:
        m_handle = -1;
        updateHandles();
        break;
    case State::Idle: break;
    }
    return true;
}

bool RegionBoxTool::keyPress(Viewport&, QKeyEvent* event)
{
    if (event->key() != Qt::Key_Escape || m_state != State::Drawing)
        return false;
    m_state = State::Idle;
    m_viewport->removeLayer(QString::fromLatin1(kRegionDraftLayer));
    emit statusMessage(tr("Region drawing cancelled"));
    return true;
}

void RegionBoxTool::finishDrawing()
{
    m_viewport->removeLayer(QString::fromLatin1(kRegionDraftLayer));
    const model::Box3 box = boxFromFootprint(m_start, m_end);
    const model::Vec3 size = box.size();
    if (!(size.x >= kMinSide && size.y >= kMinSide && size.z >= kMinSide)) {
        emit statusMessage(tr("The box is too thin; drag a larger rectangle"));
        return;
    }
    model::Region region;
    region.id = m_document->scene().uniqueId("region");
    region.min = box.min;
    region.max = box.max;
    const std::string id = region.id;
    if (m_document->push(new AddRegion(m_document, std::move(region)))) {
        m_document->setSelection(Selection::single(SelectionKind::Region, id));
        emit statusMessage(tr("Added region %1").arg(toQString(id)));
    }
}

void RegionBoxTool::selectRegionAt(double px, double py)
{
    const Ray ray = m_viewport->screenView().ray(px, py);
    const model::Scene& scene = m_document->scene();
    int best = -1;
    double bestT = std::numeric_limits<double>::infinity(), bestVolume = bestT;
    for (size_t r = 0; r < scene.regions.size(); ++r) {
        const model::Box3 box = boxOf(scene.regions[r]);
        const std::optional<double> t = rayEntersBox(ray, box);
        if (!t)
            continue;
        const model::Vec3 s = box.size();
        const double volume = s.x * s.y * s.z;
        // Nearest entry; among boxes around the eye (entry 0) the smallest.
        if (*t < bestT - 1e-9 || (std::abs(*t - bestT) <= 1e-9 && volume < bestVolume)) {
            best = int(r);
            bestT = *t;
            bestVolume = volume;
        }
    }
    if (best >= 0)
        m_document->setSelection(Selection::single(SelectionKind::Region, scene.regions[size_t(best)].id));
    else if (m_document->selection().kind == SelectionKind::Region)
        m_document->clearSelection();
}

void RegionBoxTool::updateHandles()
{
    const QString name = QString::fromLatin1(kRegionHandlesLayer);
    const model::Region* region = selectedRegion();
    if (!region || !isActive()) {
        m_viewport->removeLayer(name);
        return;
    }
    const model::Box3 box = boxOf(*region);
    const double size = kHandleSizePixels * m_viewport->screenView().worldPerPixelAt(box.center());
    m_viewport->setLayer(name, buildHandlesLayer(box, size, m_handle >= 0 ? m_handle : m_hoverHandle));
}

void RegionBoxTool::updateDraftLayer()
{
    ViewportLayer layer;
    layer.depthTest = false;
    layer.order = 25;
    const model::Box3 box = boxFromFootprint(m_start, m_end);
    layer.lines.addBox(box.min, box.max, glm::vec4(1.0f, 0.85f, 0.2f, 1.0f));
    // The footprint on the drawing plane, filled.
    const model::Vec3 a(box.min.x, m_planeY, box.min.z), b(box.max.x, m_planeY, box.min.z),
        c(box.max.x, m_planeY, box.max.z), d(box.min.x, m_planeY, box.max.z);
    const glm::vec4 fill(1.0f, 0.85f, 0.2f, 0.25f);
    layer.triangles.addTriangle(a, b, c, fill);
    layer.triangles.addTriangle(a, c, d, fill);
    m_viewport->setLayer(QString::fromLatin1(kRegionDraftLayer), layer);
}

} // namespace regio::editor
