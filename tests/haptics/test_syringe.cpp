// The loss-of-resistance syringe (haptics/syringe/): every expectation is a closed form of the
// parameters (the pressure a thumb makes on a held plunger, F/A; Hagen–Poiseuille's flow through
// the lumen; Boyle's law for the air), a conservation law (the air's content), or an energy
// account the test keeps itself, not a result recorded from the code.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "haptics/syringe/loss_of_resistance.hpp"
#include "haptics/syringe/syringe_insertion.hpp"
#include "haptics/syringe/syringe_step.hpp"

namespace needle::haptics {
namespace {

constexpr double kDt = 0.001;
const LayerInjection kLigament{150e3, 1e13};  // holds the plunger under any thumb below 26.5 N
const LayerInjection kEpidural{1.0e3, 2e9};
const LayerInjection kFat{20e3, 1e11};

SyringeParams syringe(SyringeFluid fluid) {
  SyringeParams p;
  p.fluid = fluid;
  return p;
}

// R = 8 μ L / (π r⁴), computed here from the numbers of the default syringe.
double poiseuille(double viscosity) { return 8.0 * viscosity * 0.09 / (std::numbers::pi * std::pow(4.5e-4, 4)); }

SyringeState press(const SyringeParams& p, double force, const LayerInjection* tip, double seconds, SyringeState s) {
  const FlowPath path = flow_path(p, tip);
  for (long k = 0; k < std::lround(seconds / kDt); ++k) step_syringe(p, s, force, path, kDt);
  return s;
}

TEST(SyringeModel, TheLumensResistanceIsHagenPoiseuilles) {
  EXPECT_NEAR(lumen_resistance_Pa_s_per_m3(syringe(SyringeFluid::kSaline)) / poiseuille(1.002e-3), 1.0, 1e-12);
  EXPECT_NEAR(lumen_resistance_Pa_s_per_m3(syringe(SyringeFluid::kAir)) / poiseuille(1.81e-5), 1.0, 1e-12);
  // The tissue's resistance is given for saline and scales with the fluid's viscosity (Darcy).
  const FlowPath air = flow_path(syringe(SyringeFluid::kAir), &kEpidural);
  EXPECT_NEAR(air.resistance_Pa_s_per_m3, poiseuille(1.81e-5) + 2e9 * 1.81e-5 / 1.002e-3, 1.0);
  EXPECT_EQ(air.opening_pressure_Pa, 1.0e3);
  EXPECT_EQ(flow_path(syringe(SyringeFluid::kAir), nullptr).opening_pressure_Pa, 0.0);  // the tip in the open
}

TEST(SyringeModel, TheDefaultPlungerGivesVaughansForceToPressureRatio) {
  // Vaughan et al. 2012: 11.1 N at 470 mmHg and 11.8 N at 500 mmHg on the plunger.
  const double mmHg = 101325.0 / 760.0, area = SyringeParams{}.plunger_area_m2;
  EXPECT_NEAR(11.1 / (470 * mmHg), area, 0.01 * area);
  EXPECT_NEAR(11.8 / (500 * mmHg), area, 0.01 * area);
}

TEST(SyringeClosedForms, ALigamentHoldsTheSalinePlungerAtThumbForceOverArea) {
  const SyringeParams p = syringe(SyringeFluid::kSaline);
  const SyringeState s = press(p, 11.0, &kLigament, 2.0, syringe_at_rest(p));
  EXPECT_DOUBLE_EQ(s.pressure_Pa, 11.0 / p.plunger_area_m2);
  EXPECT_EQ(s.travel_m, 0.0);
  EXPECT_EQ(s.flow_m3_per_s, 0.0);
  EXPECT_EQ(s.work_J, 0.0);
}

TEST(SyringeClosedForms, SalineFlowsIntoTheEpiduralSpaceAtTheClosedFormRate) {
  const SyringeParams p = syringe(SyringeFluid::kSaline);
  const double a = p.plunger_area_m2, f = 8.0, r = poiseuille(1.002e-3) + 2e9;
  const double v = (f - a * 1.0e3) / (p.thumb_damping_Ns_per_m + a * a * r);  // the plunger's speed
  const SyringeState s = press(p, f, &kEpidural, 0.2, syringe_at_rest(p));
  EXPECT_NEAR(s.travel_m, v * 0.2, 1e-12);
  EXPECT_NEAR(s.flow_m3_per_s, a * v, 1e-15);
  EXPECT_NEAR(s.pressure_Pa, 1.0e3 + r * a * v, 1e-6);
  EXPECT_NEAR(s.injected_m3, a * v * 0.2, 1e-15);
  // The thumb's push falls by its damping while the plunger runs: F − b v = A p.
  EXPECT_NEAR(a * s.pressure_Pa, f - p.thumb_damping_Ns_per_m * v, 1e-9);
}

TEST(SyringeClosedForms, TheSalinePlungerStopsAtTheBarrelsEnd) {
  const SyringeParams p = syringe(SyringeFluid::kSaline);
  const SyringeState s = press(p, 11.0, nullptr, 5.0, syringe_at_rest(p));
  EXPECT_DOUBLE_EQ(s.travel_m, p.fill_volume_m3 / p.plunger_area_m2);
  EXPECT_NEAR(s.injected_m3, p.fill_volume_m3, 1e-18);
  EXPECT_EQ(s.pressure_Pa, 0.0);
  EXPECT_EQ(s.flow_m3_per_s, 0.0);
}

TEST(SyringeClosedForms, AirInALigamentCompressesByBoylesLaw) {
  const SyringeParams p = syringe(SyringeFluid::kAir);
  const double a = p.plunger_area_m2, p0 = 101325.0, volume = p.fill_volume_m3 + kSyringeDeadVolume_m3;
  SyringeState s = syringe_at_rest(p);
  for (const double f : {2.0, 6.0, 11.0}) {
    s = press(p, f, &kLigament, 2.0, s);  // settled: 2 s is 200 times the compression's b/k
    const double pressure = f / a;
    EXPECT_NEAR(s.pressure_Pa, pressure, 1e-6 * pressure);
    // p₀ V₀ = (p₀ + p) V: the plunger's travel is the volume the air lost.
    EXPECT_NEAR(s.travel_m, (volume - p0 * volume / (p0 + pressure)) / a, 1e-9);
    EXPECT_EQ(s.flow_m3_per_s, 0.0);
  }
  // Let go: the air pushes the plunger back to full and gives back what it held; the thumb's net work is
  // what the damping took.
  const double held = syringe_stored_energy(p, s), work = s.work_J;
  EXPECT_GT(held, 0.0);
  s = press(p, 0.0, &kLigament, 2.0, s);
  EXPECT_NEAR(s.travel_m, 0.0, 1e-9);
  EXPECT_NEAR(s.pressure_Pa, 0.0, 1e-3);
  EXPECT_NEAR(syringe_stored_energy(p, s), 0.0, 1e-12);
  // The release gives back what was held, bar backward Euler's own damping (the air's b/k is 4 ms, 4 ticks).
  EXPECT_LT(s.work_J, work - 0.9 * held);
  EXPECT_GE(s.work_J, 0.0);
}

TEST(SyringeClosedForms, AirLeavesThroughTheNeedleAndTheGasIsConserved) {
  const SyringeParams p = syringe(SyringeFluid::kAir);
  const SyringeState rest = syringe_at_rest(p);
  SyringeState s = press(p, 11.0, &kLigament, 1.0, rest);
  for (int k = 0; k < 400; ++k) {  // into the epidural space
    const double before = s.gas_J;
    step_syringe(p, s, 11.0, flow_path(p, &kEpidural), kDt);
    EXPECT_LE(s.gas_J, before);
    // The flow out at the barrel's pressure is what the gas lost: (p₀ + p) Q dt = Δm.
    EXPECT_NEAR((101325.0 + s.pressure_Pa) * s.flow_m3_per_s * kDt, before - s.gas_J, 1e-12 * before);
    EXPECT_GE(s.pressure_Pa, 1.0e3 - 1e-6);  // the implicit leak never takes the pressure below the opening
  }
  // Every mole is in the barrel or in the tissue: m₀ = m + p₀ V_injected.
  EXPECT_NEAR(s.gas_J + 101325.0 * s.injected_m3, rest.gas_J, 1e-12 * rest.gas_J);
  EXPECT_GT(s.travel_m, 0.9 * p.fill_volume_m3 / p.plunger_area_m2);  // the plunger ran to the barrel's end
}

// Randomised thumb cycles (presses, holds, taps, releases) with the tip moving between ligament, fat,
// the epidural space and the open: the work the thumb did on the plunger, integrated here from the
// plunger's force and travel, never falls below zero, and never below the energy the air holds.
TEST(SyringePassivity, TheSyringeNeverGivesTheThumbMoreWorkThanItTook) {
  std::mt19937 random(37);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const LayerInjection* tips[] = {&kLigament, &kFat, &kEpidural, nullptr};
  for (const SyringeFluid fluid : {SyringeFluid::kSaline, SyringeFluid::kAir}) {
    for (int run = 0; run < 20; ++run) {
      SyringeParams p = syringe(fluid);
      p.thumb_damping_Ns_per_m = 0.5 + 20.0 * unit(random);
      SyringeState s = syringe_at_rest(p);
      double work = 0.0, least = 0.0;
      for (int leg = 0; leg < 30; ++leg) {
        const LayerInjection* tip = tips[int(unit(random) * 4) % 4];
        const double from = s.thumb_force_N, to = 20.0 * unit(random) * (unit(random) < 0.3 ? 0.0 : 1.0);
        const long ticks = 1 + long(unit(random) * 300);
        for (long k = 0; k < ticks; ++k) {
          const double travel = s.travel_m;
          step_syringe(p, s, from + (to - from) * double(k + 1) / double(ticks), flow_path(p, tip), kDt);
          work += s.plunger_force_N * (s.travel_m - travel);
          least = std::min(least, work);
          ASSERT_GE(work - syringe_stored_energy(p, s), -1e-12) << syringe_fluid_name(fluid) << " run " << run;
        }
      }
      EXPECT_GE(least, -1e-12);
      EXPECT_NEAR(work, s.work_J, 1e-12);
    }
  }
}

// The losses of resistance along a drive through ligament, flavum, epidural space and dura: the
// loss at the flavum's far face is found within one tick's travel of it, with the faces off the
// tick grid and exactly on it.
TissueModel flavum_stack(double shift) {
  const auto slab = [&](double top, double thickness) {
    return LayerShape::slab(Eigen::Vector3d(0, 0, top + shift), Eigen::Vector3d::UnitZ(), thickness);
  };
  LayerMechanics ligament{.stiffness_N_per_m = 300,
                          .stiffness2_N_per_m2 = 40000,
                          .puncture_force_N = 2.0,
                          .cutting_force_N = 1.0,
                          .friction_N_per_m = 80,
                          .static_friction_N_per_m = 120};
  LayerMechanics flavum{.stiffness_N_per_m = 500,
                        .stiffness2_N_per_m2 = 600000,
                        .puncture_force_N = 5.0,
                        .cutting_force_N = 1.5,
                        .friction_N_per_m = 150,
                        .static_friction_N_per_m = 225};
  LayerMechanics space{.cutting_force_N = 0.05, .friction_N_per_m = 10, .static_friction_N_per_m = 15};
  LayerMechanics dura{.stiffness_N_per_m = 250,
                      .puncture_force_N = 1.0,
                      .cutting_force_N = 0.2,
                      .friction_N_per_m = 50,
                      .static_friction_N_per_m = 75};
  return TissueModel({{"ligament", slab(0.0, 0.010), ligament, std::nullopt, kLigament},
                      {"flavum", slab(-0.010, 0.005), flavum, std::nullopt, kLigament},
                      {"space", slab(-0.015, 0.005), space, std::nullopt, kEpidural},
                      {"dura", slab(-0.020, 0.0005), dura, std::nullopt, kLigament},
                      {"fluid", slab(-0.0205, 0.010), space, std::nullopt, kEpidural}});
}

TEST(SyringeLossOfResistance, IsFoundWithinOneTickOfTheFlavumsFarFace) {
  for (const SyringeFluid fluid : {SyringeFluid::kSaline, SyringeFluid::kAir}) {
    for (const double shift : {0.0, 3.3e-7}) {  // 0: every face on the tick grid (5 mm/s at 2 ms: 10 µm a tick)
      InsertionPlan plan;
      plan.from = Eigen::Vector3d(0, 0, 0.002);
      plan.depth_m = 0.021;
      plan.speed_mps = 0.005;
      plan.period_s = 0.002;
      const SyringeInsertionRun run = run_syringe_insertion(flavum_stack(shift), plan, {syringe(fluid), 11.0});
      ASSERT_FALSE(run.losses.empty()) << syringe_fluid_name(fluid);
      const SyringeLoss& loss = run.losses.front();
      EXPECT_EQ(loss.layer, 2) << "the epidural space";
      const double face = 0.002 + 0.015 - shift, tick = plan.speed_mps * plan.period_s;
      EXPECT_GE(loss.depth_m, face - 1e-12) << syringe_fluid_name(fluid) << " shift " << shift;
      EXPECT_LE(loss.depth_m, face + tick + 1e-12) << syringe_fluid_name(fluid) << " shift " << shift;
      // Before it the thumb held the plunger in the ligaments at F/A.
      EXPECT_NEAR(loss.pressure_before_Pa, 11.0 / SyringeParams{}.plunger_area_m2,
                  1e-6 * 11.0 / SyringeParams{}.plunger_area_m2);
      EXPECT_LT(loss.pressure_after_Pa, loss.pressure_before_Pa);
    }
  }
}

TEST(SyringeLossOfResistance, TheDetectorReadsThePressureAfterTheSettlingTime) {
  LossDetector detector;
  EXPECT_FALSE(detector.add(0.000, 0.0, 5e4, 1, 1.0));
  EXPECT_FALSE(detector.add(0.001, 0.0, 6e4, 1, 1.0));
  EXPECT_TRUE(detector.add(0.002, 1e-6, 5.9e4, 2, 1.0));
  EXPECT_EQ(detector.current().pressure_before_Pa, 6e4);
  EXPECT_FALSE(detector.current().settled);
  for (int k = 3; k < 52; ++k) EXPECT_FALSE(detector.add(0.001 * k, 1e-6, 1e4, 2, 1.0));
  EXPECT_FALSE(detector.current().settled);
  EXPECT_FALSE(detector.add(0.052, 1e-6, 2e3, 2, 1.0));
  EXPECT_TRUE(detector.settled_now());
  EXPECT_EQ(detector.current().pressure_after_Pa, 2e3);
  EXPECT_EQ(detector.current().layer, 2);
  // A residue bleeding out with the thumb off the plunger is no loss.
  EXPECT_FALSE(LossDetector().add(0.0, 1e-5, 1e3, -1, 0.0));
}

}  // namespace
}  // namespace needle::haptics
