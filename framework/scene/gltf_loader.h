// Loads a glTF 2.0 file (.gltf with external or data-URI buffers, or .glb) into the scene model.
//
// What is read: the default scene's node hierarchy (TRS or matrix transforms, flattened so that
// every mesh instance gets its own world-space copy of its positions), TRIANGLES primitives with
// any index type or none, baseColorFactor and baseColorTexture (sRGB texels converted to linear,
// sampled with TEXCOORD_0), emissiveFactor x KHR_materials_emissive_strength, doubleSided, the
// first perspective camera found depth-first, and the background radiance from the scene's extras
// {"pathway_background": [r, g, b]}.
//
// What is ignored: NORMAL and TANGENT attributes are skipped without a word, because the course
// renders Lambertian surfaces with geometric normals. Everything else the model cannot express
// (other textures, metallicFactor != 0, alpha modes, animations, skins, morph targets, vertex
// colours, orthographic cameras, other primitive modes, texture wrap modes, other extensions)
// earns one warning per feature per file, printed as "pathway: warning: <message>" once the load
// succeeds and kept in Scene::warnings. KHR_lights_punctual lamps are ignored with one warning
// that names them, even when extensionsRequired lists the extension (Blender's exporter does so
// for any scene with a lamp): Pathway's only lights are emissive meshes.
//
// What fails: anything malformed or unsupported that would change the geometry (bad JSON, missing
// buffers, accessors reading past their data, indices out of range, non-finite positions, sparse
// accessors, a required extension we lack other than KHR_lights_punctual, a scene without
// triangles) throws one PathwayError naming the file and the problem; nothing is printed and no
// partial scene escapes. SceneLoadOptions::strict also refuses a required KHR_lights_punctual.
#pragma once

#include <string>

#include "scene/scene.h"

namespace pathway {

struct SceneLoadOptions {
  // Refuse a file whose extensionsRequired lists KHR_lights_punctual instead of loading it without
  // its lamps, for users who would rather fix the file than render a scene lit differently
  // (the CLI's --strict).
  bool strict = false;
  // Every light resized about its centre by this factor at fixed power (resize_lights.h).
  float lightScale = 1.0f;
};

Scene loadScene(const std::string& path, const SceneLoadOptions& options = {});

}  // namespace pathway
