#include "nao_interface/camera/scene_renderer.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <opencv2/imgproc.hpp>

namespace nao_interface {

namespace {

// Colours in BGR order.
const cv::Scalar kArmColour(215, 215, 220);
const cv::Scalar kLegColour(200, 200, 205);
const cv::Scalar kBumperColour(70, 70, 70);
const cv::Scalar kCymbalColour(60, 160, 200);
const cv::Vec3d kPinkBgr(170, 80, 255);

/// One thing to paint, with the depth used to order painting.
struct Primitive {
  double depth = 0.0;
  std::function<void(cv::Mat&)> paint;
};

/// Clips a convex polygon (optical frame) at z = near (Sutherland-Hodgman).
std::vector<Eigen::Vector3d> clipNear(const std::vector<Eigen::Vector3d>& poly, double near) {
  std::vector<Eigen::Vector3d> out;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Eigen::Vector3d& a = poly[i];
    const Eigen::Vector3d& b = poly[(i + 1) % poly.size()];
    const bool ain = a.z() >= near, bin = b.z() >= near;
    if (ain) out.push_back(a);
    if (ain != bin) {
      const double t = (near - a.z()) / (b.z() - a.z());
      out.push_back(a + t * (b - a));
    }
  }
  return out;
}

}  // namespace

SceneRenderer::SceneRenderer(RenderOptions options) : options_(options) {}

cv::Mat SceneRenderer::background(const Eigen::Isometry3d& camera) const {
  if (!cachedBackground_.empty() && camera.isApprox(cachedCamera_, 1e-12)) {
    return cachedBackground_.clone();
  }
  const PinholeCamera& cam = options_.camera;
  cv::Mat img(cam.height, cam.width, CV_8UC3);
  const Eigen::Vector3d origin = camera.translation();
  for (int v = 0; v < cam.height; ++v) {
    auto* row = img.ptr<cv::Vec3b>(v);
    for (int u = 0; u < cam.width; ++u) {
      const Eigen::Vector3d d = camera.linear() * cam.ray(u + 0.5, v + 0.5);
      if (d.z() < -1e-9) {
        // Floor: a 10 cm checker of beige and brown, darker with distance.
        const double t = (options_.floorZ - origin.z()) / d.z();
        const Eigen::Vector3d p = origin + t * d;
        const bool dark = (static_cast<long>(std::floor(p.x() / 0.1)) +
                           static_cast<long>(std::floor(p.y() / 0.1))) %
                              2 !=
                          0;
        const double fade = std::max(0.5, 1.0 - 0.15 * t);
        const cv::Vec3d c = dark ? cv::Vec3d(90, 120, 150) : cv::Vec3d(150, 180, 205);
        row[u] =
            cv::Vec3b(cv::saturate_cast<uchar>(c[0] * fade), cv::saturate_cast<uchar>(c[1] * fade),
                      cv::saturate_cast<uchar>(c[2] * fade));
      } else {
        // Wall: pale blue-grey, a little darker upwards.
        const double up = d.z() / d.norm();
        row[u] = cv::Vec3b(cv::saturate_cast<uchar>(205 - 40 * up),
                           cv::saturate_cast<uchar>(195 - 40 * up),
                           cv::saturate_cast<uchar>(185 - 40 * up));
      }
    }
  }
  cachedBackground_ = img;
  cachedCamera_ = camera;
  return img.clone();
}

cv::Mat SceneRenderer::render(const SceneGeometry& scene, rl_common::Random* noise) const {
  const PinholeCamera& cam = options_.camera;
  const double near = 0.01;
  cv::Mat img = background(scene.camera);
  const Eigen::Isometry3d toCam = scene.camera.inverse();
  std::vector<Primitive> prims;

  auto toPoints = [&cam](const std::vector<Eigen::Vector3d>& poly) {
    std::vector<cv::Point> pts;
    for (const Eigen::Vector3d& p : poly) {
      const Eigen::Vector2d px = *cam.project(p, 0.0);
      pts.emplace_back(static_cast<int>(std::lround(px.x())),
                       static_cast<int>(std::lround(px.y())));
    }
    return pts;
  };
  // A convex polygon given in the torso frame.
  auto addPolygon = [&](const std::vector<Eigen::Vector3d>& world,
                        std::function<cv::Scalar()> colour) {
    std::vector<Eigen::Vector3d> poly;
    double depth = 0.0;
    for (const Eigen::Vector3d& p : world) {
      poly.push_back(toCam * p);
      depth += poly.back().z();
    }
    poly = clipNear(poly, near);
    if (poly.size() < 3) return;
    const std::vector<cv::Point> pts = toPoints(poly);
    prims.push_back({depth / world.size(), [pts, colour](cv::Mat& m) {
                       cv::fillConvexPoly(m, pts, colour(), cv::LINE_8);
                     }});
  };
  // A capsule of radius r between two points in the torso frame.
  auto addCapsule = [&](const Eigen::Vector3d& a0, const Eigen::Vector3d& b0, double r,
                        const cv::Scalar& colour) {
    Eigen::Vector3d a = toCam * a0, b = toCam * b0;
    if (a.z() < near && b.z() < near) return;
    if (a.z() < near) a = a + (near - a.z()) / (b.z() - a.z()) * (b - a);
    if (b.z() < near) b = b + (near - b.z()) / (a.z() - b.z()) * (a - b);
    const double z = 0.5 * (a.z() + b.z());
    const int thickness = std::max(1, static_cast<int>(std::lround(2.0 * r * cam.fx / z)));
    const std::vector<cv::Point> pts = toPoints({a, b});
    prims.push_back({z, [pts, thickness, colour](cv::Mat& m) {
                       cv::line(m, pts[0], pts[1], colour, std::min(thickness, 400), cv::LINE_8);
                     }});
  };

  // Leg and foot bumper.
  addCapsule(scene.hip, scene.ankle, 0.035, kLegColour);
  addCapsule(scene.ankle, scene.bumper, 0.03, kLegColour);
  addCapsule(scene.bumper - Eigen::Vector3d(0, 0.02, 0), scene.bumper + Eigen::Vector3d(0, 0.02, 0),
             0.008, kBumperColour);
  // Cymbal: a 24-gon in the plane normal to its y axis.
  {
    std::vector<Eigen::Vector3d> disc;
    for (int i = 0; i < 24; ++i) {
      const double t = 2.0 * M_PI * i / 24;
      disc.push_back(scene.cymbal * Eigen::Vector3d(scene.cymbalRadius * std::cos(t), 0.0,
                                                    scene.cymbalRadius * std::sin(t)));
    }
    addPolygon(disc, [] { return kCymbalColour; });
  }
  // Arm.
  const double radii[] = {0.03, 0.025, 0.025};
  for (std::size_t i = 0; i + 1 < scene.arm.size() && i < 3; ++i) {
    addCapsule(scene.arm[i], scene.arm[i + 1], radii[i], kArmColour);
  }
  // Pink square, shaded by orientation and distance to the lens.
  {
    const Eigen::Vector3d c = scene.pinkSquare.translation();
    const Eigen::Vector3d ex = scene.pinkSquare.linear().col(0) * (scene.squareSize / 2);
    const Eigen::Vector3d ey = scene.pinkSquare.linear().col(1) * (scene.squareSize / 2);
    const Eigen::Vector3d n = scene.pinkSquare.linear().col(2);
    const Eigen::Vector3d toLens = scene.camera.translation() - c;
    const double d = toLens.norm();
    const double facing = d > 0 ? std::abs(n.dot(toLens / d)) : 1.0;
    const double lit = options_.ambient + (1.0 - options_.ambient) * facing;
    const double shadow = std::clamp(
        (d - options_.shadowNear) / (options_.shadowFar - options_.shadowNear), 0.1, 1.0);
    const cv::Scalar colour(kPinkBgr[0] * lit * shadow, kPinkBgr[1] * lit * shadow,
                            kPinkBgr[2] * lit * shadow);
    // Drawn slightly in front of the hand it is taped to.
    std::vector<Eigen::Vector3d> sq = {c + ex + ey, c - ex + ey, c - ex - ey, c + ex - ey};
    const std::size_t before = prims.size();
    addPolygon(sq, [colour] { return colour; });
    if (prims.size() > before) prims.back().depth -= 0.01;
  }

  std::stable_sort(prims.begin(), prims.end(),
                   [](const Primitive& a, const Primitive& b) { return a.depth > b.depth; });
  for (const Primitive& p : prims) p.paint(img);

  if (noise != nullptr && options_.pixelNoise > 0.0) {
    cv::Mat n(img.size(), CV_16SC3);
    cv::RNG rng(noise->nextU64());
    rng.fill(n, cv::RNG::NORMAL, 0.0, options_.pixelNoise);
    cv::Mat tmp;
    img.convertTo(tmp, CV_16SC3);
    tmp += n;
    tmp.convertTo(img, CV_8UC3);
  }
  return img;
}

}  // namespace nao_interface
