#pragma once
// How a preview frame becomes viewport layers (paper §6, docs/architecture.md "From JSON to pixels"):
// the Gouraud-shaded lit mesh with the ambient term, tone-mapped (exposure,
// gamma) or in false colour, and the element mesh as lines (it shows where
// adaptive subdivision split elements and how anchoring closed T-vertices).
// Plain functions of their inputs, so they run on a pool thread.
#include "editor/preview/preview_session.h"
#include "editor/viewport/viewport_layers.h"
#include "output/export.h"
#include "output/false_colour.h"

#include <glm/vec4.hpp>

#include <optional>
#include <vector>

namespace regio::editor {

struct PreviewDisplay {
    double exposure = 0.0; // stops
    double gamma = 2.2;
    bool falseColour = false;
    output::FalseColourScale falseColourScale = output::FalseColourScale::Logarithmic;
    bool ambient = true;   // add the ambient term of progressive refinement (Cohen et al. 1988)
    bool showMesh = false; // element mesh overlay

    bool operator==(const PreviewDisplay&) const = default;
};

// Layer names in the viewport.
inline constexpr const char* kSolutionLayer = "preview.solution";
inline constexpr const char* kMeshLayer = "preview.mesh";

// Colours of the element mesh overlay: element edges, and the anchoring
// edges (the "special edges" of the paper's Figure 5 that anchoring adds to
// close T-vertices; edges of SolutionMesh::anchoredTriangles that are no
// element's edge) in a colour of their own, so anchoring can be told apart
// from subdivision at a glance.
struct MeshOverlayColours {
    glm::vec4 element;
    glm::vec4 anchoring;
};
MeshOverlayColours meshOverlayColours(const PreviewDisplay& display);

struct PreviewLayers {
    ViewportLayer solution;
    std::optional<ViewportLayer> mesh; // when showMesh is on
    int elementEdges = 0;              // line segments of the mesh layer: element edges
    int anchoringEdges = 0;            // and anchoring edges (see MeshOverlayColours)
    std::optional<output::FalseColourLegend> legend;
    double whiteReference = 1.0; // W/m^2 shown white at exposure 0 (tone mapping)
};

// The display settings the exports share with the viewport.
output::DisplaySettings displaySettings(const PreviewDisplay& display, const PreviewFrame& frame);

PreviewLayers buildPreviewLayers(const PreviewFrame& frame, const PreviewDisplay& display);

// Area-weighted mean radiosity per input face of the snapshot's own mesh (the
// figures `regio-solve solve --report` lists), in the mesh's face order.
std::vector<solver::FaceResult> faceMeans(const solver::SolutionSnapshot& snapshot);

} // namespace regio::editor
