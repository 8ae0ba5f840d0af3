// The review plots' time range (ui/time_span.hpp): zooming keeps the time under the pointer in its
// place on the axis and scales the width by the factor; the range never leaves the session,
// never gets narrower than kMinSpanS, and an unchosen range is the whole session.
#include <gtest/gtest.h>

#include "ui/time_span.hpp"

namespace needle::test {
namespace {

const ui::TimeSpan kWhole{0.5, 54.5};

double place(const ui::TimeSpan& s, double t) { return (t - s.lo) / s.width(); }  // 0 at the left edge, 1 at the right

TEST(TimeSpan, UnchosenIsTheWholeSession) {
  const ui::TimeSpan s = ui::clamped({}, kWhole);
  EXPECT_DOUBLE_EQ(s.lo, kWhole.lo);
  EXPECT_DOUBLE_EQ(s.hi, kWhole.hi);
}

TEST(TimeSpan, ZoomKeepsThePointersTimeInPlace) {
  const ui::TimeSpan s{10.0, 20.0};
  for (double t : {10.0, 12.5, 17.0, 20.0}) {
    for (double factor : {0.8, 0.5, 1.25}) {
      const ui::TimeSpan z = ui::zoomed(s, kWhole, t, factor);
      EXPECT_NEAR(z.width(), 10.0 * factor, 1e-12) << t << " " << factor;
      EXPECT_NEAR(place(z, t), place(s, t), 1e-12) << t << " " << factor;
    }
  }
}

TEST(TimeSpan, ZoomingInAndOutAgainReturns) {
  ui::TimeSpan s{10.0, 20.0};
  for (int k = 0; k < 5; ++k) s = ui::zoomed(s, kWhole, 13.0, 0.8);
  for (int k = 0; k < 5; ++k) s = ui::zoomed(s, kWhole, 13.0, 1.25);
  EXPECT_NEAR(s.lo, 10.0, 1e-9);
  EXPECT_NEAR(s.hi, 20.0, 1e-9);
}

TEST(TimeSpan, StaysInsideTheSessionWithItsWidth) {
  const ui::TimeSpan right = ui::panned({50.0, 54.0}, kWhole, 3.0);  // would end at 57 s
  EXPECT_DOUBLE_EQ(right.hi, kWhole.hi);
  EXPECT_DOUBLE_EQ(right.width(), 4.0);
  const ui::TimeSpan left = ui::panned({1.0, 5.0}, kWhole, -3.0);
  EXPECT_DOUBLE_EQ(left.lo, kWhole.lo);
  EXPECT_DOUBLE_EQ(left.width(), 4.0);
  const ui::TimeSpan out = ui::zoomed({10.0, 50.0}, kWhole, 30.0, 3.0);  // wider than the session
  EXPECT_DOUBLE_EQ(out.lo, kWhole.lo);
  EXPECT_DOUBLE_EQ(out.hi, kWhole.hi);
  const ui::TimeSpan mid = ui::panned({10.0, 12.0}, kWhole, 0.25);
  EXPECT_DOUBLE_EQ(mid.lo, 10.25);
  EXPECT_DOUBLE_EQ(mid.hi, 12.25);
}

TEST(TimeSpan, NeverNarrowerThanTheMinimum) {
  ui::TimeSpan s{10.0, 11.0};
  for (int k = 0; k < 40; ++k) s = ui::zoomed(s, kWhole, 10.5, 0.5);
  EXPECT_NEAR(s.width(), ui::kMinSpanS, 1e-12);
  EXPECT_NEAR(0.5 * (s.lo + s.hi), 10.5, 1e-9);  // widened about its centre
  const ui::TimeSpan tiny = ui::clamped({3.0, 3.001}, kWhole);
  EXPECT_NEAR(tiny.width(), ui::kMinSpanS, 1e-12);
}

}  // namespace
}  // namespace needle::test
