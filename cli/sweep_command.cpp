// `regio-solve sweep`: a parameter study in one command. Each --set names a
// value of the scene file and the values it takes; every combination becomes
// a variant scene in the output directory, checked like any scene, and with
// --solve the batch (batch.h) solves them there.
#include "cli/batch.h"
#include "cli/commands.h"
#include "cli/scene_input.h"
#include "cli/solve_options.h"

#include "model/io/file_io.h"
#include "model/io/printable.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace regio::cli {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const char* const kSweepUsage =
    "Usage: regio-solve sweep SCENE.json --set PATH=VALUES... --out-dir DIR\n"
    "                         [--solve [SOLVE OPTIONS]]\n"
    "\n"
    "Writes a variant of the scene for every combination of the values that\n"
    "each --set gives, as DIR/NAME-001.json, DIR/NAME-002.json, ... (NAME is\n"
    "the scene file's name without .json), and DIR/NAME.sweep.csv, a table\n"
    "of the values of each variant. Every variant is checked as\n"
    "'regio-solve check' would; none is written unless all are valid.\n"
    "\n"
    "PATH names a value of the scene file by its keys, separated by dots; in a\n"
    "list (materials, objects, parts, faces, regions) a key picks the entry of\n"
    "that id, or of that index:\n"
    "  solver.hemicube=150,300,600\n"
    "  solver.adaptive.threshold=0.02,0.05\n"
    "  materials.wall.reflectance=0.5,0.7          (a number sets all three channels)\n"
    "  materials.lamp.emission=[10,9,8],[20,18,16]\n"
    "A value the file leaves out is added; one the scene format does not know\n"
    "is an error.\n"
    "VALUES are separated by commas outside brackets; each is JSON, or text.\n"
    "\n"
    "Options:\n"
    "  --set PATH=VALUES  a value and what it takes (repeatable)\n"
    "  --out-dir DIR      where the variants go (made if missing)\n"
    "  --solve ...        then solve the variants into DIR: every argument after\n"
    "                     --solve is an option of 'regio-solve solve --out-dir'\n"
    "                     (--format, --jobs, --force, --progress, ...)\n"
    "  -q, --quiet        no list of the variants\n"
    "  -h, --help         show this help\n"
    "\n"
    "Exit status: as 'regio-solve solve' with --solve; otherwise 0 written,\n"
    "1 a variant is not a valid scene, 2 usage error or unreadable file.\n";

// At most this many variants: a typo in a list should not fill a disk.
constexpr std::size_t kMaxVariants = 10000;

int usageError(const std::string& message)
{
    std::cerr << "regio-solve sweep: " << message << "\nTry 'regio-solve sweep --help'.\n";
    return kExitFailure;
}

struct Setting {
    std::string path;
    std::vector<json> values;
};

// "0.5,[1,2,3],abc" -> 0.5, [1,2,3], "abc": commas inside brackets or
// quotes belong to their value.
std::optional<std::vector<json>> parseValues(const std::string& text)
{
    std::vector<std::string> pieces;
    std::string piece;
    int depth = 0;
    bool quoted = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (quoted) {
            if (c == '\\' && i + 1 < text.size())
                piece += text[i++];
            else if (c == '"')
                quoted = false;
        } else if (c == '"') {
            quoted = true;
        } else if (c == '[' || c == '{') {
            ++depth;
        } else if (c == ']' || c == '}') {
            --depth;
        } else if (c == ',' && depth == 0) {
            pieces.push_back(piece);
            piece.clear();
            continue;
        }
        piece += c;
    }
    pieces.push_back(piece);
    std::vector<json> values;
    for (const std::string& p : pieces) {
        if (p.empty())
            return std::nullopt;
        json value = json::parse(p, nullptr, false);
        values.push_back(value.is_discarded() ? json(p) : std::move(value));
    }
    return values;
}

// The value `path` names in `scene`, or an error message.
std::variant<json*, std::string> locate(json& scene, const std::string& path)
{
    std::vector<std::string> keys;
    std::size_t start = 0;
    for (;;) {
        const std::size_t dot = path.find('.', start);
        keys.push_back(path.substr(start, dot == std::string::npos ? std::string::npos : dot - start));
        if (dot == std::string::npos)
            break;
        start = dot + 1;
    }
    json* node = &scene;
    std::string walked;
    for (std::size_t k = 0; k < keys.size();) {
        if (node->is_object()) {
            // A key the file leaves out (at its default) is added; a key the
            // scene format does not know is caught by the check that follows.
            walked += (walked.empty() ? "" : ".") + keys[k];
            node = &(*node)[keys[k]];
            ++k;
            if (node->is_null() && k < keys.size())
                *node = json::object();
        } else if (node->is_array()) {
            // Ids may hold dots ("light.panel"): the longest run of keys that
            // is an id wins; else a key of digits is an index.
            json* found = nullptr;
            std::size_t used = 0;
            for (std::size_t n = keys.size() - k; n >= 1 && !found; --n) {
                std::string id = keys[k];
                for (std::size_t j = 1; j < n; ++j)
                    id += "." + keys[k + j];
                for (json& entry : *node)
                    if (entry.is_object() && entry.contains("id") && entry["id"] == id) {
                        found = &entry;
                        used = n;
                        break;
                    }
            }
            if (!found) {
                const std::string& key = keys[k];
                if (!key.empty() && key.find_first_not_of("0123456789") == std::string::npos && key.size() < 9 &&
                    std::stoul(key) < node->size()) {
                    found = &(*node)[std::stoul(key)];
                    used = 1;
                } else {
                    return "'" + walked + "' has no entry of id or index '" + key + "'";
                }
            }
            for (std::size_t j = 0; j < used; ++j)
                walked += (walked.empty() ? "" : ".") + keys[k + j];
            node = found;
            k += used;
        } else {
            return "'" + walked + "' is a value, not a list or an object";
        }
    }
    return node;
}

// A number where the file has three (a colour) sets all three.
json fitted(const json& current, const json& value)
{
    if (value.is_number() && current.is_array() && current.size() == 3 &&
        std::all_of(current.begin(), current.end(), [](const json& c) { return c.is_number(); }))
        return json::array({value, value, value});
    return value;
}

std::string shortText(const json& value)
{
    return value.is_string() ? value.get<std::string>() : value.dump(-1, ' ', false, json::error_handler_t::replace);
}

} // namespace

int runSweep(int argc, char** argv)
{
    std::string sceneFile;
    std::optional<std::string> outDir;
    std::vector<Setting> settings;
    bool quiet = false;
    std::vector<std::string> solveArguments;
    bool solve = false;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--solve") {
            solve = true;
            for (++i; i < argc; ++i)
                solveArguments.push_back(argv[i]);
            break;
        }
        if (arg == "-h" || arg == "--help") {
            std::cout << kSweepUsage;
            return kExitOk;
        }
        if (arg == "-q" || arg == "--quiet") {
            quiet = true;
        } else if (arg == "--set" || arg == "--out-dir") {
            if (i + 1 >= argc)
                return usageError(arg + " needs a value");
            const std::string value = argv[++i];
            if (arg == "--out-dir") {
                outDir = value;
                continue;
            }
            const std::size_t eq = value.find('=');
            if (eq == std::string::npos || eq == 0)
                return usageError("--set expects PATH=VALUES, not '" + model::printable(value) + "'");
            const auto values = parseValues(value.substr(eq + 1));
            if (!values)
                return usageError("--set " + model::printable(value.substr(0, eq)) + " has an empty value");
            settings.push_back({value.substr(0, eq), *values});
        } else if (!arg.empty() && arg[0] == '-') {
            return usageError("unknown option '" + model::printable(arg) + "'");
        } else if (sceneFile.empty()) {
            sceneFile = arg;
        } else {
            return usageError("one scene at a time: '" + model::printable(arg) + "'");
        }
    }
    if (sceneFile.empty())
        return usageError("no scene file given");
    if (settings.empty())
        return usageError("no --set given: nothing to vary");
    if (!outDir)
        return usageError("--out-dir is needed: the variants go there");
    std::size_t variants = 1;
    for (const Setting& setting : settings) {
        variants *= setting.values.size();
        if (variants > kMaxVariants)
            return usageError("more than " + std::to_string(kMaxVariants) + " variants");
    }

    const model::Result<std::string> text = model::readFile(sceneFile);
    if (!text) {
        std::cerr << formatDiagnostic(sceneFile, text.error()) << "\n";
        return kExitFailure;
    }
    const json original = json::parse(*text, nullptr, false);
    if (!original.is_object()) {
        std::cerr << model::printable(sceneFile) << ": error: not a scene (check it with 'regio-solve check')\n";
        return kExitErrors;
    }

    const model::Diagnostics known = sceneInputFromText(sceneFile, *text).diagnostics;
    const std::string name = sceneNameOf(sceneFile);
    const int digits = variants >= 1000 ? 4 : 3;

    // Every variant made and checked before any is written.
    std::vector<std::pair<std::string, std::string>> files; // name, text
    json index = json::array();
    int exitCode = kExitOk;
    for (std::size_t v = 0; v < variants; ++v) {
        json scene = original;
        json values = json::object();
        std::size_t rest = v;
        for (std::size_t s = settings.size(); s-- > 0;) {
            const Setting& setting = settings[s];
            const json& value = setting.values[rest % setting.values.size()];
            rest /= setting.values.size();
            auto located = locate(scene, setting.path);
            if (std::holds_alternative<std::string>(located))
                return usageError("--set " + model::printable(setting.path) + ": " +
                                  model::printable(std::get<std::string>(located)));
            json& target = *std::get<json*>(located);
            target = fitted(target, value);
            values[setting.path] = target;
        }
        char number[16];
        std::snprintf(number, sizeof number, "-%0*zu", digits, v + 1);
        const std::string file = name + number + ".json";
        const std::string variantText = scene.dump(2) + "\n";
        SceneInput input = sceneInputFromText(file, variantText);
        // A warning the original does not have (an unknown key is ignored)
        // means the value would not do what it says: an error here.
        for (model::Diagnostic& d : input.diagnostics)
            if (!d.isError() && std::none_of(known.begin(), known.end(), [&](const model::Diagnostic& o) {
                    return o.pointer == d.pointer && o.message == d.message;
                }))
                d.severity = model::Severity::Error;
        if (const int code = exitCodeOf(input); code != kExitOk) {
            std::string what;
            for (const Setting& setting : settings)
                what += (what.empty() ? "" : ", ") + setting.path + "=" + shortText(values[setting.path]);
            std::cerr << model::printable(file) << " (" << model::printable(what) << "):\n";
            printDiagnostics(std::cerr, input);
            exitCode = std::max(exitCode, code);
            continue;
        }
        files.emplace_back(file, variantText);
        index.push_back({{"scene", file}, {"values", values}});
    }
    if (exitCode != kExitOk) {
        std::cerr << "regio-solve sweep: no variant written: some are not valid scenes\n";
        return exitCode;
    }

    std::error_code ec;
    fs::create_directories(*outDir, ec);
    if (ec || !fs::is_directory(*outDir)) {
        std::cerr << "regio-solve sweep: cannot create the directory " << model::printable(*outDir) << ": "
                  << (ec ? ec.message() : "a file of that name is in the way") << "\n";
        return kExitFailure;
    }
    std::vector<std::string> paths;
    for (const auto& [file, variantText] : files) {
        const std::string path = (fs::path(*outDir) / file).string();
        // Unchanged bytes are not rewritten, so a batch's record of them stays true.
        const model::Result<std::string> before = model::readFile(path);
        if (!(before && *before == variantText)) {
            if (model::Check written = model::writeFileAtomically(path, variantText); !written) {
                std::cerr << "regio-solve sweep: " << model::printable(written.error().message) << "\n";
                return kExitFailure;
            }
        }
        paths.push_back(path);
    }
    // The study's table: a row per variant, a column per --set.
    const auto csvField = [](const std::string& field) {
        if (field.find_first_of(",\"\n") == std::string::npos)
            return field;
        std::string quoted = "\"";
        for (char c : field)
            quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
        return quoted + "\"";
    };
    std::string table = "scene";
    for (const Setting& setting : settings)
        table += "," + csvField(setting.path);
    table += "\n";
    for (const json& entry : index) {
        table += csvField(entry["scene"].get<std::string>());
        for (const Setting& setting : settings)
            table += "," + csvField(shortText(entry["values"][setting.path]));
        table += "\n";
    }
    const std::string indexPath = (fs::path(*outDir) / (name + ".sweep.csv")).string();
    if (model::Check written = model::writeFileAtomically(indexPath, table); !written) {
        std::cerr << "regio-solve sweep: " << model::printable(written.error().message) << "\n";
        return kExitFailure;
    }
    if (!quiet) {
        std::ostream& out = solve ? std::cerr : std::cout;
        for (const json& entry : index) {
            out << entry["scene"].get<std::string>() << ":";
            for (const Setting& setting : settings)
                out << " " << model::printable(setting.path) << "="
                    << model::printable(shortText(entry["values"][setting.path]));
            out << "\n";
        }
        out << variants << (variants == 1 ? " variant" : " variants") << " in " << model::printable(*outDir) << " ("
            << model::printable(indexPath) << ")\n";
    }
    if (!solve)
        return kExitOk;

    // The batch, as 'regio-solve solve --out-dir DIR SOLVE-OPTIONS VARIANTS...'.
    std::vector<std::string> arguments{"solve", "--out-dir", *outDir};
    arguments.insert(arguments.end(), solveArguments.begin(), solveArguments.end());
    arguments.push_back("--");
    arguments.insert(arguments.end(), paths.begin(), paths.end());
    std::vector<char*> solveArgv;
    for (std::string& a : arguments)
        solveArgv.push_back(a.data());
    return runSolve(static_cast<int>(solveArgv.size()), solveArgv.data());
}

} // namespace regio::cli
