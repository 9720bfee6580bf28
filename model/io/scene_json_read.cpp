// Reads the structure of a scene document: types, required keys, value
// ranges, loop indices. Every problem is reported with the JSON pointer of the
// offending value and reading goes on, so one pass lists all of them. Ids and
// references between elements are checked by validateScene, not here.
#include "model/io/scene_json_detail.h"
#include "model/limits.h"

#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <string_view>

namespace regio::model::detail {

using nlohmann::json;

std::optional<std::int64_t> asInteger(const json& value)
{
    if (value.is_number_integer() && !value.is_number_unsigned())
        return value.get<std::int64_t>();
    if (value.is_number_unsigned()) {
        const auto u = value.get<std::uint64_t>();
        if (u <= static_cast<std::uint64_t>(INT64_MAX))
            return static_cast<std::int64_t>(u);
        return std::nullopt;
    }
    if (value.is_number_float()) {
        const double d = value.get<double>();
        constexpr double kExact = 9007199254740992.0; // 2^53
        if (std::isfinite(d) && d == std::trunc(d) && std::fabs(d) <= kExact)
            return static_cast<std::int64_t>(d);
    }
    return std::nullopt;
}

namespace {

class Reader {
public:
    explicit Reader(Diagnostics& diagnostics)
        : m_diagnostics(diagnostics)
    {
    }

    void read(const json& document, Scene& scene)
    {
        checkKeys(document, "", {"format", "version", "materials", "objects", "regions", "solver", "camera"});
        if (const json* materials = arrayMember(document, "", "materials", Required::Yes)) {
            for (std::size_t i = 0; i < materials->size(); ++i)
                readMaterial((*materials)[i], appendPointer("/materials", i), scene.materials.emplace_back());
        }
        if (const json* objects = arrayMember(document, "", "objects", Required::Yes)) {
            for (std::size_t i = 0; i < objects->size(); ++i)
                readObject((*objects)[i], appendPointer("/objects", i), scene.objects.emplace_back());
        }
        if (const json* regions = arrayMember(document, "", "regions", Required::No)) {
            for (std::size_t i = 0; i < regions->size(); ++i)
                readRegion((*regions)[i], appendPointer("/regions", i), scene.regions.emplace_back());
        }
        if (const json* solver = member(document, "", "solver", Required::No))
            readSolver(*solver, "/solver", scene.solver);
        if (const json* camera = member(document, "", "camera", Required::No))
            readCamera(*camera, "/camera", scene.camera.emplace());
    }

private:
    enum class Required { No, Yes };

    // Diagnostics name the ids of the enclosing elements (object, part, face)
    // so the editor can select the culprit.
    class IdScope {
    public:
        IdScope(Reader& reader, const std::string& id)
            : m_reader(reader)
        {
            m_reader.m_idPath.push_back(id);
        }
        ~IdScope() { m_reader.m_idPath.pop_back(); }
        IdScope(const IdScope&) = delete;
        IdScope& operator=(const IdScope&) = delete;

    private:
        Reader& m_reader;
    };

    void error(const std::string& pointer, std::string message)
    {
        m_diagnostics.push_back(makeError(std::move(message), pointer, m_idPath));
    }
    void warning(const std::string& pointer, std::string message)
    {
        m_diagnostics.push_back(makeWarning(std::move(message), pointer, m_idPath));
    }

    // Unknown keys are warnings: a file from a newer minor revision still
    // loads, and the user learns that those values will not be saved.
    void checkKeys(const json& object, const std::string& pointer, std::initializer_list<std::string_view> known)
    {
        for (const auto& [key, value] : object.items()) {
            bool isKnown = false;
            for (std::string_view k : known)
                isKnown = isKnown || k == key;
            if (!isKnown)
                warning(appendPointer(pointer, key), "unknown key \"" + key + "\" is ignored and will not be saved");
        }
    }

    const json* member(const json& object, const std::string& pointer, const char* key, Required required)
    {
        const auto it = object.find(key);
        if (it == object.end()) {
            if (required == Required::Yes)
                error(pointer, std::string("missing key \"") + key + "\"");
            return nullptr;
        }
        return &*it;
    }

    bool expectObject(const json& value, const std::string& pointer)
    {
        if (value.is_object())
            return true;
        error(pointer, "expected an object");
        return false;
    }

    const json* arrayMember(const json& object, const std::string& pointer, const char* key, Required required)
    {
        const json* value = member(object, pointer, key, required);
        if (value && !value->is_array()) {
            error(appendPointer(pointer, key), "expected an array");
            return nullptr;
        }
        return value;
    }

    bool readString(const json& object, const std::string& pointer, const char* key, Required required,
                    std::string& out)
    {
        const json* value = member(object, pointer, key, required);
        if (!value)
            return false;
        if (!value->is_string()) {
            error(appendPointer(pointer, key), "expected a string");
            return false;
        }
        out = value->get<std::string>();
        return true;
    }

    bool readBool(const json& object, const std::string& pointer, const char* key, bool& out)
    {
        const json* value = member(object, pointer, key, Required::No);
        if (!value)
            return false;
        if (!value->is_boolean()) {
            error(appendPointer(pointer, key), "expected true or false");
            return false;
        }
        out = value->get<bool>();
        return true;
    }

    // The parser refuses numbers that overflow a double, so a value read here
    // is finite; the check stays for documents built in memory.
    bool readNumber(const json& object, const std::string& pointer, const char* key, double& out)
    {
        const json* value = member(object, pointer, key, Required::No);
        if (!value)
            return false;
        if (!value->is_number() || !std::isfinite(value->get<double>())) {
            error(appendPointer(pointer, key), "expected a finite number");
            return false;
        }
        out = value->get<double>();
        return true;
    }

    bool readInteger(const json& object, const std::string& pointer, const char* key, std::int64_t& out)
    {
        const json* value = member(object, pointer, key, Required::No);
        if (!value)
            return false;
        const std::optional<std::int64_t> integer = asInteger(*value);
        if (!integer) {
            error(appendPointer(pointer, key), "expected an integer");
            return false;
        }
        out = *integer;
        return true;
    }

    bool readVec3(const json& object, const std::string& pointer, const char* key, Required required, Vec3& out)
    {
        const json* value = member(object, pointer, key, required);
        if (!value)
            return false;
        return readVec3Value(*value, appendPointer(pointer, key), out);
    }

    // A point of the scene: finite and within kMaxCoordinate of the origin.
    bool readPositionValue(const json& value, const std::string& pointer, Vec3& out)
    {
        if (!readVec3Value(value, pointer, out))
            return false;
        for (glm::length_t i = 0; i < 3; ++i)
            if (std::abs(out[i]) > kMaxCoordinate) {
                char text[160];
                std::snprintf(text, sizeof text,
                              "coordinate %g m is beyond %g m from the origin, the largest scene Regio handles "
                              "(a model in the wrong unit?)",
                              out[i], kMaxCoordinate);
                error(appendPointer(pointer, static_cast<std::size_t>(i)), text);
                return false;
            }
        return true;
    }

    bool readPosition(const json& object, const std::string& pointer, const char* key, Required required, Vec3& out)
    {
        const json* value = member(object, pointer, key, required);
        if (!value)
            return false;
        return readPositionValue(*value, appendPointer(pointer, key), out);
    }

    bool readVec3Value(const json& value, const std::string& pointer, Vec3& out)
    {
        if (!value.is_array() || value.size() != 3) {
            error(pointer, "expected an array of 3 numbers");
            return false;
        }
        bool ok = true;
        for (std::size_t i = 0; i < 3; ++i) {
            const json& component = value[i];
            if (!component.is_number() || !std::isfinite(component.get<double>())) {
                error(appendPointer(pointer, i), "expected a finite number");
                ok = false;
                continue;
            }
            out[static_cast<glm::length_t>(i)] = component.get<double>();
        }
        return ok;
    }

    void readMaterial(const json& value, const std::string& pointer, Material& material)
    {
        if (!expectObject(value, pointer))
            return;
        readString(value, pointer, "id", Required::Yes, material.id);
        IdScope scope(*this, material.id);
        checkKeys(value, pointer, {"id", "name", "reflectance", "emission"});
        readString(value, pointer, "name", Required::No, material.name);
        // A reflectance of 1 or more would create energy (paper §5.1: the
        // iteration converges only for rho < 1).
        if (readVec3(value, pointer, "reflectance", Required::Yes, material.reflectance)) {
            for (int c = 0; c < 3; ++c) {
                const double r = material.reflectance[c];
                if (!(r >= 0.0 && r < 1.0))
                    error(appendPointer(pointer + "/reflectance", static_cast<std::size_t>(c)),
                          "reflectance must be at least 0 and below 1 (got " + formatNumber(r) + ")");
            }
        }
        if (readVec3(value, pointer, "emission", Required::No, material.emission)) {
            for (int c = 0; c < 3; ++c) {
                const double e = material.emission[c];
                if (e < 0.0)
                    error(appendPointer(pointer + "/emission", static_cast<std::size_t>(c)),
                          "emission must not be negative (got " + formatNumber(e) + ")");
            }
        }
    }

    void readObject(const json& value, const std::string& pointer, Object& object)
    {
        if (!expectObject(value, pointer))
            return;
        readString(value, pointer, "id", Required::Yes, object.id);
        IdScope scope(*this, object.id);
        checkKeys(value, pointer, {"id", "name", "parts"});
        readString(value, pointer, "name", Required::No, object.name);
        if (const json* parts = arrayMember(value, pointer, "parts", Required::Yes)) {
            for (std::size_t i = 0; i < parts->size(); ++i)
                readPart((*parts)[i], appendPointer(pointer + "/parts", i), object.parts.emplace_back());
        }
    }

    void readPart(const json& value, const std::string& pointer, Part& part)
    {
        if (!expectObject(value, pointer))
            return;
        readString(value, pointer, "id", Required::Yes, part.id);
        IdScope scope(*this, part.id);
        checkKeys(value, pointer, {"id", "name", "material", "vertices", "faces"});
        readString(value, pointer, "name", Required::No, part.name);
        readString(value, pointer, "material", Required::No, part.material);

        bool verticesOk = false;
        if (const json* vertices = arrayMember(value, pointer, "vertices", Required::Yes)) {
            verticesOk = true;
            const std::string here = pointer + "/vertices";
            part.vertices.reserve(vertices->size());
            for (std::size_t i = 0; i < vertices->size(); ++i)
                verticesOk &=
                    readPositionValue((*vertices)[i], appendPointer(here, i), part.vertices.emplace_back(0.0));
        }
        if (const json* faces = arrayMember(value, pointer, "faces", Required::Yes)) {
            for (std::size_t i = 0; i < faces->size(); ++i)
                readFace((*faces)[i], appendPointer(pointer + "/faces", i), part,
                         verticesOk ? static_cast<std::int64_t>(part.vertices.size()) : -1, part.faces.emplace_back());
        }
    }

    // `vertexCount` < 0: the part's vertices are broken, so indices cannot be
    // range-checked (their error is reported already).
    void readFace(const json& value, const std::string& pointer, const Part& part, std::int64_t vertexCount, Face& face)
    {
        if (!expectObject(value, pointer))
            return;
        readString(value, pointer, "id", Required::Yes, face.id);
        IdScope scope(*this, face.id);
        checkKeys(value, pointer, {"id", "loop", "material"});
        readString(value, pointer, "material", Required::No, face.material);
        const json* loop = arrayMember(value, pointer, "loop", Required::Yes);
        if (!loop)
            return;
        const std::string here = pointer + "/loop";
        face.loop.reserve(loop->size());
        for (std::size_t i = 0; i < loop->size(); ++i) {
            const std::optional<std::int64_t> index = asInteger((*loop)[i]);
            if (!index) {
                error(appendPointer(here, i), "expected an integer vertex index");
                continue;
            }
            if (vertexCount >= 0 && (*index < 0 || *index >= vertexCount)) {
                error(appendPointer(here, i), "vertex index " + std::to_string(*index) + " is out of range (part \"" +
                                                  part.id + "\" has " + std::to_string(vertexCount) + " vertices)");
                continue;
            }
            if (*index < 0 || *index > INT32_MAX) {
                error(appendPointer(here, i), "vertex index " + std::to_string(*index) + " is out of range");
                continue;
            }
            face.loop.push_back(static_cast<int>(*index));
        }
    }

    void readRegion(const json& value, const std::string& pointer, Region& region)
    {
        if (!expectObject(value, pointer))
            return;
        readString(value, pointer, "id", Required::Yes, region.id);
        IdScope scope(*this, region.id);
        checkKeys(value, pointer, {"id", "name", "min", "max", "bspOrder"});
        readString(value, pointer, "name", Required::No, region.name);
        readPosition(value, pointer, "min", Required::Yes, region.min);
        readPosition(value, pointer, "max", Required::Yes, region.max);
        if (const json* order = arrayMember(value, pointer, "bspOrder", Required::No)) {
            for (std::size_t i = 0; i < order->size(); ++i) {
                if (!(*order)[i].is_string()) {
                    error(appendPointer(pointer + "/bspOrder", i), "expected a face id (a string)");
                    continue;
                }
                region.bspOrder.push_back((*order)[i].get<std::string>());
            }
        }
    }

    // Every solver key is optional: a missing one keeps SolverSettings' default.
    void readSolver(const json& value, const std::string& pointer, SolverSettings& solver)
    {
        if (!expectObject(value, pointer))
            return;
        checkKeys(value, pointer,
                  {"hemicube", "patchSize", "elementsPerPatch", "adaptive", "maxIterations", "convergence",
                   "visibility", "regions"});
        std::int64_t integer = 0;
        double number = 0.0;
        // The sides of the hemicube are N x N/2 (paper §5.6), so N is even; the
        // cap keeps the item buffers of a hostile file within memory.
        if (readInteger(value, pointer, "hemicube", integer)) {
            if (integer < kMinHemicube || integer > kMaxHemicube || integer % 2 != 0)
                error(pointer + "/hemicube", "expected an even integer from " + std::to_string(kMinHemicube) + " to " +
                                                 std::to_string(kMaxHemicube) + " (the hemicube sides are N x N/2)");
            else
                solver.hemicube = static_cast<int>(integer);
        }
        if (readNumber(value, pointer, "patchSize", number)) {
            if (number <= 0.0)
                error(pointer + "/patchSize", "expected a positive length in metres");
            else
                solver.patchSize = number;
        }
        if (readInteger(value, pointer, "elementsPerPatch", integer)) {
            if (integer < 1 || integer > kMaxElementsPerPatch)
                error(pointer + "/elementsPerPatch",
                      "expected an integer from 1 to " + std::to_string(kMaxElementsPerPatch));
            else
                solver.elementsPerPatch = static_cast<int>(integer);
        }
        if (const json* adaptive = member(value, pointer, "adaptive", Required::No))
            readAdaptive(*adaptive, pointer + "/adaptive", solver.adaptive);
        if (readInteger(value, pointer, "maxIterations", integer)) {
            if (integer < 0 || integer > INT32_MAX)
                error(pointer + "/maxIterations", "expected an integer from 0 to " + std::to_string(INT32_MAX));
            else
                solver.maxIterations = static_cast<int>(integer);
        }
        if (readNumber(value, pointer, "convergence", number)) {
            if (number < 0.0 || number > 1.0)
                error(pointer + "/convergence", "expected a fraction of the emitted power from 0 to 1");
            else
                solver.convergence = number;
        }
        std::string text;
        if (readString(value, pointer, "visibility", Required::No, text)) {
            if (auto v = parseVisibility(text))
                solver.visibility = *v;
            else
                error(pointer + "/visibility", "expected \"painter\" or \"zbuffer\"");
        }
        if (readString(value, pointer, "regions", Required::No, text)) {
            if (auto mode = parseRegionsMode(text))
                solver.regions = *mode;
            else
                error(pointer + "/regions", "expected \"authored\", \"none\" or \"auto\"");
        }
    }

    void readAdaptive(const json& value, const std::string& pointer, AdaptiveSettings& adaptive)
    {
        if (!expectObject(value, pointer))
            return;
        checkKeys(value, pointer, {"enabled", "threshold", "minEdge", "anchoring"});
        readBool(value, pointer, "enabled", adaptive.enabled);
        readBool(value, pointer, "anchoring", adaptive.anchoring);
        double number = 0.0;
        if (readNumber(value, pointer, "threshold", number)) {
            if (number < 0.0)
                error(pointer + "/threshold", "expected a non-negative number");
            else
                adaptive.threshold = number;
        }
        if (readNumber(value, pointer, "minEdge", number)) {
            if (number <= 0.0)
                error(pointer + "/minEdge", "expected a positive length in metres");
            else
                adaptive.minEdge = number;
        }
    }

    void readCamera(const json& value, const std::string& pointer, Camera& camera)
    {
        if (!expectObject(value, pointer))
            return;
        checkKeys(value, pointer, {"position", "target", "up", "fovY"});
        readPosition(value, pointer, "position", Required::No, camera.position);
        readPosition(value, pointer, "target", Required::No, camera.target);
        readVec3(value, pointer, "up", Required::No, camera.up);
        double fovY = 0.0;
        if (readNumber(value, pointer, "fovY", fovY)) {
            if (!(fovY > 0.0 && fovY < 180.0))
                error(pointer + "/fovY", "expected an angle in degrees above 0 and below 180");
            else
                camera.fovY = fovY;
        }
    }

    static constexpr std::int64_t kMinHemicube = 2;
    static constexpr std::int64_t kMaxHemicube = 4096;
    static constexpr std::int64_t kMaxElementsPerPatch = 1024;

    Diagnostics& m_diagnostics;
    std::vector<std::string> m_idPath;
};

} // namespace

void readSceneDocument(const json& document, Scene& scene, Diagnostics& diagnostics)
{
    Reader(diagnostics).read(document, scene);
}

} // namespace regio::model::detail
