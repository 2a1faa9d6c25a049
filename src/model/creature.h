// The creature as immutable data: particles, springs, legs, polygons and physical constants.
// Hot data (masses, spring ends, stiffness) is kept in flat arrays (structure of arrays) so the
// step loop streams through it; names and polygons are only read by tools and the renderer.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace hexgait {

struct PhysicsConstants {
  double gravity = 0.2;  // length / time^2, acting along -z
  // Gravity's component along +x: a slope (the ground tilted about the y axis; an uphill walk
  // has it negative). 0 in the paper and in every creature file; set only by `hexgait
  // endurance`, and modelled by the scalar steppers only (the batched kernels refuse it).
  double gravity_x = 0.0;
  double ground_stiffness = 400.0;  // penalty force per unit penetration depth
  double ground_damping = 4.0;      // normal damping per unit penetration speed
  double friction = 0.8;            // Coulomb coefficient
  double slip_velocity = 0.02;  // regularisation: below this tangential speed friction is viscous
  double fall_height = 0.2;     // a body particle below this height means "fell"
  double fall_tilt_degrees = 45.0;  // or the body's up axis tilted past this angle
};

enum class Side { kRight = -1, kLeft = 1 };

// The most legs a creature may have: a run counts each leg's ground contacts in a fixed array
// (RunResult::foot_down_checks), so results stay plain data for MPI and checkpoints.
inline constexpr int kMaxLegs = 8;

struct Leg {
  std::string name;  // e.g. "right_rear"
  int foot = -1;     // particle index of the foot
  Side side = Side::kRight;
  int mirror = -1;           // index of the mirror-image leg on the other side
  std::vector<int> springs;  // indices of this leg's motor springs, in file order
};

// A polygon vertex that is not a particle: an affine blend of particle positions (weights sum
// to 1; a weight may be negative, to extrapolate). Rendering only: the physics never sees it.
struct SkinVertex {
  std::string name;
  std::vector<std::pair<int, double>> blend;  // (particle index, weight)
};

struct Polygon {
  // Counter-clockwise seen from outside. v < num_particles(): particle v;
  // otherwise skin_vertices[v - num_particles()].
  std::vector<int> vertices;
  bool is_leg = false;  // body and legs are drawn in different colours
};

struct CreatureModel {
  std::string name;

  // Particles.
  std::vector<std::string> particle_names;
  std::vector<double> mass;
  std::vector<double> inv_mass;
  std::vector<Eigen::Vector3d> rest_position;  // the standing pose the creature starts from

  // Springs, structure of arrays.
  std::vector<std::string> spring_names;
  std::vector<int> spring_a;
  std::vector<int> spring_b;
  std::vector<double> stiffness;
  std::vector<double> damping;
  std::vector<double> rest_length;  // at the standing pose; motor springs are driven
  std::vector<int> spring_leg;      // -1 for body springs
  std::vector<char> spring_motor;   // 1 if the controller drives this spring's rest length
  std::vector<int> motor_springs;   // indices of the springs the controller drives
  // Damage (model/damage.h), per spring; both empty for an intact creature. They act where a
  // program's rest lengths are made (motor/leg_targets.h, ga/genome.h), so every simulation
  // path sees them: a locked motor spring keeps rest_length whatever the program says, and a
  // motor spring's commanded lengths are scaled by its motor_length_scale (a shortened leg).
  std::vector<char> spring_locked;
  std::vector<double> motor_length_scale;
  std::string damage;  // what was applied, as --damage writes it; "" intact (for the records)
  std::vector<char> leg_damaged;  // per leg, 1 when damaged (pictures mark it); empty: intact
  // Bit l set: leg l is lost (its foot a loose particle): its foot's contacts are not counted
  // (sim/state.h's FeetOnGround) and pictures leave the leg out.
  uint32_t lost_legs = 0;
  // What pictures leave out of a lost leg: its cut springs (no stiffness, no damping) and its
  // loose foot.
  bool spring_cut(int spring) const { return stiffness[spring] == 0 && damping[spring] == 0; }
  bool particle_loose(int particle) const;

  std::vector<Leg> legs;
  std::vector<Polygon> polygons;
  std::vector<SkinVertex> skin_vertices;  // extra polygon vertices; see Polygon
  PhysicsConstants physics;

  // Derived at load time: which particles make the body and where it faces.
  std::vector<int> body_particles;
  std::vector<int> body_front, body_rear, body_left, body_right;
  double standing_height = 0;  // mean body-particle height in the rest pose

  int num_particles() const { return static_cast<int>(mass.size()); }
  int num_springs() const { return static_cast<int>(spring_a.size()); }
  int LegIndex(const std::string& leg_name) const;  // -1 if none
  bool locked(int spring) const { return !spring_locked.empty() && spring_locked[spring]; }
  double length_scale(int spring) const {
    return motor_length_scale.empty() ? 1.0 : motor_length_scale[spring];
  }
};

// Where polygon vertex `v` is (a particle, or a skin vertex blended from the particle
// positions x, y, z: arrays of num_particles() values).
Eigen::Vector3d VertexPosition(const CreatureModel& model, const double* x, const double* y,
                               const double* z, int v);

// Which leg each polygon belongs to (-1: body), from the leg springs that reach its particles;
// a leg polygon made only of blended skin vertices goes to the leg whose foot is nearest its
// centre in the rest pose (where every foot is at its leg, even a lost leg's). Pictures colour
// and leave out legs by it; computed once per creature.
std::vector<int> PolygonLegs(const CreatureModel& model);

// Fills the derived fields (body particle lists, facing, standing height) and checks the model
// is self-consistent. Throws InputError naming `source` on any problem.
void FinalizeCreature(CreatureModel& model, const std::string& source);

}  // namespace hexgait
