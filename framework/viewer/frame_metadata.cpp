#include "viewer/frame_metadata.h"

#include <sstream>

namespace pathway {
namespace {

std::string vec3Text(const Vec3& v) {
  std::ostringstream text;
  text << v.x << " " << v.y << " " << v.z;
  return text.str();
}

}  // namespace

ImageMetadata frameMetadata(const LaneFrame& frame) {
  ImageMetadata metadata = frame.metadata;
  metadata.push_back({"pathway:cameraPosition", vec3Text(frame.camera.position)});
  metadata.push_back({"pathway:cameraLookAt", vec3Text(frame.camera.lookAt)});
  metadata.push_back({"pathway:cameraUp", vec3Text(frame.camera.up)});
  metadata.push_back({"pathway:cameraYfov", std::to_string(frame.camera.yfov)});
  return metadata;
}

}  // namespace pathway
