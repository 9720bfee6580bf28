#pragma once
// Output of a solution: the lit model in the format
// its file name asks for, and a software picture from a camera. This is what
// `regio-solve solve --out FILE --image FILE.png` calls, and what the editor
// can call to export.
//
//   .gltf  glTF 2.0 JSON + FILE.bin          (export_gltf.h)
//   .glb   glTF 2.0 binary                   (export_gltf.h)
//   .ply   binary PLY, colours + raw radiosity (export_ply.h)
//   .obj   OBJ with vertex colours (+ .mtl)  (export_obj.h)
//   .png   the Gouraud-shaded picture        (software_render.h, png_writer.h)
//
// Display values (exposure, gamma, ambient, false colour) are applied to the
// copies written out, never to the solution.
#include "model/scene.h"
#include "output/false_colour.h"
#include "output/lit_mesh.h"
#include "output/software_render.h"
#include "output/tone_map.h"
#include "solver/solver.h"

#include <optional>
#include <string>

namespace regio::output {

enum class ModelFormat { Gltf, Glb, Ply, Obj };

// The format of a model file by its extension (case-insensitive); empty for
// an extension no writer knows.
std::optional<ModelFormat> modelFormatForPath(const std::string& path);

// Writes the lit model in the format of the path's extension.
model::Check writeLitModel(const std::string& path, const LitMesh& mesh, const DisplayColours& colours);

enum class ColourMode {
    ToneMapped, // exposure and gamma (tone_map.h)
    FalseColour // luminance through the viridis ramp (false_colour.h); images get a legend
};

struct DisplaySettings {
    ToneMapSettings toneMap; // exposure, white reference, encoding, clamp, ambient
    ColourMode colours = ColourMode::ToneMapped;
    FalseColourSettings falseColour;
};

// The display colours of a mesh under the settings (with the false-colour
// scale when that mode is on, for drawing a legend).
struct PreparedColours {
    DisplayColours colours;
    std::optional<FalseColour> falseColour;
};
PreparedColours prepareColours(const LitMesh& mesh, const DisplaySettings& settings);

struct OutputRequest {
    std::string modelPath; // --out; empty = no model
    std::string imagePath; // --image (.png); empty = no picture
    int imageWidth = 1024;
    int imageHeight = 768;
    int supersample = 2;                 // samples per pixel along each axis
    std::optional<model::Camera> camera; // the scene's camera; empty = a view of the whole model
    DisplaySettings display;
    // Add the snapshot's ambient term (Cohen et al. 1988) to what is shown:
    // a plausible picture of an early, unconverged solution. Off, the files
    // show the solution as it stands (and toneMap.ambient is used as given).
    bool includeAmbient = false;
};

// Writes what the request asks for from a solver snapshot (flat element
// values: litMeshFromSolution). Returns the first error, naming the file, or
// nothing when every requested file was written.
model::Check writeOutputs(const SolutionSnapshot& snapshot, const OutputRequest& request);

// The same from a lit mesh (e.g. one with smooth vertex radiosity, §6).
// `includeAmbient` is not used here: the ambient is toneMap.ambient.
model::Check writeOutputs(const LitMesh& mesh, const OutputRequest& request);

} // namespace regio::output
