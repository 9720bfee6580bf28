// Scene files on disk: read whole and parsed; written only after the text
// has been read back as the same scene, and then atomically (file_io.h).
#include "model/io/file_io.h"
#include "model/io/scene_json.h"

#include <new>

namespace regio::model {

Result<Scene> loadSceneFile(const std::string& path)
{
    Result<std::string> text = readFile(path);
    if (!text)
        return Result<Scene>::failureOf(text);
    return parseScene(*text);
}

Check saveSceneFile(const Scene& scene, const std::string& path)
{
    try {
        const std::string text = serializeScene(scene);
        // Whatever Regio saves, Regio must load: a value the reader refuses
        // (a NaN that JSON would turn into null, a reflectance of 1) is refused
        // here, while the user still has the scene in memory.
        const Result<Scene> check = parseScene(text);
        if (!check) {
            const Diagnostic& d = check.error();
            return makeError("cannot save " + path + ": the scene would not load back: " +
                                 (d.pointer.empty() ? "" : d.pointer + ": ") + d.message,
                             d.pointer, d.idPath);
        }
        if (!(*check == scene))
            return makeError("cannot save " + path +
                             ": the scene would not read back unchanged (a name or id that is not "
                             "valid UTF-8?)");
        return writeFileAtomically(path, text, "save");
    } catch (const std::bad_alloc&) {
        return makeError("cannot save " + path + ": out of memory");
    }
}

} // namespace regio::model
