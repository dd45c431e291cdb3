// boreas tests: flow primitive bookkeeping — ids, lifetimes, gust envelopes.
#include <gtest/gtest.h>

#include <cmath>

#include "errors.h"
#include "wind/flow_field.h"
#include "wind/wind_params.h"

namespace boreas::test {
namespace {

TEST(FlowField, GustEnvelopeRisesHoldsAndFalls) {
  boreas_gust_def g = boreas_default_gust_def();
  g.delay = 1.0f;
  g.rise = 2.0f;
  g.hold = 1.0f;
  g.fall = 4.0f;
  double created = 10.0;
  EXPECT_EQ(impl::FlowField::gust_envelope(g, created, 10.5), 0.0);
  EXPECT_NEAR(impl::FlowField::gust_envelope(g, created, 12.0), 0.5, 1e-12);  // mid-rise
  EXPECT_EQ(impl::FlowField::gust_envelope(g, created, 13.5), 1.0);           // hold
  EXPECT_NEAR(impl::FlowField::gust_envelope(g, created, 16.0), 0.5, 1e-12);  // mid-fall
  EXPECT_EQ(impl::FlowField::gust_envelope(g, created, 18.0), 0.0);
  // The envelope is continuous: no step larger than its steepest slope allows.
  double prev = 0.0;
  for (double t = 10.0; t < 19.0; t += 0.001) {
    double e = impl::FlowField::gust_envelope(g, created, t);
    EXPECT_LE(std::fabs(e - prev), 1.5 / 2.0 * 0.001 + 1e-9);
    prev = e;
  }
}

TEST(FlowField, LifetimesAndGustsExpire) {
  impl::FlowField f(impl::claim_world_serial());
  boreas_flow_primitive_def p = impl::checked_primitive(boreas_default_flow_primitive_def(), "p");
  p.lifetime = 2.0f;
  boreas_primitive_id a = f.add_primitive(p, 1.0);
  boreas_gust_id b =
      f.add_gust(impl::checked_gust(boreas_default_gust_def(), "g"), 1.0);  // ends at 5
  boreas_flow_primitive_def forever =
      impl::checked_primitive(boreas_default_flow_primitive_def(), "p");
  boreas_primitive_id c = f.add_primitive(forever, 1.0);
  f.expire(2.9);
  EXPECT_EQ(f.forcing(2.9).size(), 3u);
  f.expire(3.0);
  EXPECT_EQ(f.forcing(3.0).size(), 2u);
  EXPECT_THROW(f.remove(a), impl::Error);
  f.expire(5.0);
  EXPECT_EQ(f.forcing(5.0).size(), 1u);
  EXPECT_THROW(f.remove(b), impl::Error);
  f.remove(c);
  EXPECT_TRUE(f.empty());
}

}  // namespace
}  // namespace boreas::test
