// The creature kernel (creature_kernel.h) in AVX-512 intrinsics; compiled with AVX-512 flags
// (CMakeLists.txt) and called only on CPUs that have them. Every operation below is the one
// batch_kernel_impl.h performs per lane, in the same order, so that each creature's result is
// bit-identical to a float lane's.
#include <immintrin.h>

#include "sim/creature_kernel.h"

namespace hexgait {

namespace {

// One creature's step.
inline void StepOne(const CreatureKernelModel& m, CreatureRegisters& r,
                    const CreatureRestLengths& rest) {
  const __m512 x = _mm512_load_ps(r.x), y = _mm512_load_ps(r.y), z = _mm512_load_ps(r.z);
  const __m512 vx = _mm512_load_ps(r.vx), vy = _mm512_load_ps(r.vy), vz = _mm512_load_ps(r.vz);
  const __m512 one = _mm512_set1_ps(1.0f);

  // Springs, 16 at a time: f = (k (L - L0) + c dL/dt) u.
  __m512 sfx[3], sfy[3], sfz[3];
  for (int g = 0; g < m.num_groups; ++g) {
    const __m512i a = _mm512_load_si512(m.spring_a[g]);
    const __m512i b = _mm512_load_si512(m.spring_b[g]);
    const __m512 dx = _mm512_sub_ps(_mm512_permutexvar_ps(b, x), _mm512_permutexvar_ps(a, x));
    const __m512 dy = _mm512_sub_ps(_mm512_permutexvar_ps(b, y), _mm512_permutexvar_ps(a, y));
    const __m512 dz = _mm512_sub_ps(_mm512_permutexvar_ps(b, z), _mm512_permutexvar_ps(a, z));
    const __m512 length = _mm512_sqrt_ps(_mm512_add_ps(
        _mm512_add_ps(_mm512_mul_ps(dx, dx), _mm512_mul_ps(dy, dy)), _mm512_mul_ps(dz, dz)));
    const __m512 inv = _mm512_div_ps(one, length);
    const __m512 ux = _mm512_mul_ps(dx, inv), uy = _mm512_mul_ps(dy, inv);
    const __m512 uz = _mm512_mul_ps(dz, inv);
    const __m512 dvx = _mm512_sub_ps(_mm512_permutexvar_ps(b, vx), _mm512_permutexvar_ps(a, vx));
    const __m512 dvy = _mm512_sub_ps(_mm512_permutexvar_ps(b, vy), _mm512_permutexvar_ps(a, vy));
    const __m512 dvz = _mm512_sub_ps(_mm512_permutexvar_ps(b, vz), _mm512_permutexvar_ps(a, vz));
    const __m512 rate = _mm512_add_ps(_mm512_add_ps(_mm512_mul_ps(dvx, ux), _mm512_mul_ps(dvy, uy)),
                                      _mm512_mul_ps(dvz, uz));
    const __m512 rest_length = _mm512_load_ps(rest.length + 16 * g);
    const __m512 magnitude = _mm512_add_ps(
        _mm512_mul_ps(_mm512_load_ps(m.stiffness[g]), _mm512_sub_ps(length, rest_length)),
        _mm512_mul_ps(_mm512_load_ps(m.damping[g]), rate));
    sfx[g] = _mm512_mul_ps(magnitude, ux);
    sfy[g] = _mm512_mul_ps(magnitude, uy);
    sfz[g] = _mm512_mul_ps(magnitude, uz);
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

  // Ground: as the lanes kernel, for the particles below it whose normal force would push.
  const __m512 zero = _mm512_setzero_ps();
  const __mmask16 above = _mm512_cmp_ps_mask(z, zero, _CMP_GE_OQ);
  if (above != 0xffff) {
    const __m512 normal = _mm512_sub_ps(_mm512_mul_ps(_mm512_set1_ps(-m.ground_stiffness), z),
                                        _mm512_mul_ps(_mm512_set1_ps(m.ground_damping), vz));
    const __mmask16 pulls = _mm512_cmp_ps_mask(normal, zero, _CMP_LE_OQ);
    const __mmask16 apply = static_cast<__mmask16>(~above & ~pulls);
    const __m512 slide =
        _mm512_sqrt_ps(_mm512_add_ps(_mm512_add_ps(_mm512_mul_ps(vx, vx), _mm512_mul_ps(vy, vy)),
                                     _mm512_set1_ps(m.slip_velocity2)));
    const __m512 scale = _mm512_div_ps(_mm512_mul_ps(_mm512_set1_ps(m.friction), normal), slide);
    fz = _mm512_mask_add_ps(fz, apply, fz, normal);
    fx = _mm512_mask_sub_ps(fx, apply, fx, _mm512_mul_ps(scale, vx));
    fy = _mm512_mask_sub_ps(fy, apply, fy, _mm512_mul_ps(scale, vy));
  }

  // Explicit Euler: positions from the old velocities, velocities from the forces.
  const __m512 dt = _mm512_set1_ps(m.dt);
  const __m512 h = _mm512_load_ps(m.h);
  _mm512_store_ps(r.x, _mm512_add_ps(x, _mm512_mul_ps(dt, vx)));
  _mm512_store_ps(r.y, _mm512_add_ps(y, _mm512_mul_ps(dt, vy)));
  _mm512_store_ps(r.z, _mm512_add_ps(z, _mm512_mul_ps(dt, vz)));
  _mm512_store_ps(r.vx, _mm512_add_ps(vx, _mm512_mul_ps(h, fx)));
  _mm512_store_ps(r.vy, _mm512_add_ps(vy, _mm512_mul_ps(h, fy)));
  _mm512_store_ps(r.vz, _mm512_add_ps(vz, _mm512_mul_ps(h, fz)));
}

}  // namespace

void StepCreaturesAvx512(const CreatureKernelModel& model, CreatureRegisters* creatures,
                         const CreatureRestLengths* rest_length, int count) {
  for (int c = 0; c < count; ++c) StepOne(model, creatures[c], rest_length[c]);
}

}  // namespace hexgait
