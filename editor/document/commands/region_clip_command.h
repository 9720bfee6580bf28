#pragma once
// Undo command for the one-click fix of a part that straddles region
// boundaries: model::clipPartToRegions cuts it into one piece per region it
// reaches (paper §3, whole-part modelling; §5.2, the separating planes), and
// model::unclipPart restores the exact scene.
#include "editor/document/commands/scene_command.h"
#include "model/geometry/region_clip.h"

#include <optional>
#include <string>
#include <vector>

namespace regio::editor {

class ClipPartToRegions : public SceneCommand {
public:
    ClipPartToRegions(SceneDocument* document, std::string partId);
    void redo() override;
    void undo() override;

    // The parts the clip made (after redo), in object order.
    std::vector<std::string> pieces() const { return m_clip ? m_clip->pieces : std::vector<std::string>{}; }

private:
    std::string m_partId;
    std::optional<model::RegionClip> m_clip;
};

} // namespace regio::editor
