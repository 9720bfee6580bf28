// The time of `regio-solve import` on a big model: a room of boxes whose
// every face is cut into 2 x 2 quads, written as an OBJ of about 100 000
// triangles (the way exporters write subdivided furniture), imported with and
// without automatic regions. Medians of the whole import (read, merge, build,
// validate, regions).
//
//   build-release/tests/bench/import_bench
#include "importer/import_model.h"

#include <benchmark/benchmark.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <string>

namespace {

// Writes the model once; its path.
std::string boxesObj(int boxes)
{
    const auto path = std::filesystem::temp_directory_path() / ("regio-import-bench-" + std::to_string(boxes) + ".obj");
    if (std::filesystem::exists(path))
        return path.string();
    std::ofstream out(path);
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int vertex = 0;
    const int side = int(std::ceil(std::sqrt(double(boxes))));
    for (int b = 0; b < boxes; ++b) {
        out << "o box" << b << "\n";
        const double x = (b % side) * 1.0, z = (b / side) * 1.0;
        const double w = 0.3 + 0.5 * unit(random), h = 0.3 + 1.5 * unit(random), d = 0.3 + 0.5 * unit(random);
        // Six faces, each 2 x 2 quads of two triangles, wound outward.
        const double lo[3] = {x, 0.0, z}, hi[3] = {x + w, h, z + d};
        for (int axis = 0; axis < 3; ++axis)
            for (int sign = 0; sign < 2; ++sign) {
                const int u = (axis + 1) % 3, v = (axis + 2) % 3;
                const auto corner = [&](double s, double t) {
                    double p[3];
                    p[axis] = sign ? hi[axis] : lo[axis];
                    p[u] = lo[u] + (hi[u] - lo[u]) * s;
                    p[v] = lo[v] + (hi[v] - lo[v]) * t;
                    out << "v " << p[0] << " " << p[1] << " " << p[2] << "\n";
                };
                for (int i = 0; i < 2; ++i)
                    for (int j = 0; j < 2; ++j) {
                        corner(i / 2.0, j / 2.0);
                        corner((i + 1) / 2.0, j / 2.0);
                        corner((i + 1) / 2.0, (j + 1) / 2.0);
                        corner(i / 2.0, (j + 1) / 2.0);
                        const int a = vertex + 1, b2 = vertex + 2, c = vertex + 3, e = vertex + 4;
                        if (sign)
                            out << "f " << a << " " << b2 << " " << c << "\nf " << a << " " << c << " " << e << "\n";
                        else
                            out << "f " << a << " " << c << " " << b2 << "\nf " << a << " " << e << " " << c << "\n";
                        vertex += 4;
                    }
            }
    }
    return path.string();
}

void importBoxes(benchmark::State& state)
{
    const std::string path = boxesObj(int(state.range(0)));
    regio::importer::ImportOptions options;
    options.autoRegions = state.range(1) != 0;
    std::size_t faces = 0, triangles = 0;
    int fragments = 0, single = 0, regions = 0;
    for (auto _ : state) {
        auto imported = regio::importer::importModel(path, options);
        if (!imported) {
            state.SkipWithError(imported.diagnostics().front().message.c_str());
            return;
        }
        triangles = imported->report.merge.trianglesIn;
        faces = imported->report.merge.faces;
        fragments = imported->report.fragments;
        single = imported->report.singleTreeFragments;
        regions = imported->report.regions;
    }
    state.counters["triangles"] = double(triangles);
    state.counters["faces"] = double(faces);
    state.counters["regions"] = regions;
    state.counters["fragments"] = fragments;
    state.counters["one_tree"] = single;
}

} // namespace

// 2084 boxes x 48 triangles = 100 032 triangles.
BENCHMARK(importBoxes)->ArgsProduct({{2084}, {0, 1}})->Unit(benchmark::kMillisecond)->Iterations(1)->Repetitions(3);
BENCHMARK_MAIN();
