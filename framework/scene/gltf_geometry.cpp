// glTF primitives to scene meshes: reading accessors (checked against their buffer views and
// buffers, since a file may lie about every size), indices, and the placement in world space.
#include <cstring>
#include <initializer_list>
#include <limits>
#include <sstream>

#include "scene/gltf_detail.h"

namespace pathway::gltf {
namespace {

using Positions = std::vector<Vec3, PaddedAllocator<Vec3>>;

std::string typeName(int type) {
  if (type == TINYGLTF_TYPE_SCALAR) return "SCALAR";
  return type <= TINYGLTF_TYPE_VEC4 ? "VEC" + std::to_string(type)
                                    : "MAT" + std::to_string(type - 32);
}

std::string componentTypeName(int componentType) {
  static const char* const kNames[] = {"BYTE", "UNSIGNED_BYTE", "SHORT", "UNSIGNED_SHORT",
                                       "INT",  "UNSIGNED_INT",  "FLOAT"};
  const int index = componentType - TINYGLTF_COMPONENT_TYPE_BYTE;
  return index >= 0 && index < 7 ? kNames[index] : std::to_string(componentType);
}

// "VEC2 of FLOAT or UNSIGNED_BYTE", in messages.
std::string layoutName(int type, std::initializer_list<int> componentTypes) {
  std::string name = typeName(type) + " of ";
  for (const int* c = componentTypes.begin(); c != componentTypes.end(); ++c) {
    name += (c == componentTypes.begin() ? "" : " or ") + componentTypeName(*c);
  }
  return name;
}

// "mode 1 (LINES)", in warnings.
std::string modeName(int mode) {
  static const char* const kNames[] = {"POINTS",    "LINES",          "LINE_LOOP",   "LINE_STRIP",
                                       "TRIANGLES", "TRIANGLE_STRIP", "TRIANGLE_FAN"};
  const bool known = mode >= 0 && mode < 7;
  return "mode " + std::to_string(mode) + " (" + (known ? kNames[mode] : "unknown") + ")";
}

std::string toString(const Vec3& v) {
  std::ostringstream out;
  out << "(" << v.x << ", " << v.y << ", " << v.z << ")";
  return out.str();
}

template <class T>
T load(const unsigned char* bytes) {
  T value;
  std::memcpy(&value, bytes, sizeof value);  // glTF data need not be aligned for T
  return value;
}

// An accessor's elements as they lie in memory: `count` elements, `stride` bytes apart.
struct Elements {
  const unsigned char* first = nullptr;
  size_t stride = 0;
  size_t count = 0;

  const unsigned char* operator[](size_t i) const { return first + i * stride; }
};

size_t saturatingAdd(size_t a, size_t b) {
  return a > std::numeric_limits<size_t>::max() - b ? std::numeric_limits<size_t>::max() : a + b;
}

// One past the last byte that `count` elements of `size` bytes, `stride` apart from `offset`,
// read; SIZE_MAX when that does not fit in size_t (a hostile count).
size_t endOfElements(size_t offset, size_t stride, size_t count, size_t size) {
  if (count == 0) return offset;
  const size_t lastOffset = saturatingAdd(offset, size);
  if (count - 1 > (std::numeric_limits<size_t>::max() - lastOffset) / stride) {
    return std::numeric_limits<size_t>::max();
  }
  return lastOffset + (count - 1) * stride;
}

// "bytes 16..64", in messages; a saturated end is a count no memory could hold.
std::string byteRange(size_t begin, size_t end) {
  const bool saturated = end == std::numeric_limits<size_t>::max();
  return "bytes " + std::to_string(begin) + ".." + (saturated ? "2^64" : std::to_string(end));
}

// Checks that an accessor exists, has one of the expected layouts, and reads only bytes its
// buffer view and buffer hold. `role` names its use, e.g. `POSITION of mesh "box" primitive 0`.
Elements locate(const tinygltf::Model& model, int index, const std::string& role, int type,
                std::initializer_list<int> componentTypes, const Diagnostics& diagnostics) {
  diagnostics.checkIndex(index, model.accessors.size(), role + " refers to accessor");
  const tinygltf::Accessor& accessor = model.accessors[index];
  const std::string label = "accessor " + std::to_string(index) + " (" + role + ")";
  if (accessor.sparse.isSparse) diagnostics.fail(label + ": sparse accessors are not supported");
  bool componentOk = false;
  for (int componentType : componentTypes) componentOk |= accessor.componentType == componentType;
  if (accessor.type != type || !componentOk) {
    diagnostics.fail(label + " is " + layoutName(accessor.type, {accessor.componentType}) +
                     ", expected " + layoutName(type, componentTypes));
  }
  if (accessor.bufferView < 0) diagnostics.fail(label + " has no bufferView");
  diagnostics.checkIndex(accessor.bufferView, model.bufferViews.size(),
                         label + " refers to bufferView");
  const tinygltf::BufferView& view = model.bufferViews[accessor.bufferView];
  const std::string viewLabel = "bufferView " + std::to_string(accessor.bufferView);
  diagnostics.checkIndex(view.buffer, model.buffers.size(), viewLabel + " refers to buffer");
  const size_t bufferSize = model.buffers[view.buffer].data.size();
  const size_t viewEnd = saturatingAdd(view.byteOffset, view.byteLength);
  if (viewEnd > bufferSize) {
    diagnostics.fail(viewLabel + " spans " + byteRange(view.byteOffset, viewEnd) + " but buffer " +
                     std::to_string(view.buffer) + " holds " + std::to_string(bufferSize) +
                     " (out of range)");
  }
  const size_t size = tinygltf::GetComponentSizeInBytes(accessor.componentType) *
                      tinygltf::GetNumComponentsInType(accessor.type);
  const size_t stride = view.byteStride != 0 ? view.byteStride : size;
  if (stride < size) {
    diagnostics.fail(viewLabel + " has byteStride " + std::to_string(stride) + ", less than the " +
                     std::to_string(size) + "-byte elements of " + label);
  }
  const size_t end = endOfElements(accessor.byteOffset, stride, accessor.count, size);
  if (end > view.byteLength) {
    diagnostics.fail(label + " reads " + byteRange(accessor.byteOffset, end) + " but its " +
                     viewLabel + " holds " + std::to_string(view.byteLength) + " (out of range)");
  }
  const unsigned char* first =
      model.buffers[view.buffer].data.data() + view.byteOffset + accessor.byteOffset;
  return Elements{first, stride, accessor.count};
}

Positions readPositions(const tinygltf::Model& model, int index, const std::string& where,
                        const Diagnostics& diagnostics) {
  const Elements elements = locate(model, index, "POSITION of " + where, TINYGLTF_TYPE_VEC3,
                                   {TINYGLTF_COMPONENT_TYPE_FLOAT}, diagnostics);
  Positions positions(elements.count);
  for (size_t i = 0; i < elements.count; ++i) {
    const unsigned char* element = elements[i];
    positions[i] = Vec3(load<float>(element), load<float>(element + 4), load<float>(element + 8));
    if (!isFinite(positions[i])) {
      diagnostics.fail(where + ": vertex " + std::to_string(i) + " has a non-finite position " +
                       toString(positions[i]));
    }
  }
  return positions;
}

// A texture coordinate component: float, or an unsigned integer normalized to [0, 1].
float loadTexcoord(const unsigned char* bytes, int componentType) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return load<uint8_t>(bytes) / 255.0f;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return load<uint16_t>(bytes) / 65535.0f;
    default:
      return load<float>(bytes);
  }
}

std::vector<Vec2> readTexcoords(const tinygltf::Model& model, int index, const std::string& where,
                                const Diagnostics& diagnostics) {
  const std::string role = "TEXCOORD_0 of " + where;
  const Elements elements =
      locate(model, index, role, TINYGLTF_TYPE_VEC2,
             {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
              TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT},
             diagnostics);
  const tinygltf::Accessor& accessor = model.accessors[index];
  const int componentType = accessor.componentType;
  if (componentType != TINYGLTF_COMPONENT_TYPE_FLOAT && !accessor.normalized) {
    diagnostics.fail("accessor " + std::to_string(index) + " (" + role +
                     ") holds integers but is not normalized");
  }
  const size_t componentSize = tinygltf::GetComponentSizeInBytes(componentType);
  std::vector<Vec2> texcoords(elements.count);
  for (size_t i = 0; i < elements.count; ++i) {
    texcoords[i] = Vec2(loadTexcoord(elements[i], componentType),
                        loadTexcoord(elements[i] + componentSize, componentType));
    if (!std::isfinite(texcoords[i].x) || !std::isfinite(texcoords[i].y)) {
      diagnostics.fail(where + ": vertex " + std::to_string(i) + " has a non-finite TEXCOORD_0");
    }
  }
  return texcoords;
}

uint32_t loadIndex(const unsigned char* bytes, int componentType) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return load<uint8_t>(bytes);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return load<uint16_t>(bytes);
    default:
      return load<uint32_t>(bytes);
  }
}

void checkTriangleCount(size_t count, const std::string& what, const std::string& where,
                        const Diagnostics& diagnostics) {
  if (count % 3 != 0) {
    diagnostics.fail(where + " has " + std::to_string(count) + " " + what +
                     ", not a multiple of 3 as TRIANGLES needs");
  }
}

std::vector<glm::uvec3> readTriangles(const tinygltf::Model& model, int index,
                                      const std::string& where, size_t vertexCount,
                                      const Diagnostics& diagnostics) {
  const Elements elements =
      locate(model, index, "indices of " + where, TINYGLTF_TYPE_SCALAR,
             {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
              TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT},
             diagnostics);
  checkTriangleCount(elements.count, "indices", where, diagnostics);
  const int componentType = model.accessors[index].componentType;
  std::vector<glm::uvec3> triangles(elements.count / 3);
  for (size_t i = 0; i < elements.count; ++i) {
    const uint32_t vertex = loadIndex(elements[i], componentType);
    if (vertex >= vertexCount) {
      diagnostics.fail(where + ": index " + std::to_string(i) + " is " + std::to_string(vertex) +
                       ", out of range for its " + std::to_string(vertexCount) + " vertices");
    }
    triangles[i / 3][i % 3] = vertex;
  }
  return triangles;
}

// Non-indexed TRIANGLES: every three consecutive vertices form a triangle.
std::vector<glm::uvec3> consecutiveTriangles(size_t vertexCount, const std::string& where,
                                             const Diagnostics& diagnostics) {
  checkTriangleCount(vertexCount, "vertices", where, diagnostics);
  if (vertexCount > std::numeric_limits<uint32_t>::max()) {
    diagnostics.fail(where + " has more vertices than 32-bit indices can address");
  }
  std::vector<glm::uvec3> triangles(vertexCount / 3);
  for (size_t t = 0; t < triangles.size(); ++t) {
    const auto first = static_cast<uint32_t>(3 * t);
    triangles[t] = glm::uvec3(first, first + 1, first + 2);
  }
  return triangles;
}

void placeInWorld(Positions& positions, const glm::dmat4& toWorld, const std::string& where,
                  const Diagnostics& diagnostics) {
  for (size_t i = 0; i < positions.size(); ++i) {
    // Double precision, so that a deep hierarchy adds no more rounding than one float store.
    positions[i] = Vec3(toWorld * glm::dvec4(glm::dvec3(positions[i]), 1.0));
    if (!isFinite(positions[i])) {
      diagnostics.fail(where + ": vertex " + std::to_string(i) +
                       " has a non-finite position in world space " + toString(positions[i]));
    }
  }
}

void warnAboutIgnoredParts(const tinygltf::Primitive& primitive, Diagnostics& diagnostics) {
  if (!primitive.targets.empty()) {
    diagnostics.warnOnce("morph targets", "ignoring morph targets (not supported)");
  }
  if (primitive.attributes.count("COLOR_0") != 0) {
    diagnostics.warnOnce("COLOR_0", "ignoring vertex colors COLOR_0 (not supported)");
  }
}

void addPrimitive(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                  const std::string& meshName, const std::string& where, const glm::dmat4& toWorld,
                  MaterialTable& materials, Scene& scene, Diagnostics& diagnostics) {
  if (primitive.mode != TINYGLTF_MODE_TRIANGLES) {
    const std::string mode = modeName(primitive.mode);
    diagnostics.warnOnce(mode, "ignoring primitive " + mode + ": only TRIANGLES is supported");
    return;
  }
  warnAboutIgnoredParts(primitive, diagnostics);
  const auto position = primitive.attributes.find("POSITION");
  if (position == primitive.attributes.end()) diagnostics.fail(where + " has no POSITION");

  Mesh mesh;
  mesh.name = meshName;
  mesh.positions = readPositions(model, position->second, where, diagnostics);
  mesh.triangles =
      primitive.indices >= 0
          ? readTriangles(model, primitive.indices, where, mesh.positions.size(), diagnostics)
          : consecutiveTriangles(mesh.positions.size(), where, diagnostics);
  if (mesh.triangles.empty()) return;

  if (primitive.material >= 0) {
    diagnostics.checkIndex(primitive.material, model.materials.size(),
                           where + " refers to material");
  }
  mesh.material = materials.sceneMaterial(primitive.material);
  if (scene.materials[mesh.material].baseColorTexture >= 0) {
    const auto texcoord = primitive.attributes.find("TEXCOORD_0");
    if (texcoord == primitive.attributes.end()) {
      diagnostics.fail(where + " has a textured material but no TEXCOORD_0");
    }
    mesh.texcoords = readTexcoords(model, texcoord->second, where, diagnostics);
    if (mesh.texcoords.size() != mesh.positions.size()) {
      diagnostics.fail(where + " has " + std::to_string(mesh.texcoords.size()) +
                       " TEXCOORD_0 values for " + std::to_string(mesh.positions.size()) +
                       " vertices");
    }
  }
  placeInWorld(mesh.positions, toWorld, where, diagnostics);
  scene.meshes.push_back(std::move(mesh));
}

}  // namespace

void addMeshInstance(const tinygltf::Model& model, int meshIndex, const glm::dmat4& toWorld,
                     MaterialTable& materials, Scene& scene, Diagnostics& diagnostics) {
  const tinygltf::Mesh& mesh = model.meshes[meshIndex];
  const std::string meshName = mesh.name.empty() ? "mesh " + std::to_string(meshIndex) : mesh.name;
  for (size_t p = 0; p < mesh.primitives.size(); ++p) {
    const std::string where =
        describe("mesh", meshIndex, mesh.name) + " primitive " + std::to_string(p);
    addPrimitive(model, mesh.primitives[p], meshName, where, toWorld, materials, scene,
                 diagnostics);
  }
}

}  // namespace pathway::gltf
