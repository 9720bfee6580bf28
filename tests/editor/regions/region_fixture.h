#pragma once
// The region views of the Regions tests without a main window: a document, a
// viewport and a diagnostics dock, and the region authoring that ties them.
#include "editor/docks/diagnostics_dock.h"
#include "editor/document/scene_document.h"
#include "editor/regions/region_authoring.h"
#include "editor/regions/regions_dock.h"
#include "editor/viewport/viewport.h"
#include "support/editor_documents.h"

#include <QMainWindow>

namespace regio::test {

struct RegionFixture {
    editor::SceneDocument document; // outlives the window and everything in it
    QMainWindow window;
    editor::Viewport* viewport;
    editor::DiagnosticsDock* diagnostics;
    editor::RegionAuthoring* regions;

    explicit RegionFixture(model::Scene scene)
    {
        resetDocument(document, std::move(scene));
        viewport = new editor::Viewport(&document, &window);
        window.setCentralWidget(viewport);
        diagnostics = new editor::DiagnosticsDock(&document, &window);
        regions = new editor::RegionAuthoring(&document, viewport, nullptr, diagnostics, &window);
    }
    editor::RegionsDock* dock() const { return regions->dock(); }
};

} // namespace regio::test
