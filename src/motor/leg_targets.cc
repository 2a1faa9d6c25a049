#include "motor/leg_targets.h"

namespace hexgait {

Eigen::Vector3d FootTarget(const CreatureModel& model, const MotorProgram& program, int leg,
                           int position) {
  const Leg& l = model.legs[leg];
  Eigen::Vector3d offset = program.positions[position].foot_offset;
  // Offsets are written with y pointing outward; the right side's outward is -y.
  offset.y() *= l.side == Side::kLeft ? 1.0 : -1.0;
  return model.rest_position[l.foot] + offset;
}

RestLengthTable GeometricRestLengths(const CreatureModel& model, const MotorProgram& program) {
  RestLengthTable table;
  table.num_springs = model.num_springs();
  table.num_positions = program.num_positions();
  table.length.resize(static_cast<size_t>(table.num_springs) * table.num_positions);
  for (int p = 0; p < table.num_positions; ++p) {
    for (int s = 0; s < table.num_springs; ++s) {
      double length = model.rest_length[s];
      if (model.spring_motor[s] && !model.locked(s)) {
        const int leg = model.spring_leg[s];
        const int foot = model.legs[leg].foot;
        const int other = model.spring_a[s] == foot ? model.spring_b[s] : model.spring_a[s];
        length = (model.rest_position[other] - FootTarget(model, program, leg, p)).norm() *
                 model.length_scale(s);
      }
      table.length[p * table.num_springs + s] = length;
    }
  }
  return table;
}

}  // namespace hexgait
