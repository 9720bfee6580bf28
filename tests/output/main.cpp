// output_tests' main: GoogleTest's, and one more mode for the glTF
// validator's fixture. `output_tests --write-gltf-samples FOLDER` writes the
// sample glTF files (gltf_samples.h) into FOLDER instead of running tests.
#include "gltf_samples.h"

#include <gtest/gtest.h>

#include <cstring>
#include <iostream>

int main(int argc, char** argv)
{
    if (argc > 1 && std::strcmp(argv[1], "--write-gltf-samples") == 0) {
        if (argc != 3) {
            std::cerr << "usage: output_tests --write-gltf-samples OUTPUT_FOLDER\n";
            return 2;
        }
        return regio::test::writeGltfSamples(argv[2]) ? 0 : 1;
    }
    testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
