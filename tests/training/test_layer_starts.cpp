// Where along a planned axis each layer begins (the depth gauge's marks), against the
// layers' planes by closed form: a plane through p with unit normal n meets the axis o + t·d at
// t = n·(o − p) / (−n·d), i.e. the plane's distance from the origin divided by the cosine of the
// angle between the axis and the plane's inward normal. The planes are read from the scenario
// files here, not through the tissue model.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "haptics/sim/scenario.hpp"
#include "tests/support/test_paths.hpp"
#include "training/tasks/layer_starts.hpp"

namespace needle::training {
namespace {

using nlohmann::json;

json scenario_json(const char* name) {
  return json::parse(std::ifstream(test::source_dir() / "assets/scenarios" / name));
}

// A scenario's tissue is in the robots' base frame; the axes below are in the world.
std::vector<LayerStart> starts_in(const char* scenario, const Vec3& origin, const Vec3& direction) {
  const haptics::Scenario s = haptics::load_scenario((test::source_dir() / "assets/scenarios" / scenario).string());
  return layer_starts_along(s.scene.tissue, {s.base_in_world.x(), s.base_in_world.y(), s.base_in_world.z()}, origin,
                            direction);
}

// The start found for `layer`, or NaN.
double start_of(const std::vector<LayerStart>& starts, int layer) {
  for (const LayerStart& s : starts)
    if (s.layer == layer) return s.depth_m;
  return std::nan("");
}

// The layered block (boxes stacked along z, skin top at z = 0.07 m), the axis from the skin's top
// tilted 20° from the vertical in the xz plane: each box's top plane z = h at (0.07 − h)/cos 20°,
// out of the bone's bottom into no layer.
TEST(LayerStarts, TiltedAxisThroughTheLayeredBlockMeetsEachBoxTopAtItsPlaneDistanceOverCos) {
  const json layers = scenario_json("tissue_block_layers.json")["tissue"]["layers"];
  const double angle = 20.0 * M_PI / 180.0;
  const Vec3 origin{0.33, 0.0, 0.07}, direction{std::sin(angle), 0.0, -std::cos(angle)};
  const std::vector<LayerStart> starts = starts_in("tissue_block_layers.json", origin, direction);
  ASSERT_EQ(starts.size(), layers.size() + 1) << "each layer once, then out of the tissue";
  for (size_t i = 0; i < layers.size(); ++i) {
    const double top = layers[i]["shape"]["box"]["max"][2].get<double>();
    EXPECT_EQ(starts[i].layer, int(i)) << layers[i]["name"];
    EXPECT_NEAR(starts[i].depth_m, (origin[2] - top) / std::cos(angle), 1e-6) << layers[i]["name"];
  }
  const double bottom = layers.back()["shape"]["box"]["min"][2].get<double>();
  EXPECT_EQ(starts.back().layer, -1);
  EXPECT_NEAR(starts.back().depth_m, (origin[2] - bottom) / std::cos(angle), 1e-6);
}

// The lumbar section (slabs with the laminae as boxes beside the midline), the axis on the midline
// tilted 15° across it (in the yz plane, so it stays between the laminae): every slab layer begins
// at n·(o − p)/(−n·d); the laminae are never met.
TEST(LayerStarts, MidlineAxisThroughTheLumbarSlabsMeetsEachAtItsPlaneDistanceOverCos) {
  const json layers = scenario_json("epidural.json")["tissue"]["layers"];
  const double angle = 15.0 * M_PI / 180.0;
  const Vec3 origin{0.33, 0.0, 0.07}, direction{0.0, std::sin(angle), -std::cos(angle)};
  const std::vector<LayerStart> starts = starts_in("epidural.json", origin, direction);
  size_t slabs = 0;
  for (size_t i = 0; i < layers.size(); ++i) {
    const json& shape = layers[i]["shape"];
    if (!shape.contains("slab")) {
      EXPECT_TRUE(std::isnan(start_of(starts, int(i)))) << layers[i]["name"] << " lies beside the midline";
      continue;
    }
    ++slabs;
    const json& p = shape["slab"]["point"];
    const json& n = shape["slab"]["normal"];
    double n_op = 0.0, n_d = 0.0;
    for (int k = 0; k < 3; ++k) {
      n_op += n[k].get<double>() * (origin[size_t(k)] - p[k].get<double>());
      n_d += n[k].get<double>() * direction[size_t(k)];
    }
    EXPECT_NEAR(start_of(starts, int(i)), n_op / -n_d, 1e-6) << layers[i]["name"];
  }
  EXPECT_GE(slabs, 8u);
  for (size_t k = 1; k < starts.size(); ++k) EXPECT_GT(starts[k].depth_m, starts[k - 1].depth_m) << "in order of depth";
}

// Loading a layered task computes its axis markers' starts once (the gauge reads them); a task on
// the thesis's single-surface tissue has none.
TEST(LayerStarts, ALayeredTaskCarriesThemOnItsAxisMarkers) {
  const Task task = load_task(test::source_dir() / "assets/tasks/layered_target.json");
  const size_t index = size_t(task.marker_index("planned_axis"));
  const Marker& axis = task.markers[index];
  const std::vector<LayerStart> expected = starts_in("tissue_block_layers.json", axis.position, axis.direction);
  ASSERT_EQ(task.layer_starts.size(), task.markers.size());
  const std::vector<LayerStart>& starts = task.layer_starts[index];
  ASSERT_EQ(starts.size(), expected.size());
  for (size_t k = 0; k < expected.size(); ++k) {
    EXPECT_EQ(starts[k].layer, expected[k].layer);
    EXPECT_EQ(starts[k].depth_m, expected[k].depth_m);
  }
  EXPECT_EQ(starts[2].layer, task.layer_index("muscle"));
  EXPECT_NEAR(starts[2].depth_m, 0.012, 1e-6);  // skin 2 mm and fat 10 mm above it
  const Task sphere = load_task(test::source_dir() / "assets/tasks/penetrable_sphere.json");
  ASSERT_EQ(sphere.layer_starts.size(), sphere.markers.size());
  for (const std::vector<LayerStart>& s : sphere.layer_starts) EXPECT_TRUE(s.empty());
}

}  // namespace
}  // namespace needle::training
