// libFuzzer harness: any bytes as a scene file. The reader and the validator
// must turn every input into a scene or diagnostics: no crash, no
// sanitizer finding, no exception, and a scene they accept saves and reads
// back the same.
#include "model/io/scene_json.h"
#include "model/validation/validation.h"

#include <cstdint>
#include <cstdlib>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    using namespace regio::model;
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const Result<Scene> read = parseScene(text);
    if (!read)
        return 0;
    (void)validateScene(*read);
    // What was read saves and reads back as the same scene.
    const std::string saved = serializeScene(*read);
    const Result<Scene> again = parseScene(saved);
    if (!again || !(*again == *read))
        std::abort();
    return 0;
}
