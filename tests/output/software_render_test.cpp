// The software picture: projection from a model::Camera, z-buffer, near-plane
// clipping, Gouraud shading, and PNG output that decodes to the same pixels.
#include "output/software_render.h"

#include "export_test_support.h"
#include "lit_mesh_fixtures.h"
#include "output/png_writer.h"

#include <gtest/gtest.h>

#include <algorithm>

#include <stb/stb_image.h>

using namespace regio;
using namespace regio::output;
using namespace regio::solver;
using regio::test::addQuad;
using regio::test::addTriangle;
using regio::test::freshOutputFolder;

namespace {

using Pixel = std::array<uint8_t, 3>;

// Looks down -z from z = 5 with a 90 degree field: at z = 0 the picture is
// 10 m tall, so 1 m is 10 pixels of a 100 x 100 image.
model::Camera frontCamera()
{
    model::Camera c;
    c.position = {0.0, 0.0, 5.0};
    c.target = {0.0, 0.0, 0.0};
    c.up = {0.0, 1.0, 0.0};
    c.fovY = 90.0;
    return c;
}

RenderOptions exactOptions(int w = 100, int h = 100)
{
    RenderOptions o;
    o.width = w;
    o.height = h;
    o.supersample = 1;
    o.background = {0.0f, 0.0f, 0.0f};
    o.backFace = {0.5f, 0.5f, 0.5f}; // distinguishable from the background here
    return o;
}

// Linear encoding: radiosity 1 = display 1, bytes are exactly predictable.
DisplayColours plain(const LitMesh& mesh)
{
    ToneMapSettings s;
    s.whiteReference = 1.0;
    s.encoding.transfer = Transfer::Linear;
    return toneMappedColours(mesh, ToneMap::forMesh(s, mesh));
}

const Pixel kRed{255, 0, 0};
const Pixel kBlue{0, 0, 255};
const Pixel kBlack{0, 0, 0};

} // namespace

TEST(SoftwareRender, ARedTriangleInFrontOfTheCameraLandsWhereItProjects)
{
    LitMesh mesh;
    addTriangle(mesh, {-1, -1, 0}, {1, -1, 0}, {0, 1, 0}, {1, 0, 0}, "red");
    const Image image = renderImage(mesh, plain(mesh), frontCamera(), exactOptions());
    ASSERT_EQ(image.width, 100);
    ASSERT_EQ(image.height, 100);

    // Corners project to (40, 60), (60, 60) and (50, 40).
    const auto apex = projectToImage(frontCamera(), 100, 100, {0, 1, 0});
    ASSERT_TRUE(apex);
    EXPECT_NEAR(apex->x, 50.0, 1e-9);
    EXPECT_NEAR(apex->y, 40.0, 1e-9);
    EXPECT_NEAR(apex->z, 5.0, 1e-9);
    const auto right = projectToImage(frontCamera(), 100, 100, {1, -1, 0});
    EXPECT_NEAR(right->x, 60.0, 1e-9);
    EXPECT_NEAR(right->y, 60.0, 1e-9);

    EXPECT_EQ(image.pixel(50, 55), kRed);
    EXPECT_EQ(image.pixel(50, 42), kRed);
    EXPECT_EQ(image.pixel(41, 59), kRed);
    EXPECT_EQ(image.pixel(58, 59), kRed);
    EXPECT_EQ(image.pixel(42, 45), kBlack) << "left of the slanted edge";
    EXPECT_EQ(image.pixel(50, 38), kBlack) << "above the apex";
    EXPECT_EQ(image.pixel(50, 61), kBlack) << "below the base";
    EXPECT_EQ(image.pixel(10, 10), kBlack);

    int covered = 0;
    for (int y = 0; y < 100; ++y)
        for (int x = 0; x < 100; ++x)
            covered += image.pixel(x, y) == kRed ? 1 : 0;
    EXPECT_NEAR(covered, 200, 10) << "the triangle's area is 200 pixels";
}

TEST(SoftwareRender, TheNearerOfTwoOverlappingTrianglesWinsInEitherOrder)
{
    LitMesh redFirst;
    addTriangle(redFirst, {-2, -2, 0}, {2, -2, 0}, {0, 2, 0}, {1, 0, 0}, "far-red");
    addTriangle(redFirst, {-1, -1, 1}, {1, -1, 1}, {0, 1, 1}, {0, 0, 1}, "near-blue");
    LitMesh blueFirst;
    addTriangle(blueFirst, {-1, -1, 1}, {1, -1, 1}, {0, 1, 1}, {0, 0, 1}, "near-blue");
    addTriangle(blueFirst, {-2, -2, 0}, {2, -2, 0}, {0, 2, 0}, {1, 0, 0}, "far-red");
    for (const LitMesh* mesh : {&redFirst, &blueFirst}) {
        const Image image = renderImage(*mesh, plain(*mesh), frontCamera(), exactOptions());
        EXPECT_EQ(image.pixel(50, 52), kBlue) << "the near triangle covers the centre";
        EXPECT_EQ(image.pixel(50, 66), kRed) << "the far one shows below it";
    }
}

TEST(SoftwareRender, ATriangleCrossingTheNearPlaneIsClippedNotWrapped)
{
    // A floor running from behind the eye to far ahead, seen from 1 m above
    // it looking straight ahead: the lower half of the picture is floor, the
    // upper half sky. Projecting the corners behind the eye without clipping
    // would throw floor into the sky.
    LitMesh mesh;
    addQuad(mesh, {-50, 0, 5}, {50, 0, 5}, {50, 0, -100}, {-50, 0, -100}, {1, 0, 0}, "floor");
    model::Camera c;
    c.position = {0, 1, 0};
    c.target = {0, 1, -1};
    c.fovY = 60.0;
    const Image image = renderImage(mesh, plain(mesh), c, exactOptions(80, 60));
    for (int y = 0; y < 29; ++y)
        for (int x = 0; x < 80; ++x)
            ASSERT_EQ(image.pixel(x, y), kBlack) << "sky at " << x << ", " << y;
    for (int y = 31; y < 60; ++y)
        for (int x = 0; x < 80; ++x)
            ASSERT_EQ(image.pixel(x, y), kRed) << "floor at " << x << ", " << y;
}

TEST(SoftwareRender, ASurfaceSeenFromBehindShowsItsBackAndStillHides)
{
    LitMesh mesh;
    addTriangle(mesh, {-2, -2, 0}, {2, -2, 0}, {0, 2, 0}, {1, 0, 0}, "far-red");
    // Wound clockwise seen from the camera: its front faces away.
    addTriangle(mesh, {-1, -1, 1}, {0, 1, 1}, {1, -1, 1}, {0, 0, 1}, "turned-away");
    const Image image = renderImage(mesh, plain(mesh), frontCamera(), exactOptions());
    EXPECT_EQ(image.pixel(50, 52), (Pixel{128, 128, 128})) << "the back-face colour, not blue, not red";
    EXPECT_EQ(image.pixel(50, 66), kRed);
}

TEST(SoftwareRender, GouraudShadingInterpolatesTheVertexColours)
{
    LitMesh mesh;
    addTriangle(mesh, {-3, -3, 0}, {3, -3, 0}, {0, 3, 0}, {0, 0, 0}, "rgb");
    mesh.radiosity = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const Image image = renderImage(mesh, plain(mesh), frontCamera(), exactOptions());
    // The centroid (0, -1) is at pixel (50, 60): a third of each colour.
    const Pixel centre = image.pixel(50, 59);
    for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(centre[static_cast<size_t>(k)], 85, 4);
    // Near the red corner (-3, -3) -> pixel (20, 80) the red dominates.
    const Pixel nearRed = image.pixel(23, 79);
    EXPECT_GT(nearRed[0], 200);
    EXPECT_LT(nearRed[2], 40);
}

TEST(SoftwareRender, InterpolationIsPerspectiveCorrect)
{
    // A floor going away from the eye, black at the near edge and white at
    // the far edge: the point halfway in depth is grey 0.5, which is not
    // halfway up the image between the two edges' pixels.
    LitMesh mesh;
    addQuad(mesh, {-1, 0, -1}, {1, 0, -1}, {1, 0, -3}, {-1, 0, -3}, {0, 0, 0}, "floor");
    mesh.radiosity = {{0, 0, 0}, {0, 0, 0}, {1, 1, 1}, {0, 0, 0}, {1, 1, 1}, {1, 1, 1}};
    model::Camera c;
    c.position = {0, 1, 0};
    c.target = {0, 0, -2};
    c.fovY = 90.0;
    const Image image = renderImage(mesh, plain(mesh), c, exactOptions(200, 200));
    const auto middle = projectToImage(c, 200, 200, {0, 0, -2});
    ASSERT_TRUE(middle);
    const Pixel p = image.pixel(static_cast<int>(middle->x), static_cast<int>(middle->y));
    EXPECT_NEAR(p[0], 128, 4);
}

TEST(SoftwareRender, SupersamplingSoftensEdges)
{
    LitMesh mesh;
    addTriangle(mesh, {-1, -1, 0}, {1, -1, 0}, {0, 1, 0}, {1, 0, 0}, "red");
    RenderOptions o = exactOptions();
    o.supersample = 4;
    const Image image = renderImage(mesh, plain(mesh), frontCamera(), o);
    int partial = 0;
    for (int y = 40; y < 61; ++y)
        for (int x = 38; x < 62; ++x)
            partial += (image.pixel(x, y)[0] > 0 && image.pixel(x, y)[0] < 255) ? 1 : 0;
    EXPECT_GT(partial, 20) << "edge pixels are partly covered";
    EXPECT_EQ(image.pixel(50, 55), kRed);
}

TEST(SoftwareRender, APngDecodesToTheSamePixels)
{
    const auto folder = freshOutputFolder();
    LitMesh mesh = test::sampleRoom();
    model::Camera c;
    c.position = {0.5, 0.5, -1.5};
    c.target = {0.5, 0.5, 0.5};
    c.fovY = 50.0;
    ToneMapSettings s;
    const Image image = renderImage(mesh, toneMappedColours(mesh, ToneMap::forMesh(s, mesh)), c, {});
    const std::string path = (folder / "room.png").string();
    ASSERT_TRUE(writePng(path, image));

    int w = 0, h = 0, channels = 0;
    unsigned char* decoded = stbi_load(path.c_str(), &w, &h, &channels, 3);
    ASSERT_NE(decoded, nullptr) << stbi_failure_reason();
    EXPECT_EQ(w, image.width);
    EXPECT_EQ(h, image.height);
    EXPECT_EQ(channels, 3);
    EXPECT_TRUE(std::equal(image.rgb.begin(), image.rgb.end(), decoded));
    stbi_image_free(decoded);
}

TEST(SoftwareRender, PngErrorsNameThePath)
{
    const auto folder = freshOutputFolder();
    const std::string path = (folder / "none" / "x.png").string();
    const auto error = writePng(path, Image(4, 4));
    ASSERT_FALSE(error.ok());
    EXPECT_NE(error.error().message.find(path), std::string::npos) << error.error().message;
    EXPECT_FALSE(writePng((folder / "empty.png").string(), Image{}));
}

TEST(SoftwareRender, UnusableCamerasAreRecognised)
{
    model::Camera c = frontCamera();
    EXPECT_TRUE(checkCamera(c));
    c.target = c.position;
    EXPECT_FALSE(checkCamera(c));
    c = frontCamera();
    c.up = {0, 0, 1};
    EXPECT_FALSE(checkCamera(c)) << "up along the view direction";
    c = frontCamera();
    c.fovY = 180.0;
    EXPECT_FALSE(checkCamera(c));
    const LitMesh mesh = test::sampleRoom();
    c.target = c.position;
    const Image image = renderImage(mesh, plain(mesh), c, exactOptions());
    EXPECT_EQ(image.pixel(50, 50), kBlack) << "background only";
}

TEST(SoftwareRender, AFramingCameraShowsTheWholeModel)
{
    const LitMesh mesh = test::sampleRoom();
    const LitBounds bounds = litMeshBounds(mesh);
    const model::Camera c = frameCamera(bounds, 45.0, 640.0 / 480.0);
    EXPECT_TRUE(checkCamera(c));
    for (int i = 0; i < 8; ++i) {
        const glm::dvec3 corner((i & 1) ? bounds.max.x : bounds.min.x, (i & 2) ? bounds.max.y : bounds.min.y,
                                (i & 4) ? bounds.max.z : bounds.min.z);
        const auto p = projectToImage(c, 640, 480, corner);
        ASSERT_TRUE(p);
        EXPECT_GE(p->x, 0.0);
        EXPECT_LE(p->x, 640.0);
        EXPECT_GE(p->y, 0.0);
        EXPECT_LE(p->y, 480.0);
    }
}
