#include "editor/preview/preview_display.h"

#include "model/geometry/edge_key.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cstdint>
#include <unordered_set>

namespace regio::editor {

output::DisplaySettings displaySettings(const PreviewDisplay& display, const PreviewFrame& frame)
{
    output::DisplaySettings s;
    s.toneMap.exposure = display.exposure;
    s.toneMap.encoding.transfer = output::Transfer::Gamma;
    s.toneMap.encoding.gamma = display.gamma;
    if (display.ambient)
        s.toneMap.ambient = glm::vec3(frame.snapshot.stats.ambient);
    s.colours = display.falseColour ? output::ColourMode::FalseColour : output::ColourMode::ToneMapped;
    s.falseColour.scale = display.falseColourScale;
    return s;
}

MeshOverlayColours meshOverlayColours(const PreviewDisplay& display)
{
    // On false colour (viridis: purple to yellow) the element edges are white
    // and the anchoring edges magenta, a hue viridis never takes; on the
    // tone-mapped picture the element edges are dark and the anchoring edges
    // a saturated orange that stands out from both them and lit surfaces.
    if (display.falseColour)
        return {glm::vec4(1.0f, 1.0f, 1.0f, 0.45f), glm::vec4(1.0f, 0.2f, 1.0f, 0.9f)};
    return {glm::vec4(0.05f, 0.05f, 0.1f, 0.55f), glm::vec4(1.0f, 0.45f, 0.0f, 0.9f)};
}

PreviewLayers buildPreviewLayers(const PreviewFrame& frame, const PreviewDisplay& display)
{
    PreviewLayers out;
    out.solution.replacesSurfaces = true;
    out.solution.depthTest = true;
    out.solution.offsetTriangles = true;
    out.solution.order = 0;
    if (!frame.lit || frame.lit->empty())
        return out;
    const output::LitMesh& lit = *frame.lit;
    const output::DisplaySettings settings = displaySettings(display, frame);
    const output::PreparedColours prepared = output::prepareColours(lit, settings);
    if (prepared.falseColour)
        out.legend = prepared.falseColour->legend();
    else
        out.whiteReference = output::automaticWhiteReference(lit, settings.toneMap.ambient);

    std::vector<glm::vec4> colours(lit.vertexCount());
    for (size_t v = 0; v < colours.size(); ++v)
        colours[v] = glm::vec4(glm::clamp(prepared.colours.encoded(v), glm::vec3(0.0f), glm::vec3(1.0f)), 1.0f);
    out.solution.triangles.reserve(lit.indices.size());
    for (size_t i = 0; i + 2 < lit.indices.size(); i += 3) {
        const uint32_t a = lit.indices[i], b = lit.indices[i + 1], c = lit.indices[i + 2];
        out.solution.triangles.addTriangle(model::Vec3(lit.positions[a]), model::Vec3(lit.positions[b]),
                                           model::Vec3(lit.positions[c]), colours[a], colours[b], colours[c]);
    }

    if (display.showMesh && frame.snapshot.mesh) {
        ViewportLayer mesh;
        mesh.depthTest = true;
        mesh.order = 1;
        const solver::SolutionMesh& m = *frame.snapshot.mesh;
        const MeshOverlayColours edgeColours = meshOverlayColours(display);
        auto vertex = [&m](int v) { return m.vertices[static_cast<size_t>(v)]; };
        std::unordered_set<uint64_t> seen;
        seen.reserve(m.triangles.size() * 2 + m.anchoredTriangles.size());
        for (const auto& t : m.triangles) {
            for (size_t k = 0; k < 3; ++k) {
                const int a = t[k], b = t[(k + 1) % 3];
                if (seen.insert(model::undirectedEdgeKey(a, b)).second) {
                    mesh.lines.add(vertex(a), vertex(b), edgeColours.element);
                    ++out.elementEdges;
                }
            }
        }
        // Element edges hold every side of a coarse element whole, also where
        // finer neighbours put a vertex on it; what anchoring adds is the fan
        // from such vertices into the coarse element.
        for (const auto& t : m.anchoredTriangles) {
            for (size_t k = 0; k < 3; ++k) {
                const int a = t[k], b = t[(k + 1) % 3];
                if (seen.insert(model::undirectedEdgeKey(a, b)).second) {
                    mesh.lines.add(vertex(a), vertex(b), edgeColours.anchoring);
                    ++out.anchoringEdges;
                }
            }
        }
        out.mesh = std::move(mesh);
    }
    return out;
}

std::vector<solver::FaceResult> faceMeans(const solver::SolutionSnapshot& snapshot)
{
    std::vector<solver::FaceResult> out;
    if (!snapshot.mesh)
        return out;
    const solver::SolutionMesh& m = *snapshot.mesh;
    out.resize(m.faceIds.size());
    for (size_t f = 0; f < m.faceIds.size(); ++f)
        out[f].id = m.faceIds[f];
    for (size_t e = 0; e < m.triangles.size() && e < snapshot.radiosity.size(); ++e) {
        const auto& t = m.triangles[e];
        const model::Vec3& a = m.vertices[static_cast<size_t>(t[0])];
        const model::Vec3& b = m.vertices[static_cast<size_t>(t[1])];
        const model::Vec3& c = m.vertices[static_cast<size_t>(t[2])];
        const double area = 0.5 * glm::length(glm::cross(b - a, c - a));
        solver::FaceResult& r = out[static_cast<size_t>(m.elementFace[e])];
        r.area += area;
        r.radiosity += area * snapshot.radiosity[e];
    }
    for (solver::FaceResult& r : out)
        if (r.area > 0.0)
            r.radiosity /= r.area;
    return out;
}

} // namespace regio::editor
