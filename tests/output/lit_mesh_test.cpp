// The lit mesh: the solver's element solution turned into the triangle mesh
// every output draws from, flat (one value per element).
#include "output/lit_mesh.h"

#include "lit_mesh_fixtures.h"
#include "output/vertex_radiosity.h"
#include "solver/solver.h"
#include "support/adaptive_scenes.h"
#include "support/prepared_scenes.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <stdexcept>

using namespace regio;
using namespace regio::output;
using namespace regio::solver;

namespace {

// A lamp 1 m above a grey floor, both 1 m squares facing each other.
model::Scene lampOverFloor()
{
    model::Scene scene;
    model::Material grey;
    grey.id = "grey";
    grey.reflectance = {0.5, 0.4, 0.3};
    model::Material lamp;
    lamp.id = "lamp";
    lamp.reflectance = {0.2, 0.2, 0.2};
    lamp.emission = {10.0, 10.0, 10.0};
    scene.materials = {grey, lamp};
    auto square = [&](const std::string& id, std::vector<model::Vec3> corners, const std::string& material) {
        model::Part part;
        part.id = id + ".part";
        part.material = material;
        part.vertices = std::move(corners);
        model::Face face;
        face.id = id + ".face";
        face.loop = {0, 1, 2, 3};
        part.faces.push_back(face);
        model::Object object;
        object.id = id;
        object.parts.push_back(part);
        scene.objects.push_back(object);
    };
    square("floor", {{0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}}, "grey");
    square("lamp", {{0, 1, 0}, {1, 1, 0}, {1, 1, 1}, {0, 1, 1}}, "lamp");
    scene.solver.patchSize = 0.5;
    scene.solver.elementsPerPatch = 4;
    scene.solver.hemicube = 32;
    return scene;
}

std::unique_ptr<Solver> solvedLamp()
{
    auto built = Solver::create(lampOverFloor());
    EXPECT_TRUE(built.ok()) << "the scene prepares";
    // Every patch of the lamp shoots (lights are cut finer than the rest,
    // solver/prepare/meshing.h), and a few more shots follow.
    if (built.ok())
        (*built)->step(static_cast<int>((*built)->prepared().patches.size()) + 2);
    return std::move(*built);
}

} // namespace

TEST(LitMesh, AFlatMeshGivesEveryElementItsOwnThreeVerticesAndValue)
{
    const auto solver = solvedLamp();
    ASSERT_TRUE(solver);
    const SolutionSnapshot snapshot = solver->snapshot();
    const LitMesh lit = litMeshFromSolution(snapshot);
    const SolutionMesh& m = *snapshot.mesh;
    ASSERT_EQ(lit.triangleCount(), m.triangles.size());
    ASSERT_EQ(lit.vertexCount(), 3 * m.triangles.size());
    EXPECT_TRUE(checkLitMesh(lit));
    EXPECT_EQ(lit.faceIds, m.faceIds);
    for (size_t e = 0; e < m.triangles.size(); ++e) {
        EXPECT_EQ(lit.triangleFace[e], m.elementFace[e]);
        for (size_t k = 0; k < 3; ++k) {
            const uint32_t v = lit.indices[3 * e + k];
            EXPECT_EQ(v, 3 * e + k);
            const model::Vec3& p = m.vertices[static_cast<size_t>(m.triangles[e][k])];
            EXPECT_FLOAT_EQ(lit.positions[v].x, static_cast<float>(p.x));
            EXPECT_FLOAT_EQ(lit.positions[v].z, static_cast<float>(p.z));
            EXPECT_FLOAT_EQ(lit.radiosity[v].x, static_cast<float>(snapshot.radiosity[e].x));
            EXPECT_FLOAT_EQ(lit.radiosity[v].z, static_cast<float>(snapshot.radiosity[e].z));
            EXPECT_FLOAT_EQ(lit.reflectance[v].y, static_cast<float>(m.reflectance[e].y));
            EXPECT_NEAR(glm::length(lit.normals[v]), 1.0f, 1e-6f);
            EXPECT_FLOAT_EQ(lit.normals[v].y, static_cast<float>(m.normals[e].y));
        }
    }
}

TEST(LitMesh, TheFloorIsLitAndTheLampKeepsItsEmission)
{
    const auto solver = solvedLamp();
    ASSERT_TRUE(solver);
    const LitMesh lit = litMeshFromSolution(solver->snapshot());
    bool sawFloor = false, sawLamp = false;
    for (size_t t = 0; t < lit.triangleCount(); ++t) {
        const std::string& face = lit.faceIds[static_cast<size_t>(lit.triangleFace[t])];
        const glm::vec3 b = lit.radiosity[lit.indices[3 * t]];
        if (face == "floor.face") {
            sawFloor = true;
            EXPECT_GT(b.x, 0.0f);
            EXPECT_GT(b.x, b.z) << "the floor reflects more red than blue";
            EXPECT_NEAR(lit.normals[lit.indices[3 * t]].y, 1.0f, 1e-6f);
        } else {
            sawLamp = true;
            EXPECT_GE(b.x, 10.0f);
            EXPECT_NEAR(lit.normals[lit.indices[3 * t]].y, -1.0f, 1e-6f);
        }
    }
    EXPECT_TRUE(sawFloor);
    EXPECT_TRUE(sawLamp);
}

TEST(LitMesh, ThePreparedSceneOverloadBuildsTheSameMesh)
{
    const auto solver = solvedLamp();
    ASSERT_TRUE(solver);
    const SolutionSnapshot snapshot = solver->snapshot();
    const LitMesh a = litMeshFromSolution(snapshot);
    const LitMesh b = litMeshFromSolution(solver->prepared(), snapshot.radiosity);
    EXPECT_EQ(a.positions, b.positions);
    EXPECT_EQ(a.normals, b.normals);
    EXPECT_EQ(a.radiosity, b.radiosity);
    EXPECT_EQ(a.reflectance, b.reflectance);
    EXPECT_EQ(a.indices, b.indices);
    EXPECT_EQ(a.triangleFace, b.triangleFace);
    EXPECT_EQ(a.faceIds, b.faceIds);
}

TEST(LitMesh, ARadiosityArrayOfTheWrongLengthIsRefused)
{
    const auto solver = solvedLamp();
    ASSERT_TRUE(solver);
    std::vector<model::Rgb> tooShort(solver->prepared().elements.size() - 1, model::Rgb(1.0));
    EXPECT_THROW(litMeshFromSolution(solver->prepared(), tooShort), std::invalid_argument);
    SolutionSnapshot broken = solver->snapshot();
    broken.radiosity.pop_back();
    EXPECT_THROW(litMeshFromSolution(broken), std::invalid_argument);
    EXPECT_TRUE(litMeshFromSolution(SolutionSnapshot{}).empty()) << "no mesh yet: nothing to show";
}

TEST(LitMesh, TheConsistencyCheckNamesWhatIsWrong)
{
    LitMesh good = test::sampleRoom();
    EXPECT_TRUE(checkLitMesh(good));

    LitMesh badIndex = good;
    badIndex.indices[4] = 999;
    ASSERT_FALSE(checkLitMesh(badIndex));
    EXPECT_NE(checkLitMesh(badIndex).error().message.find("vertex index 999"), std::string::npos);

    LitMesh badFace = good;
    badFace.triangleFace[0] = 17;
    ASSERT_FALSE(checkLitMesh(badFace));
    EXPECT_NE(checkLitMesh(badFace).error().message.find("face index 17"), std::string::npos);

    LitMesh shortColumn = good;
    shortColumn.radiosity.pop_back();
    EXPECT_FALSE(checkLitMesh(shortColumn));

    LitMesh notFinite = good;
    notFinite.radiosity[5].y = std::nanf("");
    ASSERT_FALSE(checkLitMesh(notFinite));
    EXPECT_NE(checkLitMesh(notFinite).error().message.find("vertex 5"), std::string::npos);
}

TEST(LitMesh, BoundsEncloseEveryVertex)
{
    const LitBounds b = litMeshBounds(test::sampleRoom());
    EXPECT_FALSE(b.empty);
    EXPECT_EQ(b.min, glm::vec3(0.0f));
    EXPECT_EQ(b.max, glm::vec3(1.0f));
    EXPECT_TRUE(litMeshBounds(LitMesh{}).empty);
}

TEST(LitMesh, AMeshOfAPreparedSceneKnowsEachFacesObjectAndMaterialAndWhatSolidsCover)
{
    const PreparedScene scene = test::prepared(test::boxUnderLamp());
    const std::vector<Rgb> radiosity(scene.elements.size(), Rgb(1.0));
    for (const LitMesh& mesh : {litMeshFromSolution(scene, radiosity), smoothLitMesh(scene, radiosity)}) {
        ASSERT_TRUE(checkLitMesh(mesh));
        ASSERT_EQ(mesh.faceObjects.size(), mesh.faceIds.size());
        ASSERT_EQ(mesh.faceMaterials.size(), mesh.faceIds.size());
        const auto floor =
            size_t(std::find(mesh.faceIds.begin(), mesh.faceIds.end(), "floor.face") - mesh.faceIds.begin());
        const auto lamp =
            size_t(std::find(mesh.faceIds.begin(), mesh.faceIds.end(), "lamp.face") - mesh.faceIds.begin());
        ASSERT_LT(floor, mesh.faceIds.size());
        ASSERT_LT(lamp, mesh.faceIds.size());
        EXPECT_EQ(mesh.faceObjects[floor], "floor");
        const LitMaterial& grey = mesh.materials[size_t(mesh.faceMaterials[floor])];
        EXPECT_EQ(grey.id, "grey");
        EXPECT_EQ(grey.reflectance, glm::vec3(0.5f));
        EXPECT_EQ(mesh.materials[size_t(mesh.faceMaterials[lamp])].emission, glm::vec3(40.0f));
        EXPECT_EQ(mesh.materials.size(), 2u) << "one entry per material, however many faces use it";

        // The box stands on the floor: its 0.6 m square is the one covered part.
        ASSERT_EQ(mesh.covered.size(), 1u);
        EXPECT_EQ(size_t(mesh.covered[0].face), floor);
        EXPECT_EQ(mesh.covered[0].normal, glm::vec3(0.0f, 1.0f, 0.0f));
        auto area = [](const LitMesh& m, size_t face) {
            double sum = 0.0;
            for (size_t t = 0; t < m.triangleCount(); ++t)
                if (size_t(m.triangleFace[t]) == face)
                    sum += 0.5 * double(glm::length(
                                     glm::cross(m.positions[m.indices[3 * t + 1]] - m.positions[m.indices[3 * t]],
                                                m.positions[m.indices[3 * t + 2]] - m.positions[m.indices[3 * t]])));
            return sum;
        };
        EXPECT_NEAR(area(mesh, floor), 9.0 - 0.36, 1e-5) << "the lit floor leaves out what the box covers";
        const LitMesh whole = withCoveredParts(mesh);
        ASSERT_TRUE(checkLitMesh(whole));
        EXPECT_TRUE(whole.covered.empty());
        EXPECT_NEAR(area(whole, floor), 9.0, 1e-5) << "a model file's floor is whole";
        for (size_t v = mesh.vertexCount(); v < whole.vertexCount(); ++v) {
            EXPECT_EQ(whole.radiosity[v], glm::vec3(0.0f)) << "no light reaches under the box";
            EXPECT_EQ(whole.reflectance[v], glm::vec3(0.5f));
        }
    }
}
