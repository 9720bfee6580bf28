#include "solver/picture/direct_light.h"

#include "solver/shooting/near_field.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vector_relational.hpp>

#include <algorithm>
#include <cmath>

namespace regio::solver {

namespace {

using Vec2 = glm::dvec2;
using Polygon2 = std::vector<Vec2>;

double cross2(const Vec2& a, const Vec2& b) { return a.x * b.y - a.y * b.x; }

// Plane::signedDistance, inline: the loops below call it for every corner
// of every face near every point.
double distanceTo(const Plane& plane, const Vec3& p) { return glm::dot(plane.normal, p) + plane.d; }

double signedArea(const Polygon2& p)
{
    double sum = 0.0;
    for (size_t i = 0; i < p.size(); ++i)
        sum += cross2(p[i], p[(i + 1) % p.size()]);
    return 0.5 * sum;
}

// The part of the convex polygon on the left of the directed line a -> b
// (left = true) or on its right (Sutherland-Hodgman against one line).
Polygon2 clipByLine(const Polygon2& polygon, const Vec2& a, const Vec2& b, bool left)
{
    Polygon2 out;
    const Vec2 d = b - a;
    const auto side = [&](const Vec2& p) {
        const double s = cross2(d, p - a);
        return left ? s : -s;
    };
    for (size_t i = 0; i < polygon.size(); ++i) {
        const Vec2& p = polygon[i];
        const Vec2& q = polygon[(i + 1) % polygon.size()];
        const double sp = side(p), sq = side(q);
        if (sp >= 0.0)
            out.push_back(p);
        if ((sp >= 0.0) != (sq >= 0.0))
            out.push_back(p + (q - p) * (sp / (sp - sq)));
    }
    return out;
}

struct Box2 {
    Vec2 min{1e300}, max{-1e300};
    explicit Box2(const Polygon2& p)
    {
        for (const Vec2& v : p) {
            min = glm::min(min, v);
            max = glm::max(max, v);
        }
    }
    bool overlaps(const Box2& o) const
    {
        return min.x < o.max.x && o.min.x < max.x && min.y < o.max.y && o.min.y < max.y;
    }
};

// Cuts the convex polygon `hole` (counter-clockwise) out of every piece: what
// lies outside each of its edges in turn is kept, what is inside all of them
// is dropped. Pieces smaller than `tiny` are dropped too.
void cutOut(std::vector<Polygon2>& pieces, const Polygon2& hole, double tiny)
{
    const Box2 holeBox(hole);
    std::vector<Polygon2> kept;
    for (Polygon2& piece : pieces) {
        if (!Box2(piece).overlaps(holeBox)) {
            kept.push_back(std::move(piece));
            continue;
        }
        Polygon2 rest = std::move(piece);
        for (size_t i = 0; i < hole.size() && rest.size() >= 3; ++i) {
            const Vec2& a = hole[i];
            const Vec2& b = hole[(i + 1) % hole.size()];
            Polygon2 outside = clipByLine(rest, a, b, false);
            if (outside.size() >= 3 && std::abs(signedArea(outside)) > tiny)
                kept.push_back(std::move(outside));
            rest = clipByLine(rest, a, b, true);
        }
    }
    pieces = std::move(kept);
}

// The polygon's part where lo <= plane distance <= hi.
std::vector<Vec3> clipToSlab(const std::vector<Vec3>& polygon, const Plane& plane, double lo, double hi)
{
    std::vector<Vec3> a, b;
    const auto clip = [&](const std::vector<Vec3>& in, std::vector<Vec3>& out, double bound, double sign) {
        out.clear();
        for (size_t i = 0; i < in.size(); ++i) {
            const Vec3& p = in[i];
            const Vec3& q = in[(i + 1) % in.size()];
            const double dp = sign * (distanceTo(plane, p) - bound), dq = sign * (distanceTo(plane, q) - bound);
            if (dp >= 0.0)
                out.push_back(p);
            if ((dp >= 0.0) != (dq >= 0.0))
                out.push_back(p + (q - p) * (dp / (dp - dq)));
        }
    };
    clip(polygon, a, lo, 1.0);
    if (a.size() < 3)
        return {};
    clip(a, b, hi, -1.0);
    return b.size() >= 3 ? b : std::vector<Vec3>{};
}

// The form factor from the point to a convex polygon by the contour
// formula, which takes at most kMaxContourCorners corners: a larger polygon
// (a round lamp, a piece cut by many outlines) goes as a fan of triangles,
// whose inner edges cancel in the sum.
double contourFactor(const Vec3& x, const Vec3& n, const std::vector<Vec3>& polygon)
{
    if (polygon.size() <= kMaxContourCorners)
        return pointToPolygonFormFactor(x, n, polygon);
    double factor = 0.0;
    for (size_t k = 1; k + 1 < polygon.size(); ++k)
        factor += pointToPolygonFormFactor(x, n, {polygon[0], polygon[k], polygon[k + 1]});
    return factor;
}

} // namespace

DirectLight::DirectLight(const PreparedScene& scene)
    : m_scene(scene)
{
    m_faceBox.resize(scene.faces.size());
    for (size_t f = 0; f < scene.faces.size(); ++f) {
        const std::vector<Vec3>& polygon = scene.faces[f].polygon;
        if (polygon.size() < 3)
            continue;
        for (const Vec3& p : polygon)
            m_faceBox[f].extend(p);
        m_order.push_back(int(f));
        if (scene.properties[f].emits())
            m_lights.push_back({int(f), m_faceBox[f]});
    }
    if (!m_order.empty()) {
        m_nodes.reserve(2 * m_order.size());
        build(0, int(m_order.size()));
    }
}

int DirectLight::build(int first, int count)
{
    const int index = int(m_nodes.size());
    m_nodes.push_back({});
    Box3 box;
    for (int i = first; i < first + count; ++i) {
        box.extend(m_faceBox[size_t(m_order[size_t(i)])].min);
        box.extend(m_faceBox[size_t(m_order[size_t(i)])].max);
    }
    m_nodes[size_t(index)].box = box;
    constexpr int kLeafSize = 4;
    if (count <= kLeafSize) {
        m_nodes[size_t(index)].first = first;
        m_nodes[size_t(index)].count = count;
        return index;
    }
    // Median split along the box's longest side, by the faces' box centres.
    const Vec3 size = box.size();
    const int axis = size.x >= size.y && size.x >= size.z ? 0 : (size.y >= size.z ? 1 : 2);
    const auto middle = m_order.begin() + first + count / 2;
    std::nth_element(m_order.begin() + first, middle, m_order.begin() + first + count, [&](int a, int b) {
        return m_faceBox[size_t(a)].center()[axis] < m_faceBox[size_t(b)].center()[axis];
    });
    const int left = build(first, count / 2);
    const int right = build(first + count / 2, count - count / 2);
    m_nodes[size_t(index)].first = left;
    m_nodes[size_t(index)].second = right;
    return index;
}

template <typename Visit>
void DirectLight::overlapping(const Pyramid& pyramid, Visit&& visit) const
{
    if (m_nodes.empty())
        return;
    const Box3& box = pyramid.box;
    // A box reaches into the pyramid unless it misses its bounds or lies
    // wholly outside one of its planes (its corner farthest along the
    // plane's normal is behind it).
    const auto overlaps = [&](const Box3& b) {
        if (glm::any(glm::lessThan(b.max, box.min)) || glm::any(glm::greaterThan(b.min, box.max)))
            return false;
        for (const Plane& plane : pyramid.planes) {
            const Vec3 farthest(plane.normal.x >= 0.0 ? b.max.x : b.min.x, plane.normal.y >= 0.0 ? b.max.y : b.min.y,
                                plane.normal.z >= 0.0 ? b.max.z : b.min.z);
            if (distanceTo(plane, farthest) < 0.0)
                return false;
        }
        return true;
    };
    int stack[64];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const Node& node = m_nodes[size_t(stack[--top])];
        if (!overlaps(node.box))
            continue;
        if (node.count > 0) {
            for (int i = node.first; i < node.first + node.count; ++i)
                if (overlaps(m_faceBox[size_t(m_order[size_t(i)])]))
                    visit(m_order[size_t(i)]);
            continue;
        }
        stack[top++] = node.first;
        stack[top++] = node.second;
    }
}

double DirectLight::factorOf(int face, const Vec3& x, const Vec3& n, const Light& light) const
{
    const std::vector<Vec3>& polygon = m_scene.faces[size_t(light.face)].polygon;
    const Plane& plane = m_scene.properties[size_t(light.face)].plane;
    const double height = plane.signedDistance(x);
    if (height <= model::kDistanceEpsilon)
        return 0.0; // behind the light, or in its plane: it emits forwards only
    if (std::all_of(polygon.begin(), polygon.end(), [&](const Vec3& p) { return glm::dot(n, p - x) <= 0.0; }))
        return 0.0; // wholly behind the point's plane

    // The light's plane as 2D coordinates, its polygon counter-clockwise.
    const Vec3 origin = polygon[0];
    const Vec3 u = glm::normalize(polygon[1] - polygon[0]);
    const Vec3 v = glm::cross(plane.normal, u);
    const auto to2 = [&](const Vec3& p) { return Vec2(glm::dot(p - origin, u), glm::dot(p - origin, v)); };
    std::vector<Polygon2> pieces(1);
    for (const Vec3& p : polygon)
        pieces[0].push_back(to2(p));
    if (signedArea(pieces[0]) < 0.0)
        std::reverse(pieces[0].begin(), pieces[0].end());
    const double tiny = 1e-12 * std::abs(signedArea(pieces[0]));

    // Where a face must reach to stand between: the pyramid from x over
    // the light, short of the light's plane and of x's height above it.
    Pyramid between;
    between.box = light.box;
    between.box.extend(x);
    const Vec3 inside = model::polygonCentroid(polygon);
    for (size_t i = 0; i < polygon.size(); ++i) {
        Plane side;
        side.normal = glm::cross(polygon[i] - x, polygon[(i + 1) % polygon.size()] - x);
        const double length = glm::length(side.normal);
        if (length <= 0.0)
            continue;
        side.normal /= length;
        side.d = -glm::dot(side.normal, x);
        if (side.signedDistance(inside) < 0.0) {
            side.normal = -side.normal;
            side.d = -side.d;
        }
        between.planes.push_back(side);
    }
    between.planes.push_back(plane);                                    // in front of the light
    between.planes.push_back(Plane::fromPointNormal(x, -plane.normal)); // nearer to it than x
    bool cut = false;
    // Projections of occluders a hair short of the point's own height: a
    // face that reaches down to the point's height (a block's side beside a
    // floor point) projects to infinity there.
    const double near = height * (1.0 - 1e-7);
    overlapping(between, [&](int o) {
        if (o == face || o == light.face || pieces.empty())
            return;
        // A face whose plane passes through the point (within rounding)
        // hides nothing from it: seen edge-on, its projection is a sliver,
        // or a strip of the rounding's making. Of a closed solid, the faces
        // turned away from the point cover its outline as well as those
        // turned towards it, and unlike those they still do from a point
        // in the plane of one of its faces (on a block's foot line): only
        // they are cut out. A point inside a solid (under a block) has
        // every face turned away and is in its shadow.
        const Properties& occluder = m_scene.properties[size_t(o)];
        const double side = distanceTo(occluder.plane, x);
        if (std::abs(side) <= model::kDistanceEpsilon || (occluder.solid && side > 0.0))
            return;
        const std::vector<Vec3>& outline = m_scene.faces[size_t(o)].polygon;
        const std::vector<Vec3> slab = clipToSlab(outline, plane, model::kDistanceEpsilon, near);
        if (slab.empty())
            return;
        Polygon2 hole;
        hole.reserve(slab.size());
        for (const Vec3& p : slab)
            hole.push_back(to2(x + (p - x) * (height / (height - distanceTo(plane, p)))));
        const double area = signedArea(hole);
        if (std::abs(area) <= tiny)
            return;
        if (area < 0.0)
            std::reverse(hole.begin(), hole.end());
        cutOut(pieces, hole, tiny);
        cut = true;
    });
    if (!cut)
        return contourFactor(x, n, polygon);
    double factor = 0.0;
    std::vector<Vec3> piece3;
    for (const Polygon2& piece : pieces) {
        piece3.clear();
        for (const Vec2& p : piece)
            piece3.push_back(origin + u * p.x + v * p.y);
        factor += contourFactor(x, n, piece3);
    }
    return factor;
}

double DirectLight::visibleFactor(int face, const Vec3& x, int light) const
{
    for (const Light& l : m_lights)
        if (l.face == light)
            return factorOf(face, x, m_scene.properties[size_t(face)].plane.normal, l);
    return 0.0;
}

Rgb DirectLight::irradiance(int face, const Vec3& x) const
{
    const Vec3& n = m_scene.properties[size_t(face)].plane.normal;
    Rgb sum(0.0);
    for (const Light& light : m_lights)
        if (light.face != face)
            sum += m_scene.properties[size_t(light.face)].emission * factorOf(face, x, n, light);
    return sum;
}

Rgb DirectLight::radiosity(int face, const Vec3& x) const
{
    return m_scene.properties[size_t(face)].reflectance * irradiance(face, x);
}

} // namespace regio::solver
