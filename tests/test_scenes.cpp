#include "test_scenes.h"

#include <glm/gtc/matrix_transform.hpp>

namespace pathway::test {

void addQuad(Scene& scene, const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3,
             uint32_t material) {
  Mesh mesh;
  mesh.name = "quad" + std::to_string(scene.meshes.size());
  mesh.positions = {p0, p1, p2, p3};
  mesh.triangles = {glm::uvec3(0, 1, 2), glm::uvec3(0, 2, 3)};
  mesh.material = material;
  scene.meshes.push_back(std::move(mesh));
}

void finishScene(Scene& scene) {
  if (scene.materials.empty()) scene.materials.push_back(Material{});
  scene.bounds = Bounds{};
  for (const Mesh& mesh : scene.meshes)
    for (const Vec3& p : mesh.positions) scene.bounds.extend(p);
  if (scene.bounds.isEmpty()) {
    scene.bounds.extend(Vec3(-1.0f));
    scene.bounds.extend(Vec3(1.0f));
  }
}

Scene openPlane(float scale, float offset, float halfSize) {
  Scene scene;
  scene.sourcePath = "open plane (test)";
  const Vec3 shift(offset);
  const float h = halfSize * scale;
  addQuad(scene, shift + Vec3(-h, 0, h), shift + Vec3(h, 0, h), shift + Vec3(h, 0, -h),
          shift + Vec3(-h, 0, -h), 0);
  CameraPlacement camera;
  camera.yfov = glm::radians(40.0f);
  camera.cameraToWorld =
      glm::inverse(glm::lookAt(shift + Vec3(0, 2, 2) * scale, shift, Vec3(0, 1, 0)));
  scene.camera = camera;
  finishScene(scene);
  return scene;
}

Scene constantScene(const Color& background) {
  Scene scene;
  scene.sourcePath = "constant (test)";
  scene.background = background;
  CameraPlacement camera;
  camera.yfov = glm::radians(40.0f);
  scene.camera = camera;
  finishScene(scene);
  return scene;
}

Scene boxRoom() {
  Scene scene;
  scene.sourcePath = "box room (test)";
  Material white;
  white.baseColor = Color(0.7f);
  Material red;
  red.baseColor = Color(0.7f, 0.1f, 0.1f);
  Material light;
  light.baseColor = Color(0.5f);
  light.emission = Color(5.0f);
  scene.materials = {white, red, light};
  const float s = 1.0f;
  // Room walls, front faces inward.
  addQuad(scene, {-s, -s, -s}, {s, -s, -s}, {s, -s, s}, {-s, -s, s}, 0);  // floor, up
  addQuad(scene, {-s, s, -s}, {-s, s, s}, {s, s, s}, {s, s, -s}, 0);      // ceiling, down
  addQuad(scene, {-s, -s, -s}, {-s, s, -s}, {s, s, -s}, {s, -s, -s}, 0);  // back, +z
  addQuad(scene, {-s, -s, -s}, {-s, -s, s}, {-s, s, s}, {-s, s, -s}, 1);  // left, +x
  addQuad(scene, {s, -s, -s}, {s, s, -s}, {s, s, s}, {s, -s, s}, 0);      // right, -x
  // A block on the floor (only its visible sides matter).
  addQuad(scene, {-0.3f, -0.2f, -0.3f}, {-0.3f, -0.2f, 0.3f}, {0.3f, -0.2f, 0.3f},
          {0.3f, -0.2f, -0.3f}, 0);  // top, up
  addQuad(scene, {-0.3f, -s, 0.3f}, {0.3f, -s, 0.3f}, {0.3f, -0.2f, 0.3f}, {-0.3f, -0.2f, 0.3f},
          0);  // front, +z
  // Light patch just under the ceiling, facing down.
  const float l = 0.25f, y = s - 1e-3f;
  addQuad(scene, {-l, y, -l}, {-l, y, l}, {l, y, l}, {l, y, -l}, 2);
  CameraPlacement camera;
  camera.yfov = glm::radians(60.0f);
  camera.cameraToWorld =
      glm::inverse(glm::lookAt(Vec3(0, 0, 0.95f * s), Vec3(0, -0.3f, 0), Vec3(0, 1, 0)));
  scene.camera = camera;
  finishScene(scene);
  return scene;
}

Scene smallLight(float side) {
  Scene scene;
  scene.sourcePath = "small light (test)";
  Material floor;
  floor.baseColor = Color(0.5f);
  Material light;
  light.baseColor = Color(0.0f);
  light.emission = Color(1.0f / (kPi * side * side));
  scene.materials = {floor, light};
  addQuad(scene, {-50, 0, 30}, {50, 0, 30}, {50, 0, -70}, {-50, 0, -70}, 0);
  const float h = 0.5f * side;
  addQuad(scene, {-h, 1, -h}, {h, 1, -h}, {h, 1, h}, {-h, 1, h}, 1);  // facing down
  CameraPlacement camera;
  camera.yfov = 0.7f;
  camera.cameraToWorld = glm::inverse(glm::lookAt(Vec3(0, 0.6f, 1.5f), Vec3(0), Vec3(0, 1, 0)));
  scene.camera = camera;
  finishScene(scene);
  return scene;
}

}  // namespace pathway::test
