// model::Result, the one way the libraries say that input was refused: a
// value (with warnings beside it) or the diagnostics that explain why not.
#include "model/result.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>

namespace regio::model {
namespace {

TEST(Result, AValueComesWithItsWarnings)
{
    const Result<int> r(42, {makeWarning("a face without area", "/objects/0/parts/0/faces/3/loop")});
    ASSERT_TRUE(r.ok());
    EXPECT_TRUE(static_cast<bool>(r));
    EXPECT_EQ(*r, 42);
    ASSERT_EQ(r.diagnostics().size(), 1u);
    EXPECT_FALSE(r.diagnostics()[0].isError());
}

TEST(Result, AFailureHoldsItsErrorAndEverythingFoundBeforeIt)
{
    const Result<std::string> r(
        Diagnostics{makeWarning("first a warning"), makeError("then the error", "/version"), makeError("and another")});
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().message, "then the error") << "error() is the first error, not the first diagnostic";
    EXPECT_EQ(r.error().pointer, "/version");
    EXPECT_EQ(r.diagnostics().size(), 3u);
}

TEST(Result, AFailurePassesOnToAResultOfAnotherType)
{
    const Result<int> read = makeError("cannot open: No such file or directory");
    const Result<std::unique_ptr<int>> built = Result<std::unique_ptr<int>>::failureOf(read);
    ASSERT_FALSE(built.ok());
    EXPECT_EQ(built.error().message, "cannot open: No such file or directory");
}

TEST(Result, MoveOnlyValuesMoveOut)
{
    Result<std::unique_ptr<int>> r(std::make_unique<int>(7));
    ASSERT_TRUE(r.ok());
    std::unique_ptr<int> taken = std::move(*r);
    ASSERT_TRUE(taken);
    EXPECT_EQ(*taken, 7);
}

TEST(Result, ACheckIsSuccessOrTheProblem)
{
    EXPECT_TRUE(success().ok());
    EXPECT_TRUE(success().diagnostics().empty());
    const Check refused = makeError("reflectance must be below 1", "/materials/0/reflectance/0");
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(withPointer(refused.error(), "/materials/2/reflectance").pointer, "/materials/2/reflectance");
}

} // namespace
} // namespace regio::model
