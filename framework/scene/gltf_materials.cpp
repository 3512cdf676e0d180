// glTF materials to the course's model: Lambertian albedo (baseColorFactor x baseColorTexture),
// emission, double-sidedness. Everything else a glTF material can say is reported, once.
#include <array>
#include <cmath>
#include <cstring>

#include "scene/gltf_detail.h"

namespace pathway::gltf {
namespace {

constexpr const char* kEmissiveStrength = "KHR_materials_emissive_strength";
constexpr const char* kTextureTransform = "KHR_texture_transform";

// The exact sRGB EOTF (IEC 61966-2-1): encoded value in [0, 1] to linear.
float srgbToLinear(float encoded) {
  return encoded <= 0.04045f ? encoded / 12.92f : std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

const std::array<float, 256>& srgb8ToLinear() {
  static const std::array<float, 256> table = [] {
    std::array<float, 256> values{};
    for (int i = 0; i < 256; ++i) values[i] = srgbToLinear(i / 255.0f);
    return values;
  }();
  return table;
}

// Channel `channel` of texel `texel`, decoded to linear.
float linearChannel(const tinygltf::Image& image, size_t texel, int channel) {
  const size_t i = texel * image.component + channel;
  if (image.bits == 8) return srgb8ToLinear()[image.image[i]];
  uint16_t value;  // stb_image stores 16-bit channels in native byte order
  std::memcpy(&value, &image.image[2 * i], sizeof value);
  return srgbToLinear(value / 65535.0f);
}

Texture decodeTexture(const tinygltf::Image& image, const std::string& name,
                      Diagnostics& diagnostics) {
  const bool decoded = image.width > 0 && image.height > 0 && image.component >= 1 &&
                       image.component <= 4 && (image.bits == 8 || image.bits == 16) &&
                       image.image.size() == static_cast<size_t>(image.width) * image.height *
                                                 image.component * (image.bits / 8);
  if (!decoded) diagnostics.fail(name + " could not be loaded or decoded");
  if (image.bits == 16) {
    diagnostics.warnOnce("16-bit images",
                         "reading 16-bit " + name + " as 16-bit sRGB values (glTF expects 8-bit)");
  }
  Texture texture;
  texture.width = image.width;
  texture.height = image.height;
  texture.texels.resize(static_cast<size_t>(image.width) * image.height);
  // Grey (+ alpha) images repeat their one colour channel; alpha is never used.
  const bool grey = image.component < 3;
  for (size_t t = 0; t < texture.texels.size(); ++t) {
    for (int c = 0; c < 3; ++c) texture.texels[t][c] = linearChannel(image, t, grey ? 0 : c);
  }
  return texture;
}

// A colour factor from the file: `size` numbers (the rgb part is returned), each finite, not
// negative, and at most 1 when `atMostOne`.
Color colorFactor(const std::vector<double>& values, size_t size, bool atMostOne,
                  const std::string& what, const Diagnostics& diagnostics) {
  if (values.size() != size) {
    diagnostics.fail(what + " has " + std::to_string(values.size()) + " numbers instead of " +
                     std::to_string(size));
  }
  for (double value : values) {
    if (!std::isfinite(value) || value < 0.0 || (atMostOne && value > 1.0)) {
      diagnostics.fail(what + " holds " + std::to_string(value) + ", outside " +
                       (atMostOne ? "[0, 1]" : "the finite non-negative numbers"));
    }
  }
  return Color(values[0], values[1], values[2]);
}

float emissiveStrength(const tinygltf::Material& material, const std::string& what,
                       const Diagnostics& diagnostics) {
  const auto extension = material.extensions.find(kEmissiveStrength);
  if (extension == material.extensions.end() || !extension->second.Has("emissiveStrength")) {
    return 1.0f;
  }
  const tinygltf::Value& strength = extension->second.Get("emissiveStrength");
  const double value = strength.IsNumber() ? strength.GetNumberAsDouble() : -1.0;
  if (!(value >= 0.0 && std::isfinite(value))) {
    diagnostics.fail(what + ": emissiveStrength must be a finite non-negative number");
  }
  return static_cast<float>(value);
}

// glTF's material for primitives without one: white, not emissive, one-sided.
Material defaultMaterial() {
  Material material;
  material.name = "default";
  return material;
}

void warnAboutIgnoredParts(const tinygltf::Material& material, Diagnostics& diagnostics) {
  const std::pair<const char*, int> textures[] = {
      {"normalTexture", material.normalTexture.index},
      {"occlusionTexture", material.occlusionTexture.index},
      {"emissiveTexture", material.emissiveTexture.index},
      {"metallicRoughnessTexture", material.pbrMetallicRoughness.metallicRoughnessTexture.index},
  };
  for (const auto& [name, index] : textures) {
    if (index >= 0)
      diagnostics.warnOnce(name, std::string("ignoring ") + name + " (not supported)");
  }
  if (material.pbrMetallicRoughness.metallicFactor != 0.0) {
    diagnostics.warnOnce("metallicFactor",
                         "ignoring metallicFactor (materials are Lambertian, as if it were 0)");
  }
  if (material.alphaMode != "OPAQUE") {
    diagnostics.warnOnce("alphaMode " + material.alphaMode,
                         "ignoring alphaMode " + material.alphaMode + " (materials are opaque)");
  }
  if (material.pbrMetallicRoughness.baseColorFactor.size() == 4 &&
      material.pbrMetallicRoughness.baseColorFactor[3] < 1.0) {
    diagnostics.warnOnce("baseColorFactor alpha",
                         "ignoring baseColorFactor alpha below 1 (materials are opaque)");
  }
}

}  // namespace

uint32_t MaterialTable::sceneMaterial(int gltfMaterial) {
  const auto known = materials_.find(gltfMaterial);
  if (known != materials_.end()) return known->second;
  scene_.materials.push_back(gltfMaterial >= 0 ? convertMaterial(gltfMaterial) : defaultMaterial());
  const auto index = static_cast<uint32_t>(scene_.materials.size() - 1);
  materials_.emplace(gltfMaterial, index);
  return index;
}

Material MaterialTable::convertMaterial(int gltfMaterial) {
  const tinygltf::Material& material = model_.materials[gltfMaterial];
  const std::string what = describe("material", gltfMaterial, material.name);
  warnAboutIgnoredParts(material, diagnostics_);
  const tinygltf::PbrMetallicRoughness& pbr = material.pbrMetallicRoughness;
  Material converted;
  converted.name = material.name.empty() ? what : material.name;
  converted.baseColor =
      colorFactor(pbr.baseColorFactor, 4, true, what + " baseColorFactor", diagnostics_);
  converted.baseColorTexture = baseColorTexture(pbr.baseColorTexture, what);
  converted.emission =
      colorFactor(material.emissiveFactor, 3, false, what + " emissiveFactor", diagnostics_) *
      emissiveStrength(material, what, diagnostics_);
  converted.doubleSided = material.doubleSided;
  return converted;
}

// The scene texture for a material's baseColorTexture, or -1 for none.
int MaterialTable::baseColorTexture(const tinygltf::TextureInfo& info,
                                    const std::string& material) {
  if (info.index < 0) return -1;
  if (info.texCoord != 0) {
    // Meshes keep TEXCOORD_0 only; another set would map the texture wrongly, so drop it.
    diagnostics_.warnOnce("texCoord", "ignoring baseColorTexture with texCoord " +
                                          std::to_string(info.texCoord) +
                                          " (only TEXCOORD_0 is supported)");
    return -1;
  }
  if (info.extensions.count(kTextureTransform) != 0) {
    diagnostics_.warnOnce(kTextureTransform, std::string("ignoring extension ") +
                                                 kTextureTransform + " (not supported)");
  }
  return sceneTexture(info.index, material);
}

int MaterialTable::sceneTexture(int gltfTexture, const std::string& material) {
  diagnostics_.checkIndex(gltfTexture, model_.textures.size(), material + " refers to texture");
  const auto known = textures_.find(gltfTexture);
  if (known != textures_.end()) return known->second;

  const tinygltf::Texture& texture = model_.textures[gltfTexture];
  const std::string what = "texture " + std::to_string(gltfTexture);
  if (texture.source < 0) diagnostics_.fail(what + " has no source image (PNG or JPEG)");
  diagnostics_.checkIndex(texture.source, model_.images.size(), what + " refers to image");
  if (texture.sampler >= 0) {
    diagnostics_.checkIndex(texture.sampler, model_.samplers.size(), what + " refers to sampler");
    const tinygltf::Sampler& sampler = model_.samplers[texture.sampler];
    if (sampler.wrapS != TINYGLTF_TEXTURE_WRAP_REPEAT ||
        sampler.wrapT != TINYGLTF_TEXTURE_WRAP_REPEAT) {
      diagnostics_.warnOnce("wrap modes", "ignoring texture wrap modes (textures always repeat)");
    }
  }
  const tinygltf::Image& image = model_.images[texture.source];
  const std::string imageName =
      describe("image", texture.source, image.name.empty() ? image.uri : image.name);
  scene_.textures.push_back(decodeTexture(image, imageName, diagnostics_));
  const int index = static_cast<int>(scene_.textures.size() - 1);
  textures_.emplace(gltfTexture, index);
  return index;
}

}  // namespace pathway::gltf
