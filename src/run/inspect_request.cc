#include "run/inspect_request.h"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "ga/genome_eval.h"
#include "model/rigidity.h"
#include "motor/leg_targets.h"

namespace hexgait {
namespace {

// printf onto the end of `out`, whatever the length (a creature's name is the user's).
[[gnu::format(printf, 2, 3)]] void Appendf(std::string* out, const char* format, ...) {
  va_list args, again;
  va_start(args, format);
  va_copy(again, args);
  const int length = std::vsnprintf(nullptr, 0, format, args);
  va_end(args);
  if (length > 0) {
    const size_t at = out->size();
    out->resize(at + static_cast<size_t>(length) + 1);
    std::vsnprintf(out->data() + at, static_cast<size_t>(length) + 1, format, again);
    out->resize(at + static_cast<size_t>(length));
  }
  va_end(again);
}

}  // namespace

// The whole-creature analyses solve dense eigenvalue and rank problems of 3 to 6 times the
// particles a side, cubic in the size: 14 particles take 0.1 s, 50 take 2 s, 100 take 15 s
// (this machine), 1,000 would take hours. Past this many they are skipped, saying so.
constexpr int kMaxDenseParticles = 100;

std::string InspectReport(const SceneOptions& opt) {
  CheckStep(opt.dt);  // the margins are quoted at this step: 0, -1 or nan printed "inf"
  std::string out;
  const Scene scene = LoadScene(opt);
  const CreatureModel& m = scene.model;
  const bool dense = m.num_particles() <= kMaxDenseParticles;
  const double dt = opt.dt;
  Appendf(&out, "creature   %s: %d particles, %d springs (%zu motor), %d first-order ODEs\n",
          m.name.c_str(), m.num_particles(), m.num_springs(), m.motor_springs.size(),
          6 * m.num_particles());
  double total_mass = 0, moment = 0;
  for (int i = 0; i < m.num_particles(); ++i) {
    total_mass += m.mass[i];
    moment += m.mass[i] * m.rest_position[i].z();
  }
  const double com_height = moment / total_mass;
  Appendf(&out,
          "standing   mass %.3f, centre of mass at height %.3f, tipping time sqrt(h/g) %.2f\n",
          total_mass, com_height, std::sqrt(com_height / m.physics.gravity));
  if (dense) {
    const auto [rank, rigid] = BodyTrussRank(m);
    Appendf(&out, "body truss rigidity rank %d of %d needed (%s)\n", rank, rigid,
            rank == rigid ? "rigid" : "NOT rigid");
  }
  Appendf(&out, "program    %s: %d instructions (with the loop), %d positions, cycle %.1f\n",
          scene.program.name.c_str(), scene.program.num_written_instructions(),
          scene.program.num_positions(), scene.program.cycle_period);

  Appendf(&out,
          "legs (springs; conditioning: smallest singular value of the anchor-to-foot unit "
          "vectors, 1 = orthogonal):\n");
  for (size_t leg = 0; leg < m.legs.size(); ++leg) {
    Appendf(&out, "  %-14s %zu springs, conditioning %.3f\n", m.legs[leg].name.c_str(),
            m.legs[leg].springs.size(), LegConditioning(m, static_cast<int>(leg)));
  }

  if (dense) {
    const std::vector<double> w = PinnedFeetFrequencies(m);
    Appendf(&out,
            "\nnatural frequencies with feet pinned (rad/time unit; period in time units):\n");
    for (size_t i = 0; i < std::min<size_t>(w.size(), 8); ++i) {
      Appendf(&out, "  mode %zu: w = %7.3f  period %7.3f\n", i + 1, w[i], 2 * M_PI / w[i]);
    }
    Appendf(&out, "  highest: w = %.3f, period %.4f\n", w.back(), 2 * M_PI / w.back());
  }

  Appendf(&out, "\nexplicit Euler margins at dt = %g (largest stable step / dt):\n", dt);
  Appendf(&out, "  %-36s %9s %9s %9s %9s\n", "spring or contact", "w", "c", "dt_max", "margin");
  double worst = INFINITY;
  auto row = [&](const std::string& name, double w2, double c) {
    const double dt_max = EulerLargestStableStep(w2, c);
    worst = std::min(worst, dt_max / dt);
    Appendf(&out, "  %-36s %9.3f %9.3f %9.5f %9.2f\n", name.c_str(), std::sqrt(w2), c, dt_max,
            dt_max / dt);
  };
  // Springs with the same stiffness, damping and end masses behave alike: one row per group.
  struct Group {
    std::string name;
    double w2, c;
    int count;
  };
  std::vector<Group> groups;
  for (int s = 0; s < m.num_springs(); ++s) {
    const double ma = m.mass[m.spring_a[s]], mb = m.mass[m.spring_b[s]];
    const double reduced = ma * mb / (ma + mb);
    const double w2 = m.stiffness[s] / reduced, c = m.damping[s] / reduced;
    const std::string kind = m.spring_leg[s] >= 0 ? "leg springs" : "body springs";
    bool found = false;
    for (Group& g : groups) {
      if (g.w2 == w2 && g.c == c && g.name == kind) {
        ++g.count;
        found = true;
      }
    }
    if (!found) groups.push_back({kind, w2, c, 1});
  }
  for (const Group& g : groups) row(g.name + " (" + std::to_string(g.count) + ")", g.w2, g.c);
  double lightest = INFINITY, heaviest = 0;
  for (double mass : m.mass) {
    lightest = std::min(lightest, mass);
    heaviest = std::max(heaviest, mass);
  }
  row("ground contact, lightest particle", m.physics.ground_stiffness / lightest,
      m.physics.ground_damping / lightest);
  row("ground contact, heaviest particle", m.physics.ground_stiffness / heaviest,
      m.physics.ground_damping / heaviest);
  // Friction below slip_velocity is a viscous drag mu N / v_slip on a foot carrying its share
  // of the weight: stable while dt * that / mass < 2.
  const double normal = total_mass * m.physics.gravity / 5.0;  // five feet share the weight
  const double drag = m.physics.friction * normal / m.physics.slip_velocity / lightest;
  Appendf(&out, "  %-36s %9s %9.3f %9.5f %9.2f\n", "friction, foot carrying 1/5 weight", "-", drag,
          2.0 / drag, 2.0 / drag / dt);
  worst = std::min(worst, 2.0 / drag / dt);
  Appendf(&out, "smallest margin: %.2f (stable at dt = %g when above 1)\n", worst, dt);
  if (!dense) {
    Appendf(
        &out,
        "\nwhole-creature analyses (body truss rigidity, pinned-feet frequencies, the linearised "
        "Euler step map) skipped: %d particles is past the %d for which their dense eigenvalue "
        "problems take seconds, not hours\n",
        m.num_particles(), kMaxDenseParticles);
    return out;
  }
  const double radius = LinearisedEulerSpectralRadius(m, dt);
  const double dt_max = LinearisedEulerLargestStableStep(m);
  Appendf(&out, "\nwhole creature, linearised at rest (%d x %d Euler step map):\n",
          6 * m.num_particles(), 6 * m.num_particles());
  Appendf(&out, "  spectral radius at dt = %g: %.9f\n", dt, radius);
  Appendf(&out, "  largest stable step: %.5f (margin %.2f)\n", dt_max, dt_max / dt);
  return out;
}

}  // namespace hexgait
