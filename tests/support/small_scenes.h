#pragma once
// Scene files small enough to solve in a fraction of a second, for the tests
// that run regio-solve on real files.
namespace regio::test {

// Two facing panels: a lamp and a grey receiver, 8 triangles in all.
inline constexpr const char* kSmallScene = R"({ "format": "regio-scene", "version": 1,
  "materials": [ { "id": "lamp", "reflectance": [0, 0, 0], "emission": [10, 8, 6] },
                 { "id": "grey", "reflectance": [0.5, 0.4, 0.3], "emission": [0, 0, 0] } ],
  "objects": [ { "id": "light", "parts": [ { "id": "light.panel", "material": "lamp",
      "vertices": [[0,1,0], [1,1,0], [1,1,1], [0,1,1]],
      "faces": [ { "id": "light.down", "loop": [0, 1, 2, 3] } ] } ] },
    { "id": "floor", "parts": [ { "id": "floor.panel", "material": "grey",
      "vertices": [[0,0,0], [0,0,1], [1,0,1], [1,0,0]],
      "faces": [ { "id": "floor.up", "loop": [0, 1, 2, 3] } ] } ] } ],
  "solver": { "hemicube": 50, "patchSize": 0.5, "elementsPerPatch": 1, "maxIterations": 500, "convergence": 0.001 }
})";

} // namespace regio::test
