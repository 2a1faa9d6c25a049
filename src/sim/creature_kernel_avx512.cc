// The creature kernel (creature_kernel.h) in AVX-512 intrinsics; compiled with AVX-512 flags
// (CMakeLists.txt) and called only on CPUs that have them. The physics is sim/physics_terms.h's,
// as in the lanes kernel, and the spring forces reach each particle in the same order, so that
// each creature's result is bit-identical to a float lane's.
#include <immintrin.h>

#include "sim/creature_kernel.h"
#include "sim/physics_terms.h"

namespace hexgait {

namespace {

// Physics<Ops> (sim/physics_terms.h) on 16 floats in one AVX-512 register.
struct F16 {
  __m512 v;
};
inline F16 operator+(F16 a, F16 b) {
  return {_mm512_add_ps(a.v, b.v)};
}
inline F16 operator-(F16 a, F16 b) {
  return {_mm512_sub_ps(a.v, b.v)};
}
inline F16 operator*(F16 a, F16 b) {
  return {_mm512_mul_ps(a.v, b.v)};
}
inline F16 operator/(F16 a, F16 b) {
  return {_mm512_div_ps(a.v, b.v)};
}

struct Avx512Ops {
  using T = float;
  using V = F16;
  using M = __mmask16;
  static V Splat(T value) { return {_mm512_set1_ps(value)}; }
  static V Sqrt(V a) { return {_mm512_sqrt_ps(a.v)}; }
  static M GreaterEqual(V a, V b) { return _mm512_cmp_ps_mask(a.v, b.v, _CMP_GE_OQ); }
  static M LessEqual(V a, V b) { return _mm512_cmp_ps_mask(a.v, b.v, _CMP_LE_OQ); }
  static M NeitherOf(M a, M b) { return static_cast<M>(~a & ~b); }
  static bool All(M m) { return m == 0xffff; }
  static V Select(M m, V a, V b) { return {_mm512_mask_blend_ps(m, b.v, a.v)}; }
};
using Kernel = Physics<Avx512Ops>;

inline F16 Load(const float* p) {
  return {_mm512_load_ps(p)};
}
inline F16 Gather(__m512i index, F16 from) {
  return {_mm512_permutexvar_ps(index, from.v)};
}

// One creature's step: the particles across the lanes of one register per quantity, the
// springs 16 at a time.
inline void StepOne(const CreatureKernelModel& m, CreatureRegisters& r,
                    const CreatureRestLengths& rest) {
  F16 x = Load(r.x), y = Load(r.y), z = Load(r.z);
  F16 vx = Load(r.vx), vy = Load(r.vy), vz = Load(r.vz);

  // Every spring's force, gathering its ends' particles by index.
  __m512 sfx[3], sfy[3], sfz[3];
  for (int g = 0; g < m.num_groups; ++g) {
    const __m512i a = _mm512_load_si512(m.spring_a[g]);
    const __m512i b = _mm512_load_si512(m.spring_b[g]);
    F16 fx, fy, fz;
    Kernel::Spring(
        Gather(b, x) - Gather(a, x), Gather(b, y) - Gather(a, y), Gather(b, z) - Gather(a, z),
        Gather(b, vx) - Gather(a, vx), Gather(b, vy) - Gather(a, vy), Gather(b, vz) - Gather(a, vz),
        Load(m.stiffness[g]), Load(m.damping[g]), Load(rest.length + 16 * g), fx, fy, fz);
    sfx[g] = fx.v;
    sfy[g] = fy.v;
    sfz[g] = fz.v;
  }
  for (int g = m.num_groups; g < 3; ++g) sfx[g] = sfy[g] = sfz[g] = _mm512_setzero_ps();

  // Each particle's sum, rank by rank: rank r adds (or subtracts) every particle's r-th spring,
  // so each particle's terms arrive in spring order, as in the lanes kernel.
  __m512 fx = _mm512_setzero_ps(), fy = _mm512_setzero_ps();
  __m512 fz = _mm512_load_ps(m.weight);
  for (int k = 0; k < m.num_ranks; ++k) {
    const __m512i s = _mm512_load_si512(m.rank_spring[k]);
    // Springs 0-31 from groups 0 and 1, 32-47 from group 2.
    const __mmask16 high = _mm512_cmpge_epi32_mask(s, _mm512_set1_epi32(32));
    const __m512 gx = _mm512_mask_blend_ps(high, _mm512_permutex2var_ps(sfx[0], s, sfx[1]),
                                           _mm512_permutexvar_ps(s, sfx[2]));
    const __m512 gy = _mm512_mask_blend_ps(high, _mm512_permutex2var_ps(sfy[0], s, sfy[1]),
                                           _mm512_permutexvar_ps(s, sfy[2]));
    const __m512 gz = _mm512_mask_blend_ps(high, _mm512_permutex2var_ps(sfz[0], s, sfz[1]),
                                           _mm512_permutexvar_ps(s, sfz[2]));
    // Particles with no r-th spring keep their sum: the subtraction is masked to the b ends,
    // the addition computed everywhere and blended in at the a ends (one op shorter a chain).
    const __mmask16 add = m.rank_add[k], sub = m.rank_sub[k];
    fx = _mm512_mask_blend_ps(add, _mm512_mask_sub_ps(fx, sub, fx, gx), _mm512_add_ps(fx, gx));
    fy = _mm512_mask_blend_ps(add, _mm512_mask_sub_ps(fy, sub, fy, gy), _mm512_add_ps(fy, gy));
    fz = _mm512_mask_blend_ps(add, _mm512_mask_sub_ps(fz, sub, fz, gz), _mm512_add_ps(fz, gz));
  }

  F16 force_x{fx}, force_y{fy}, force_z{fz};
  const GroundConstants<float> ground = {m.ground_stiffness, m.ground_damping, m.friction,
                                         m.slip_velocity2};
  Kernel::Ground(ground, z, vx, vy, vz, force_x, force_y, force_z);
  Kernel::Euler(Avx512Ops::Splat(m.dt), Load(m.h), force_x, force_y, force_z, x, y, z, vx, vy, vz);
  _mm512_store_ps(r.x, x.v);
  _mm512_store_ps(r.y, y.v);
  _mm512_store_ps(r.z, z.v);
  _mm512_store_ps(r.vx, vx.v);
  _mm512_store_ps(r.vy, vy.v);
  _mm512_store_ps(r.vz, vz.v);
}

}  // namespace

void StepCreaturesAvx512(const CreatureKernelModel& model, CreatureRegisters* creatures,
                         const CreatureRestLengths* rest_length, int count) {
  for (int c = 0; c < count; ++c) StepOne(model, creatures[c], rest_length[c]);
}

}  // namespace hexgait
