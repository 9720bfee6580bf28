// The scene file's outer layer: JSON syntax (with hostile input kept harmless),
// the format tag, the version and its migrations. The document's structure is
// read in scene_json_read.cpp, written in scene_json_write.cpp.
#include "model/io/scene_json.h"

#include "model/io/printable.h"
#include "model/io/scene_json_detail.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <exception>
#include <map>
#include <new>
#include <vector>

namespace regio::model {

namespace detail {

using nlohmann::json;

void setTextPosition(std::string_view text, std::size_t offset, Diagnostic& diagnostic)
{
    offset = std::min(offset, text.size());
    int line = 1;
    int column = 1;
    // A UTF-8 byte order mark is no character an editor shows.
    const std::size_t first = text.substr(0, 3) == "\xEF\xBB\xBF" && offset >= 3 ? 3 : 0;
    for (std::size_t i = first; i < offset; ++i) {
        const auto byte = static_cast<unsigned char>(text[i]);
        if (byte == '\n') {
            ++line;
            column = 1;
        } else if ((byte & 0xC0) != 0x80) { // count code points, not continuation bytes
            ++column;
        }
    }
    diagnostic.line = line;
    diagnostic.column = column;
}

std::string formatNumber(double value) { return json(value).dump(); }

namespace {

// Messages quote bits of the input (nlohmann's "last read: '...'"); keep them
// short and printable whatever bytes the file holds.
std::string excerpt(std::string_view text, std::size_t maxBytes = 160) { return printable(text, maxBytes); }

// Refuses what would make the real parser slow or its recursive tree
// operations unsafe, before it runs (see the limits in scene_json_detail.h).
// Everything else is left for the parser to judge.
Check prescan(std::string_view text)
{
    auto refuse = [&](std::size_t offset, std::string message) {
        Diagnostic d = makeError(std::move(message));
        setTextPosition(text, offset, d);
        return d;
    };
    auto isNumberChar = [](char c) {
        return (c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.' || c == 'e' || c == 'E';
    };
    auto isWhitespace = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; };
    int depth = 0;
    std::size_t values = 0;
    for (std::size_t i = 0; i < text.size();) {
        const char c = text[i];
        const std::size_t start = i;
        if (c == '"') {
            for (++i; i < text.size() && text[i] != '"'; ++i) {
                if (text[i] == '\\')
                    ++i;
                if (i - start > kMaxStringLength)
                    return refuse(start, "string longer than 1 MiB (a missing closing quote?)");
            }
            ++i;
        } else if (isNumberChar(c)) {
            while (i < text.size() && isNumberChar(text[i]))
                ++i;
            if (i - start > kMaxNumberLength)
                return refuse(start, "number longer than " + std::to_string(kMaxNumberLength) + " characters");
        } else if (isWhitespace(c)) {
            while (i < text.size() && isWhitespace(text[i]))
                ++i;
            if (i - start > kMaxWhitespaceRun)
                return refuse(start, "more than 1 MiB of white space in a row");
        } else {
            if (c == '[' || c == '{') {
                if (++depth > kMaxNestingDepth)
                    return refuse(i, "arrays and objects nested deeper than " + std::to_string(kMaxNestingDepth) +
                                         " levels (a scene needs 7)");
            } else if ((c == ']' || c == '}') && depth > 0) {
                --depth;
            } else if (c == ',' && ++values > kMaxValueCount) {
                return refuse(i, "more than " + std::to_string(kMaxValueCount) +
                                     " values (more than a scene of a million faces needs)");
            }
            ++i;
        }
    }
    return success();
}

// The first byte of the complete token whose last byte is at `end` (a number,
// a string, a literal or one structural character); text.size() at the end.
std::size_t tokenStart(std::string_view text, std::size_t end)
{
    if (end >= text.size())
        return text.size();
    auto isNumberChar = [](char c) {
        return (c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.' || c == 'e' || c == 'E';
    };
    std::size_t start = end;
    if (text[end] == '"') {
        // Back to the opening quote: the first '"' not escaped by an odd
        // number of backslashes.
        while (start > 0) {
            --start;
            if (text[start] != '"')
                continue;
            std::size_t backslashes = 0;
            while (backslashes < start && text[start - 1 - backslashes] == '\\')
                ++backslashes;
            if (backslashes % 2 == 0)
                break;
        }
    } else if (text[end] >= 'a' && text[end] <= 'z') {
        while (start > 0 && text[start - 1] >= 'a' && text[start - 1] <= 'z')
            --start;
    } else if (isNumberChar(text[end])) {
        while (start > 0 && isNumberChar(text[start - 1]))
            --start;
    }
    return start;
}

// Builds the document like nlohmann's own DOM parser, but keeps track of the
// JSON pointer of the value being read (so a syntax error or an overflowing
// number can say where it is) and reports duplicate keys.
class DocumentBuilder : public nlohmann::json_sax<json> {
public:
    explicit DocumentBuilder(std::string_view text)
        : m_text(text)
    {
    }

    bool null() override { return add(json(nullptr)); }
    bool boolean(bool value) override { return add(json(value)); }
    bool number_integer(number_integer_t value) override { return add(json(value)); }
    bool number_unsigned(number_unsigned_t value) override { return add(json(value)); }
    bool number_float(number_float_t value, const string_t&) override { return add(json(value)); }
    bool string(string_t& value) override { return add(json(std::move(value))); }
    bool binary(binary_t& value) override { return add(json::binary(std::move(value))); }

    bool start_object(std::size_t) override { return open(json::object()); }
    bool start_array(std::size_t) override { return open(json::array()); }
    bool end_object() override { return close(); }
    bool end_array() override { return close(); }

    bool key(string_t& key) override
    {
        Level& level = m_stack.back();
        level.key = key;
        level.memberOpen = true;
        if (level.value->contains(key))
            m_diagnostics.push_back(makeError("duplicate key \"" + excerpt(key) + "\"", pointerHere()));
        m_member = &(*level.value)[key];
        *m_member = nullptr;
        return true;
    }

    bool parse_error(std::size_t position, const std::string& lastToken, const nlohmann::detail::exception& ex) override
    {
        std::string message;
        if (ex.id == 406) {
            message = "number " + excerpt(lastToken, 40) + " is out of range (not a finite double)";
        } else {
            // "[json.exception.parse_error.101] parse error at line 1, column 5: <what>"
            std::string what = ex.what();
            const std::size_t columnAt = what.find(", column ");
            const std::size_t colon = what.find(": ", columnAt == std::string::npos ? 0 : columnAt);
            message = colon == std::string::npos ? what : what.substr(colon + 2);
            message = excerpt(message);
        }
        // `position` counts the characters read. A token the lexer could not
        // finish ("last read: ...") is located at the character that broke it;
        // a complete token in the wrong place (a number where a comma belongs,
        // an overflowing number) at its first character.
        std::size_t offset = position > 0 ? position - 1 : 0;
        if (message.find("unexpected end of input") != std::string::npos)
            offset = m_text.size();
        else if (ex.id == 406 || message.find("; last read: '") == std::string::npos)
            offset = tokenStart(m_text, offset);
        Diagnostic d = makeError(std::move(message), pointerHere());
        setTextPosition(m_text, offset, d);
        m_diagnostics.push_back(std::move(d));
        return false;
    }

    json takeDocument() { return std::move(m_root); }
    Diagnostics takeDiagnostics() { return std::move(m_diagnostics); }

private:
    struct Level {
        json* value;
        std::string key;         // the member being read, for objects
        bool memberOpen = false; // its key is read, its value not yet complete
    };

    json* place(json&& value)
    {
        if (m_stack.empty()) {
            m_root = std::move(value);
            return &m_root;
        }
        json& parent = *m_stack.back().value;
        if (parent.is_array()) {
            parent.push_back(std::move(value));
            return &parent.back();
        }
        *m_member = std::move(value);
        return m_member;
    }
    void memberComplete()
    {
        if (!m_stack.empty() && m_stack.back().value->is_object())
            m_stack.back().memberOpen = false;
    }
    bool add(json&& value)
    {
        place(std::move(value));
        memberComplete();
        return true;
    }
    bool open(json&& container)
    {
        m_stack.push_back(Level{place(std::move(container)), {}});
        return true;
    }
    bool close()
    {
        m_stack.pop_back();
        memberComplete();
        return true;
    }

    // The pointer of the value being read: inner levels name the container
    // being filled (the last element of an array, the member being read); the
    // innermost level names the next array slot, or the member whose key is
    // read, or nothing when the object itself waits for a key or a comma.
    std::string pointerHere() const
    {
        std::string pointer;
        for (std::size_t i = 0; i < m_stack.size(); ++i) {
            const Level& level = m_stack[i];
            if (level.value->is_array()) {
                std::size_t index = level.value->size();
                if (i + 1 < m_stack.size() && index > 0)
                    --index;
                pointer = appendPointer(pointer, index);
            } else if (i + 1 < m_stack.size() || level.memberOpen) {
                pointer = appendPointer(pointer, level.key);
            }
        }
        return pointer;
    }

    std::string_view m_text;
    json m_root;
    std::vector<Level> m_stack;
    json* m_member = nullptr;
    Diagnostics m_diagnostics;
};

} // namespace

JsonText parseJsonText(std::string_view text)
{
    JsonText result;
    if (Check refused = prescan(text); !refused) {
        result.diagnostics = refused.takeDiagnostics();
        return result;
    }
    DocumentBuilder builder(text);
    const bool ok = json::sax_parse(text.begin(), text.end(), &builder);
    result.diagnostics = builder.takeDiagnostics();
    if (ok)
        result.document = builder.takeDocument();
    return result;
}

} // namespace detail

namespace {

using nlohmann::json;

// A migration upgrades a document of version `from` to `from + 1` in place,
// adding a warning for anything it had to guess. When kSceneFormatVersion is
// raised, the step from the previous version goes here; version 1 is the
// first, so there are none yet.
using MigrationStep = void (*)(json& document, Diagnostics& diagnostics);

const std::map<int, MigrationStep>& migrations()
{
    static const std::map<int, MigrationStep> steps{};
    return steps;
}

constexpr int kFirstSceneFormatVersion = 1;

// Checks the format tag and the version, migrating older documents. Returns
// false when the document cannot be read as a current scene.
bool checkFormatAndMigrate(json& document, Diagnostics& diagnostics)
{
    if (!document.is_object()) {
        diagnostics.push_back(
            makeError("expected a JSON object with \"format\": \"regio-scene\"; this is not a Regio scene"));
        return false;
    }
    const auto format = document.find("format");
    if (format == document.end()) {
        diagnostics.push_back(
            makeError("missing key \"format\" (expected \"regio-scene\"); this is not a Regio scene"));
        return false;
    }
    if (!format->is_string() || format->get_ref<const std::string&>() != kSceneFormatTag) {
        diagnostics.push_back(makeError("expected \"regio-scene\"; this is not a Regio scene", "/format"));
        return false;
    }
    const auto versionValue = document.find("version");
    if (versionValue == document.end()) {
        diagnostics.push_back(makeError("missing key \"version\""));
        return false;
    }
    const std::optional<std::int64_t> integer = detail::asInteger(*versionValue);
    // An integer too large for int64 (or for a double to hold exactly) is
    // still a version, and certainly a newer one.
    const bool hugeInteger = !integer && versionValue->is_number() &&
                             versionValue->get<double>() > kSceneFormatVersion &&
                             std::trunc(versionValue->get<double>()) == versionValue->get<double>();
    if (!integer && !hugeInteger) {
        diagnostics.push_back(makeError("expected an integer", "/version"));
        return false;
    }
    const std::int64_t version = integer ? *integer : INT64_MAX;
    if (version > kSceneFormatVersion) {
        diagnostics.push_back(makeError(
            "scene format version " + (integer ? std::to_string(version) : versionValue->dump()) +
                " is newer than this Regio supports (" + std::to_string(kSceneFormatVersion) + "); update Regio",
            "/version"));
        return false;
    }
    if (version < kFirstSceneFormatVersion) {
        diagnostics.push_back(makeError("scene format version " + std::to_string(version) +
                                            " does not exist; versions start at " +
                                            std::to_string(kFirstSceneFormatVersion),
                                        "/version"));
        return false;
    }
    for (auto v = static_cast<int>(version); v < kSceneFormatVersion; ++v) {
        const auto step = migrations().find(v);
        if (step == migrations().end()) {
            diagnostics.push_back(
                makeError("scene format version " + std::to_string(v) + " can no longer be read", "/version"));
            return false;
        }
        step->second(document, diagnostics);
        document["version"] = v + 1;
    }
    return !hasErrors(diagnostics);
}

} // namespace

namespace {

// The reader names a value at fault by its pointer. This gives each of its
// diagnostics the ids of the elements the pointer enters, read from the
// document itself, so that it names the face (part, material, region) at
// fault even where the reader stopped before it knew the face's id.
void nameElements(const nlohmann::json& document, Diagnostics& diagnostics)
{
    static const char* const kCollections[] = {"materials", "objects", "parts", "faces", "regions"};
    for (Diagnostic& d : diagnostics) {
        if (!d.idPath.empty() || d.pointer.empty())
            continue;
        const nlohmann::json* node = &document;
        std::string previous;
        for (const std::string& token : pointerTokens(d.pointer)) {
            if (!node)
                break;
            if (node->is_object()) {
                const auto it = node->find(token);
                node = it == node->end() ? nullptr : &*it;
            } else if (node->is_array() && !token.empty() && token.size() < 10 &&
                       token.find_first_not_of("0123456789") == std::string::npos && std::stoul(token) < node->size()) {
                node = &(*node)[std::stoul(token)];
                const bool collection = std::any_of(std::begin(kCollections), std::end(kCollections),
                                                    [&](const char* name) { return previous == name; });
                if (collection && node->is_object() && node->contains("id") && (*node)["id"].is_string())
                    d.idPath.push_back((*node)["id"].get<std::string>());
            } else {
                node = nullptr;
            }
            previous = token;
        }
    }
}

} // namespace

Result<Scene> parseScene(std::string_view text)
{
    Diagnostics diagnostics;
    try {
        detail::JsonText parsed = detail::parseJsonText(text);
        diagnostics = std::move(parsed.diagnostics);
        if (!parsed.document)
            return diagnostics;
        if (hasErrors(diagnostics) || !checkFormatAndMigrate(*parsed.document, diagnostics)) {
            nameElements(*parsed.document, diagnostics);
            return diagnostics;
        }
        Scene scene;
        detail::readSceneDocument(*parsed.document, scene, diagnostics);
        nameElements(*parsed.document, diagnostics);
        if (hasErrors(diagnostics))
            return diagnostics;
        return {std::move(scene), std::move(diagnostics)};
    } catch (const std::bad_alloc&) {
        diagnostics.push_back(makeError("out of memory while reading the scene"));
    } catch (const std::exception& e) {
        // The reader checks every type before it converts; reaching this is a bug,
        // but the promise is a diagnostic, never an exception.
        diagnostics.push_back(makeError(std::string("internal error while reading: ") + e.what()));
    }
    return diagnostics;
}

} // namespace regio::model
