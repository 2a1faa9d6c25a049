// Structural checks of a creature: is the body truss rigid, how stiff is it, and how do the
// springs' stiffness and damping bound the explicit Euler step.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "model/creature.h"

namespace hexgait {

// Rank of the rigidity matrix of the bar framework (points, edges). A framework of n points in
// 3-D is infinitesimally rigid when the rank is 3n - 6.
int RigidityRank(const std::vector<Eigen::Vector3d>& points,
                 const std::vector<std::pair<int, int>>& edges);

// Rank for the body particles joined by the body (non-leg) springs, and the rigid target 3n-6.
std::pair<int, int> BodyTrussRank(const CreatureModel& model);

// Angular frequencies (rad per time unit, ascending) of the creature standing with its feet
// pinned: the linearised spring stiffness at the rest pose, body particles free.
std::vector<double> PinnedFeetFrequencies(const CreatureModel& model);

// Explicit Euler stability of a damped oscillator x'' = -w^2 x - c x' with step dt: both
// eigenvalues of the step map inside the unit circle. For c = alpha w^2 (damping proportional
// to stiffness), this needs dt < alpha and w^2 dt (2 alpha - dt) < 4.
bool EulerStableOscillator(double w2, double c, double dt);
// The largest stable dt for that oscillator (bisection on EulerStableOscillator).
double EulerLargestStableStep(double w2, double c);

}  // namespace hexgait

namespace hexgait {

// Spectral radius of the explicit Euler step map I + dt A, where A is the 6N x 6N Jacobian of
// the creature's ODEs linearised at its rest pose: springs, ground contact springs and dampers
// on the particles touching the ground, and friction linearised as a viscous drag (each foot
// carrying an equal share of the weight). Below 1: small disturbances decay.
double LinearisedEulerSpectralRadius(const CreatureModel& model, double dt);
// The largest dt with spectral radius below 1 (bisection).
double LinearisedEulerLargestStableStep(const CreatureModel& model);

}  // namespace hexgait

namespace hexgait {

// How firmly a leg's springs fix its foot relative to the body: the smallest singular value of
// the matrix whose rows are the unit vectors from the leg's body particles to its foot, in the
// rest pose. 1 for three orthogonal springs; near 0 when the foot lies almost in the plane of
// its anchors, where it can snap through under load.
double LegConditioning(const CreatureModel& model, int leg);

}  // namespace hexgait
