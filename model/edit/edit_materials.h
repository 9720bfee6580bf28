#pragma once
// Edits of materials. Each validates first and leaves the scene unchanged
// when it refuses; each returns what its inverse needs:
//   addMaterial(m, i) -> index      <-> removeMaterial(m.id) -> {material, index}
//   removeMaterial(id) -> r         <-> addMaterial(r.material, r.index)
//   renameMaterial(a, b)            <-> renameMaterial(b, a)
//   setMaterialReflectance/Emission/Name return the previous value
// A material in use cannot be removed: the diagnostic names a part or face
// that uses it, so the editor can select it.
#include "model/result.h"
#include "model/scene.h"

#include <optional>
#include <string>

namespace regio::model {

// Reflectance: finite, each channel in [0, 1) - a channel of 1 would reflect
// all light and the progressive solution would never converge (B = E / (1 - rho)).
Check checkReflectance(const Rgb& reflectance);
// Emission: finite and non-negative per channel (W/m^2).
Check checkEmission(const Rgb& emission);

// Inserts at `index` (-1 = append); returns the index.
Result<int> addMaterial(Scene& scene, Material material, int index = -1);

struct RemovedMaterial {
    Material material;
    int index = -1;
    bool operator==(const RemovedMaterial&) const = default;
};
Result<RemovedMaterial> removeMaterial(Scene& scene, const std::string& materialId);

// Renames the material and every part and face reference to it.
Result<Unit> renameMaterial(Scene& scene, const std::string& materialId, const std::string& newId);

Result<Rgb> setMaterialReflectance(Scene& scene, const std::string& materialId, const Rgb& reflectance);
Result<Rgb> setMaterialEmission(Scene& scene, const std::string& materialId, const Rgb& emission);
Result<std::string> setMaterialName(Scene& scene, const std::string& materialId, std::string name);

} // namespace regio::model
