// The GPU deformation pass on lavapipe against the double-precision CPU reference, vertex by
// vertex, on random needle states and spheres of several sizes; the culled pass writes exactly
// the vertices it reports and every vertex the field reaches; no change, no dispatch; and the
// surface is back at rest after withdrawal.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <random>

#include "deformation_fixture.hpp"
#include "vulkan_fixture.hpp"

namespace needle::test {
namespace {

using engine::NeedleContact;

// float32 on the GPU against double: positions within a micrometre (coordinates are ~0.5 m,
// float's spacing there is 6e-8 m, and a dozen operations per load), normals within 0.01°.
constexpr double kPositionTolerance_m = 1e-6;
constexpr double kNormalTolerance_rad = 2e-4;

struct Comparison {
  size_t written = 0;     // vertices that are not NaN
  size_t mismatched = 0;  // written vertices off the reference
  double worst_position = 0.0, worst_angle = 0.0;
};

Comparison compare(const GpuSphere& s, const std::vector<engine::MeshVertex>& gpu,
                   const engine::DeformationField& field) {
  Comparison c;
  const glm::dmat3 normal_matrix = glm::transpose(glm::inverse(glm::dmat3(s.model_to_world)));
  for (size_t i = 0; i < gpu.size(); ++i) {
    if (std::isnan(gpu[i].position.x)) continue;
    ++c.written;
    glm::dvec3 rest_world = glm::dvec3(s.model_to_world * glm::dvec4(glm::dvec3(s.rest.vertices[i].position), 1.0));
    glm::dvec3 rest_normal = glm::normalize(normal_matrix * glm::dvec3(s.rest.vertices[i].normal));
    engine::DeformedVertex expected = engine::deform(field, rest_world, rest_normal);
    glm::dvec3 got = glm::dvec3(s.model_to_world * glm::dvec4(glm::dvec3(gpu[i].position), 1.0));
    glm::dvec3 got_normal = glm::normalize(normal_matrix * glm::dvec3(gpu[i].normal));
    double dp = glm::length(got - expected.position);
    double angle = std::acos(std::clamp(glm::dot(got_normal, expected.normal), -1.0, 1.0));
    c.worst_position = std::max(c.worst_position, dp);
    c.worst_angle = std::max(c.worst_angle, angle);
    if (!(dp <= kPositionTolerance_m && angle <= kNormalTolerance_rad)) ++c.mismatched;
  }
  return c;
}

void run(const engine::VulkanContext& context, engine::DeformationPass& pass, const engine::DeformationField& field,
         bool every_vertex = false) {
  auto recorder = pass.update(field, every_vertex);
  if (recorder) context.submit_and_wait(recorder);
}

engine::NeedleLoad random_load(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0), depth(0.001, 0.03), pivot(0.0, 0.8), force(0.0, 1.5);
  glm::dvec3 dir(u(rng), u(rng), u(rng));
  bool inserted = rng() % 2;
  return sphere_load(inserted ? NeedleContact::Inserted : NeedleContact::Touching, dir,
                     inserted ? depth(rng) : depth(rng) * 0.3, inserted ? pivot(rng) : 0.0, force(rng));
}

class DeformationPassTest : public VulkanTest {};

TEST_F(DeformationPassTest, EveryVertexMatchesTheCpuReference) {
  std::mt19937 rng(11);
  const glm::dmat4 moved = glm::translate(glm::dmat4(1.0), glm::dvec3(0.01, -0.02, 0.03)) *
                           glm::rotate(glm::dmat4(1.0), 0.3, glm::dvec3(1, 2, 3));
  for (int resolution : {12, 60, 150}) {
    for (const glm::dmat4& extra : {glm::dmat4(1.0), moved}) {
      GpuSphere sphere = make_gpu_sphere(context(), resolution, extra);
      engine::DeformationPass pass(context());
      pass.add_target(sphere.gpu, sphere.rest, engine::VertexGrid::sort_vertices(sphere.rest, 0.01),
                      sphere.model_to_world);
      for (int trial = 0; trial < 3; ++trial) {
        engine::NeedleLoad load = random_load(rng);
        // The load was made for the sphere at its asset position; move it with the sphere.
        load.tip = glm::dvec3(extra * glm::dvec4(load.tip, 1.0));
        load.surface_point = glm::dvec3(extra * glm::dvec4(load.surface_point, 1.0));
        load.axis = glm::dmat3(extra) * load.axis;
        load.surface_normal = glm::dmat3(extra) * load.surface_normal;
        load.lateral_force_on_tissue_N = glm::dmat3(extra) * load.lateral_force_on_tissue_N;
        engine::DeformationField field = engine::build_field(load, engine::TissueParams{});
        poison(context(), sphere.gpu);
        run(context(), pass, field, true);
        Comparison c = compare(sphere, engine::read_back_vertices(context(), sphere.gpu), field);
        EXPECT_EQ(c.written, sphere.rest.vertices.size()) << "resolution " << resolution;
        EXPECT_EQ(c.mismatched, 0u) << "resolution " << resolution << " trial " << trial << ": worst position "
                                    << c.worst_position << " m, worst normal " << c.worst_angle << " rad";
      }
    }
  }
}

TEST_F(DeformationPassTest, CulledPassWritesWhatItReportsAndAllTheFieldReaches) {
  GpuSphere sphere = make_gpu_sphere(context(), 150);
  engine::DeformationPass pass(context());
  pass.add_target(sphere.gpu, sphere.rest, engine::VertexGrid::sort_vertices(sphere.rest, 0.01), sphere.model_to_world);
  engine::DeformationField field =
      engine::build_field(sphere_load(NeedleContact::Touching, {-1, 0.2, 0.1}, 0.005), engine::TissueParams{});
  poison(context(), sphere.gpu);
  run(context(), pass, field);
  std::vector<engine::MeshVertex> gpu = engine::read_back_vertices(context(), sphere.gpu);
  Comparison c = compare(sphere, gpu, field);
  EXPECT_EQ(c.mismatched, 0u) << "worst position " << c.worst_position << " m";
  EXPECT_EQ(c.written, pass.last_frame().processed);
  EXPECT_EQ(pass.last_frame().processed + pass.last_frame().skipped, sphere.rest.vertices.size());
  EXPECT_LT(pass.last_frame().processed, sphere.rest.vertices.size() / 5)
      << "the support is a small part of the sphere";
  // Every vertex inside some load's support was written (the skipped ones are all outside).
  for (size_t i = 0; i < gpu.size(); ++i) {
    glm::dvec3 p = glm::dvec3(sphere.model_to_world * glm::dvec4(glm::dvec3(sphere.rest.vertices[i].position), 1.0));
    for (const engine::Kelvinlet& k : field.loads) {
      if (glm::length(p - k.center) < k.support) {
        EXPECT_FALSE(std::isnan(gpu[i].position.x)) << "vertex " << i << " is in the support but was skipped";
      }
    }
  }
}

TEST_F(DeformationPassTest, UnchangedFieldDispatchesNothing) {
  GpuSphere sphere = make_gpu_sphere(context(), 40);
  engine::DeformationPass pass(context());
  pass.add_target(sphere.gpu, sphere.rest, engine::VertexGrid::sort_vertices(sphere.rest, 0.01), sphere.model_to_world);
  EXPECT_FALSE(pass.update(engine::DeformationField{}));  // free needle, tissue at rest: nothing to do
  EXPECT_FALSE(pass.last_frame().dispatched);
  engine::DeformationField field =
      engine::build_field(sphere_load(NeedleContact::Touching, {-1, 0, 0}, 0.004), engine::TissueParams{});
  run(context(), pass, field);
  EXPECT_TRUE(pass.last_frame().dispatched);
  EXPECT_FALSE(pass.update(field));  // needle held still
  EXPECT_FALSE(pass.last_frame().dispatched);
  EXPECT_EQ(pass.last_frame().processed, 0u);
}

TEST_F(DeformationPassTest, WithdrawnNeedleLeavesTheSurfaceAtRest) {
  GpuSphere sphere = make_gpu_sphere(context(), 80);
  engine::DeformationPass pass(context());
  pass.add_target(sphere.gpu, sphere.rest, engine::VertexGrid::sort_vertices(sphere.rest, 0.01), sphere.model_to_world);
  for (double depth : {0.002, 0.004, 0.006}) {
    run(context(), pass, engine::build_field(sphere_load(NeedleContact::Touching, {-1, 0.3, 0}, depth), {}));
  }
  run(context(), pass, engine::build_field(sphere_load(NeedleContact::Inserted, {-1, 0.3, 0}, 0.02, 0.5, 1.0), {}));
  run(context(), pass, engine::DeformationField{});  // withdrawn
  EXPECT_TRUE(pass.last_frame().dispatched);         // once, to put the touched vertices back
  std::vector<engine::MeshVertex> gpu = engine::read_back_vertices(context(), sphere.gpu);
  for (size_t i = 0; i < gpu.size(); ++i) {
    ASSERT_EQ(gpu[i].position, sphere.rest.vertices[i].position) << "vertex " << i;
    ASSERT_LT(glm::length(gpu[i].normal - sphere.rest.vertices[i].normal), 1e-6f) << "vertex " << i;
  }
}

}  // namespace
}  // namespace needle::test
