// The body's frame (forward, left and up axes) and its lowest point, written once for one state
// (sim/state.cc, on doubles) and for many lanes at a time (sim/lane_measures.cc, on vectors of
// doubles): the fall monitor measures every lane with the same operations in the same order, so
// a lane's tilt is the bits the one-creature path computes.
//
// `Ops` supplies V (a double or a vector of doubles, with element-wise + - * /) and
//   static V Splat(double)          every lane the value
//   static V Sqrt(V)                correctly rounded, as std::sqrt
//   static V SelectPositive(V s, V a, V b)   per lane s > 0 ? a : b
//   static V Min(V a, V b)          per lane std::fmin(a, b) for numbers that are not NaN
// `position(i)` returns particle i's position as a Point<V>.
#pragma once

#include <vector>

#include "model/creature.h"

namespace hexgait {

template <class V>
struct Point {
  V x, y, z;
};

template <class Ops>
struct BodyFrame {
  using V = typename Ops::V;

  // The mean of the particles' positions: summed from zero in index order, divided by the count.
  template <class Position>
  [[gnu::always_inline]] static Point<V> Mean(const std::vector<int>& indices,
                                              const Position& position) {
    Point<V> sum{Ops::Splat(0), Ops::Splat(0), Ops::Splat(0)};
    for (int i : indices) {
      const Point<V> p = position(i);
      sum.x = sum.x + p.x;
      sum.y = sum.y + p.y;
      sum.z = sum.z + p.z;
    }
    const V count = Ops::Splat(static_cast<double>(indices.size()));
    return {sum.x / count, sum.y / count, sum.z / count};
  }

  // The unit vector along `a`, and `a` itself where its length is 0 (as Eigen's normalized()).
  [[gnu::always_inline]] static Point<V> Normalized(const Point<V>& a) {
    const V norm2 = a.x * a.x + a.y * a.y + a.z * a.z;
    const V norm = Ops::Sqrt(norm2);
    return {Ops::SelectPositive(norm2, a.x / norm, a.x),
            Ops::SelectPositive(norm2, a.y / norm, a.y),
            Ops::SelectPositive(norm2, a.z / norm, a.z)};
  }

  [[gnu::always_inline]] static Point<V> Cross(const Point<V>& a, const Point<V>& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
  }

  // Forward: rear to front; left: right to left; up: their cross product, each of unit length.
  template <class Position>
  [[gnu::always_inline]] static void Axes(const CreatureModel& model, const Position& position,
                                          Point<V>& forward, Point<V>& left, Point<V>& up) {
    const Point<V> front = Mean(model.body_front, position);
    const Point<V> rear = Mean(model.body_rear, position);
    forward = Normalized({front.x - rear.x, front.y - rear.y, front.z - rear.z});
    const Point<V> l = Mean(model.body_left, position);
    const Point<V> r = Mean(model.body_right, position);
    left = Normalized({l.x - r.x, l.y - r.y, l.z - r.z});
    up = Normalized(Cross(forward, left));
  }

  // The lowest body particle's height (+infinity for a model without body particles).
  template <class Position>
  [[gnu::always_inline]] static V Lowest(const CreatureModel& model, const Position& position) {
    V lowest = Ops::Splat(__builtin_inf());
    for (int i : model.body_particles) lowest = Ops::Min(lowest, position(i).z);
    return lowest;
  }
};

}  // namespace hexgait
