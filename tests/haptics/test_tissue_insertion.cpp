// The layered tissue model driven kinematically: every expectation is the closed form
// of the parameters (puncture at d = F_p/k, or the root of k₁d + k₂d² = F_p; friction the sum of
// per-metre friction times the shaft length per layer), not a recorded result of the code.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "haptics/tissue/kinematic_insertion.hpp"
#include "haptics/tissue/tissue_step.hpp"
#include "tests/support/allocation_count.hpp"

namespace needle::haptics {
namespace {

using Eigen::Vector3d;

// Three slabs and a bone plate under z = 0, the needle coming down the z axis from z = +5 mm.
//   outer  0 to −10 mm: linear surface, F_p = 1 N at k = 200 N/m      → d_p = 5 mm
//   middle −10 to −30 mm: quadratic, k₁ = 100, k₂ = 20000, F_p = 2 N   → d_p = the root below
//   inner  −30 to −60 mm: no surface (entered as soon as reached)
//   bone   −60 to −70 mm: rigid
constexpr double kStart = 0.005;
const Vector3d kDown = -Vector3d::UnitZ();

LayerMechanics mechanics(double k1, double k2, double fp, double cut, double f, double fs) {
  return {.stiffness_N_per_m = k1,
          .stiffness2_N_per_m2 = k2,
          .puncture_force_N = fp,
          .cutting_force_N = cut,
          .friction_N_per_m = f,
          .static_friction_N_per_m = fs};
}

LayerShape slab(double top, double thickness) {
  return LayerShape::slab(Vector3d(0, 0, top), Vector3d::UnitZ(), thickness);
}

// The stack's thicknesses: outer from 0 to −outer, middle to −(outer + middle), inner below it, the
// tip starting `start` above the outer surface.
struct StackGeometry {
  double start, outer, middle, inner;
};

TissueModel slab_stack(const StackGeometry& g) {
  LayerMechanics bone;
  bone.rigid = true;
  return TissueModel({{"outer", slab(0.0, g.outer), mechanics(200, 0, 1.0, 0.3, 40, 60)},
                      {"middle", slab(-g.outer, g.middle), mechanics(100, 20000, 2.0, 0.5, 80, 120)},
                      {"inner", slab(-g.outer - g.middle, g.inner), mechanics(0, 0, 0, 0.1, 20, 30)},
                      {"bone", slab(-g.outer - g.middle - g.inner, 0.010), bone}});
}

TissueModel slab_stack() { return slab_stack({kStart, 0.010, 0.020, 0.030}); }

// The middle surface's deflection when it gives way: the root of k₁d + k₂d² = F_p.
const double kMiddleDeflection = (-100.0 + std::sqrt(100.0 * 100.0 + 4.0 * 20000.0 * 2.0)) / (2.0 * 20000.0);

// Σ fᵢ Lᵢ for the shaft down to `depth` (all layers punctured above it).
double friction_to(double depth, bool stick) {
  const double outer = std::clamp(depth - 0.005, 0.0, 0.010), middle = std::clamp(depth - 0.015, 0.0, 0.020),
               inner = std::clamp(depth - 0.035, 0.0, 0.030);
  return stick ? 60 * outer + 120 * middle + 30 * inner : 40 * outer + 80 * middle + 20 * inner;
}

InsertionPlan plan(double depth, double hold) {
  InsertionPlan p;
  p.from = Vector3d(0, 0, kStart);
  p.dir = kDown;
  p.depth_m = depth;
  p.speed_mps = 0.005;
  p.hold_s = hold;
  p.period_s = 0.001;
  return p;
}

// The sample of the insertion (or of the withdrawal) nearest to `depth`.
const InsertionSample& sample_at(const InsertionRun& run, double depth, bool withdrawing) {
  const auto deepest = std::max_element(run.samples.begin(), run.samples.end(),
                                        [](const auto& a, const auto& b) { return a.depth_m < b.depth_m; });
  auto begin = withdrawing ? deepest : run.samples.begin(), end = withdrawing ? run.samples.end() : deepest;
  return *std::min_element(begin, end, [&](const auto& a, const auto& b) {
    return std::abs(a.depth_m - depth) < std::abs(b.depth_m - depth);
  });
}

void expect_closed_form_punctures(const StackGeometry& g, const InsertionPlan& p) {
  const double outer_pop = g.start + 1.0 / 200, middle_pop = g.start + g.outer + kMiddleDeflection;
  const InsertionRun run = run_kinematic_insertion(slab_stack(g), p);
  ASSERT_EQ(run.punctures.size(), 2u);  // the inner layer has no surface: entered, not punctured
  EXPECT_EQ(run.punctures[0].layer, 0);
  EXPECT_NEAR(run.punctures[0].depth_m, outer_pop, 0.02 * (outer_pop - g.start));
  EXPECT_NEAR(run.punctures[0].peak_force_N, 1.0, 0.02);  // no shaft in tissue yet: the surface alone
  EXPECT_EQ(run.punctures[1].layer, 1);
  EXPECT_NEAR(run.punctures[1].depth_m, middle_pop, 0.02 * kMiddleDeflection);
  // The middle surface plus the outer layer's friction (slipping) on all the shaft: while the tip
  // tents a surface, the tissue around the shaft is the layer above, carried down with the tent.
  const double peak = 2.0 + 40 * (middle_pop - g.start);
  EXPECT_NEAR(run.punctures[1].peak_force_N, peak, 0.02 * peak);
  // The drop: one tick later only the friction is left.
  const InsertionSample& after = sample_at(run, middle_pop + p.speed_mps * p.period_s, false);
  EXPECT_LT(after.axial_force_N, 0.5 * run.punctures[1].peak_force_N);
  // Once the outer surface gave way the tip is always in some layer: a shared face is no "outside".
  for (const InsertionSample& s : run.samples)
    if (s.depth_m > run.punctures[0].depth_m && s.depth_m < g.start + g.outer + g.middle + g.inner &&
        s.t < p.depth_m / p.speed_mps)
      EXPECT_GE(s.layer, 0) << s.depth_m;
}

TEST(TissueInsertion, PuncturesHappenAtTheClosedFormDepthsAndForces) {
  expect_closed_form_punctures({kStart, 0.010, 0.020, 0.030}, plan(0.050, 1.0));
}

// Every number a dyadic fraction, so the drive lands exactly on each face between two layers (the
// tick grid meets the boundaries, as round millimetres at round speeds do): the tip on a shared face
// belongs to the inner layer, never to none.
TEST(TissueInsertion, PuncturesHappenAtTheClosedFormDepthsAndForcesWithFacesOnTheTickGrid) {
  const StackGeometry g{std::ldexp(1.0, -8), std::ldexp(1.0, -7), std::ldexp(1.0, -6), std::ldexp(1.0, -5)};
  InsertionPlan p = plan(g.start + g.outer + g.middle + std::ldexp(1.0, -7), 0.25);
  p.from = Vector3d(0, 0, g.start);
  p.speed_mps = std::ldexp(1.0, -8);
  p.period_s = std::ldexp(1.0, -10);
  const double step = p.speed_mps * p.period_s;
  for (double face : {g.start, g.start + g.outer, g.start + g.outer + g.middle})
    ASSERT_EQ(std::fmod(face, step), 0.0) << "the faces must lie on the tick grid";
  expect_closed_form_punctures(g, p);
}

TEST(TissueInsertion, InsideALayerTheForceIsCuttingPlusFrictionPerLayer) {
  const InsertionRun run = run_kinematic_insertion(slab_stack(), plan(0.050, 1.0));
  for (const auto& [depth, layer, cutting] :
       {std::tuple{0.0130, 0, 0.3}, std::tuple{0.0280, 1, 0.5}, std::tuple{0.0450, 2, 0.1}}) {
    const InsertionSample& s = sample_at(run, depth, false);
    const double expected = cutting + friction_to(s.depth_m, false);
    EXPECT_EQ(s.layer, layer) << depth;
    EXPECT_NEAR(s.axial_force_N, expected, 0.02 * expected) << depth;
  }
}

TEST(TissueInsertion, HeldItStaysInTheStaticBandAndWithdrawnItIsFrictionWithTheOppositeSign) {
  const InsertionRun run = run_kinematic_insertion(slab_stack(), plan(0.050, 1.0));
  const double band = friction_to(0.050, true);
  int held = 0;
  for (const InsertionSample& s : run.samples)
    if (s.depth_m == 0.050) {
      ++held;
      EXPECT_LE(std::abs(s.axial_force_N), band + 1e-9);
    }
  EXPECT_GE(held, 1000);  // 1 s at 1 ms
  // Past the first millimetre of withdrawal (the stick element unloading), the friction alone.
  for (double depth : {0.045, 0.030, 0.012}) {
    const InsertionSample& s = sample_at(run, depth, true);
    const double expected = -friction_to(s.depth_m, false);
    EXPECT_NEAR(s.axial_force_N, expected, 0.02 * std::abs(expected)) << depth;
  }
  EXPECT_EQ(run.samples.back().depth_m, 0.0);
  EXPECT_EQ(run.samples.back().axial_force_N, 0.0);  // out of the tissue: nothing left
  EXPECT_EQ(run.samples.back().layer, -1);
}

// Drives the model tick by tick through a list of depths (1 ms ticks) and returns the outputs.
std::vector<TissueOutput> drive(const TissueModel& model, TissueState& state, const std::vector<double>& depths) {
  std::vector<TissueOutput> outs;
  for (double d : depths) outs.push_back(step_tissue(model, state, Vector3d(0, 0, kStart) + d * kDown, kDown, 0.001));
  return outs;
}

std::vector<double> ramp(double from, double to, double speed) {
  std::vector<double> d;
  const int n = int(std::ceil(std::abs(to - from) / (speed * 0.001)));
  for (int k = 1; k <= n; ++k) d.push_back(from + (to - from) * k / n);
  return d;
}

TEST(TissueInsertion, ReinsertingAlongTheTrackMeetsNoPunctureAndNoCutting) {
  const TissueModel model = slab_stack();
  TissueState state;
  drive(model, state, {0.0});
  drive(model, state, ramp(0.0, 0.030, 0.005));
  drive(model, state, ramp(0.030, 0.008, 0.005));  // back into the outer layer: middle freed
  EXPECT_EQ(state.out.holding_layer, 0);
  const std::vector<double> path = ramp(0.008, 0.030, 0.005);
  const auto again = drive(model, state, path);
  for (const TissueOutput& o : again) {
    EXPECT_EQ(o.punctured_layer, -1);
    EXPECT_EQ(o.surface_layer, -1);
  }
  // At 28 mm: friction only (the channel is cut), without the middle layer's 0.5 N of cutting.
  const size_t k = path.size() - 400;
  EXPECT_NEAR(again[k].axial_force_N, friction_to(path[k], false), 0.02 * friction_to(path[k], false));
  // Past the old deepest point the middle layer is cut again.
  const auto beyond = drive(model, state, ramp(0.030, 0.032, 0.005));
  EXPECT_NEAR(beyond.back().axial_force_N, 0.5 + friction_to(0.032, false), 0.02 * (0.5 + friction_to(0.032, false)));
}

TEST(TissueInsertion, WithdrawingFullyClearsTheTrack) {
  const TissueModel model = slab_stack();
  TissueState state;
  drive(model, state, {0.0});
  drive(model, state, ramp(0.0, 0.012, 0.005));
  drive(model, state, ramp(0.012, 0.0, 0.005));
  EXPECT_FALSE(state.on_track);
  const auto again = drive(model, state, ramp(0.0, 0.012, 0.005));
  int punctures = 0;
  for (const TissueOutput& o : again) punctures += o.punctured_layer == 0;
  EXPECT_EQ(punctures, 1);  // a new insertion punctures the outer surface again
}

TEST(TissueInsertion, BoneIsAHardStopAndARigidContactForTheVirtualRobot) {
  const TissueModel model = slab_stack();
  const InsertionRun run = run_kinematic_insertion(model, plan(0.080, 0.0));
  ASSERT_TRUE(run.hard_stop.has_value());
  EXPECT_EQ(run.hard_stop->layer, 3);
  EXPECT_NEAR(run.hard_stop->depth_m, 0.065, 1e-9);  // the bone's surface at z = −60 mm
  for (const InsertionSample& s : run.samples) EXPECT_LE(s.depth_m, 0.065 + 1e-9);
  // Driven past it by hand, the model reports the rigid contact with its distance and normal.
  TissueState state;
  drive(model, state, {0.0});
  drive(model, state, ramp(0.0, 0.0652, 0.005));
  ASSERT_TRUE(state.out.rigid_contact);
  EXPECT_EQ(state.out.surface_layer, 3);
  EXPECT_NEAR(state.out.rigid_surface.phi, -0.0002, 1e-9);
  EXPECT_NEAR(state.out.rigid_surface.gradient.z(), 1.0, 1e-12);
  EXPECT_EQ(state.out.surface_force_N, 0.0);  // the GPM (3.15) renders it, not the tissue model
}

TEST(TissueInsertion, TheThesisSingleSurfaceTissueGivesNoForce) {
  // The thesis's penetrable sphere, r = 0.1 m (section 4.4), as a layer with every parameter zero.
  const TissueModel sphere = TissueModel::single_surface(LayerShape::of_surface(
      std::array{SurfacePrimitive::sphere(Vector3d(0.4, 0, 0), 0.1)}, ImplicitSurface::Combine::Union));
  InsertionPlan p;
  p.from = Vector3d(0.2, 0.0, 0.0);
  p.dir = Vector3d::UnitX();
  p.depth_m = 0.15;
  p.speed_mps = 0.01;
  p.hold_s = 0.5;
  const InsertionRun run = run_kinematic_insertion(sphere, p);
  bool inside = false;
  for (const InsertionSample& s : run.samples) {
    EXPECT_EQ(s.axial_force_N, 0.0);
    inside |= s.layer == 0;
    if (std::abs(s.depth_m - 0.1) > 1e-6) {
      EXPECT_EQ(s.layer, s.depth_m > 0.1 ? 0 : -1) << s.depth_m;  // the surface is at x = 0.3
    }
  }
  EXPECT_TRUE(inside);
  EXPECT_TRUE(run.punctures.empty());
  EXPECT_EQ(run.tissue_work_J, 0.0);
}

TEST(TissueInsertion, NestedSpheresArePuncturedAtTheirRadii) {
  const Vector3d c(0.4, 0, 0);
  auto sphere = [&](double r) {
    return LayerShape::of_surface(std::array{SurfacePrimitive::sphere(c, r)}, ImplicitSurface::Combine::Union);
  };
  const TissueModel nested({{"wall", sphere(0.10), mechanics(200, 0, 1.0, 0.2, 30, 45)},
                            {"organ", sphere(0.07), mechanics(150, 0, 1.5, 0.2, 10, 15)}});
  InsertionPlan p;
  p.from = Vector3d(0.29, 0, 0);  // 1 cm outside, towards the centre
  p.dir = Vector3d::UnitX();
  p.depth_m = 0.06;
  p.speed_mps = 0.005;
  p.period_s = 0.001;
  const InsertionRun run = run_kinematic_insertion(nested, p);
  ASSERT_EQ(run.punctures.size(), 2u);
  EXPECT_NEAR(run.punctures[0].depth_m, 0.010 + 1.0 / 200, 0.02 * 0.005);    // wall met at r = 0.1
  EXPECT_NEAR(run.punctures[1].depth_m, 0.040 + 1.5 / 150, 0.02 * 0.010);    // organ met at r = 0.07
  EXPECT_NEAR(run.punctures[1].peak_force_N, 1.5 + 30 * 0.040, 0.02 * 2.7);  // the wall's friction up to the tip
}

// Randomised insert–hold–withdraw cycles (fast, slow inside the stick band, partial withdrawals,
// re-insertions): the work of the needle on the tissue, integrated here from the forces and the
// displacements the test imposes, never goes negative, and the model's own account agrees.
TEST(TissueInsertion, TheTissueNeverDoesNetPositiveWorkOnTheNeedle) {
  const TissueModel model = slab_stack();
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> depth(0.0, 0.07), speed(0.0002, 0.02), hold(0.0, 0.3);
  for (int trial = 0; trial < 20; ++trial) {
    TissueState state;
    double d = 0.0, work = 0.0, force = 0.0, lowest = 0.0, lowest_dissipated = 0.0;
    drive(model, state, {d});
    for (int leg = 0; leg < 12; ++leg) {
      std::vector<double> path = ramp(d, std::min(depth(rng), 0.0649), speed(rng));
      path.insert(path.end(), size_t(hold(rng) / 0.001), path.empty() ? d : path.back());
      for (double next : path) {
        const double f = drive(model, state, {next}).back().axial_force_N;
        work += 0.5 * (force + f) * (next - d);
        force = f;
        d = next;
        lowest = std::min(lowest, work);
        lowest_dissipated = std::min(lowest_dissipated, work - tissue_stored_energy(model, state));
      }
    }
    // The trapezoid rule's error on the quadratic surface (k₂h³/6 a tick, a few 1e-11 J) is the
    // only way below zero: exactly, the work is ≥ 0.
    EXPECT_GE(lowest, -1e-9) << "trial " << trial;
    // Stronger: it never gives back more than it holds (tented surface, stick spring), so the work
    // minus the stored energy, the dissipated part, never falls below zero either.
    EXPECT_GE(lowest_dissipated, -1e-9) << "trial " << trial;
    EXPECT_NEAR(state.tissue_work_J, work, 1e-9 + 1e-9 * std::abs(work)) << "trial " << trial;
  }
}

TEST(TissueInsertion, ATickAllocatesNothing) {
  const TissueModel model = slab_stack();
  TissueState state;
  std::vector<Vector3d> tips;
  for (double d : ramp(0.0, 0.06, 0.005)) tips.push_back(Vector3d(0, 0, kStart) + d * kDown);
  for (double d : ramp(0.06, 0.0, 0.005)) tips.push_back(Vector3d(0, 0, kStart) + d * kDown);
  needle::test::allocation_counter::start();
  for (const Vector3d& tip : tips) step_tissue(model, state, tip, kDown, 0.001);
  EXPECT_EQ(needle::test::allocation_counter::stop(), 0);
  EXPECT_GT(state.tissue_work_J, 0.0);  // the ticks did cross the layers
}

}  // namespace
}  // namespace needle::haptics
