#include "solver/shooting/contact_lines.h"

#include "solver/prepare/covered_parts.h"
#include "solver/prepare/face_polygon.h"
#include "solver/prepare/near_outlines.h"
#include "solver/prepare/shadow_lines.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace regio::solver {

namespace {

// The point lies on face `face` (in its plane, inside its polygon).
bool liesOn(const PreparedScene& scene, int face, const Vec3& point)
{
    const Plane& plane = scene.properties[size_t(face)].plane;
    if (std::abs(plane.signedDistance(point)) > model::kDistanceEpsilon)
        return false;
    return insideConvex(scene.faces[size_t(face)].polygon, plane.normal, point);
}

// The active elements of the faces f with lines[f] (not empty) that have a
// corner for which on(f, corner) holds, ascending.
template <typename Lines, typename On>
std::vector<int> elementsWithACornerOn(const AdaptiveMesh& mesh, const std::vector<Lines>& lines, On&& on)
{
    const PreparedScene& scene = mesh.scene();
    std::vector<int> found;
    for (size_t f = 0; f < scene.faces.size() && f < lines.size(); ++f) {
        if (lines[f].empty())
            continue;
        for (int e : scene.faces[f].elements) {
            const auto& v = scene.elements[size_t(e)].vertices;
            if (mesh.isActive(e) &&
                std::any_of(v.begin(), v.end(), [&](int corner) { return on(f, scene.vertices[size_t(corner)]); }))
                found.push_back(e);
        }
    }
    std::sort(found.begin(), found.end());
    return found;
}

} // namespace

std::vector<std::vector<int>> contactFaces(const PreparedScene& scene)
{
    const size_t count = scene.faces.size();
    std::vector<std::vector<int>> contacts(count);
    const std::vector<std::vector<size_t>> coversOf = coversOfFaces(scene);
    const double minWidth = ShadowLineLimits{}.solidMinWidth * scene.patchSize;
    // The faces of each part, found once: a hall's floor may carry hundreds of solids.
    std::map<std::pair<int, int>, std::vector<size_t>> facesOfPart;
    for (size_t s = 0; s < count; ++s)
        if (scene.faces[s].polygon.size() >= 3)
            facesOfPart[{scene.faces[s].object, scene.faces[s].part}].push_back(s);
    for (size_t f = 0; f < count; ++f) {
        // A face that solids cover whole has no mesh to meet anything: a
        // block's bottom, which a closed room's floor covers as much as the
        // block covers the floor.
        if (scene.faces[f].elements.empty())
            continue;
        for (size_t g : coversOf[f]) {
            if (footprintWidth(scene.faces[g].polygon) < minWidth)
                continue;
            for (size_t s : facesOfPart[{scene.faces[g].object, scene.faces[g].part}]) {
                if (s == g || s == f)
                    continue;
                contacts[f].push_back(int(s));
                contacts[s].push_back(int(f));
            }
        }
    }
    for (std::vector<int>& faces : contacts) {
        std::sort(faces.begin(), faces.end());
        faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
    }
    return contacts;
}

std::vector<int> elementsOnContactLines(const AdaptiveMesh& mesh, const std::vector<std::vector<int>>& contacts)
{
    const PreparedScene& scene = mesh.scene();
    // A corner on the line is enough: of the two triangles of a quad along
    // the line one has an edge on it and the other only a corner, and left
    // whole the second carried the light of its far corners to the foot (the
    // short block's side 1 cm above the floor read +8 %, docs/accuracy.md).
    return elementsWithACornerOn(mesh, contacts, [&](size_t f, const Vec3& corner) {
        return std::any_of(contacts[f].begin(), contacts[f].end(), [&](int s) { return liesOn(scene, s, corner); });
    });
}

std::vector<int> elementsOnNearOutlines(const AdaptiveMesh& mesh,
                                        const std::vector<std::vector<std::vector<Vec3>>>& outlines)
{
    return elementsWithACornerOn(mesh, outlines,
                                 [&](size_t f, const Vec3& corner) { return liesOnOutline(outlines[f], corner); });
}

} // namespace regio::solver
