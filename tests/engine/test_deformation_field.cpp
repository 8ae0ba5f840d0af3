// The field built from the needle state: the dimple follows the tip exactly, an inserted
// needle's entry point stays on its shaft wherever it pivots, and the tissue is at rest when
// the needle is free or pulled back.
#include <gtest/gtest.h>

#include "engine/deformation/deformation_field.hpp"

namespace needle::test {
namespace {

using engine::NeedleContact;
using engine::NeedleLoad;

double distance_to_line(const glm::dvec3& p, const glm::dvec3& on_line, const glm::dvec3& unit_dir) {
  glm::dvec3 d = p - on_line;
  return glm::length(d - unit_dir * glm::dot(d, unit_dir));
}

engine::TissueParams tissue() { return engine::TissueParams{}; }

TEST(DeformationField, FreeNeedleLeavesTissueAtRest) {
  NeedleLoad load;
  load.contact = NeedleContact::Free;
  engine::DeformationField field = engine::build_field(load, tissue());
  EXPECT_TRUE(field.empty());
  engine::DeformedVertex v = engine::deform(field, {0.1, 0.2, 0.3}, {0, 0, 1});
  EXPECT_EQ(v.position, glm::dvec3(0.1, 0.2, 0.3));
  EXPECT_EQ(v.normal, glm::dvec3(0, 0, 1));
}

TEST(DeformationField, DimpleSurfaceFollowsTheTipExactly) {
  NeedleLoad load;
  load.contact = NeedleContact::Touching;
  load.surface_point = {0.3, 0.0, 0.0};  // on a sphere of radius 0.1 at (0.4, 0, 0)
  load.surface_normal = {-1.0, 0.0, 0.0};
  load.tip = {0.304, 0.001, -0.0005};  // 4 mm in, a little oblique
  engine::DeformedVertex v =
      engine::deform(engine::build_field(load, tissue()), load.surface_point, load.surface_normal);
  EXPECT_NEAR(glm::length(v.position - load.tip), 0.0, 1e-12);
  // The dimple's floor faces the needle: the normal has turned but still points out of the tissue.
  EXPECT_LT(glm::dot(v.normal, glm::dvec3(1, 0, 0)), 0.0);
}

TEST(DeformationField, PullingAwayIsNoPush) {
  NeedleLoad load;
  load.contact = NeedleContact::Touching;
  load.surface_point = {0.3, 0.0, 0.0};
  load.surface_normal = {-1.0, 0.0, 0.0};
  load.tip = {0.299, 0.0, 0.0};  // outside the rest surface
  EXPECT_TRUE(engine::build_field(load, tissue()).empty());
}

TEST(DeformationField, EntryPointStaysOnThePivotedShaft) {
  NeedleLoad load;
  load.contact = NeedleContact::Inserted;
  load.surface_point = {0.3, 0.0, 0.0};
  load.surface_normal = {-1.0, 0.0, 0.0};
  for (double pivot_deg : {0.0, 10.0, 25.0, 45.0}) {
    double th = glm::radians(pivot_deg);
    load.axis = {std::cos(th), std::sin(th), 0.0};
    load.tip = {0.33, 0.0, 0.0};  // pivoting about the tip, 3 cm deep
    load.lateral_force_on_tissue_N = glm::dvec3(0.0, 0.8, 0.0) * std::sin(th);
    engine::DeformedVertex entry =
        engine::deform(engine::build_field(load, tissue()), load.surface_point, load.surface_normal);
    EXPECT_NEAR(distance_to_line(entry.position, load.tip, load.axis), 0.0, 1e-12) << pivot_deg << " deg";
  }
}

TEST(DeformationField, LateralForcePushesTissueAlongIt) {
  NeedleLoad load;
  load.contact = NeedleContact::Inserted;
  load.surface_point = {0.3, 0.0, 0.0};
  load.surface_normal = {-1.0, 0.0, 0.0};
  load.axis = {1.0, 0.0, 0.0};
  load.tip = {0.33, 0.0, 0.0};
  load.lateral_force_on_tissue_N = {0.0, 0.5, 0.0};
  engine::DeformationField field = engine::build_field(load, tissue());
  // Tissue beside the middle of the shaft moves with the force, not against it.
  glm::dvec3 beside(0.315, 0.004, 0.0);
  EXPECT_GT(engine::deform(field, beside, {0, 1, 0}).position.y - beside.y, 0.0);
}

}  // namespace
}  // namespace needle::test
