// `needle-sim bench render --json`: the row keys other tools read.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "cli_process.hpp"

namespace needle::test {
namespace {

TEST(CliBenchRender, JsonRowsCarryTheContractKeys) {
  auto json_path = test_output_dir("cli_bench_render") / "render.json";
  ProcessResult r =
      run_needle_sim("bench render --spheres 4,8 --frames 2 --size 64x48 --msaa 1 --json " + quoted(json_path));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  nlohmann::json rows = nlohmann::json::parse(std::ifstream(json_path));
  // One row per sphere and renderer variant, the variants in turn.
  ASSERT_EQ(rows.size(), 8u);
  for (const char* key : {"sphere", "vertices", "width", "height", "frame_ms_median", "frame_ms_p95", "draws",
                          "triangles", "triangles_drawn"}) {
    EXPECT_TRUE(rows[0].contains(key)) << key;
  }
  const char* variants[] = {"whole", "culled", "lod", "lod+culled"};
  for (size_t i = 0; i < rows.size(); ++i) {
    EXPECT_EQ(rows[i]["draws"], variants[i % 4]);
    EXPECT_LE(rows[i]["triangles_drawn"].get<int>(), rows[i]["triangles"].get<int>());
  }
  EXPECT_EQ(rows[0]["triangles_drawn"], rows[0]["triangles"]);  // whole draws every triangle
  // A p x m sphere grid has (p + 1)(m + 1) vertices (seam and poles duplicated for UVs).
  EXPECT_EQ(rows[0]["sphere"], "4x4");
  EXPECT_EQ(rows[0]["vertices"], 25);
  EXPECT_EQ(rows[4]["vertices"], 81);
  EXPECT_EQ(rows[0]["width"], 64);
  EXPECT_EQ(rows[0]["height"], 48);
  EXPECT_LE(rows[0]["frame_ms_median"].get<double>(), rows[0]["frame_ms_p95"].get<double>());
}

}  // namespace
}  // namespace needle::test
