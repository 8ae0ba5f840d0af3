// The ultrasound's scan lines as the GPU traced them against the double-precision reference's
// (engine::trace_scan_lines), line by line.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "engine/ultrasound.hpp"

namespace needle::test {

// The same interfaces between the same layers, each within `depth_tolerance_m`, the same needle
// walls within it, and the shadow in the same lines, from the same sample or the next where float
// and double part (within 1.01 `sample_m`).
inline void expect_scan_lines_match(const std::vector<engine::ScanLine>& gpu, const std::vector<engine::ScanLine>& cpu,
                                    double depth_tolerance_m, double sample_m) {
  ASSERT_EQ(gpu.size(), cpu.size());
  for (size_t i = 0; i < cpu.size(); ++i) {
    ASSERT_EQ(gpu[i].interfaces.size(), cpu[i].interfaces.size()) << "line " << i;
    for (size_t k = 0; k < cpu[i].interfaces.size(); ++k) {
      const engine::EchoInterface &g = gpu[i].interfaces[k], &c = cpu[i].interfaces[k];
      EXPECT_EQ(g.from_layer, c.from_layer) << "line " << i << " interface " << k;
      EXPECT_EQ(g.to_layer, c.to_layer) << "line " << i << " interface " << k;
      EXPECT_NEAR(g.depth_m, c.depth_m, depth_tolerance_m) << "line " << i << " interface " << k;
    }
    EXPECT_EQ(std::isinf(gpu[i].needle_depth_m), std::isinf(cpu[i].needle_depth_m)) << "line " << i;
    if (!std::isinf(cpu[i].needle_depth_m)) {
      EXPECT_NEAR(gpu[i].needle_depth_m, cpu[i].needle_depth_m, depth_tolerance_m) << "line " << i;
    }
    EXPECT_EQ(std::isinf(gpu[i].shadow_depth_m), std::isinf(cpu[i].shadow_depth_m)) << "line " << i;
    if (!std::isinf(cpu[i].shadow_depth_m)) {
      EXPECT_NEAR(gpu[i].shadow_depth_m, cpu[i].shadow_depth_m, 1.01 * sample_m) << "line " << i;
    }
  }
}

}  // namespace needle::test
