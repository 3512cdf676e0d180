#include "viewer/frame_metadata.h"

namespace pathway {

RenderMetadata frameMetadata(const LaneFrame& frame) {
  RenderMetadata metadata = frame.metadata;
  const CameraPose& pose = frame.camera;
  metadata.camera = CameraRecord{pose.position, pose.lookAt, pose.up, pose.yfov};
  return metadata;
}

}  // namespace pathway
