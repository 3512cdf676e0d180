// glTF file to Scene: parsing (tinygltf), file-wide checks, the node hierarchy flattened into
// world space, the camera, the background, and the final bounds and warnings.
#include "scene/gltf_loader.h"

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <iostream>
#include <sstream>
#include <utility>

#include "core/error.h"
#include "scene/gltf_detail.h"
#include "scene/resize_lights.h"

namespace pathway {
namespace gltf {

void Diagnostics::fail(const std::string& problem) const {
  throw PathwayError(file_ + ": " + problem);
}

void Diagnostics::checkIndex(int index, size_t count, const std::string& reference) const {
  if (index < 0 || static_cast<size_t>(index) >= count) {
    fail(reference + " " + std::to_string(index) + ", which does not exist (the file has " +
         std::to_string(count) + ")");
  }
}

void Diagnostics::warnOnce(const std::string& feature, const std::string& message) {
  if (warnedFeatures_.insert(feature).second) warnings_.push_back(file_ + ": " + message);
}

std::string describe(const std::string& kind, int index, const std::string& name) {
  return name.empty() ? kind + " " + std::to_string(index) : kind + " \"" + name + "\"";
}

namespace {

const char* const kSupportedExtensions[] = {"KHR_materials_emissive_strength"};

// Blender's exporter lists this one in extensionsRequired for any scene with a lamp, yet the
// meshes load fine without it, so only strict loading refuses it.
const char* const kLamps = "KHR_lights_punctual";

bool isSupported(const std::string& extension) {
  return std::find(std::begin(kSupportedExtensions), std::end(kSupportedExtensions), extension) !=
         std::end(kSupportedExtensions);
}

bool lists(const std::vector<std::string>& extensions, const std::string& extension) {
  return std::find(extensions.begin(), extensions.end(), extension) != extensions.end();
}

// One warning for all the lamps, naming them and what to use instead, so that a Blender user
// knows why the render is dark.
std::string lampWarning(const std::vector<tinygltf::Light>& lights) {
  std::string names;
  for (size_t i = 0; i < lights.size(); ++i) {
    if (i > 0) names += ", ";
    names += lights[i].name.empty() ? lights[i].type + " light " + std::to_string(i)
                                    : "\"" + lights[i].name + "\"";
  }
  return "ignoring " + std::to_string(lights.size()) + " " + kLamps + " lamp" +
         (lights.size() == 1 ? "" : "s") + (names.empty() ? "" : " (" + names + ")") +
         ": Pathway lights a scene only with emissive meshes (a material's emissiveFactor, "
         "optionally scaled by KHR_materials_emissive_strength)";
}

// tinygltf hands an image's bufferView bytes to the decoder without checking that the view lies
// inside its buffer; this check keeps a hostile .glb from making the decoder read past it.
bool loadImageInsideBuffer(tinygltf::Image* image, int index, std::string* err, std::string* warn,
                           int width, int height, const unsigned char* bytes, int size,
                           void* model) {
  if (image->bufferView >= 0) {
    const auto& parsed = *static_cast<const tinygltf::Model*>(model);
    const tinygltf::BufferView& view = parsed.bufferViews[image->bufferView];
    const size_t bufferSize = parsed.buffers[view.buffer].data.size();
    if (view.byteOffset > bufferSize || view.byteLength > bufferSize - view.byteOffset) {
      *err += "image " + std::to_string(index) + ": its bufferView lies outside its buffer\n";
      return false;
    }
  }
  return tinygltf::LoadImageData(image, index, err, warn, width, height, bytes, size, nullptr);
}

bool hasBinaryMagic(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  char magic[4] = {};
  return file.read(magic, sizeof magic) && std::memcmp(magic, "glTF", sizeof magic) == 0;
}

// tinygltf quotes whole data URIs in its messages; their first characters identify them.
std::string shortenDataUris(std::string line) {
  const std::string marker = ";base64,";
  const size_t kept = 16;
  for (size_t at = line.find(marker); at != std::string::npos; at = line.find(marker, at + 1)) {
    const size_t begin = at + marker.size();
    const size_t end = std::min(line.size(), line.find_first_of(" '\"", begin));
    if (end - begin > kept) line.replace(begin + kept, end - begin - kept, "...");
  }
  return line;
}

// tinygltf's messages are newline-terminated lines; ours are one line.
std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> result;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (!line.empty()) result.push_back(shortenDataUris(line));
  }
  return result;
}

tinygltf::Model parseFile(const std::string& path, Diagnostics& diagnostics) {
  std::error_code error;
  if (!std::filesystem::exists(path, error)) diagnostics.fail("no such file");
  if (!std::filesystem::is_regular_file(path, error)) diagnostics.fail("not a regular file");

  tinygltf::Model model;
  tinygltf::TinyGLTF parser;
  parser.SetImageLoader(&loadImageInsideBuffer, &model);
  std::string errors, warnings;
  bool parsed = false;
  try {
    // Chosen by content, not by extension: a .gltf that is really binary still loads.
    parsed = hasBinaryMagic(path) ? parser.LoadBinaryFromFile(&model, &errors, &warnings, path)
                                  : parser.LoadASCIIFromFile(&model, &errors, &warnings, path);
  } catch (const std::exception& e) {
    // tinygltf indexes some empty vectors with at(), e.g. for a zero-length GLB buffer.
    diagnostics.fail(std::string("invalid glTF (tinygltf failed: ") + e.what() + ")");
  }
  // On success, tinygltf's errors only name properties it wants but the glTF spec makes optional
  // (asset.version, a skin's inverseBindMatrices), so they matter only on failure.
  if (!parsed) {
    std::string message = "invalid glTF:";
    for (const std::string& line : lines(errors)) message += " " + line;
    diagnostics.fail(errors.empty() ? "invalid glTF (tinygltf gave no reason)" : message);
  }
  for (const std::string& warning : lines(warnings)) diagnostics.warnOnce(warning, warning);
  return model;
}

void checkFileWideFeatures(const tinygltf::Model& model, const SceneLoadOptions& options,
                           Diagnostics& diagnostics) {
  for (const std::string& extension : model.extensionsRequired) {
    if (extension == kLamps && !options.strict) continue;  // warned about below
    if (!isSupported(extension)) {
      diagnostics.fail(
          "requires extension " + extension + ", which is not supported" +
          (extension == kLamps ? " (without --strict its lamps would be ignored)" : ""));
    }
  }
  for (const std::string& extension : model.extensionsUsed) {
    if (!isSupported(extension) && extension != kLamps) {
      diagnostics.warnOnce(extension, "ignoring extension " + extension + " (not supported)");
    }
  }
  if (!model.animations.empty()) {
    diagnostics.warnOnce("animations", "ignoring animations (not supported)");
  }
  if (!model.skins.empty()) diagnostics.warnOnce("skins", "ignoring skins (not supported)");
  // One warning whether the file lists the extension as used, required, both, or (a sloppy
  // exporter) not at all.
  if (!model.lights.empty() || lists(model.extensionsUsed, kLamps) ||
      lists(model.extensionsRequired, kLamps)) {
    diagnostics.warnOnce(kLamps, lampWarning(model.lights));
  }
}

// The scene to show: the file's `scene`, else scene 0; none when the file has no scenes.
const tinygltf::Scene* chooseScene(const tinygltf::Model& model, const Diagnostics& diagnostics) {
  if (model.scenes.empty()) return nullptr;
  const int index = model.defaultScene >= 0 ? model.defaultScene : 0;
  diagnostics.checkIndex(index, model.scenes.size(), "the file's default is scene");
  return &model.scenes[index];
}

// The chosen scene's nodes or, without scenes, every node that is nobody's child.
std::vector<int> rootNodes(const tinygltf::Model& model, const tinygltf::Scene* scene) {
  if (scene != nullptr) return scene->nodes;
  std::vector<bool> isChild(model.nodes.size(), false);
  for (const tinygltf::Node& node : model.nodes) {
    for (int child : node.children) {
      if (child >= 0 && static_cast<size_t>(child) < isChild.size()) isChild[child] = true;
    }
  }
  std::vector<int> roots;
  for (size_t i = 0; i < isChild.size(); ++i) {
    if (!isChild[i]) roots.push_back(static_cast<int>(i));
  }
  return roots;
}

void checkSize(const std::vector<double>& values, size_t size, const std::string& what,
               const Diagnostics& diagnostics) {
  if (!values.empty() && values.size() != size) {
    diagnostics.fail(what + " has " + std::to_string(values.size()) + " numbers instead of " +
                     std::to_string(size));
  }
}

// The node's transform: its column-major `matrix`, or translation * rotation * scale.
glm::dmat4 localTransform(const tinygltf::Node& node, const std::string& what,
                          const Diagnostics& diagnostics) {
  checkSize(node.matrix, 16, what + " matrix", diagnostics);
  if (!node.matrix.empty()) return glm::make_mat4(node.matrix.data());
  checkSize(node.translation, 3, what + " translation", diagnostics);
  checkSize(node.rotation, 4, what + " rotation", diagnostics);
  checkSize(node.scale, 3, what + " scale", diagnostics);
  glm::dmat4 transform(1.0);
  if (!node.translation.empty()) {
    transform = glm::translate(transform, glm::make_vec3(node.translation.data()));
  }
  if (!node.rotation.empty()) {
    const std::vector<double>& q = node.rotation;  // x, y, z, w
    const glm::dquat rotation(q[3], q[0], q[1], q[2]);
    // Exporters round unit quaternions; normalizing keeps the rotation free of scale.
    if (!(glm::length(rotation) > 0.0)) diagnostics.fail(what + " rotation is not a rotation");
    transform *= glm::mat4_cast(glm::normalize(rotation));
  }
  if (!node.scale.empty()) transform = glm::scale(transform, glm::make_vec3(node.scale.data()));
  return transform;
}

// The camera keeps its position, view direction (-Z) and up direction (+Y) but sheds scale and
// shear, so that the renderer may treat cameraToWorld as a rigid motion.
glm::mat4 rigidCameraToWorld(const glm::dmat4& toWorld, const std::string& what,
                             const Diagnostics& diagnostics) {
  const glm::dvec3 back = glm::dvec3(toWorld[2]);
  const glm::dvec3 up =
      glm::dvec3(toWorld[1]) - glm::dot(glm::dvec3(toWorld[1]), back) / glm::dot(back, back) * back;
  if (!(glm::length(back) > 0.0 && glm::length(up) > 0.0) || !isFinite(Vec3(toWorld[3]))) {
    diagnostics.fail(what + " has a degenerate transform");
  }
  const glm::dvec3 z = glm::normalize(back), y = glm::normalize(up), x = glm::cross(y, z);
  return glm::mat4(
      glm::dmat4(glm::dvec4(x, 0.0), glm::dvec4(y, 0.0), glm::dvec4(z, 0.0), toWorld[3]));
}

// Sets the scene's camera from the first perspective camera met; warns about orthographic ones.
void considerCamera(const tinygltf::Model& model, int index, const glm::dmat4& toWorld,
                    Scene& scene, Diagnostics& diagnostics) {
  const tinygltf::Camera& camera = model.cameras[index];
  const std::string what = describe("camera", index, camera.name);
  if (camera.type == "orthographic") {
    diagnostics.warnOnce("orthographic cameras", "ignoring orthographic cameras (not supported)");
    return;
  }
  if (scene.camera) return;
  const tinygltf::PerspectiveCamera& perspective = camera.perspective;
  if (!(perspective.yfov > 0.0 && perspective.yfov < kPi)) {
    diagnostics.fail(what + " has yfov " + std::to_string(perspective.yfov) + ", outside (0, pi)");
  }
  // tinygltf reports an absent aspectRatio as 0.
  if (!(perspective.aspectRatio >= 0.0 && std::isfinite(perspective.aspectRatio))) {
    diagnostics.fail(what + " has an invalid aspectRatio");
  }
  CameraPlacement placement;
  placement.cameraToWorld = rigidCameraToWorld(toWorld, what, diagnostics);
  placement.yfov = static_cast<float>(perspective.yfov);
  if (perspective.aspectRatio > 0.0) {
    placement.aspectRatio = static_cast<float>(perspective.aspectRatio);
  }
  scene.camera = placement;
}

// Walks the node trees depth-first, parents before children, adding meshes and the camera.
void addNodeTrees(const tinygltf::Model& model, const std::vector<int>& roots, Scene& scene,
                  Diagnostics& diagnostics) {
  MaterialTable materials(model, scene, diagnostics);
  // An explicit stack, so that a deep hierarchy cannot overflow the call stack.
  std::vector<std::pair<int, glm::dmat4>> pending;
  for (auto root = roots.rbegin(); root != roots.rend(); ++root) {
    diagnostics.checkIndex(*root, model.nodes.size(), "the scene refers to node");
    pending.emplace_back(*root, glm::dmat4(1.0));
  }
  // A node met twice would be instanced twice, or forever if the "tree" has a cycle.
  std::vector<bool> visited(model.nodes.size(), false);
  while (!pending.empty()) {
    const auto [index, parentToWorld] = pending.back();
    pending.pop_back();
    const tinygltf::Node& node = model.nodes[index];
    const std::string what = describe("node", index, node.name);
    if (visited[index]) diagnostics.fail(what + " has two parents or is its own ancestor");
    visited[index] = true;

    const glm::dmat4 toWorld = parentToWorld * localTransform(node, what, diagnostics);
    if (node.skin >= 0) diagnostics.warnOnce("skins", "ignoring skins (not supported)");
    if (node.mesh >= 0) {
      diagnostics.checkIndex(node.mesh, model.meshes.size(), what + " refers to mesh");
      addMeshInstance(model, node.mesh, toWorld, materials, scene, diagnostics);
    }
    if (node.camera >= 0) {
      diagnostics.checkIndex(node.camera, model.cameras.size(), what + " refers to camera");
      considerCamera(model, node.camera, toWorld, scene, diagnostics);
    }
    for (auto child = node.children.rbegin(); child != node.children.rend(); ++child) {
      diagnostics.checkIndex(*child, model.nodes.size(), what + " refers to child node");
      pending.emplace_back(*child, toWorld);
    }
  }
}

// The radiance of rays that leave the scene: extras {"pathway_background": [r, g, b]}.
Color background(const tinygltf::Scene* scene, const Diagnostics& diagnostics) {
  if (scene == nullptr || !scene->extras.Has("pathway_background")) return Color(0.0f);
  const tinygltf::Value& value = scene->extras.Get("pathway_background");
  Color color(0.0f);
  bool valid = value.IsArray() && value.ArrayLen() == 3;
  for (int c = 0; valid && c < 3; ++c) {
    const tinygltf::Value& component = value.Get(c);
    color[c] = component.IsNumber() ? static_cast<float>(component.GetNumberAsDouble()) : -1.0f;
    valid = std::isfinite(color[c]) && color[c] >= 0.0f;
  }
  if (!valid) diagnostics.fail("pathway_background must be 3 finite non-negative numbers");
  return color;
}

bool isDegenerate(const Mesh& mesh, const glm::uvec3& triangle) {
  const Vec3& a = mesh.positions[triangle[0]];
  const Vec3 normal = glm::cross(mesh.positions[triangle[1]] - a, mesh.positions[triangle[2]] - a);
  return normal == Vec3(0.0f);
}

void finish(Scene& scene, Diagnostics& diagnostics) {
  if (scene.triangleCount() == 0) diagnostics.fail("the scene has no triangles");
  size_t degenerate = 0;
  for (const Mesh& mesh : scene.meshes) {
    for (const Vec3& position : mesh.positions) scene.bounds.extend(position);
    for (const glm::uvec3& triangle : mesh.triangles) degenerate += isDegenerate(mesh, triangle);
  }
  if (degenerate > 0) {
    // Kept: the renderer must cope with them, and dropping them would renumber triangles.
    diagnostics.warnOnce("degenerate triangles", "keeping " + std::to_string(degenerate) +
                                                     " degenerate (zero-area) triangles");
  }
  scene.warnings = diagnostics.warnings();
  for (const std::string& warning : scene.warnings) {
    std::cerr << "pathway: warning: " << warning << "\n";
  }
}

}  // namespace
}  // namespace gltf

Scene loadScene(const std::string& path, const SceneLoadOptions& options) {
  gltf::Diagnostics diagnostics(path);
  const tinygltf::Model model = gltf::parseFile(path, diagnostics);
  gltf::checkFileWideFeatures(model, options, diagnostics);
  const tinygltf::Scene* chosen = gltf::chooseScene(model, diagnostics);

  Scene scene;
  scene.sourcePath = path;
  gltf::addNodeTrees(model, gltf::rootNodes(model, chosen), scene, diagnostics);
  scene.background = gltf::background(chosen, diagnostics);
  try {
    resizeLights(scene, options.lightScale);
  } catch (const PathwayError& error) {
    diagnostics.fail(error.what());  // named with the file, as every load error is
  }
  gltf::finish(scene, diagnostics);
  return scene;
}

}  // namespace pathway
