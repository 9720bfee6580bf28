#pragma once
// Named overlay layers of the viewport: coloured triangles and lines that a
// feature (region authoring, BSP views, the radiosity preview) hands to the
// viewport without touching its GL code. Triangles carry a colour per vertex,
// so a layer can show a Gouraud-shaded radiosity solution as well as a flat
// translucent box. Layers are drawn in ascending `order`, after the scene.
#include "editor/viewport/overlay_lines.h"

namespace regio::editor {

struct ViewportLayer {
    LineList triangles; // three vertices per triangle, xyz rgba (see LineList::addTriangle)
    LineList lines;     // two vertices per segment
    // False: drawn on top of everything (tools, highlights); true: hidden by
    // nearer surfaces like the scene itself.
    bool depthTest = true;
    // True: the scene's own surfaces are not drawn while this layer is
    // visible (a solution that replaces the material view). Edges,
    // selection and tools still are.
    bool replacesSurfaces = false;
    // Filled triangles nudged behind lines at the same depth, so edges drawn
    // on the surfaces stay visible.
    bool offsetTriangles = true;
    int order = 0;
};

} // namespace regio::editor
