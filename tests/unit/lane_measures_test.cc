// The fall check's measures, written once (sim/body_frame.h) and taken two ways: from one
// state, and from a batch's lanes all at once (sim/lane_measures.h). Both must be the bits the
// one-creature path computed before (Eigen's vector arithmetic) on any state, odd ones included.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <vector>

#include "ga/rng.h"
#include "same_result.h"
#include "sim/batch_state.h"
#include "sim/lane_measures.h"
#include "sim/state.h"
#include "sim/trace.h"
#include "test_util.h"

namespace hexgait {
namespace {

using test::SameBits;

// The body frame as the one-creature path computed it with Eigen before BodyFrame.
Eigen::Vector3d EigenMean(const std::vector<int>& indices, const SimState& s) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (int i : indices) sum += s.position(i);
  return sum / static_cast<double>(indices.size());
}
Eigen::Vector3d EigenUp(const CreatureModel& model, const SimState& s) {
  const Eigen::Vector3d f =
      (EigenMean(model.body_front, s) - EigenMean(model.body_rear, s)).normalized();
  const Eigen::Vector3d l =
      (EigenMean(model.body_left, s) - EigenMean(model.body_right, s)).normalized();
  return f.cross(l).normalized();
}

// The rest pose moved, turned over and shaken: `k` picks how far. Every fourth state has a
// body collapsed to one point (axes of length 0).
SimState ShakenState(const CreatureModel& model, Rng& rng, int k) {
  SimState s = MakeRestState(model);
  const double scale = k % 3 == 0 ? 0.01 : k % 3 == 1 ? 0.3 : 3.0;
  for (int i = 0; i < model.num_particles(); ++i) {
    s.x[i] += scale * (rng.NextDouble() - 0.5);
    s.y[i] += scale * (rng.NextDouble() - 0.5);
    s.z[i] = k % 2 ? -s.z[i] + scale * (rng.NextDouble() - 0.5) : s.z[i] - 0.01 * rng.NextDouble();
    s.vx[i] = 100 * (rng.NextDouble() - 0.5);
    s.vy[i] = 100 * (rng.NextDouble() - 0.5);
    s.vz[i] = 100 * (rng.NextDouble() - 0.5);
    if (k % 4 == 3) s.x[i] = s.y[i] = s.z[i] = 0.25;
  }
  return s;
}

TEST(BodyFrame, AxesAreEigensBitForBit) {
  for (const char* creature : {"hexapod", "wedge"}) {
    const CreatureModel model = LoadCreatureOrDefault(creature);
    Rng rng = Rng::ForStream(7, 0);
    for (int k = 0; k < 400; ++k) {
      const SimState s = ShakenState(model, rng, k);
      Eigen::Vector3d up;
      BodyAxes(model, s, nullptr, nullptr, &up);
      const Eigen::Vector3d want = EigenUp(model, s);
      for (int c = 0; c < 3; ++c) ASSERT_TRUE(SameBits(up[c], want[c])) << creature << " " << k;
      const Eigen::Vector3d centre = BodyCentre(model, s);
      const Eigen::Vector3d want_centre = EigenMean(model.body_particles, s);
      for (int c = 0; c < 3; ++c) ASSERT_TRUE(SameBits(centre[c], want_centre[c]));
    }
  }
}

// Every lane of a batch measured at once equals the lane copied out and measured alone, in
// double and in float, for lanes in bounds and out (a NaN, an infinity, a particle too fast).
template <class T>
void CheckLanesAgainstOneState(BatchIsa isa) {
  const CreatureModel model = test::DefaultCreature();
  const double limit = 40;  // above every speed ShakenState gives, scaled as below (35 at most)
  for (int lanes : {1, 2, 4, 8, 16}) {
    SCOPED_TRACE(std::to_string(lanes) + " lanes");
    BatchStateT<T> batch = MakeBatchStateT<T>(model, MakeRestState(model), lanes);
    Rng rng = Rng::ForStream(11, static_cast<uint64_t>(lanes));
    int outside = 0, inside = 0;
    for (int round = 0; round < 40; ++round) {
      for (int l = 0; l < lanes; ++l) {
        SimState s = ShakenState(model, rng, round * lanes + l);
        for (int i = 0; i < model.num_particles(); ++i) {  // within the limit, unless set below
          s.vx[i] *= 0.4;
          s.vy[i] *= 0.4;
          s.vz[i] *= 0.4;
        }
        if ((round + l) % 7 == 1) s.z[3] = std::numeric_limits<double>::quiet_NaN();
        if ((round + l) % 7 == 2) s.vy[5] = std::numeric_limits<double>::infinity();
        if ((round + l) % 7 == 3) s.vz[0] = 1e3;
        InsertLane(s, l, batch);
      }
      std::vector<BodyMeasures> body(static_cast<size_t>(lanes));
      std::vector<char> in_bounds(static_cast<size_t>(lanes), 2);
      const int first = round % 2 && lanes > 2 ? 1 : 0;
      const int count = lanes - first - (round % 3 == 1 && lanes > 3 ? 1 : 0);
      MeasureLanes(model, batch, limit, first, count, body, in_bounds, isa);
      SimState lane = MakeRestState(model);
      for (int l = 0; l < lanes; ++l) {
        if (l < first || l >= first + count) {
          EXPECT_EQ(in_bounds[static_cast<size_t>(l)], 2) << "lane " << l << " not asked for";
          continue;
        }
        ExtractLane(batch, l, lane);
        bool bounded = true;  // the one-creature check: particle by particle
        for (int i = 0; i < model.num_particles(); ++i) {
          BoundsTest<double> particle(limit);
          particle.Add(lane.x[i], lane.y[i], lane.z[i], lane.vx[i], lane.vy[i], lane.vz[i]);
          bounded = bounded && particle.Passes();
        }
        ASSERT_EQ(in_bounds[static_cast<size_t>(l)] != 0, bounded) << "lane " << l;
        if (!bounded) {
          ++outside;
          continue;
        }
        ++inside;
        const BodyMeasures& m = body[static_cast<size_t>(l)];
        Eigen::Vector3d up;
        BodyAxes(model, lane, nullptr, nullptr, &up);
        EXPECT_TRUE(SameBits(m.lowest, LowestBodyHeight(model, lane))) << "lane " << l;
        EXPECT_TRUE(SameBits(m.up_z, up.z())) << "lane " << l;
        EXPECT_EQ(m.feet, FeetOnGround(model, lane)) << "lane " << l;
      }
    }
    EXPECT_GT(inside, 0);
    EXPECT_GT(outside, 0);
  }
}

TEST(LaneMeasures, EqualTheOneStateMeasuresInDouble) {
  for (BatchIsa isa : test::SupportedIsas()) {
    SCOPED_TRACE(BatchIsaName(isa));
    CheckLanesAgainstOneState<double>(isa);
  }
}
TEST(LaneMeasures, EqualTheOneStateMeasuresInFloat) {
  for (BatchIsa isa : test::SupportedIsas()) {
    SCOPED_TRACE(BatchIsaName(isa));
    CheckLanesAgainstOneState<float>(isa);
  }
}

}  // namespace
}  // namespace hexgait
