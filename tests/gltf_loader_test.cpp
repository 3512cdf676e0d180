// The glTF loader against the files in tests/data/gltf (written by make_cases.py), the course
// scenes, and a few small files written on the fly for cases those do not cover. Every expected
// value comes from the files' construction (make_cases.py's comments), not from the loader.
#include "scene/gltf_loader.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/error.h"

namespace pathway {
namespace {

const std::string kCases = std::string(PATHWAY_TEST_DATA_DIR) + "/gltf/";
const std::string kScenes = std::string(PATHWAY_SCENES_DIR) + "/";

// make_cases.py's unit quad and its two triangles.
const std::vector<Vec3> kQuad = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
const std::vector<glm::uvec3> kQuadTriangles = {{0, 1, 2}, {0, 2, 3}};

void expectNear(const Vec3& actual, const Vec3& expected, float tolerance = 1e-5f) {
  EXPECT_NEAR(actual.x, expected.x, tolerance);
  EXPECT_NEAR(actual.y, expected.y, tolerance);
  EXPECT_NEAR(actual.z, expected.z, tolerance);
}

// The world-space corners of every triangle of the scene, in order.
std::vector<Vec3> triangleCorners(const Scene& scene) {
  std::vector<Vec3> corners;
  for (const Mesh& mesh : scene.meshes) {
    for (const glm::uvec3& triangle : mesh.triangles) {
      for (int i = 0; i < 3; ++i) corners.push_back(mesh.positions[triangle[i]]);
    }
  }
  return corners;
}

std::vector<Vec3> quadCorners() {
  std::vector<Vec3> corners;
  for (const glm::uvec3& triangle : kQuadTriangles) {
    for (int i = 0; i < 3; ++i) corners.push_back(kQuad[triangle[i]]);
  }
  return corners;
}

// The "positions" of a hierarchy_*.expected.json: one [x, y, z] per vertex.
std::vector<Vec3> readExpectedPositions(const std::string& path) {
  std::ifstream file(path);
  const nlohmann::json expected = nlohmann::json::parse(file);
  std::vector<Vec3> positions;
  for (const nlohmann::json& p : expected.at("positions"))
    positions.emplace_back(p.at(0).get<float>(), p.at(1).get<float>(), p.at(2).get<float>());
  return positions;
}

float srgbToLinear(float encoded) {
  return encoded <= 0.04045f ? encoded / 12.92f : std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

// The directory for files written on the fly: one per test process, removed at exit.
const std::filesystem::path& scratchDirectory() {
  static const struct Scratch {
    std::filesystem::path path = std::filesystem::temp_directory_path() /
                                 ("pathway_gltf_test_" + std::to_string(::getpid()));
    Scratch() { std::filesystem::create_directories(path); }
    ~Scratch() {
      std::error_code ignored;
      std::filesystem::remove_all(path, ignored);
    }
  } scratch;
  return scratch.path;
}

// Writes <name>.gltf (with <name>.bin): the unit quad as mesh 0 with `indices`. `nodes` is the
// nodes array; `extra` (top-level members) and `primitiveExtra` (members of the quad's
// primitive) are spliced in, each member led by a comma.
std::string writeQuadFile(const std::string& name, const std::string& nodes,
                          const std::string& extra = "",
                          const std::vector<uint32_t>& indices = {0, 1, 2, 0, 2, 3},
                          const std::string& primitiveExtra = "") {
  const std::filesystem::path gltfPath = scratchDirectory() / (name + ".gltf");
  std::ofstream bin(scratchDirectory() / (name + ".bin"), std::ios::binary);
  bin.write(reinterpret_cast<const char*>(kQuad.data()), kQuad.size() * sizeof(Vec3));
  bin.write(reinterpret_cast<const char*>(indices.data()), indices.size() * sizeof(uint32_t));
  const size_t indexBytes = indices.size() * sizeof(uint32_t);
  std::ofstream(gltfPath) << R"({"asset": {"version": "2.0"}, "nodes": )" << nodes << R"(,
    "meshes": [{"name": "quad", "primitives": [{"attributes": {"POSITION": 0}, "indices": 1)"
                          << primitiveExtra << R"(}]}],
    "buffers": [{"uri": ")"
                          << name << R"(.bin", "byteLength": )" << 48 + indexBytes << R"(}],
    "bufferViews": [{"buffer": 0, "byteLength": 48},
                    {"buffer": 0, "byteOffset": 48, "byteLength": )"
                          << indexBytes << R"(}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3"},
                  {"bufferView": 1, "componentType": 5125, "count": )"
                          << indices.size() << R"(, "type": "SCALAR"}])" << extra << "}";
  return gltfPath.string();
}

// Loads `path`, expecting a PathwayError; returns its message.
std::string loadError(const std::string& path, const SceneLoadOptions& options = {}) {
  try {
    loadScene(path, options);
  } catch (const PathwayError& error) {
    return error.what();
  }
  ADD_FAILURE() << path << " loaded without an error";
  return "";
}

// --- Every valid case loads with its triangle count -------------------------------------------

struct ValidCase {
  const char* file;
  size_t triangles;
};

void PrintTo(const ValidCase& c, std::ostream* out) {
  *out << c.file;
}

class GltfValidCase : public testing::TestWithParam<ValidCase> {};

TEST_P(GltfValidCase, LoadsWithItsTriangleCount) {
  const Scene scene = loadScene(kCases + GetParam().file);
  EXPECT_EQ(scene.triangleCount(), GetParam().triangles);
  EXPECT_FALSE(scene.bounds.isEmpty());
}

INSTANTIATE_TEST_SUITE_P(
    Gltf, GltfValidCase,
    testing::Values(ValidCase{"external_buffer.gltf", 2}, ValidCase{"embedded_buffer.gltf", 2},
                    ValidCase{"binary.glb", 1}, ValidCase{"indices_u8.gltf", 2},
                    ValidCase{"indices_u16.gltf", 2}, ValidCase{"indices_u32.gltf", 2},
                    ValidCase{"non_indexed.gltf", 2}, ValidCase{"interleaved.gltf", 2},
                    ValidCase{"hierarchy_trs.gltf", 1}, ValidCase{"hierarchy_matrix.gltf", 1},
                    ValidCase{"camera.gltf", 2}, ValidCase{"emissive_strength.gltf", 2},
                    ValidCase{"unsupported_features.gltf", 2}, ValidCase{"required_lamp.gltf", 2}),
    [](const testing::TestParamInfo<ValidCase>& info) {
      std::string name = info.param.file;
      for (char& c : name) c = std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
      return name;
    });

// --- Geometry ---------------------------------------------------------------------------------

TEST(GltfGeometry, EveryBufferKindAndIndexTypeGivesTheSameQuad) {
  for (const char* file : {"external_buffer.gltf", "embedded_buffer.gltf", "indices_u8.gltf",
                           "indices_u16.gltf", "indices_u32.gltf", "interleaved.gltf"}) {
    SCOPED_TRACE(file);
    const Scene scene = loadScene(kCases + file);
    ASSERT_EQ(scene.meshes.size(), 1u);
    const Mesh& mesh = scene.meshes[0];
    EXPECT_EQ(mesh.name, "quad");
    ASSERT_EQ(mesh.positions.size(), kQuad.size());
    for (size_t i = 0; i < kQuad.size(); ++i) expectNear(mesh.positions[i], kQuad[i], 0.0f);
    EXPECT_EQ(mesh.triangles, kQuadTriangles);
  }
}

TEST(GltfGeometry, GlbHoldsTheRightTriangle) {
  const Scene scene = loadScene(kCases + "binary.glb");
  const std::vector<Vec3> corners = triangleCorners(scene);
  ASSERT_EQ(corners.size(), 3u);
  expectNear(corners[0], {0, 0, 0});
  expectNear(corners[1], {1, 0, 0});
  expectNear(corners[2], {0, 1, 0});
}

TEST(GltfGeometry, NonIndexedPrimitivesUseConsecutiveTriples) {
  const Scene scene = loadScene(kCases + "non_indexed.gltf");
  const std::vector<Vec3> corners = triangleCorners(scene);
  const std::vector<Vec3> expected = quadCorners();
  ASSERT_EQ(corners.size(), expected.size());
  for (size_t i = 0; i < corners.size(); ++i) expectNear(corners[i], expected[i], 0.0f);
}

TEST(GltfGeometry, InterleavedTexcoordsAreReadWithTheStride) {
  const Scene scene = loadScene(kCases + "interleaved.gltf");
  const Mesh& mesh = scene.meshes.at(0);
  ASSERT_EQ(mesh.texcoords.size(), kQuad.size());
  for (size_t i = 0; i < kQuad.size(); ++i) {
    EXPECT_EQ(mesh.texcoords[i], Vec2(kQuad[i].x, 1.0f - kQuad[i].y)) << "vertex " << i;
  }
}

TEST(GltfGeometry, TexcoordsAreKeptOnlyForTexturedMaterials) {
  const Scene scene = loadScene(kCases + "embedded_buffer.gltf");
  EXPECT_TRUE(scene.meshes.at(0).texcoords.empty());
  EXPECT_TRUE(scene.textures.empty());
}

TEST(GltfGeometry, TrsHierarchyIsFlattenedIntoWorldSpace) {
  const Scene scene = loadScene(kCases + "hierarchy_trs.gltf");
  const std::vector<Vec3> expected = readExpectedPositions(kCases + "hierarchy_trs.expected.json");
  // Also written out, from T(1,2,3) R_y(90) S(2) T(1,0,0), so a broken sidecar cannot hide a bug.
  ASSERT_EQ(expected, (std::vector<Vec3>{{1, 2, 1}, {1, 2, -1}, {1, 4, 1}}));
  const std::vector<Vec3> corners = triangleCorners(scene);
  ASSERT_EQ(corners.size(), 3u);
  for (size_t i = 0; i < 3; ++i) expectNear(corners[i], expected[i]);
}

TEST(GltfGeometry, MatrixHierarchyIsFlattenedIntoWorldSpace) {
  const Scene scene = loadScene(kCases + "hierarchy_matrix.gltf");
  const std::vector<Vec3> expected =
      readExpectedPositions(kCases + "hierarchy_matrix.expected.json");
  ASSERT_EQ(expected, (std::vector<Vec3>{{1, 2, 1}, {1, 2, -1}, {1, 4, 1}}));
  const std::vector<Vec3> corners = triangleCorners(scene);
  ASSERT_EQ(corners.size(), 3u);
  for (size_t i = 0; i < 3; ++i) expectNear(corners[i], expected[i]);
}

TEST(GltfGeometry, MeshesOfSeveralNodesAreInstancedByCopying) {
  const std::string path =
      writeQuadFile("instances", R"([{"mesh": 0}, {"mesh": 0, "translation": [0, 0, 5]}])");
  const Scene scene = loadScene(path);
  ASSERT_EQ(scene.meshes.size(), 2u);
  expectNear(scene.meshes[1].positions[2], {1, 1, 5});
  expectNear(scene.bounds.lower, {0, 0, 0});
  expectNear(scene.bounds.upper, {1, 1, 5});
}

TEST(GltfGeometry, DegenerateTrianglesAreKeptWithOneWarning) {
  // Two zero-area triangles, each repeating a vertex, between two good ones.
  const std::string path =
      writeQuadFile("degenerate", R"([{"mesh": 0}])", "", {0, 1, 2, 0, 0, 1, 2, 2, 3, 0, 2, 3});
  const Scene scene = loadScene(path);
  EXPECT_EQ(scene.triangleCount(), 4u);
  ASSERT_EQ(scene.warnings.size(), 1u);
  EXPECT_NE(scene.warnings[0].find("2 degenerate"), std::string::npos) << scene.warnings[0];
}

// --- Camera, materials, textures, background ----------------------------------------------

TEST(GltfCamera, PerspectiveCameraIsPlacedByItsNode) {
  const Scene scene = loadScene(kCases + "camera.gltf");
  ASSERT_TRUE(scene.camera.has_value());
  EXPECT_FLOAT_EQ(scene.camera->yfov, 0.8f);
  ASSERT_TRUE(scene.camera->aspectRatio.has_value());
  EXPECT_FLOAT_EQ(*scene.camera->aspectRatio, 1.5f);
  EXPECT_EQ(scene.camera->cameraToWorld, glm::translate(glm::mat4(1.0f), Vec3(0, 1, 5)));
}

TEST(GltfCamera, ScaleIsRemovedAndOrthographicCamerasAreIgnored) {
  const std::string path = writeQuadFile("cameras",
                                         R"([{"mesh": 0}, {"camera": 0}, {"camera": 0},
          {"camera": 1, "translation": [1, 2, 3], "rotation": [0, 0.70710678, 0, 0.70710678],
           "scale": [2, 3, 4]}])",
                                         R"(, "scenes": [{"nodes": [0, 1, 2, 3]}],
      "cameras": [{"type": "orthographic", "orthographic": {"xmag": 1, "ymag": 1, "znear": 0.1, "zfar": 9}},
                  {"type": "perspective", "perspective": {"yfov": 0.5, "znear": 0.1}}])");
  const Scene scene = loadScene(path);
  ASSERT_TRUE(scene.camera.has_value());
  EXPECT_FLOAT_EQ(scene.camera->yfov, 0.5f);
  EXPECT_FALSE(scene.camera->aspectRatio.has_value());
  // T(1,2,3) R_y(90 degrees), without the scale: R_y maps x to -z, y to y, z to x.
  const glm::mat4 expected(0, 0, -1, 0, 0, 1, 0, 0, 1, 0, 0, 0, 1, 2, 3, 1);
  for (int column = 0; column < 4; ++column) {
    expectNear(Vec3(scene.camera->cameraToWorld[column]), Vec3(expected[column]));
    EXPECT_EQ(scene.camera->cameraToWorld[column].w, expected[column].w);
  }
  ASSERT_EQ(scene.warnings.size(), 1u);
  EXPECT_NE(scene.warnings[0].find("orthographic"), std::string::npos);
}

TEST(GltfCamera, NoCameraLeavesItEmpty) {
  EXPECT_FALSE(loadScene(kCases + "embedded_buffer.gltf").camera.has_value());
}

TEST(GltfMaterials, EmissiveStrengthScalesEmissionAndDoubleSidedIsRead) {
  const Scene scene = loadScene(kCases + "emissive_strength.gltf");
  ASSERT_EQ(scene.meshes.size(), 2u);
  const Material& emitter = scene.materials.at(scene.meshes[0].material);
  const Material& plain = scene.materials.at(scene.meshes[1].material);
  EXPECT_EQ(emitter.emission, Color(4.0f, 2.0f, 1.0f));
  EXPECT_TRUE(emitter.doubleSided);
  EXPECT_EQ(plain.emission, Color(1.0f, 0.5f, 0.25f));
  EXPECT_FALSE(plain.doubleSided);
  EXPECT_EQ(plain.baseColor, Color(0.5f));
  EXPECT_TRUE(scene.warnings.empty());
}

TEST(GltfMaterials, PrimitivesWithoutMaterialAreWhite) {
  const Scene scene = loadScene(writeQuadFile("default_material", R"([{"mesh": 0}])"));
  const Material& material = scene.materials.at(scene.meshes.at(0).material);
  EXPECT_EQ(material.baseColor, Color(1.0f));
  EXPECT_FALSE(material.isEmissive());
  EXPECT_EQ(material.baseColorTexture, -1);
}

TEST(GltfMaterials, TextureTexelsAreConvertedFromSrgb) {
  // scenes/generate.py's checkerboard: 4x4, texel (0, 0) sRGB 255, its neighbours sRGB 128.
  for (const std::string& path : {kCases + "interleaved.gltf", kScenes + "textured_quad.gltf"}) {
    SCOPED_TRACE(path);
    const Scene scene = loadScene(path);
    const Material& material = scene.materials.at(scene.meshes.at(0).material);
    ASSERT_GE(material.baseColorTexture, 0);
    const Texture& texture = scene.textures.at(material.baseColorTexture);
    ASSERT_EQ(texture.width, 4);
    ASSERT_EQ(texture.height, 4);
    EXPECT_EQ(texture.texels[0], Color(1.0f));
    const float dark = srgbToLinear(128.0f / 255.0f);
    EXPECT_NEAR(dark, 0.2158605f, 1e-6f);
    EXPECT_NEAR(texture.texels[1].x, dark, 1e-6f);
    EXPECT_NEAR(texture.texels[4].y, dark, 1e-6f);
    EXPECT_EQ(texture.texels[5], Color(1.0f));
  }
}

TEST(GltfScenes, CourseScenesLoad) {
  const Scene cornell = loadScene(kScenes + "cornell_box.gltf");
  EXPECT_EQ(cornell.triangleCount(), 32u);
  EXPECT_TRUE(cornell.camera.has_value());
  EXPECT_TRUE(cornell.warnings.empty());
  const Scene textured = loadScene(kScenes + "textured_quad.gltf");
  EXPECT_EQ(textured.triangleCount(), 2u);
  EXPECT_EQ(textured.background, Color(1.0f));  // its extras.pathway_background
}

// Each light's power is its radiance × area × π (one-sided Lambertian): resizing at fixed power
// keeps radiance × area, and moves nothing else.
TEST(GltfScenes, LightScaleResizesEachLightAboutItsCentreAtFixedPower) {
  const Scene original = loadScene(kScenes + "cornell_box.gltf");
  SceneLoadOptions quarter;
  quarter.lightScale = 0.25f;
  const Scene resized = loadScene(kScenes + "cornell_box.gltf", quarter);
  auto area = [](const Mesh& mesh) {
    double sum = 0.0;
    for (const glm::uvec3& t : mesh.triangles)
      sum += 0.5 * glm::length(glm::cross(mesh.positions[t.y] - mesh.positions[t.x],
                                          mesh.positions[t.z] - mesh.positions[t.x]));
    return sum;
  };
  auto centre = [](const Mesh& mesh) {
    Bounds bounds;
    for (const Vec3& p : mesh.positions) bounds.extend(p);
    return bounds.center();
  };
  int lights = 0;
  ASSERT_EQ(original.meshes.size(), resized.meshes.size());
  for (size_t i = 0; i < original.meshes.size(); ++i) {
    const Mesh& before = original.meshes[i];
    const Mesh& after = resized.meshes[i];
    const Material& materialBefore = original.materials[before.material];
    const Material& materialAfter = resized.materials[after.material];
    if (!materialBefore.isEmissive()) {
      EXPECT_EQ(std::vector<Vec3>(before.positions.begin(), before.positions.end()),
                std::vector<Vec3>(after.positions.begin(), after.positions.end()))
          << before.name;
      EXPECT_EQ(materialBefore.emission, materialAfter.emission);
      continue;
    }
    ++lights;
    EXPECT_NEAR(area(after), area(before) / 16.0, 1e-6 * area(before)) << before.name;
    EXPECT_NEAR(glm::length(centre(after) - centre(before)), 0.0, 1e-5) << before.name;
    EXPECT_NEAR(materialAfter.emission.y * area(after), materialBefore.emission.y * area(before),
                1e-4 * materialBefore.emission.y * area(before))
        << before.name;
  }
  EXPECT_EQ(lights, 1);
  SceneLoadOptions none;
  none.lightScale = 0.0f;
  EXPECT_NE(loadError(kScenes + "cornell_box.gltf", none).find("positive and finite"),
            std::string::npos);
}

TEST(GltfScenes, BackgroundMustBeThreeNonNegativeNumbers) {
  const auto withBackground = [](const std::string& name, const std::string& value) {
    return writeQuadFile(
        name, R"([{"mesh": 0}])",
        R"(, "scenes": [{"nodes": [0], "extras": {"pathway_background": )" + value + "}}]");
  };
  EXPECT_EQ(loadScene(withBackground("background", "[0.25, 0.5, 2]")).background,
            Color(0.25f, 0.5f, 2.0f));
  for (const char* bad : {"[1, -1, 0]", "[1, 1]", "\"white\""}) {
    const std::string message = loadError(withBackground("bad_background", bad));
    EXPECT_NE(message.find("pathway_background"), std::string::npos) << message;
  }
}

// --- Warnings -------------------------------------------------------------------------------

TEST(GltfWarnings, EachUnsupportedFeatureIsNamedExactlyOnce) {
  const std::string path = kCases + "unsupported_features.gltf";
  testing::internal::CaptureStderr();
  const Scene scene = loadScene(path);
  const std::string printed = testing::internal::GetCapturedStderr();

  const std::vector<std::string> features = {"normalTexture", "animations", "skins",
                                             "KHR_lights_punctual", "LINES"};
  EXPECT_EQ(scene.warnings.size(), features.size());
  for (const std::string& feature : features) {
    int naming = 0;
    for (const std::string& warning : scene.warnings)
      naming += warning.find(feature) != std::string::npos;
    EXPECT_EQ(naming, 1) << feature;
  }
  for (const std::string& warning : scene.warnings) {
    EXPECT_EQ(warning.rfind(path + ": ", 0), 0u) << warning;
    EXPECT_NE(printed.find("pathway: warning: " + warning + "\n"), std::string::npos) << warning;
  }
}

TEST(GltfWarnings, IgnoredMaterialFeaturesAreNamed) {
  // metallicFactor defaults to 1; a baseColorTexture on TEXCOORD_1 is dropped, not misapplied.
  const std::string path =
      writeQuadFile("material_features", R"([{"mesh": 0}])",
                    R"(, "materials": [{"alphaMode": "MASK", "emissiveTexture": {"index": 0},
                          "pbrMetallicRoughness": {"baseColorTexture": {"index": 0, "texCoord": 1}}}])",
                    {0, 1, 2, 0, 2, 3}, R"(, "material": 0)");
  const Scene scene = loadScene(path);
  EXPECT_EQ(scene.materials.at(scene.meshes.at(0).material).baseColorTexture, -1);
  EXPECT_TRUE(scene.textures.empty());
  ASSERT_EQ(scene.warnings.size(), 4u);
  for (const char* feature :
       {"emissiveTexture", "metallicFactor", "alphaMode MASK", "texCoord 1"}) {
    int naming = 0;
    for (const std::string& warning : scene.warnings)
      naming += warning.find(feature) != std::string::npos;
    EXPECT_EQ(naming, 1) << feature;
  }
}

TEST(GltfWarnings, RequiredLampsLoadWithOneWarningNamingThem) {
  // Blender's export: extensionsUsed and extensionsRequired both list KHR_lights_punctual.
  const std::string path = kCases + "required_lamp.gltf";
  testing::internal::CaptureStderr();
  const Scene scene = loadScene(path);
  const std::string printed = testing::internal::GetCapturedStderr();

  ASSERT_EQ(scene.meshes.size(), 1u);
  const Mesh& mesh = scene.meshes[0];
  ASSERT_EQ(mesh.positions.size(), kQuad.size());
  for (size_t i = 0; i < kQuad.size(); ++i) expectNear(mesh.positions[i], kQuad[i], 0.0f);
  EXPECT_EQ(mesh.triangles, kQuadTriangles);
  EXPECT_FALSE(scene.camera.has_value());

  // One warning, although the file lists the extension twice and has a lamp.
  ASSERT_EQ(scene.warnings.size(), 1u);
  const std::string& warning = scene.warnings[0];
  EXPECT_EQ(warning.rfind(path + ": ", 0), 0u) << warning;
  for (const char* part : {"1 KHR_lights_punctual lamp (\"Light\")", "emissive meshes",
                           "emissiveFactor", "KHR_materials_emissive_strength"}) {
    EXPECT_NE(warning.find(part), std::string::npos) << part << " in " << warning;
  }
  EXPECT_EQ(printed, "pathway: warning: " + warning + "\n");
}

TEST(GltfWarnings, UnnamedLampsAreNamedByTypeAndIndex) {
  const std::string path = writeQuadFile("lamps", R"([{"mesh": 0}])",
                                         R"(, "extensionsRequired": ["KHR_lights_punctual"],
      "extensionsUsed": ["KHR_lights_punctual"],
      "extensions": {"KHR_lights_punctual": {"lights": [
          {"name": "Key", "type": "directional"},
          {"type": "spot", "spot": {}}]}})");
  const Scene scene = loadScene(path);
  ASSERT_EQ(scene.warnings.size(), 1u);
  EXPECT_NE(scene.warnings[0].find("2 KHR_lights_punctual lamps (\"Key\", spot light 1)"),
            std::string::npos)
      << scene.warnings[0];
}

TEST(GltfWarnings, StrictLoadingStillIgnoresLampsThatAreNotRequired) {
  const Scene scene = loadScene(kCases + "unsupported_features.gltf", {/*strict=*/true});
  EXPECT_EQ(scene.triangleCount(), 2u);
  int naming = 0;
  for (const std::string& warning : scene.warnings)
    naming += warning.find("KHR_lights_punctual") != std::string::npos;
  EXPECT_EQ(naming, 1);
}

// --- Malformed files ------------------------------------------------------------------------

struct MalformedCase {
  std::string file;
  std::string problem;  // a word or phrase the message must contain
};

void PrintTo(const MalformedCase& c, std::ostream* out) {
  *out << c.file;
}

class GltfMalformedCase : public testing::TestWithParam<MalformedCase> {};

TEST_P(GltfMalformedCase, ThrowsNamingTheFileAndTheProblem) {
  const std::string path = kCases + GetParam().file;
  const std::string message = loadError(path);
  EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
  EXPECT_NE(message.find(GetParam().problem), std::string::npos) << message;
}

INSTANTIATE_TEST_SUITE_P(
    Gltf, GltfMalformedCase,
    testing::Values(MalformedCase{"bad_json.gltf", "parse error"},
                    MalformedCase{"accessor_out_of_range.gltf", "reads bytes 0..60"},
                    MalformedCase{"index_out_of_range.gltf", "out of range for its 4 vertices"},
                    MalformedCase{"nan_positions.gltf", "vertex 2 has a non-finite position"},
                    MalformedCase{"no_triangles.gltf", "no triangles"},
                    MalformedCase{"missing_buffer.gltf", "missing_buffer.bin"},
                    MalformedCase{"sparse_accessor.gltf", "sparse accessors are not supported"},
                    MalformedCase{"required_extension.gltf", "KHR_draco_mesh_compression"}),
    [](const testing::TestParamInfo<MalformedCase>& info) {
      return info.param.file.substr(0, info.param.file.find('.'));
    });

TEST(GltfErrors, StrictLoadingRefusesRequiredLamps) {
  const std::string path = kCases + "required_lamp.gltf";
  testing::internal::CaptureStderr();
  const std::string message = loadError(path, {/*strict=*/true});
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
  EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
  EXPECT_NE(message.find("requires extension KHR_lights_punctual"), std::string::npos) << message;
  EXPECT_NE(message.find("without --strict"), std::string::npos) << message;
}

TEST(GltfErrors, OtherRequiredExtensionsAreRefusedInBothModes) {
  const std::string path = kCases + "required_extension.gltf";
  for (const bool strict : {false, true}) {
    SCOPED_TRACE(strict ? "strict" : "default");
    const std::string message = loadError(path, {strict});
    EXPECT_NE(message.find("requires extension KHR_draco_mesh_compression"), std::string::npos)
        << message;
    EXPECT_EQ(message.find("--strict"), std::string::npos) << message;
  }
}

TEST(GltfErrors, MissingFileIsNamed) {
  const std::string path = kCases + "does_not_exist.gltf";
  EXPECT_EQ(loadError(path), path + ": no such file");
}

TEST(GltfErrors, NodeCyclesFailInsteadOfLooping) {
  const std::string path =
      writeQuadFile("cycle", R"([{"mesh": 0, "children": [1]}, {"children": [0]}])",
                    R"(, "scenes": [{"nodes": [0]}])");
  EXPECT_NE(loadError(path).find("node 0"), std::string::npos);
}

TEST(GltfErrors, NothingIsPrintedWhenTheLoadFails) {
  // A warning (the extension) comes before the error (index 7 of 4 vertices).
  const std::string path =
      writeQuadFile("warn_then_fail", R"([{"mesh": 0}])",
                    R"(, "extensionsUsed": ["KHR_lights_punctual"])", {0, 1, 2, 0, 2, 7});
  testing::internal::CaptureStderr();
  EXPECT_NE(loadError(path).find("out of range"), std::string::npos);
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
}

}  // namespace
}  // namespace pathway
