#pragma once
// The solver's preparation of a scene for a GoogleTest test: a scene that
// cannot be prepared fails the test with its first message and gives an
// empty prepared scene.
#include "solver/prepare/prepare.h"

#include <gtest/gtest.h>

#include <string>

namespace regio::test {

inline solver::PreparedScene prepared(const model::Scene& scene, const solver::PrepareOptions& options = {})
{
    model::Result<solver::PreparedScene> r = solver::prepareScene(scene, options);
    EXPECT_TRUE(r.ok()) << (r.diagnostics().empty() ? "" : r.diagnostics()[0].message);
    return r.ok() ? std::move(*r) : solver::PreparedScene{};
}

inline solver::PreparedScene prepared(const model::Scene& scene, solver::RegionsMode regions)
{
    solver::PrepareOptions options;
    options.regions = regions;
    return prepared(scene, options);
}

// The index of the input face with the file's id `id`; fails the test and
// gives 0 when there is none.
inline size_t faceNamed(const solver::PreparedScene& s, const std::string& id)
{
    for (size_t f = 0; f < s.faces.size(); ++f)
        if (s.faces[f].id == id)
            return f;
    ADD_FAILURE() << "no face " << id;
    return 0;
}

} // namespace regio::test
