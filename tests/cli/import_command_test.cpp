// `regio-solve import` as a user and a script see it: a model in, a scene
// file that `regio-solve check` passes, a report, and clear refusals.
#include "support/command_run.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <string>

using namespace regio::test;

namespace {

// A 4 x 3 x 2.5 m room of 1 m quads (every wall triangulated finely, as
// exporters write them) with a 1 m square light under the ceiling.
std::string roomObj()
{
    std::string obj = "mtllib room.mtl\no room\nusemtl wall\n";
    int vertex = 0;
    const auto quad = [&](double x0, double y0, double z0, double dx1, double dy1, double dz1, double dx2, double dy2,
                          double dz2) {
        obj += "v " + std::to_string(x0) + " " + std::to_string(y0) + " " + std::to_string(z0) + "\n";
        obj += "v " + std::to_string(x0 + dx1) + " " + std::to_string(y0 + dy1) + " " + std::to_string(z0 + dz1) + "\n";
        obj += "v " + std::to_string(x0 + dx1 + dx2) + " " + std::to_string(y0 + dy1 + dy2) + " " +
               std::to_string(z0 + dz1 + dz2) + "\n";
        obj += "v " + std::to_string(x0 + dx2) + " " + std::to_string(y0 + dy2) + " " + std::to_string(z0 + dz2) + "\n";
        obj += "f " + std::to_string(vertex + 1) + " " + std::to_string(vertex + 2) + " " + std::to_string(vertex + 3) +
               "\nf " + std::to_string(vertex + 1) + " " + std::to_string(vertex + 3) + " " +
               std::to_string(vertex + 4) + "\n";
        vertex += 4;
    };
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 3; ++j) {
            quad(i, 0, j, 0, 0, 1, 1, 0, 0);   // floor, facing up
            quad(i, 2.5, j, 1, 0, 0, 0, 0, 1); // ceiling, facing down
        }
    quad(0, 0, 0, 4, 0, 0, 0, 2.5, 0); // the wall at z = 0, facing +z
    quad(0, 0, 3, 0, 2.5, 0, 4, 0, 0); // z = 3, facing -z
    quad(0, 0, 0, 0, 2.5, 0, 0, 0, 3); // x = 0, facing +x
    quad(4, 0, 0, 0, 0, 3, 0, 2.5, 0); // x = 4, facing -x
    obj += "o lamp\nusemtl light\n";
    quad(1.5, 2.45, 1, 1, 0, 0, 0, 0, 1); // facing down
    return obj;
}

} // namespace

TEST(ImportCommand, ARoomImportsIntoFewerFacesThanTrianglesAndPassesCheck)
{
    ScratchDir dir;
    dir.write("room.mtl", "newmtl wall\nKd 0.7 0.7 0.7\nnewmtl light\nKd 0.5 0.5 0.5\nKe 10 10 10\n");
    dir.write("room.obj", roomObj());
    const CommandRun run = runRegioSolve({"import", "room.obj", "room.json", "--report", "report.json"}, dir.path());
    ASSERT_TRUE(run.exited);
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.out.find("58 triangles -> 7 faces"), std::string::npos) << run.out;

    const nlohmann::json report = nlohmann::json::parse(readText(dir.path() / "report.json"));
    EXPECT_EQ(report["triangles_in"], 58);
    EXPECT_EQ(report["faces_out"], 7);
    EXPECT_EQ(report["objects"], 2);
    EXPECT_EQ(report["emitting_faces"], 1);
    EXPECT_LE(report["bsp"]["fragments"].get<int>(), report["bsp"]["single_tree_fragments"].get<int>());

    const CommandRun check = runRegioSolve({"check", "room.json"}, dir.path());
    EXPECT_EQ(check.exitCode, 0) << check.out << check.err;
}

TEST(ImportCommand, OptionsScaleAndTurnTheModel)
{
    ScratchDir dir;
    dir.write("room.mtl", "newmtl wall\nKd 0.7 0.7 0.7\nnewmtl light\nKd 0.5 0.5 0.5\nKe 10 10 10\n");
    dir.write("room.obj", roomObj());
    const CommandRun run = runRegioSolve(
        {"import", "room.obj", "room.json", "--scale", "0.5", "--up", "z", "--regions", "none", "-q"}, dir.path());
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_TRUE(run.out.empty());
    const nlohmann::json scene = nlohmann::json::parse(readText(dir.path() / "room.json"));
    double lowestY = 1e9, highestY = -1e9;
    for (const auto& object : scene["objects"])
        for (const auto& part : object["parts"])
            for (const auto& v : part["vertices"]) {
                lowestY = std::min(lowestY, v[1].get<double>());
                highestY = std::max(highestY, v[1].get<double>());
            }
    EXPECT_NEAR(highestY - lowestY, 1.5, 1e-9) << "the model's z (3 m deep) is up, halved";
}

TEST(ImportCommand, BadArgumentsAndModelsAreRefusedWithTheReason)
{
    ScratchDir dir;
    dir.write("lines.obj", "v 0 0 0\nv 1 0 0\nl 1 2\n");
    const CommandRun missing = runRegioSolve({"import", "none.obj", "out.json"}, dir.path());
    EXPECT_EQ(missing.exitCode, 2);
    EXPECT_NE(missing.err.find("not a readable file"), std::string::npos) << missing.err;
    const CommandRun lines = runRegioSolve({"import", "lines.obj", "out.json"}, dir.path());
    EXPECT_EQ(lines.exitCode, 1);
    EXPECT_NE(lines.err.find("not imported"), std::string::npos) << lines.err;
    EXPECT_FALSE(fs::exists(dir.path() / "out.json")) << "nothing written when nothing was imported";
    for (const std::vector<std::string>& args : {std::vector<std::string>{"import", "lines.obj"},
                                                 {"import", "a.obj", "b.json", "--scale", "-1"},
                                                 {"import", "a.obj", "b.json", "--up", "x"},
                                                 {"import", "a.obj", "b.json", "--merge-tolerance", "1"},
                                                 {"import", "a.obj", "b.json", "--frobnicate"}}) {
        const CommandRun run = runRegioSolve(args, dir.path());
        EXPECT_EQ(run.exitCode, 2) << args.back();
        EXPECT_NE(run.err.find("regio-solve import:"), std::string::npos) << run.err;
    }
}

TEST(ImportCommand, NamesFromTheModelAreEscapedInItsMessages)
{
    // A texture name with a terminal escape sequence: the warning that it
    // cannot be read names it with the escape written out, not sent.
    ScratchDir dir;
    dir.write("m.mtl", "newmtl wood\nKd 0.5 0.5 0.5\nmap_Kd \x1b[2Jwood.png\n");
    dir.write("m.obj", "mtllib m.mtl\no slab\nusemtl wood\nv 0 0 0\nv 1 0 0\nv 1 0 1\nv 0 0 1\nf 1 4 3 2\n");
    const CommandRun run = runRegioSolve({"import", "m.obj", "m.json", "-q"}, dir.path());
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.err.find("\\x1B[2Jwood.png"), std::string::npos) << run.err;
    EXPECT_EQ(run.err.find('\x1b'), std::string::npos);
}
