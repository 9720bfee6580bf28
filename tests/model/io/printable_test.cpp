// Text from files and command lines shown back to people: printable UTF-8
// stays as it is, anything else becomes \xNN.
#include "model/io/json_pointer.h"
#include "model/io/printable.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <string>

namespace regio::model {
namespace {

TEST(Printable, KeepsAsciiAndValidUtf8)
{
    EXPECT_EQ(printable("scene.json: /objects/0"), "scene.json: /objects/0");
    EXPECT_EQ(printable("čeština, 日本語, 🙂"), "čeština, 日本語, 🙂");
}

TEST(Printable, EscapesControlCharactersAndInvalidBytes)
{
    EXPECT_EQ(printable("a\nb\tc\x7f"), "a\\x0Ab\\x09c\\x7F");
    EXPECT_EQ(printable("\xff\xfe"), "\\xFF\\xFE");
    EXPECT_EQ(printable(std::string("nul\0", 4)), "nul\\x00");
    // A lead byte without its continuation bytes is not UTF-8.
    EXPECT_EQ(printable("\xc4"), "\\xC4");
    EXPECT_EQ(printable("\xe6\x97"), "\\xE6\\x97");
}

TEST(Printable, CutsLongTextAtTheLimit)
{
    EXPECT_EQ(printable("abcdefgh", 3), "abc...");
    EXPECT_EQ(printable("abc", 3), "abc");
}

TEST(JsonPointer, EscapesTildeAndSlashInKeys)
{
    EXPECT_EQ(appendPointer("/materials/0", "a/b~c"), "/materials/0/a~1b~0c");
    EXPECT_EQ(appendPointer("", std::size_t(3)), "/3");
}

TEST(JsonPointer, NamesTheElementsOfASceneFileWhateverTheIndexType)
{
    EXPECT_EQ(facePointer(1, 2, 3), "/objects/1/parts/2/faces/3");
    EXPECT_EQ(facePointer(std::size_t(1), std::size_t(2), std::size_t(3)), "/objects/1/parts/2/faces/3");
    EXPECT_EQ(partPointer(0, std::size_t(4)), "/objects/0/parts/4");
    EXPECT_EQ(materialPointer(5), "/materials/5");
    EXPECT_EQ(regionPointer(std::size_t(2)), "/regions/2");
}

} // namespace
} // namespace regio::model
