#include "training/tasks/layer_starts.hpp"

namespace needle::training {
namespace {
constexpr double kTouchGap_m = 1e-6;
}  // namespace

std::vector<LayerStart> layer_starts_along(const haptics::TissueModel& tissue, const Vec3& tissue_frame_in_world,
                                           const Vec3& origin, const Vec3& direction) {
  std::vector<LayerStart> out;
  if (tissue.empty()) return out;
  const Vec3 o = origin - tissue_frame_in_world;
  const auto layer_at = [&](double depth) {
    return tissue.layer_at(
        Eigen::Vector3d(o[0] + depth * direction[0], o[1] + depth * direction[1], o[2] + depth * direction[2]));
  };
  double before = -kLayerSearchBehind_m;
  int layer = layer_at(before);
  const int steps = int((kLayerSearchBehind_m + kLayerSearchAhead_m) / kLayerSearchStep_m + 0.5);
  for (int k = 1; k <= steps; ++k) {
    const double depth = -kLayerSearchBehind_m + k * kLayerSearchStep_m;
    const int now = layer_at(depth);
    if (now != layer) {
      // Bisect (before, depth]: `layer` holds `lo`, something else holds `hi`.
      double lo = before, hi = depth;
      while (hi - lo > kLayerStartTolerance_m) {
        const double mid = 0.5 * (lo + hi);
        (layer_at(mid) == layer ? lo : hi) = mid;
      }
      // Layers that touch (1 µm, as the overlap check allows) share a face that neither holds: a
      // gap thinner than that is not a layer of its own, the next one begins where it did.
      if (!out.empty() && hi - out.back().depth_m < kTouchGap_m)
        out.back().layer = now;
      else
        out.push_back({now, hi});
      if (out.size() > 1 && out.back().layer == out[out.size() - 2].layer) out.pop_back();
      layer = now;
    }
    before = depth;
  }
  return out;
}

}  // namespace needle::training
