// The model's physics, written once: a spring's force, ground contact with friction, and the
// explicit Euler update. Every stepping kernel composes these three: the scalar path
// (sim/forces.cc, sim/integrator.cc) on doubles, the batched lanes (sim/batch_kernel_impl.h) on
// GCC vectors of double or float, and the AVX-512 creature kernel
// (sim/creature_kernel_avx512.cc) on 16 floats. The kernels differ only in how they lay out,
// gather and sum their data; the arithmetic and its order are these functions', which is what
// makes a lane bit-identical to the scalar path (docs/model.md, "Batched simulation"). A change
// to the physics, or a new term, is an edit here.
//
// `Ops` supplies the scalar type T, the value type V (one number or a vector of lanes, with
// element-wise + - * /), the lane mask type M, and what plain arithmetic lacks:
//   static V Splat(T)              every lane the value, exactly
//   static V Sqrt(V)               correctly rounded, as std::sqrt
//   static M GreaterEqual(V, V)    ordered comparisons: false where either side is NaN
//   static M LessEqual(V, V)
//   static M NeitherOf(M a, M b)   lanes set in neither
//   static bool All(M)             every lane set
//   static V Select(M, V a, V b)   per lane mask ? a : b, bitwise (signed zeros, NaNs kept)
//
// Linkage matters: the lane kernels are compiled once per instruction set. Each kernel defines
// its Ops in its translation unit's anonymous namespace, so every instantiation of Physics<Ops>
// is private to that unit and the linker can never hand an AVX-512 copy to a generic caller.
#pragma once

namespace hexgait {

template <class T>
struct GroundConstants {
  T stiffness = 0, damping = 0, friction = 0;
  T slip_velocity2 = 0;  // slip_velocity squared
};

template <class Ops>
struct Physics {
  using T = typename Ops::T;
  using V = typename Ops::V;
  using M = typename Ops::M;

  // A spring's force on its `a` end (its `b` end gets the opposite): f = (k (L - L0) + c dL/dt) u,
  // with d = x_b - x_a, dv = v_b - v_a and u = d / L, so a stretched spring pulls its ends
  // together and the damping opposes the rate of stretch.
  [[gnu::always_inline]] static inline void Spring(V dx, V dy, V dz, V dvx, V dvy, V dvz, V k, V c,
                                                   V rest, V& fx, V& fy, V& fz) {
    V length, inv;
    SpringLength(dx, dy, dz, length, inv);
    SpringForce(dx, dy, dz, dvx, dvy, dvz, length, inv, k, c, rest, fx, fy, fz);
  }

  // Spring's two halves, for kernels that start one spring's square root and division before
  // they finish the spring before it (sim/batch_kernel_impl.h): the length and its inverse...
  [[gnu::always_inline]] static inline void SpringLength(V dx, V dy, V dz, V& length, V& inv) {
    length = Ops::Sqrt(dx * dx + dy * dy + dz * dz);
    inv = Ops::Splat(T(1)) / length;
  }
  // ...and the force from them.
  [[gnu::always_inline]] static inline void SpringForce(V dx, V dy, V dz, V dvx, V dvy, V dvz,
                                                        V length, V inv, V k, V c, V rest, V& fx,
                                                        V& fy, V& fz) {
    const V ux = dx * inv, uy = dy * inv, uz = dz * inv;
    const V rate = dvx * ux + dvy * uy + dvz * uz;
    const V magnitude = k * (length - rest) + c * rate;
    fx = magnitude * ux;
    fy = magnitude * uy;
    fz = magnitude * uz;
  }

  // Ground contact, added to a particle's force: below z = 0 a damped penalty spring pushes up
  // and never pulls down; friction opposes sliding with magnitude mu N, made viscous below the
  // slip velocity so the force is smooth in the velocity. Particles above the ground (most of
  // them, most of the time) skip it. A NaN position or normal force applies it, as the lanes
  // and the scalar path must agree on every input.
  [[gnu::always_inline]] static inline void Ground(const GroundConstants<T>& g, V z, V vx, V vy,
                                                   V vz, V& fx, V& fy, V& fz) {
    const V zero = Ops::Splat(T(0));
    const M above = Ops::GreaterEqual(z, zero);
    if (Ops::All(above)) return;
    const V normal = Ops::Splat(-g.stiffness) * z - Ops::Splat(g.damping) * vz;
    const M apply = Ops::NeitherOf(above, Ops::LessEqual(normal, zero));
    const V scale = Ops::Splat(g.friction) * normal /
                    Ops::Sqrt(vx * vx + vy * vy + Ops::Splat(g.slip_velocity2));
    fz = Ops::Select(apply, fz + normal, fz);
    fx = Ops::Select(apply, fx - scale * vx, fx);
    fy = Ops::Select(apply, fy - scale * vy, fy);
  }

  // One explicit Euler step of one axis of a particle: the position from the old velocity, then
  // the velocity from the force; h = dt / mass.
  [[gnu::always_inline]] static inline void EulerAxis(V dt, V h, V f, V& x, V& v) {
    x = x + dt * v;
    v = v + h * f;
  }

  // The same for all three axes.
  [[gnu::always_inline]] static inline void Euler(V dt, V h, V fx, V fy, V fz, V& x, V& y, V& z,
                                                  V& vx, V& vy, V& vz) {
    EulerAxis(dt, h, fx, x, vx);
    EulerAxis(dt, h, fy, y, vy);
    EulerAxis(dt, h, fz, z, vz);
  }
};

}  // namespace hexgait
