// Writing a solution's outputs: the model format chosen by the file name,
// display settings, and the picture; end to end on the Cornell box sample.
#include "output/export.h"

#include "export_test_support.h"
#include "lit_mesh_fixtures.h"
#include "output/legend_overlay.h"
#include "support/sample_scenes.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <stb/stb_image.h>

#include <sstream>

using namespace regio;
using namespace regio::output;
using namespace regio::solver;
using regio::test::freshOutputFolder;
using regio::test::readBytes;
using regio::test::sampleRoom;

namespace {

struct Decoded {
    int width = 0, height = 0;
    std::vector<uint8_t> rgb;
    std::array<int, 3> pixel(int x, int y) const
    {
        const size_t i = (static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)) * 3;
        return {rgb[i], rgb[i + 1], rgb[i + 2]};
    }
};

Decoded decodePng(const std::string& path)
{
    Decoded d;
    int channels = 0;
    unsigned char* data = stbi_load(path.c_str(), &d.width, &d.height, &channels, 3);
    EXPECT_NE(data, nullptr) << path << ": " << stbi_failure_reason();
    if (data) {
        d.rgb.assign(data, data + static_cast<size_t>(d.width) * static_cast<size_t>(d.height) * 3);
        stbi_image_free(data);
    }
    return d;
}

model::Camera roomCamera()
{
    model::Camera c;
    c.position = {0.5, 0.5, -1.2};
    c.target = {0.5, 0.5, 0.5};
    c.fovY = 50.0;
    return c;
}

} // namespace

TEST(Export, TheFileExtensionChoosesTheFormat)
{
    EXPECT_EQ(modelFormatForPath("a/b/room.gltf"), ModelFormat::Gltf);
    EXPECT_EQ(modelFormatForPath("room.GLB"), ModelFormat::Glb);
    EXPECT_EQ(modelFormatForPath("room.ply"), ModelFormat::Ply);
    EXPECT_EQ(modelFormatForPath("room.Obj"), ModelFormat::Obj);
    EXPECT_FALSE(modelFormatForPath("room.stl"));
    EXPECT_FALSE(modelFormatForPath("room"));
}

TEST(Export, EveryFormatIsWrittenByItsOwnWriter)
{
    const auto folder = freshOutputFolder();
    const LitMesh mesh = sampleRoom();
    const DisplayColours c = prepareColours(mesh, {}).colours;
    for (const char* name : {"room.gltf", "room.glb", "room.ply", "room.obj"})
        ASSERT_TRUE(writeLitModel((folder / name).string(), mesh, c)) << name;
    EXPECT_EQ(readBytes(folder / "room.glb").substr(0, 4), "glTF");
    EXPECT_EQ(readBytes(folder / "room.ply").substr(0, 4), "ply\n");
    EXPECT_EQ(readBytes(folder / "room.obj").substr(0, 1), "#");
    EXPECT_EQ(nlohmann::json::parse(readBytes(folder / "room.gltf"))["asset"]["version"], "2.0");
    EXPECT_TRUE(std::filesystem::exists(folder / "room.bin"));
}

TEST(Export, AnUnknownExtensionIsRefusedWithTheKnownOnes)
{
    const auto folder = freshOutputFolder();
    OutputRequest request;
    request.modelPath = (folder / "room.stl").string();
    const auto error = writeOutputs(sampleRoom(), request);
    ASSERT_FALSE(error.ok());
    EXPECT_NE(error.error().message.find(request.modelPath), std::string::npos);
    EXPECT_NE(error.error().message.find(".gltf, .glb, .ply or .obj"), std::string::npos) << error.error().message;
    request.modelPath.clear();
    request.imagePath = (folder / "room.jpg").string();
    ASSERT_FALSE(writeOutputs(sampleRoom(), request));
    EXPECT_TRUE(std::filesystem::is_empty(folder));
}

TEST(Export, ABadCameraOrImageSizeIsRefusedBeforeAnythingIsWritten)
{
    const auto folder = freshOutputFolder();
    OutputRequest request;
    request.modelPath = (folder / "room.glb").string();
    request.imagePath = (folder / "room.png").string();
    request.camera = roomCamera();
    request.camera->target = request.camera->position;
    EXPECT_FALSE(writeOutputs(sampleRoom(), request));
    request.camera = roomCamera();
    request.imageWidth = 0;
    EXPECT_FALSE(writeOutputs(sampleRoom(), request));
    EXPECT_TRUE(std::filesystem::is_empty(folder));
}

TEST(Export, ModelAndPictureAreWrittenTogether)
{
    const auto folder = freshOutputFolder();
    OutputRequest request;
    request.modelPath = (folder / "room.ply").string();
    request.imagePath = (folder / "room.png").string();
    request.imageWidth = 160;
    request.imageHeight = 120;
    request.camera = roomCamera();
    ASSERT_TRUE(writeOutputs(sampleRoom(), request));
    EXPECT_TRUE(std::filesystem::exists(request.modelPath));
    const Decoded png = decodePng(request.imagePath);
    EXPECT_EQ(png.width, 160);
    EXPECT_EQ(png.height, 120);
}

TEST(Export, WithoutACameraThePictureFramesTheWholeModel)
{
    const auto folder = freshOutputFolder();
    OutputRequest request;
    request.imagePath = (folder / "room.png").string();
    request.imageWidth = 160;
    request.imageHeight = 120;
    ASSERT_TRUE(writeOutputs(sampleRoom(), request));
    const Decoded png = decodePng(request.imagePath);
    const auto corner = png.pixel(0, 0);
    const auto centre = png.pixel(80, 60);
    EXPECT_NE(corner, centre) << "the model is in the middle of the picture";
}

TEST(Export, ExposureBrightensThePicture)
{
    const auto folder = freshOutputFolder();
    OutputRequest request;
    request.imageWidth = 160;
    request.imageHeight = 120;
    request.camera = roomCamera();
    request.display.toneMap.whiteReference = 20.0;
    request.imagePath = (folder / "dark.png").string();
    ASSERT_TRUE(writeOutputs(sampleRoom(), request));
    request.display.toneMap.exposure = 2.0;
    request.imagePath = (folder / "bright.png").string();
    ASSERT_TRUE(writeOutputs(sampleRoom(), request));
    const Decoded dark = decodePng((folder / "dark.png").string());
    const Decoded bright = decodePng((folder / "bright.png").string());
    const auto d = dark.pixel(80, 60); // the back wall, 1 W/m^2
    const auto b = bright.pixel(80, 60);
    EXPECT_GT(b[0], d[0]);
    // Gamma 2.2: four times the light is 4^(1/2.2) = 1.88 times the value.
    EXPECT_NEAR(static_cast<double>(b[0]) / d[0], std::pow(4.0, 1.0 / 2.2), 0.05);
}

TEST(Export, AFalseColourPictureCarriesItsLegend)
{
    const auto folder = freshOutputFolder();
    OutputRequest request;
    request.imagePath = (folder / "room.png").string();
    request.imageWidth = 400;
    request.imageHeight = 300;
    request.camera = roomCamera();
    request.display.colours = ColourMode::FalseColour;
    ASSERT_TRUE(writeOutputs(sampleRoom(), request));
    const Decoded png = decodePng(request.imagePath);

    // Where the legend goes: the same layout on a blank image of that size.
    Image blank(400, 300);
    const LegendBox box = drawLegend(blank, FalseColour(FalseColourScale::Logarithmic, 1.0, 10.0).legend());
    ASSERT_GT(box.width, 0);
    // The bar runs from the top of the ramp (yellow) down to its bottom.
    const int x = box.barX + box.barWidth / 2;
    const double span = box.barBottom - box.barTop;
    for (int y : {box.barTop, (box.barTop + box.barBottom) / 2, box.barBottom - 1}) {
        const auto shown = png.pixel(x, y);
        const auto expected = toBytes(FalseColour::ramp(1.0 - (y + 0.5 - box.barTop) / span));
        for (size_t k = 0; k < 3; ++k)
            EXPECT_EQ(shown[k], expected[k]) << "row " << y;
    }
    EXPECT_GT(png.pixel(x, box.barTop)[0], 240) << "yellow at the top";
    EXPECT_LT(png.pixel(x, box.barBottom - 1)[1], 20) << "dark purple at the bottom";
}

TEST(Export, TheLegendDrawsEveryStrokeOfItsLabels)
{
    // A label is drawn with the quads of its characters, all of them: the
    // '0' of "50" once lost its right stroke to a buffer too small.
    for (const std::string label : {"0", "50", "30", "20", "100", "0.0005", "1e-05", "88888888", "%, log scale"}) {
        int sum = 0;
        for (char c : label)
            sum += legendTextQuads(std::string(1, c));
        EXPECT_EQ(legendTextQuads(label), sum) << label;
    }
}

TEST(Export, TheAmbientTermIsAddedOnlyWhenAsked)
{
    const auto folder = freshOutputFolder();
    auto mesh = std::make_shared<SolutionMesh>();
    mesh->vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh->triangles = {{0, 1, 2}};
    mesh->normals = {{0, 0, 1}};
    mesh->elementFace = {0};
    mesh->reflectance = {{0.5, 0.5, 0.5}};
    mesh->faceIds = {"tri"};
    SolutionSnapshot snapshot;
    snapshot.mesh = mesh;
    snapshot.radiosity = {{1.0, 1.0, 1.0}};
    snapshot.stats.ambient = {2.0, 2.0, 2.0};

    OutputRequest request;
    request.display.toneMap.whiteReference = 4.0;
    request.display.toneMap.encoding.transfer = Transfer::Linear;
    auto firstColour = [&](const std::string& name) {
        request.modelPath = (folder / name).string();
        EXPECT_TRUE(writeOutputs(snapshot, request));
        std::istringstream in(readBytes(folder / name));
        std::string line;
        while (std::getline(in, line) && line.rfind("v ", 0) != 0) {
        }
        std::istringstream words(line.substr(2));
        float x = 0, y = 0, z = 0, r = 0;
        words >> x >> y >> z >> r;
        return r;
    };
    EXPECT_FLOAT_EQ(firstColour("solution.obj"), 0.25f) << "1 W/m^2 of a 4 W/m^2 white";
    request.includeAmbient = true;
    EXPECT_FLOAT_EQ(firstColour("with-ambient.obj"), 0.5f) << "plus 0.5 x 2 W/m^2 of ambient";
    EXPECT_DOUBLE_EQ(snapshot.radiosity[0].x, 1.0) << "the solution is untouched";
}

TEST(Export, TheCornellBoxPictureHasARedLeftWallAndAGreenRightWall)
{
    const auto folder = freshOutputFolder();
    const model::Scene scene = test::loadSample("cornell-box");
    ASSERT_TRUE(scene.camera) << "the sample carries its camera";
    SolverOptions options; // low quality: the colours, not the digits, are under test
    options.hemicube = 48;
    options.patchSize = 0.2;
    options.elementsPerPatch = 4;
    auto built = Solver::create(scene, options);
    ASSERT_TRUE(built.ok());
    (*built)->step(60);

    OutputRequest request;
    request.imagePath = (folder / "cornell.png").string();
    request.modelPath = (folder / "cornell.glb").string();
    request.imageWidth = 320;
    request.imageHeight = 240;
    request.camera = scene.camera;
    ASSERT_TRUE(writeOutputs((*built)->snapshot(), request));
    const Decoded png = decodePng(request.imagePath);
    ASSERT_EQ(png.width, 320);

    // The camera looks along +z from z = -0.8, so the red wall (x = 0.556)
    // is on the left of the picture and the green one (x = 0) on the right.
    const auto red = projectToImage(*request.camera, 320, 240, {0.553, 0.30, 0.35});
    const auto green = projectToImage(*request.camera, 320, 240, {0.0, 0.30, 0.35});
    ASSERT_TRUE(red && green);
    EXPECT_LT(red->x, 100.0);
    EXPECT_GT(green->x, 220.0);
    const auto r = png.pixel(static_cast<int>(red->x) + 2, static_cast<int>(red->y));
    const auto g = png.pixel(static_cast<int>(green->x) - 3, static_cast<int>(green->y));
    EXPECT_GT(r[0], 80) << "the red wall is lit";
    EXPECT_GT(r[0], 2 * r[1]);
    EXPECT_GT(r[0], 2 * r[2]);
    EXPECT_GT(g[1], 80) << "the green wall is lit";
    EXPECT_GT(g[1], r[1]);
    EXPECT_GT(g[1], g[0] + 20);
    EXPECT_GT(g[1], g[2] + 20);
    // The back wall between them is white-ish (it reflects all channels).
    const auto back = projectToImage(*request.camera, 320, 240, {0.278, 0.30, 0.559});
    ASSERT_TRUE(back);
    const auto w = png.pixel(static_cast<int>(back->x), static_cast<int>(back->y));
    EXPECT_GT(w[0], 60);
    EXPECT_GT(w[1], 60);
    EXPECT_GT(w[2], 30);
    EXPECT_GT(std::filesystem::file_size(request.modelPath), 1000u);
}
