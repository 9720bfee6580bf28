#pragma once
// The glTF files the gltf_validator test checks with the Khronos validator:
// every shape of output the exporter produces (separate and binary
// containers, 16- and 32-bit indices, an empty solution, a file name that
// needs URI escaping, tone-mapped and false colours) including a solved
// Cornell box. Written by `output_tests --write-gltf-samples FOLDER`.
#include <filesystem>

namespace regio::test {

// Empties `folder` and writes the samples into it; false (with the reason on
// standard error) when one could not be written.
bool writeGltfSamples(const std::filesystem::path& folder);

} // namespace regio::test
