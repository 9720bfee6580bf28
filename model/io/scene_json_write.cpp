// Writes the canonical text of a scene. The layout is a pure function of the
// scene, so save -> load -> save is byte-identical, and it is meant to be read
// and diffed by people: key order of the format, 2-space indent, arrays of
// numbers on one line ("[0.0, 0.7, 1.0]"), small flat objects such as faces on
// one line when they fit, everything else one member per line.
#include "model/io/scene_json.h"

#include "model/io/scene_json_detail.h"

#include <new>

namespace regio::model {

namespace detail {

using nlohmann::ordered_json;

namespace {

ordered_json vec3(const Vec3& v) { return ordered_json::array({v.x, v.y, v.z}); }

ordered_json materialToJson(const Material& material)
{
    ordered_json out = ordered_json::object();
    out["id"] = material.id;
    if (!material.name.empty())
        out["name"] = material.name;
    out["reflectance"] = vec3(material.reflectance);
    out["emission"] = vec3(material.emission);
    return out;
}

ordered_json partToJson(const Part& part)
{
    ordered_json out = ordered_json::object();
    out["id"] = part.id;
    if (!part.name.empty())
        out["name"] = part.name;
    if (!part.material.empty())
        out["material"] = part.material;
    ordered_json vertices = ordered_json::array();
    for (const Vec3& v : part.vertices)
        vertices.push_back(vec3(v));
    out["vertices"] = std::move(vertices);
    ordered_json faces = ordered_json::array();
    for (const Face& face : part.faces) {
        ordered_json f = ordered_json::object();
        f["id"] = face.id;
        f["loop"] = face.loop;
        if (!face.material.empty())
            f["material"] = face.material;
        faces.push_back(std::move(f));
    }
    out["faces"] = std::move(faces);
    return out;
}

ordered_json objectToJson(const Object& object)
{
    ordered_json out = ordered_json::object();
    out["id"] = object.id;
    if (!object.name.empty())
        out["name"] = object.name;
    ordered_json parts = ordered_json::array();
    for (const Part& part : object.parts)
        parts.push_back(partToJson(part));
    out["parts"] = std::move(parts);
    return out;
}

ordered_json regionToJson(const Region& region)
{
    ordered_json out = ordered_json::object();
    out["id"] = region.id;
    if (!region.name.empty())
        out["name"] = region.name;
    out["min"] = vec3(region.min);
    out["max"] = vec3(region.max);
    out["bspOrder"] = region.bspOrder;
    return out;
}

ordered_json solverToJson(const SolverSettings& solver)
{
    ordered_json out = ordered_json::object();
    out["hemicube"] = solver.hemicube;
    out["patchSize"] = solver.patchSize;
    out["elementsPerPatch"] = solver.elementsPerPatch;
    ordered_json adaptive = ordered_json::object();
    adaptive["enabled"] = solver.adaptive.enabled;
    adaptive["threshold"] = solver.adaptive.threshold;
    adaptive["minEdge"] = solver.adaptive.minEdge;
    adaptive["anchoring"] = solver.adaptive.anchoring;
    out["adaptive"] = std::move(adaptive);
    out["maxIterations"] = solver.maxIterations;
    out["convergence"] = solver.convergence;
    out["visibility"] = visibilityName(solver.visibility);
    out["regions"] = regionsModeName(solver.regions);
    return out;
}

ordered_json cameraToJson(const Camera& camera)
{
    ordered_json out = ordered_json::object();
    out["position"] = vec3(camera.position);
    out["target"] = vec3(camera.target);
    out["up"] = vec3(camera.up);
    out["fovY"] = camera.fovY;
    return out;
}

// Lines up to this width may hold a whole flat object.
constexpr std::size_t kLineWidth = 100;

std::string scalarText(const ordered_json& value)
{
    // nlohmann prints the shortest text that reads back as the same double.
    // Strings the model got from outside could hold invalid UTF-8; replacing
    // it (instead of throwing) keeps writing total, and the save path's
    // read-back check refuses the result.
    return value.dump(-1, ' ', false, ordered_json::error_handler_t::replace);
}

bool isNumberArray(const ordered_json& value)
{
    if (!value.is_array())
        return false;
    for (const ordered_json& element : value)
        if (!element.is_number())
            return false;
    return true;
}

std::string inlineNumberArray(const ordered_json& value)
{
    std::string out = "[";
    bool first = true;
    for (const ordered_json& element : value) {
        if (!first)
            out += ", ";
        first = false;
        out += scalarText(element);
    }
    return out + "]";
}

// The one-line form of an object whose members are all scalars or number
// arrays; empty if it has any other member.
std::string inlineFlatObject(const ordered_json& value)
{
    std::string out = "{ ";
    bool first = true;
    for (const auto& [key, member] : value.items()) {
        if (!member.is_primitive() && !isNumberArray(member))
            return {};
        if (!first)
            out += ", ";
        first = false;
        out += scalarText(ordered_json(key)) + ": ";
        out += member.is_array() ? inlineNumberArray(member) : scalarText(member);
    }
    return out + " }";
}

void print(const ordered_json& value, std::size_t indent, std::size_t column, std::string& out)
{
    if (value.is_array()) {
        if (value.empty()) {
            out += "[]";
        } else if (isNumberArray(value)) {
            out += inlineNumberArray(value);
        } else {
            out += "[\n";
            bool first = true;
            for (const ordered_json& element : value) {
                if (!first)
                    out += ",\n";
                first = false;
                out.append(indent + 2, ' ');
                print(element, indent + 2, indent + 2, out);
            }
            out += '\n';
            out.append(indent, ' ');
            out += ']';
        }
        return;
    }
    if (value.is_object()) {
        if (value.empty()) {
            out += "{}";
            return;
        }
        const std::string flat = inlineFlatObject(value);
        if (!flat.empty() && column + flat.size() + 1 <= kLineWidth) {
            out += flat;
            return;
        }
        out += "{\n";
        bool first = true;
        for (const auto& [key, member] : value.items()) {
            if (!first)
                out += ",\n";
            first = false;
            out.append(indent + 2, ' ');
            const std::string name = scalarText(ordered_json(key)) + ": ";
            out += name;
            print(member, indent + 2, indent + 2 + name.size(), out);
        }
        out += '\n';
        out.append(indent, ' ');
        out += '}';
        return;
    }
    out += scalarText(value);
}

} // namespace

ordered_json sceneToJson(const Scene& scene)
{
    ordered_json doc = ordered_json::object();
    doc["format"] = kSceneFormatTag;
    doc["version"] = kSceneFormatVersion;
    ordered_json materials = ordered_json::array();
    for (const Material& material : scene.materials)
        materials.push_back(materialToJson(material));
    doc["materials"] = std::move(materials);
    ordered_json objects = ordered_json::array();
    for (const Object& object : scene.objects)
        objects.push_back(objectToJson(object));
    doc["objects"] = std::move(objects);
    ordered_json regions = ordered_json::array();
    for (const Region& region : scene.regions)
        regions.push_back(regionToJson(region));
    doc["regions"] = std::move(regions);
    doc["solver"] = solverToJson(scene.solver);
    if (scene.camera)
        doc["camera"] = cameraToJson(*scene.camera);
    return doc;
}

} // namespace detail

std::string serializeScene(const Scene& scene)
{
    std::string out;
    detail::print(detail::sceneToJson(scene), 0, 0, out);
    out += '\n';
    return out;
}

} // namespace regio::model
