// The fuzz targets' structured mutations (tests/fuzz/structure.hpp) make what the readers refuse:
// an extreme number in place of one, a number nested past the JSON depth limit.
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "io/strict_json.hpp"
#include "tests/fuzz/structure.hpp"

namespace needle::io {
namespace {

TEST(FuzzStructure, MutationsMakeExtremeNumbersAndNestingPastTheLimit) {
  const std::string text = R"({"period_s": 0.002, "q0_rad": [2, 1.5]})";
  for (unsigned seed = 0; seed < 20; ++seed) {
    std::mt19937 random(seed);
    std::vector<uint8_t> bytes(text.begin(), text.end());
    bytes.resize(1 << 16);
    // One of the three numbers is now one of the extremes, the rest of the text as it was.
    const std::string mutated(
        bytes.begin(), bytes.begin() + long(fuzz::extreme_number(bytes.data(), text.size(), bytes.size(), random)));
    bool one_extreme = false;
    for (const char* number : fuzz::kExtremeNumbers)
      for (const char* place : {R"({"period_s": X, "q0_rad": [2, 1.5]})", R"({"period_s": 0.002, "q0_rad": [X, 1.5]})",
                                R"({"period_s": 0.002, "q0_rad": [2, X]})"}) {
        std::string expected = place;
        one_extreme |= mutated == expected.replace(expected.find('X'), 1, number);
      }
    EXPECT_TRUE(one_extreme) << mutated;

    std::copy(text.begin(), text.end(), bytes.begin());
    const size_t deep = fuzz::deep_json(bytes.data(), text.size(), bytes.size(), random);
    ASSERT_GT(deep, text.size() + 2 * 64) << seed;
    EXPECT_THROW(parse_json_text(std::string(bytes.begin(), bytes.begin() + long(deep))), JsonTextError) << seed;
  }
  // No room: the mutation does not apply, and libFuzzer's own are used.
  std::vector<uint8_t> bytes(text.begin(), text.end());
  std::mt19937 random(1);
  EXPECT_EQ(fuzz::deep_json(bytes.data(), bytes.size(), bytes.size(), random), 0u);
}

}  // namespace
}  // namespace needle::io
