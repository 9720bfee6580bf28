// libFuzzer harness: any bytes as a model file of the format the first byte
// picks (OBJ, glTF, GLB, PLY, STL, OFF, Collada, 3DS). The importer must
// refuse with a reason or give a valid scene: no crash, no sanitizer
// finding in Regio's code, no exception.
#include "importer/import_model.h"
#include "model/validation/validation.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include <unistd.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    static const char* const kExtensions[] = {".obj", ".gltf", ".glb", ".ply", ".stl", ".off", ".dae", ".3ds"};
    if (size < 1)
        return 0;
    const std::string path = "/tmp/regio-import-fuzz-" + std::to_string(::getpid()) + kExtensions[data[0] % 8];
    {
        std::ofstream out(path, std::ios::binary);
        out.write(reinterpret_cast<const char*>(data + 1), static_cast<std::streamsize>(size - 1));
    }
    regio::importer::ImportOptions options;
    options.autoRegions = (data[0] & 8) != 0;
    options.read.separateProcess = false; // Assimp in this process, where the fuzzer sees its code
    const regio::model::Result<regio::importer::Imported> imported = regio::importer::importModel(path, options);
    std::remove(path.c_str());
    if (imported && regio::model::hasErrors(regio::model::validateScene(imported->scene)))
        std::abort(); // an import is a valid scene or a refusal
    return 0;
}
